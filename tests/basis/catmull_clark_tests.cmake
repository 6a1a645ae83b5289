# Tests of the Catmull–Clark backend (registered with iga_add_test).
iga_add_test(test_cc_stam basis/test_cc_stam.cpp)
target_link_libraries(test_cc_stam PRIVATE OpenSubdiv::osdCPU)
iga_add_test(test_cc_space basis/test_cc_space.cpp)
target_link_libraries(test_cc_space PRIVATE OpenSubdiv::osdCPU)
iga_add_test(test_cc_refine basis/test_cc_refine.cpp)
target_link_libraries(test_cc_refine PRIVATE OpenSubdiv::osdCPU)
iga_add_test(test_cc_stam_opensubdiv basis/test_cc_stam_opensubdiv.cpp)
target_link_libraries(test_cc_stam_opensubdiv PRIVATE OpenSubdiv::osdCPU)
