# What makes a repeated build of iga fast (README, "Build times, tests and CI", has the measurements behind each):
# - ccache, when it is installed, as the compiler launcher, set up so that an object does not depend on where
#   the clone is (CI builds a fresh clone on the developer's machine: a warm cache is then legitimate);
# - source paths mapped to the repository root (-ffile-prefix-map), so __FILE__ and debug line tables do not
#   name the clone's folder.
option(IGA_CCACHE "Compile through ccache when it is installed" ON)

if(IGA_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(IGA_CCACHE_PROGRAM ccache)
  if(IGA_CCACHE_PROGRAM)
    # base_dir: paths under the repository are hashed relative to it; no hash_dir: nor is the working folder;
    # depend mode: on a miss ccache reads the compiler's own -MD list of headers instead of running the
    # preprocessor first, so a cold build costs what it costs without ccache (measured: the same to within the
    # noise, README); the sloppiness lets it cache units whose headers are written during the build
    # (io/version_info.cpp's).
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=true CCACHE_DEPEND=true
        CCACHE_SLOPPINESS=include_file_mtime,include_file_ctime ${IGA_CCACHE_PROGRAM})
    message(STATUS "iga: compiling through ${IGA_CCACHE_PROGRAM} (IGA_CCACHE=OFF to stop)")
  endif()
endif()

add_compile_options(-ffile-prefix-map=${PROJECT_SOURCE_DIR}/=)

# No precompiled headers: with GCC 12 they made the units that use them slower here, 2.6 times for an example
# program (README, "Build times, tests and CI").
