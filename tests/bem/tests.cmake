# bem/: the spline curve space, the kernel quadrature, collocation BEM on squares, holes and smooth loops.
iga_add_test(test_spline_curve_space bem/test_spline_curve_space.cpp)
iga_add_test(test_bem_quadrature bem/test_bem_quadrature.cpp)
iga_add_test(test_bem_solve bem/test_bem_solve.cpp)
# Larger systems and timings: labelled slow (excluded from the default run).
add_executable(test_bem_slow bem/test_bem_slow.cpp)
target_compile_options(test_bem_slow PRIVATE ${IGA_WARNINGS})
target_link_libraries(test_bem_slow PRIVATE iga::iga GTest::gtest_main)
target_include_directories(test_bem_slow PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
gtest_discover_tests(test_bem_slow DISCOVERY_MODE PRE_TEST PROPERTIES TIMEOUT 900 LABELS slow ENVIRONMENT "${IGA_TEST_ENVIRONMENT}")
iga_add_test(test_bem_fem_geometries bem/test_bem_fem_geometries.cpp)
