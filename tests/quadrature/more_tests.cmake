# Tests of quadrature/exact, spline_gauss and moment_fit (each helper appends its own lines).
iga_add_test(test_spline_gauss quadrature/test_spline_gauss.cpp)
iga_add_test(test_exact_series quadrature/test_exact_series.cpp)
iga_add_test(test_exact_irregular quadrature/test_exact_irregular.cpp)
iga_add_test(test_exact_geometry quadrature/test_exact_geometry.cpp)
iga_add_test(test_spline_gauss_macro quadrature/test_spline_gauss_macro.cpp)
iga_add_test(test_moment_fit quadrature/test_moment_fit.cpp)
target_link_libraries(test_exact_geometry PRIVATE OpenSubdiv::osdCPU)
iga_add_test(test_log_gauss quadrature/test_log_gauss.cpp)
