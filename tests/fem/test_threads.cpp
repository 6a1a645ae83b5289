// --threads governs every pool (issue 17): OpenMP's, parallel regions that ask for their own thread count (as
// Debian's CHOLMOD does with num_threads(4)) inside within_thread_limit, and OpenBLAS's when it is the BLAS loaded.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <stdexcept>

#include "core/error.hpp"
#include "fem/threads.hpp"

using namespace iga;

namespace {
// The team size of a parallel region that asks for 4 threads, as a library's would.
int team_of_four() {
  int team = 0;
#pragma omp parallel num_threads(4)
  {
#pragma omp single
    team = omp_get_num_threads();
  }
  return team;
}
}  // namespace

TEST(Threads, ExplicitTeamsAreHeldToTheLimit) {
  const int before = fem::num_threads();
  for (int n : {1, 2}) {
    fem::set_num_threads(n);
    EXPECT_EQ(fem::num_threads(), n);
    int inside = 0;
    fem::within_thread_limit([&] { inside = team_of_four(); });
    EXPECT_EQ(inside, n);
  }
  EXPECT_EQ(team_of_four(), 4);  // outside, the clause is what OpenMP follows (what the limit is for)
  fem::set_num_threads(before);
  EXPECT_THROW(fem::set_num_threads(0), InputError);
}

TEST(Threads, ExceptionsLeaveTheLimitedRegion) {
  EXPECT_THROW(fem::within_thread_limit([] { throw NumericalError("inside"); }), NumericalError);
}

// OpenBLAS's own pool follows set_num_threads; skipped when the process's BLAS is another (Debian alternatives).
TEST(Threads, OpenBlasFollows) {
  using Get = int (*)();
  void* get = dlsym(RTLD_DEFAULT, "openblas_get_num_threads");
  if (get == nullptr) GTEST_SKIP() << "the BLAS loaded is not OpenBLAS";
  const int before = fem::num_threads();
  fem::set_num_threads(1);
  EXPECT_EQ(reinterpret_cast<Get>(get)(), 1);
  fem::set_num_threads(2);
  EXPECT_EQ(reinterpret_cast<Get>(get)(), 2);
  fem::set_num_threads(before);
}
