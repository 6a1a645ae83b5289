// iga-quadrature end to end: exact and quadrature areas/volumes of the project's nets, JSON, errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;

namespace {
struct Outcome {
  int code;
  std::string err;
  nlohmann::json report;
};

Outcome run(const std::string& args) {
  const fs::path dir = fs::temp_directory_path() / ("iga_quadrature_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cmd = std::string("'") + IGA_QUADRATURE_EXE + "' " + args + " --json '" + (dir / "r.json").string() +
                          "' > /dev/null 2> '" + (dir / "err.txt").string() + "'";
  const int status = std::system(cmd.c_str());
  Outcome o{WEXITSTATUS(status), "", nullptr};
  std::stringstream ss;
  ss << std::ifstream(dir / "err.txt").rdbuf();
  o.err = ss.str();
  if (o.code == 0) o.report = nlohmann::json::parse(std::ifstream(dir / "r.json"));
  fs::remove_all(dir);
  return o;
}

std::string net(const std::string& name) { return "--mesh '" + std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name + "'"; }
}  // namespace

// The unit-square net (interior and boundary EVs, corners interpolated, straight boundary): area 1.
TEST(IgaQuadrature, ExactAreaOfTheSquareNet) {
  const Outcome o = run(net("square_evs.obj") + " --quantity area --method exact");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NEAR(o.report["value"].get<double>(), 1.0, 1e-13);
  EXPECT_GT(o.report["irregular_elements"].get<int>(), 0);
}

// Per-tile and macro rules report their error against the exact value and the points they spend; both
// shrink the error as levels grow.
TEST(IgaQuadrature, QuadratureErrorsAgainstExact) {
  double previous = 1.0;
  for (int levels : {4, 8, 12}) {
    const Outcome o = run(net("square_evs.obj") + " --quantity area --method tiles:4:" + std::to_string(levels));
    ASSERT_EQ(o.code, 0) << o.err;
    const double err = std::abs(o.report["error"].get<double>());
    EXPECT_LT(err, 0.02 * previous);
    previous = err;
    EXPECT_GT(o.report["points_around_evs"].get<int>(), 0);
  }
  // The macro rule (r = 2) at the same 12 levels: the same error (it is exact on the rings, like the tiles),
  // with fewer points.
  const Outcome t = run(net("square_evs.obj") + " --quantity area --method tiles:4:12");
  const Outcome m = run(net("square_evs.obj") + " --quantity area --method macro:2:12");
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_NEAR(m.report["error"].get<double>(), t.report["error"].get<double>(), 1e-14);
  EXPECT_LT(m.report["points_around_evs"].get<int>(), t.report["points_around_evs"].get<int>());
}

// Volume of the closed cube net: the exact value and per-tile quadrature agree as levels grow.
TEST(IgaQuadrature, VolumeOfTheCubeNet) {
  const Outcome e = run(net("cube.obj") + " --quantity volume --method exact");
  ASSERT_EQ(e.code, 0) << e.err;
  const double exact = e.report["value"].get<double>();
  EXPECT_GT(exact, 0.0);
  EXPECT_LT(exact, 8.0);  // inside the control cube [-1,1]^3
  const Outcome t = run(net("cube.obj") + " --quantity volume --method tiles:4:16");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NEAR(t.report["value"].get<double>(), exact, 1e-12 * exact);
}

TEST(IgaQuadrature, BadInputGivesOneLine) {
  for (const std::string& args : {net("cube.obj") + " --quantity area", net("square_evs.obj") + " --quantity volume",
                                  net("square_evs.obj") + " --method simpson:3"}) {
    const Outcome o = run(args);
    EXPECT_NE(o.code, 0) << args;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
  }
}
