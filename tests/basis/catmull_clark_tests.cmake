# Tests of the Catmull–Clark backend (registered with iga_add_test).
iga_add_test(test_cc_stam basis/test_cc_stam.cpp)
target_link_libraries(test_cc_stam PRIVATE OpenSubdiv::osdCPU)
