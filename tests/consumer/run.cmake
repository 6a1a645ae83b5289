# The installed package, relocated: installs the built project into a fresh prefix, MOVES that prefix to another
# folder (so nothing can point at where it was installed), then, with $IGA_QUADRATURE_DIR unset and from a working
# directory outside the source and build trees,
#   0. checks that no installed library or program holds a path of the source or build tree;
#   1. checks that the moved iga-poisson loads the moved iga libraries (ldd; RPATH $ORIGIN/../lib), not the build
#      tree's, which could find the repository's tables through the build tree's marker file;
#   2. runs the moved iga-poisson with --quadrature fitted on the installed Catmull–Clark net square_evs.obj
#      (the fitted tables come from the moved share/iga/quadrature, found next to the library) and checks the JSON;
#   3. hides the moved tables and checks the one-line error naming where it looked;
#   4. configures, builds and runs tests/consumer against the moved prefix.
# Variables: BUILD_DIR (the build tree), REPO_DIR (the source tree), SOURCE_DIR (tests/consumer), WORK_DIR (scratch,
# emptied first).
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(moved "${WORK_DIR}/moved/iga")
file(MAKE_DIRECTORY "${WORK_DIR}/moved" "${WORK_DIR}/run")
file(RENAME "${WORK_DIR}/prefix" "${moved}")
set(poisson "${moved}/bin/iga-poisson")
set(unset_env "${CMAKE_COMMAND}" -E env --unset=IGA_QUADRATURE_DIR --unset=LD_LIBRARY_PATH)

# 0. No installed library or program names the source tree or the build tree (the tables' place is relative).
file(GLOB installed "${moved}/lib/*.so*" "${moved}/bin/*")
foreach(f IN LISTS installed)
  file(STRINGS "${f}" hits REGEX "${REPO_DIR}/|${BUILD_DIR}/")
  if(hits)
    list(GET hits 0 hit)
    message(FATAL_ERROR "${f} names a path of the source or build tree: ${hit}")
  endif()
endforeach()

# 1. The moved program's iga libraries are the moved ones.
execute_process(COMMAND ldd "${poisson}" OUTPUT_VARIABLE ldd_out RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "ldd ${poisson} failed (${rc})")
endif()
string(REGEX MATCHALL "libiga_[a-z]+\\.so[^\n]*" iga_libs "${ldd_out}")
list(LENGTH iga_libs n_libs)
if(n_libs EQUAL 0)
  message(FATAL_ERROR "ldd lists no libiga_* for ${poisson}:\n${ldd_out}")
endif()
foreach(line IN LISTS iga_libs)
  if(NOT line MATCHES "=> ${moved}/")
    message(FATAL_ERROR "the moved iga-poisson does not load its library from the moved prefix: ${line}")
  endif()
endforeach()
message(STATUS "${n_libs} iga libraries resolved inside ${moved}")

# 2. Fitted quadrature from the moved prefix's own tables.
set(mesh "${moved}/share/iga/meshes/square_evs.obj")
execute_process(COMMAND ${unset_env} "${poisson}" --basis cc --mesh "${mesh}" --quadrature fitted --problem sine
                        --refine 2 --vtu none --json report.json --quiet
                WORKING_DIRECTORY "${WORK_DIR}/run" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the moved iga-poisson --quadrature fitted failed (${rc}): ${err}")
endif()
file(READ "${WORK_DIR}/run/report.json" report)
string(JSON quadrature GET "${report}" quadrature)
string(JSON l2 GET "${report}" l2_error)
string(JSON area GET "${report}" domain_measure)
message(STATUS "moved iga-poisson: quadrature ${quadrature}, l2_error ${l2}, domain_measure ${area}")
# The net's limit domain is the unit square (straight boundary, corners interpolated). The fitted phi rules
# integrate the subdivision splines exactly but not det J, so the area by the same rules is off by 6.5e-5
# (measured: 0.9999354); the L2 error of sin(πx) sin(πy) on 2 refinements is 4.46e-5 (measured). Bounds at about
# twice those: a table missing or wrong gives an error or a different answer.
if(NOT quadrature STREQUAL "fitted" OR NOT l2 LESS 1e-4 OR NOT l2 GREATER 0)
  message(FATAL_ERROR "unexpected report: quadrature '${quadrature}', l2_error ${l2}")
endif()
if(area LESS 0.9998 OR area GREATER 1.0002)
  message(FATAL_ERROR "domain_measure ${area}, expected 1 - 6.5e-5 (unit square, fitted rules)")
endif()

# 3. Without the moved tables: one line naming the places looked at, exit 1.
file(RENAME "${moved}/share/iga/quadrature" "${moved}/share/iga/quadrature.hidden")
execute_process(COMMAND ${unset_env} "${poisson}" --basis cc --mesh "${mesh}" --quadrature fitted --vtu none
                        --json none --quiet
                WORKING_DIRECTORY "${WORK_DIR}/run" RESULT_VARIABLE rc ERROR_VARIABLE err)
file(RENAME "${moved}/share/iga/quadrature.hidden" "${moved}/share/iga/quadrature")
string(STRIP "${err}" err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "IGA_QUADRATURE_DIR" OR NOT err MATCHES "${moved}/share/iga/quadrature")
  message(FATAL_ERROR "without tables: expected exit 1 and a line naming ${moved}/share/iga/quadrature, got ${rc}: ${err}")
endif()
message(STATUS "without tables: ${err}")

# 4. An outside project against the moved prefix.
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/build"
                        "-DCMAKE_PREFIX_PATH=${moved}" -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer project failed (${rc})")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK_DIR}/build" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer project failed (${rc})")
endif()
execute_process(COMMAND ${unset_env} "${WORK_DIR}/build/consumer" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the consumer program failed (${rc})")
endif()
