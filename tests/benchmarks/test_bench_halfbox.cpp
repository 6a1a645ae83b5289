// bench-halfbox --quick end to end: exit code 0, and a JSON report with every figure of the benchmark present
// as a finite positive number (timings and rates cannot be compared with fixed values; counts can).
#include "support/paths.hpp"
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

void expect_positive(const nlohmann::json& j, const std::string& pointer) {
  const nlohmann::json::json_pointer p(pointer);
  ASSERT_TRUE(j.contains(p)) << pointer;
  ASSERT_TRUE(j.at(p).is_number()) << pointer << " = " << j.at(p);
  const double v = j.at(p).get<double>();
  EXPECT_TRUE(std::isfinite(v) && v > 0) << pointer << " = " << v;
}

TEST(BenchHalfBox, QuickRunWritesEveryFigure) {
  const fs::path dir = fs::temp_directory_path() / ("bench_halfbox_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string data = std::string(IGA_SOURCE_DIR) + "/data/meshes/";
  const std::string cmd = "cd '" + dir.string() + "' && '" + BENCH_HALFBOX_EXE + "' --quick --quiet --tri-mesh '" + data +
                          "tri_square.obj' --quad-mesh '" + data + "square_evs.obj' --json out.json > stdout.txt 2> err.txt";
  const int status = std::system(cmd.c_str());
  std::stringstream err;
  err << std::ifstream(dir / "err.txt").rdbuf();
  ASSERT_EQ(WEXITSTATUS(status), 0) << err.str();
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "out.json"));
  fs::remove_all(dir);

  expect_positive(j, "/halfbox_points_per_second/regular");
  for (const char* n : {"3", "5", "7", "8", "12"}) {
    expect_positive(j, std::string("/halfbox_points_per_second/irregular/") + n);
    expect_positive(j, std::string("/halfbox_points_per_second/ef_time_over_regular/") + n);
    expect_positive(j, std::string("/cc_points_per_second/stam/") + n);
  }
  for (const char* k : {"regular_element", "ev_element", "ev_time_over_regular"}) {
    expect_positive(j, std::string("/cc_points_per_second/") + k);
  }
  EXPECT_TRUE(j.at("ef_within_2x_of_regular").is_boolean());
  for (const char* b : {"halfbox", "cc"}) {
    for (const char* k : {"dofs", "elements", "quadrature_points", "assembly_seconds", "solve_seconds", "threads", "l2_error"}) {
      expect_positive(j, std::string("/poisson/") + b + "/" + k);
    }
  }
  // Quick sizes: the dual of tri_square (128 patches) refined once, square_evs (144 elements) refined once.
  EXPECT_EQ(j["poisson"]["halfbox"]["elements"], 4 * 128);
  EXPECT_EQ(j["poisson"]["cc"]["elements"], 4 * 144);
  // The unit square's area by gauss:4, whose error at the extraordinary elements is 1.1e-5 at this size.
  EXPECT_NEAR(j["poisson"]["cc"]["domain_measure"].get<double>(), 1.0, 2e-5);
}

}  // namespace
