# README.md's commands for this project's programs, run from a scratch folder against this build tree
# (run_readme_commands.py says which commands run and how); fails naming the README line of a failing one.
# In two shares of the README's command groups (--shard K/2), so that no test takes over 20 s.
foreach(k 1 2)
  add_test(NAME readme_commands_${k}of2
    COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/docs/run_readme_commands.py --readme ${PROJECT_SOURCE_DIR}/README.md
            --source-dir ${PROJECT_SOURCE_DIR} --build-dir ${PROJECT_BINARY_DIR} --shard ${k}/2)
  set_tests_properties(readme_commands_${k}of2 PROPERTIES LABELS docs TIMEOUT 900)
endforeach()
