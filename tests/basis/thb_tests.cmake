iga_add_test(test_thb basis/test_thb.cpp)
