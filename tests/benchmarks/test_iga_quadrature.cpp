// iga-quadrature end to end: exact and quadrature areas/volumes of the project's nets, JSON, errors.
#include "support/paths.hpp"
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "mesh/obj_reader.hpp"
#include "mesh/obj_writer.hpp"
#include "mesh/three_valent.hpp"

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

// Mass and parametric stiffness matrices of the irregular element (--valence N) against the exact matrices
// (geometric series, quadrature/exact/irregular_integrals.hpp): every stored fitted mass/stiffness table
// reproduces them to 1e-12 relative (Frobenius) with its few points; a low-order rule does not; a fine
// per-tile rule converges to them (an independent check of the exact matrices and of the comparison).
TEST(IgaQuadrature, FittedMassAndStiffnessRulesReproduceTheExactMatrices) {
  int tables = 0;
  for (const std::string space : {"mass", "stiffness"}) {
    for (int n = 3; n <= 16; ++n) {
      const fs::path table = fs::path(IGA_SOURCE_DIR) / "data" / "quadrature" / ("cc_" + space + "_n" + std::to_string(n) + ".txt");
      if (!fs::exists(table)) continue;
      ++tables;
      const std::string element = "--quantity " + space + " --valence " + std::to_string(n);
      const Outcome f = run(element + " --method fitted:" + space);
      ASSERT_EQ(f.code, 0) << f.err;
      EXPECT_LE(f.report["relative_frobenius_error"].get<double>(), 1e-12) << space << " n=" << n;
      EXPECT_GT(f.report["points_per_irregular_element"].get<int>(), 0);
      EXPECT_EQ(f.report["irregular_elements"].get<int>(), 1);
      // 2 × 2 Gauss per tile on one level: integrands of degree 6 per direction are not integrated exactly.
      const Outcome low = run(element + " --method tiles:2:1");
      ASSERT_EQ(low.code, 0) << low.err;
      EXPECT_GT(low.report["relative_frobenius_error"].get<double>(), 1e-5) << space << " n=" << n;
    }
  }
  EXPECT_GE(tables, 2);  // at least the mass and stiffness rules of valence 4
  for (const std::string space : {"mass", "stiffness"}) {
    const Outcome fine = run("--quantity " + space + " --valence 5 --method tiles:4:24");
    ASSERT_EQ(fine.code, 0) << fine.err;
    EXPECT_LE(fine.report["relative_frobenius_error"].get<double>(), 1e-13) << space;
    EXPECT_EQ(run("--quantity " + space + " --valence 5 --method exact").report["max_abs_error"].get<double>(), 0.0);
  }
}

// --mesh: the ring sums over the elements at interior EVs. The folded macro rule (exact over a closed ring
// on the tiles it covers) gives the per-tile rule's error at the same levels with fewer points.
TEST(IgaQuadrature, MacroRuleOnRingSumsOfTheStiffnessMatrix) {
  const Outcome t = run(net("square_evs.obj") + " --quantity stiffness --method tiles:4:8");
  const Outcome m = run(net("square_evs.obj") + " --quantity stiffness --method macro:2:8");
  ASSERT_EQ(t.code, 0) << t.err;
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_GT(t.report["irregular_elements"].get<int>(), 3);
  const double et = t.report["relative_frobenius_error"].get<double>();
  EXPECT_LT(et, 1e-6);
  EXPECT_NEAR(m.report["relative_frobenius_error"].get<double>(), et, 1e-3 * et);
  EXPECT_LT(m.report["points_around_evs"].get<int>(), t.report["points_around_evs"].get<int>());
}

// --basis halfbox on the dual of the square triangulation (written here): the exact area (geometric series at
// the extraordinary faces) against the per-tile rule at 16 levels; macro rules are for Catmull–Clark elements
// and refuse half-box ones with one line.
TEST(IgaQuadrature, HalfBoxAreaExactAndPerTile) {
  const fs::path obj = fs::temp_directory_path() / ("iga_quadrature_halfbox_" + std::to_string(::getpid()) + ".obj");
  iga::mesh::write_obj(iga::mesh::dual_net(iga::mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/tri_square.obj")),
                       obj.string());
  const std::string mesh = "--basis halfbox --mesh '" + obj.string() + "' --quantity area";
  const Outcome e = run(mesh + " --method exact");
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_EQ(e.report["basis"], "halfbox");
  EXPECT_GT(e.report["irregular_elements"].get<int>(), 0);
  const Outcome t = run(mesh + " --method tiles:4:16");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NEAR(t.report["value"].get<double>(), e.report["exact"].get<double>(), 1e-12);
  const Outcome m = run(mesh + " --method macro:2");
  EXPECT_EQ(m.code, 1);
  EXPECT_NE(m.err.find("(half-box)"), std::string::npos) << m.err;
  EXPECT_EQ(std::count(m.err.begin(), m.err.end(), '\n'), 1) << m.err;
  fs::remove(obj);
}

TEST(IgaQuadrature, BadInputGivesOneLine) {
  for (const std::string& args : {net("cube.obj") + " --quantity area", net("square_evs.obj") + " --quantity volume",
                                  net("square_evs.obj") + " --method simpson:3", std::string("--quantity mass"),
                                  std::string("--quantity area --valence 5"), std::string("--quantity mass --valence 2"),
                                  net("square_evs.obj") + " --quantity mass --valence 5",
                                  std::string("--quantity stiffness --valence 5 --method fitted:mass:/nonexistent/iga"),
                                  std::string("--quantity mass --valence 5 --basis halfbox"),
                                  net("square_evs.obj") + " --basis halfbox --quantity area"}) {
    const Outcome o = run(args);
    EXPECT_NE(o.code, 0) << args;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
  }
}
