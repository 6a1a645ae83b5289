# Tests of the three-valent net constructions (registered with iga_add_test).
iga_add_test(test_three_valent mesh/test_three_valent.cpp)
