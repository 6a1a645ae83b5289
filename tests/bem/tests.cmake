# bem/: the spline curve space, the kernel quadrature, collocation BEM on squares, holes and smooth loops.
iga_add_test(test_spline_curve_space bem/test_spline_curve_space.cpp)
iga_add_test(test_bem_quadrature bem/test_bem_quadrature.cpp)
iga_add_test(test_bem_solve bem/test_bem_solve.cpp)
