#pragma once
// main() of a test program that runs on every rank of mpirun (or alone): a PETSc session around the Google Test
// run, results printed by rank 0, and the exit code 1 on every rank when any rank failed a test.
#include <gtest/gtest.h>

#include "fem/parallel.hpp"

namespace iga::test {

inline int run_tests_on_every_rank(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  int args = 1;
  fem::ParallelSession session(args, argv);
  if (fem::rank() > 0) {
    ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int failed = RUN_ALL_TESTS();
  return fem::max_over_ranks(failed) > 0 ? 1 : 0;
}

}  // namespace iga::test
