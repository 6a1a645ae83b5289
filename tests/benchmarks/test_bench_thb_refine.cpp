// bench-thb-refine on small meshes end to end: exit code 0 (the program itself refuses to report when the
// incremental build and the whole build of the same refined cells differ in dofs or prolongation entries), and a
// JSON report whose counts are the closed forms of its set-up: 4^K elements at K uniform refinements of one
// bi-quadratic interval, the marked cells refined without any closure (the mesh is uniform), and the dofs after
// refining the corner cell.
#include "support/paths.hpp"
#include "support/program_run.hpp"
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace fs = std::filesystem;

TEST(BenchThbRefine, SmallRunReportsEveryMeasurement) {
  const fs::path dir = fs::temp_directory_path() / ("bench_thb_refine_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto run = iga::test::run_program(dir, BENCH_THB_REFINE_EXE,
                                          "--min-refine 3 --max-refine 4 --repeat 1 --marked 1 5 40 --json out.json");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "out.json"));
  fs::remove_all(dir);
  // 64 elements: 1 and 5 marked (40 is above a quarter); 256 elements: all three.
  ASSERT_EQ(j["runs"].size(), 5u);
  const int elements[] = {64, 64, 256, 256, 256}, marked[] = {1, 5, 1, 5, 40};
  for (std::size_t i = 0; i < 5; ++i) {
    const nlohmann::json& r = j["runs"][i];
    EXPECT_EQ(r["elements"], elements[i]);
    EXPECT_EQ(r["marked"], marked[i]);
    EXPECT_EQ(r["refined_cells"], marked[i]);
    EXPECT_TRUE(r["incremental"].get<bool>());
    // (2^K + 2)² functions before; refining the corner cell adds the 2 × 2 fine functions supported in it (open
    // knots: supports [0, h/2] and [0, h] in each direction) and removes the coarse corner function (support [0, h]²).
    const int before = elements[i] == 64 ? 100 : 324;
    if (marked[i] == 1) {
      EXPECT_EQ(r["dofs"].get<int>(), before + 3);
    }
    EXPECT_GT(r["dofs"].get<int>(), before);
    for (const char* k : {"refine_seconds", "prolongation_seconds", "whole_build_seconds", "whole_prolongation_seconds"}) {
      const double v = r[k].get<double>();
      EXPECT_TRUE(std::isfinite(v) && v > 0) << k << " = " << v;
    }
  }
}

// --mesh: hierarchical Catmull–Clark (clamped, cell-by-cell levels) on the 48-face L-shape: 48 · 4^K elements, the
// marked cells refined without closure, incremental builds equal to whole ones (checked by the program), and
// --degree refused with it.
TEST(BenchThbRefine, CatmullClarkNet) {
  const fs::path dir = fs::temp_directory_path() / ("bench_thb_refine_cc_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string mesh = std::string(IGA_SOURCE_DIR) + "/data/meshes/l_shape.obj";
  const auto run = iga::test::run_program(dir, BENCH_THB_REFINE_EXE,
                                          "--mesh " + mesh + " --min-refine 1 --max-refine 2 --repeat 1 --marked 1 10 --json out.json");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "out.json"));
  EXPECT_EQ(j["basis"], "cc");
  ASSERT_EQ(j["runs"].size(), 4u);
  const int elements[] = {192, 192, 768, 768}, marked[] = {1, 10, 1, 10};
  for (std::size_t i = 0; i < 4; ++i) {
    const nlohmann::json& r = j["runs"][i];
    EXPECT_EQ(r["elements"], elements[i]);
    EXPECT_EQ(r["refined_cells"], marked[i]);
    EXPECT_TRUE(r["incremental"].get<bool>());
  }
  const auto bad = iga::test::run_program(dir, BENCH_THB_REFINE_EXE, "--mesh " + mesh + " --degree 3 --min-refine 1 --max-refine 1");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("--degree does not apply to --mesh"), std::string::npos) << bad.err;
  fs::remove_all(dir);
}
