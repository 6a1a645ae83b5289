# examples/: every example runs (its default is the quick variant) and checks its own result; exit 0 = passed.
# Meshes come from the source tree's data/meshes; outputs go to the test's own folder.
set(IGA_EXAMPLE_DATA ${PROJECT_SOURCE_DIR}/data/meshes)
set(IGA_EXAMPLE_DIR ${CMAKE_CURRENT_BINARY_DIR}/examples)
file(MAKE_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_poisson_annulus COMMAND poisson_annulus WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_laplace_beltrami_cube COMMAND laplace_beltrami_cube --mesh ${IGA_EXAMPLE_DATA}/cube.obj
         WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_polyhedral_square COMMAND polyhedral_square --mesh ${IGA_EXAMPLE_DATA}/square_evs.obj
         WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_refinement_series COMMAND refinement_series --out ${IGA_EXAMPLE_DIR}/series
         WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_clamped_boundary COMMAND clamped_boundary --mesh ${IGA_EXAMPLE_DATA}/square_6x6.obj
         WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_clamped_boundary_nitsche COMMAND clamped_boundary --mesh ${IGA_EXAMPLE_DATA}/square_6x6.obj --nitsche
         WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
set_tests_properties(example_poisson_annulus example_laplace_beltrami_cube example_polyhedral_square
                     example_refinement_series example_clamped_boundary example_clamped_boundary_nitsche
                     PROPERTIES LABELS examples TIMEOUT 300)
# refinement_series checks that its files exist: start it from an empty folder, so old files cannot pass for new.
add_test(NAME example_refinement_series_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${IGA_EXAMPLE_DIR}/series)
set_tests_properties(example_refinement_series_clean PROPERTIES FIXTURES_SETUP example_series LABELS examples)
set_tests_properties(example_refinement_series PROPERTIES FIXTURES_REQUIRED example_series)
# The distributed driver under mpirun at 2 ranks (as root in CI: --allow-run-as-root), one OpenMP thread each.
add_test(NAME example_poisson_petsc
         COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 --allow-run-as-root --oversubscribe $<TARGET_FILE:poisson_petsc>
         WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
set_tests_properties(example_poisson_petsc PROPERTIES LABELS "examples;mpi" TIMEOUT 300 ENVIRONMENT "OMP_NUM_THREADS=1")
# Fourth-order plates and elasticity (pde/): serial, and under mpirun at 2 ranks compared with CHOLMOD to 1e-10.
add_test(NAME example_biharmonic_plate COMMAND biharmonic_plate WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_plate_with_hole COMMAND plate_with_hole WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
add_test(NAME example_scordelis_lo_roof COMMAND scordelis_lo_roof WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
set_tests_properties(example_biharmonic_plate example_plate_with_hole example_scordelis_lo_roof PROPERTIES LABELS examples
                     TIMEOUT 300)
foreach(example biharmonic_plate plate_with_hole scordelis_lo_roof)
  add_test(NAME example_${example}_petsc
           COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 --allow-run-as-root --oversubscribe
                   $<TARGET_FILE:${example}> --petsc
           WORKING_DIRECTORY ${IGA_EXAMPLE_DIR})
  set_tests_properties(example_${example}_petsc PROPERTIES LABELS "examples;mpi" TIMEOUT 300
                       ENVIRONMENT "OMP_NUM_THREADS=1")
endforeach()
