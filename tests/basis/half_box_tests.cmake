# Tests of the half-box spline backend (registered with iga_add_test).
iga_add_test(test_half_box_regular basis/test_half_box_regular.cpp)
iga_add_test(test_half_box_subdivision basis/test_half_box_subdivision.cpp)
iga_add_test(test_half_box_structure basis/test_half_box_structure.cpp)
iga_add_test(test_half_box_irregular basis/test_half_box_irregular.cpp)
iga_add_test(test_half_box_poisson fem/test_half_box_poisson.cpp)
iga_add_test(test_exact_half_box quadrature/test_exact_half_box.cpp)
iga_add_test(test_half_box_refinement basis/test_half_box_refinement.cpp)
