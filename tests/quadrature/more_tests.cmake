# Tests of quadrature/exact, spline_gauss and moment_fit (each helper appends its own lines).
iga_add_test(test_spline_gauss quadrature/test_spline_gauss.cpp)
iga_add_test(test_spline_gauss_macro quadrature/test_spline_gauss_macro.cpp)
