iga_add_test(test_thb basis/test_thb.cpp)
iga_add_test(test_second_derivatives fem/test_second_derivatives.cpp)
