# Tests of the polyhedral-spline backend: configurations, Bézier patches, .bv I/O, iga-geometry.
iga_add_test(test_polyhedral_configuration basis/test_polyhedral_configuration.cpp)
iga_add_test(test_polyhedral_bezier basis/test_polyhedral_bezier.cpp)
iga_add_test(test_bv io/test_bv.cpp)
# The mask derivation registers its own tests.
if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/polyhedral_mask_tests.cmake)
  include(${CMAKE_CURRENT_LIST_DIR}/polyhedral_mask_tests.cmake)
endif()
# iga-geometry end to end (its .vtu read back with VTK).
iga_add_test(test_iga_geometry tools/test_iga_geometry.cpp VTK::IOXML VTK::CommonDataModel VTK::CommonCore)
add_dependencies(test_iga_geometry iga-geometry)
iga_add_test(test_polyhedral_space basis/test_polyhedral_space.cpp)
iga_add_test(test_polyhedral_poisson fem/test_polyhedral_poisson.cpp)
iga_add_test(test_polyhedral_reference_nets basis/test_polyhedral_reference_nets.cpp)
