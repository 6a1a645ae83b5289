# Tests of the polyhedral mask derivation (g1_cap, star_cap, ngon_cap, polar_cap, tjunction_cap); included by
# polyhedral_tests.cmake.
iga_add_test(test_polyhedral_star basis/test_polyhedral_star.cpp)
iga_add_test(test_polyhedral_ngon basis/test_polyhedral_ngon.cpp)
iga_add_test(test_polyhedral_polar basis/test_polyhedral_polar.cpp)
iga_add_test(test_polyhedral_tjunction basis/test_polyhedral_tjunction.cpp)
