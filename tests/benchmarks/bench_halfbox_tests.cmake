# bench-halfbox --quick end to end (its JSON): the quick variant of the benchmark, labelled "benchmark" and in
# the default run (only "slow" is excluded there).
add_executable(test_bench_halfbox benchmarks/test_bench_halfbox.cpp)
target_compile_options(test_bench_halfbox PRIVATE ${IGA_WARNINGS})
target_link_libraries(test_bench_halfbox PRIVATE GTest::gtest_main nlohmann_json::nlohmann_json)
target_include_directories(test_bench_halfbox PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
add_dependencies(test_bench_halfbox bench-halfbox)
gtest_discover_tests(test_bench_halfbox DISCOVERY_MODE PRE_TEST PROPERTIES TIMEOUT 600 LABELS benchmark
                     ENVIRONMENT "${IGA_TEST_ENVIRONMENT}")
