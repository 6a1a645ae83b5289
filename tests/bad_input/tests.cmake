# The hostile-input corpus (tests/bad_input/): every case runs one program on malformed or extreme input and
# checks its exit code and its one line on stderr (run_corpus.py; cases in tests/bad_input/cases/*.ini).
set(IGA_CORPUS_PROGRAMS iga-poisson iga-biharmonic iga-elasticity iga-shell iga-bem iga-quadrature iga-geometry iga-knots iga-fit-quadrature)
set(corpus_args)
foreach(p IN LISTS IGA_CORPUS_PROGRAMS)
  list(APPEND corpus_args --exe "${p}=$<TARGET_FILE:${p}>")
endforeach()
# In three shares (--shard K/3, every third case), so that no test takes over 20 s and two cores run it side by side.
foreach(k 1 2 3)
  add_test(NAME bad_input_corpus_${k}of3
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/bad_input/run_corpus.py ${corpus_args} --shard ${k}/3)
  set_tests_properties(bad_input_corpus_${k}of3 PROPERTIES TIMEOUT 1200 LABELS corpus)
endforeach()
