# bench-thb-refine on small meshes end to end (its JSON), labelled "benchmark" and in the default run.
add_executable(test_bench_thb_refine benchmarks/test_bench_thb_refine.cpp)
target_compile_options(test_bench_thb_refine PRIVATE ${IGA_WARNINGS})
target_link_libraries(test_bench_thb_refine PRIVATE GTest::gtest_main nlohmann_json::nlohmann_json)
target_include_directories(test_bench_thb_refine PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
add_dependencies(test_bench_thb_refine bench-thb-refine)
gtest_discover_tests(test_bench_thb_refine DISCOVERY_MODE PRE_TEST PROPERTIES TIMEOUT 600 LABELS benchmark
                     ENVIRONMENT "${IGA_TEST_ENVIRONMENT}")
