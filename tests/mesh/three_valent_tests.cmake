# Tests of the three-valent net constructions (registered with iga_add_test).
