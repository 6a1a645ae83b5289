# Finds OpenSubdiv's CPU library. Debian 12's libosd-dev ships an OpenSubdivConfig.cmake whose exported
# targets reference static libraries the package does not contain, so the CONFIG mode fails there.
# Defines OpenSubdiv_FOUND and the imported target OpenSubdiv::osdCPU.
find_path(OpenSubdiv_INCLUDE_DIR opensubdiv/version.h)
find_library(OpenSubdiv_osdCPU_LIBRARY osdCPU)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenSubdiv REQUIRED_VARS OpenSubdiv_osdCPU_LIBRARY OpenSubdiv_INCLUDE_DIR)
if(OpenSubdiv_FOUND AND NOT TARGET OpenSubdiv::osdCPU)
  add_library(OpenSubdiv::osdCPU UNKNOWN IMPORTED)
  set_target_properties(OpenSubdiv::osdCPU PROPERTIES
    IMPORTED_LOCATION "${OpenSubdiv_osdCPU_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${OpenSubdiv_INCLUDE_DIR}")
endif()
mark_as_advanced(OpenSubdiv_INCLUDE_DIR OpenSubdiv_osdCPU_LIBRARY)
