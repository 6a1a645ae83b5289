# refine/: knot insertion, refine-and-smooth, and the iga-knots program end to end.
iga_add_test(test_knot_insertion refine/test_knot_insertion.cpp)
iga_add_test(test_refine_smooth refine/test_refine_smooth.cpp)
iga_add_test(test_iga_knots refine/test_iga_knots.cpp)
add_dependencies(test_iga_knots iga-knots)
iga_add_test(test_adaptive refine/test_adaptive.cpp)
