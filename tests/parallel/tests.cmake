# parallel/: the distributed solver (fem/linear_system.hpp, "petsc") against the serial one: one program, run
# without mpirun (1 rank) and under mpirun at 2, 3 and 4 ranks (--allow-run-as-root: CI runs as root;
# --oversubscribe: 3 and 4 ranks on this 2-core machine). One OpenMP thread per rank. Label mpi.
add_executable(test_petsc ${CMAKE_CURRENT_LIST_DIR}/test_petsc.cpp)
target_compile_options(test_petsc PRIVATE ${IGA_WARNINGS})
target_link_libraries(test_petsc PRIVATE iga::iga GTest::gtest)
target_include_directories(test_petsc PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
add_test(NAME petsc_1_rank COMMAND test_petsc)
foreach(n 2 3 4)
  add_test(NAME petsc_${n}_ranks
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${n} --allow-run-as-root --oversubscribe $<TARGET_FILE:test_petsc>)
endforeach()
set_tests_properties(petsc_1_rank petsc_2_ranks petsc_3_ranks petsc_4_ranks PROPERTIES LABELS mpi TIMEOUT 600
                     ENVIRONMENT "OMP_NUM_THREADS=1")
# iga-poisson --solver petsc end to end (mpirun at 2 ranks and without it): report, errors, failures as one line.
add_test(NAME program_petsc
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/program_petsc.py $<TARGET_FILE:iga-poisson> ${MPIEXEC_EXECUTABLE}
                 ${CMAKE_CURRENT_BINARY_DIR}/program_petsc)
set_tests_properties(program_petsc PROPERTIES LABELS mpi TIMEOUT 600)
# iga-biharmonic, iga-elasticity and iga-shell --solver petsc at 2 ranks against CHOLMOD.
add_test(NAME pde_programs_petsc
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/pde_programs_petsc.py $<TARGET_FILE:iga-biharmonic>
                 $<TARGET_FILE:iga-elasticity> ${MPIEXEC_EXECUTABLE} ${CMAKE_CURRENT_BINARY_DIR}/pde_programs_petsc
                 $<TARGET_FILE:iga-shell>)
set_tests_properties(pde_programs_petsc PROPERTIES LABELS mpi TIMEOUT 600)
# Geometric multigrid (--solver mg, fem/multigrid.hpp, PCMG) against CHOLMOD, at 1 rank and under mpirun at 2.
add_executable(test_multigrid ${CMAKE_CURRENT_LIST_DIR}/test_multigrid.cpp)
target_compile_options(test_multigrid PRIVATE ${IGA_WARNINGS})
target_link_libraries(test_multigrid PRIVATE iga::iga GTest::gtest)
target_include_directories(test_multigrid PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
add_test(NAME multigrid_1_rank COMMAND test_multigrid)
add_test(NAME multigrid_2_ranks
         COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 --allow-run-as-root --oversubscribe $<TARGET_FILE:test_multigrid>)
set_tests_properties(multigrid_1_rank multigrid_2_ranks PROPERTIES LABELS mpi TIMEOUT 600 ENVIRONMENT "OMP_NUM_THREADS=1")
# A driver's own communicator (fem/parallel_mpi.hpp): the world split in two halves, each solving on its own.
add_executable(test_communicator ${CMAKE_CURRENT_LIST_DIR}/test_communicator.cpp)
target_compile_options(test_communicator PRIVATE ${IGA_WARNINGS})
target_link_libraries(test_communicator PRIVATE iga::iga GTest::gtest MPI::MPI_CXX)
target_include_directories(test_communicator PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
foreach(n 3 4)
  add_test(NAME communicator_${n}_ranks
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${n} --allow-run-as-root --oversubscribe $<TARGET_FILE:test_communicator>)
endforeach()
set_tests_properties(communicator_3_ranks communicator_4_ranks PROPERTIES LABELS mpi TIMEOUT 600 ENVIRONMENT "OMP_NUM_THREADS=1")
# A rank killed mid-run (signal 9, as the out-of-memory killer would) stops every rank within seconds, one line naming it.
add_test(NAME rank_fault COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/rank_fault.py $<TARGET_FILE:iga-poisson> ${MPIEXEC_EXECUTABLE})
set_tests_properties(rank_fault PROPERTIES LABELS mpi TIMEOUT 120)
# Every PDE on every backend, distributed, against CHOLMOD (test_pde_ranks.cpp): alone and at 2, 3 and 4 ranks.
add_executable(test_pde_ranks ${CMAKE_CURRENT_LIST_DIR}/test_pde_ranks.cpp)
target_compile_options(test_pde_ranks PRIVATE ${IGA_WARNINGS})
target_link_libraries(test_pde_ranks PRIVATE iga::iga GTest::gtest)
target_include_directories(test_pde_ranks PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
add_test(NAME pde_ranks_1 COMMAND test_pde_ranks)
foreach(n 2 3 4)
  add_test(NAME pde_ranks_${n}
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${n} --allow-run-as-root --oversubscribe $<TARGET_FILE:test_pde_ranks>)
endforeach()
set_tests_properties(pde_ranks_1 pde_ranks_2 pde_ranks_3 pde_ranks_4 PROPERTIES LABELS mpi TIMEOUT 600 ENVIRONMENT "OMP_NUM_THREADS=1")
