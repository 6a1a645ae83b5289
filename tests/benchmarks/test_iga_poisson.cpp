// iga-poisson end to end: the .vtu read back with VTK's XML reader, the JSON report, one clear error line.
#include "support/paths.hpp"
#include "support/program_run.hpp"
#include "support/rates.hpp"
#include <gtest/gtest.h>

#include <numbers>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>
#include <vtkCellType.h>

#include <algorithm>
#include <cmath>
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
using iga::test::Outcome;

class IgaPoisson : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("iga_poisson_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  Outcome run(const std::string& args) { return iga::test::run_program(dir_, IGA_POISSON_EXE, args); }
  nlohmann::json report(const std::string& name = "result.json") {
    std::ifstream in(dir_ / name);
    return nlohmann::json::parse(in);
  }
  fs::path dir_;
};

void expect_finite_array(vtkDataArray* a, int components) {
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->GetNumberOfComponents(), components);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
    for (int c = 0; c < components; ++c) ASSERT_TRUE(std::isfinite(a->GetComponent(i, c))) << a->GetName();
  }
}
}  // namespace

TEST_F(IgaPoisson, DefaultRunWritesVtuAndJson) {
  const Outcome r = run("--quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  for (const char* key : {"basis", "mesh", "dofs", "elements", "quadrature_points", "l2_error", "h1_error",
                          "domain_measure", "assembly_seconds", "solve_seconds", "solver", "residual_norm"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["basis"], "bspline");
  EXPECT_NEAR(j["domain_measure"].get<double>(), 0.75 * std::numbers::pi, 1e-12);  // the exact quarter annulus
  EXPECT_LT(j["l2_error"].get<double>(), 1e-3);
  EXPECT_LT(j["residual_norm"].get<double>(), 1e-10);

  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((dir_ / "result.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  const long elements = j["elements"].get<long>();
  // The default --vtu-format bezier: one bi-3 Bézier cell per element, control points shared (the 16 × 16 elements
  // of degree 3 have (3 · 16 + 1)² distinct control points), the outline beside it.
  EXPECT_EQ(grid->GetNumberOfCells(), elements);
  EXPECT_EQ(grid->GetCellType(0), VTK_BEZIER_QUADRILATERAL);
  EXPECT_EQ(grid->GetNumberOfPoints(), (3 * 16 + 1) * (3 * 16 + 1));
  EXPECT_EQ(j["vtu_output"]["format"], "bezier");
  EXPECT_EQ(j["vtu_outline"], "result_outline.vtu");
  EXPECT_TRUE(fs::exists(dir_ / "result_outline.vtu"));
  expect_finite_array(grid->GetPointData()->GetArray("u"), 1);
  expect_finite_array(grid->GetPointData()->GetArray("exact"), 1);
  expect_finite_array(grid->GetPointData()->GetArray("error"), 1);
  EXPECT_EQ(grid->GetPointData()->GetArray("grad_u"), nullptr);  // not polynomial: only the linear format has it
  expect_finite_array(grid->GetCellData()->GetArray("element"), 1);
  expect_finite_array(grid->GetCellData()->GetArray("element_kind"), 1);
  // The error array is u - exact (its interpolant of degree 3) on the control points: small for this run.
  double range[2];
  grid->GetPointData()->GetArray("error")->GetRange(range);
  EXPECT_LT(std::max(std::abs(range[0]), std::abs(range[1])), 1e-2);
}

TEST_F(IgaPoisson, ExpressionsNeumannAndMesh) {
  // A 4×3 quad grid of [0,2]×[0,1] as an OBJ control net, degree 2: the patch test u = 1 + x - 2y with
  // Neumann data from an expression in the normal on two sides.
  std::ofstream obj(dir_ / "grid.obj");
  for (int j = 0; j <= 3; ++j) for (int i = 0; i <= 4; ++i) obj << "v " << 0.5 * i << " " << j / 3.0 << " 0\n";
  for (int j = 0; j < 3; ++j) for (int i = 0; i < 4; ++i) {
    const int a = 1 + i + 5 * j;
    obj << "f " << a << " " << a + 1 << " " << a + 6 << " " << a + 5 << "\n";
  }
  obj.close();
  const Outcome r = run("--quiet --mesh grid.obj --degree 2 --refine 2 --source 0 --exact '1 + x - 2*y' "
                    "--neumann 'nx - 2*ny' --neumann-boundary u1,v1 --threads 1 --json out.json --vtu none");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report("out.json");
  EXPECT_EQ(j["threads"], 1);
  EXPECT_NEAR(j["domain_measure"].get<double>(), 2.0, 1e-12);
  EXPECT_LT(j["l2_error"].get<double>(), 1e-9);  // linear functions are in every isoparametric space
  EXPECT_FALSE(fs::exists(dir_ / "result.vtu"));
}

// Thesis §4.2.2 (iii): Laplace on the square with three holes (Catmull–Clark, boundary EVs at the reflex
// hole corners): u = 2 on the first hole, -1 on the second, homogeneous Neumann elsewhere; the run reports
// its global steps and the .vtu opens with finite arrays and irregular elements marked.
TEST_F(IgaPoisson, CatmullClarkSquareWithThreeHoles) {
  const std::string mesh = std::string(IGA_SOURCE_DIR) + "/data/meshes/square_three_holes.obj";
  // Holes (as made by tools/make_meshes.py): [1/6,1/3]^2, [7/12,3/4]x[1/4,5/12], [1/3,1/2]x[7/12,3/4].
  const Outcome r = run("--quiet --basis cc --mesh '" + mesh + "' --refine 1 --quadrature tiles:4:8 --source 0 "
                        "--dirichlet '2*(x < 0.4)*(y < 0.4) - (x > 0.55)*(y < 0.45)' --neumann 0 "
                        "--neumann-where '(x > 1e-9)*(x < 1 - 1e-9)*(y > 1e-9)*(y < 1 - 1e-9)*(1 - (x < 0.4)*(y < 0.4))*(1 - (x > 0.55)*(y < 0.45))' "
                        "--vtu-format linear --net net.vtu");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  EXPECT_EQ(j["basis"], "cc");
  EXPECT_GT(j["neumann_edges"].get<int>(), 0);
  EXPECT_GT(j["dirichlet_edges"].get<int>(), 0);
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((dir_ / "result.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  EXPECT_EQ(grid->GetNumberOfCells(), j["elements"].get<long>() * 9);
  expect_finite_array(grid->GetPointData()->GetArray("u"), 1);
  expect_finite_array(grid->GetPointData()->GetArray("grad_u"), 3);
  vtkDataArray* kinds = grid->GetCellData()->GetArray("element_kind");
  ASSERT_NE(kinds, nullptr);
  double range[2];
  kinds->GetRange(range);
  EXPECT_GT(range[1], range[0]);  // regular (4) and irregular (1xx) elements
  // The maximum principle: the harmonic solution stays within the Dirichlet data [-1, 2] (up to the
  // discretisation's small overshoots).
  grid->GetPointData()->GetArray("u")->GetRange(range);
  EXPECT_GT(range[0], -1.2);
  EXPECT_LT(range[1], 2.2);
  // --net: every control point of the refined geometry (the solution's dofs) as a point.
  EXPECT_EQ(j["net_vtu"], "net.vtu");
  auto net_reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  net_reader->SetFileName((dir_ / "net.vtu").c_str());
  net_reader->Update();
  EXPECT_EQ(net_reader->GetOutput()->GetNumberOfPoints(), j["dofs"].get<long>());
  EXPECT_GE(net_reader->GetOutput()->GetNumberOfCells(), j["dofs"].get<long>());
}

// --grade-evs: a priori grading toward the extraordinary vertices of square_evs.obj (clamped, Nitsche), u = sin πx
// sin πy + x y² (exact). Four graded levels on refine 1 must beat uniform refine 3 in dofs and by 10× in L2 error
// (measured: 1.3e-7 at 8,264 dofs against 2.5e-6 at 9,803; one ring per level instead of 3, 2, 1, 1 gave, with
// gauss:4, 3.1e-7 at 6,179).
TEST_F(IgaPoisson, GradingTowardExtraordinaryVertices) {
  const std::string base = "--quiet --basis cc --mesh '" + std::string(IGA_SOURCE_DIR) +
                           "/data/meshes/square_evs.obj' --cc-boundary clamped --dirichlet-method nitsche "
                           "--quadrature tiles:4:8 --source '2*pi^2*sin(pi*x)*sin(pi*y) - 2*x' "
                           "--exact 'sin(pi*x)*sin(pi*y) + x*y^2' --threads 1 --vtu none ";
  ASSERT_EQ(run(base + "--refine 1 --grade-evs 4 --json graded.json").code, 0);
  ASSERT_EQ(run(base + "--refine 3 --grade-evs 0 --json uniform.json").code, 0);
  const nlohmann::json g = report("graded.json"), u = report("uniform.json");
  EXPECT_EQ(g["graded_levels"], 4);
  EXPECT_LT(g["dofs"].get<double>(), u["dofs"].get<double>());
  EXPECT_LT(g["l2_error"].get<double>(), 0.1 * u["l2_error"].get<double>());
}

// One interior extraordinary vertex of valence 5 or 8 (data/meshes/fan_N.obj, the regular N-gon of N quads):
// uniform refinement holds L2 to about dofs^-1 (h^2: the space lacks the quadratics there), the default grading of
// the clamped rule (--refine + 3 levels) gives the optimal dofs^-2 (bicubic). Measured over refine 2..4: graded
// 2.2 (valence 5), 3.4 (valence 8, preasymptotic); uniform over refine 4..6: 0.99 (valence 5).
TEST_F(IgaPoisson, GradingRestoresTheOptimalRateAtValenceFiveAndEight) {
  const auto rate = [&](int valence, int r0, const std::string& extra) {
    std::vector<double> dofs, err;
    for (int r = r0; r < r0 + 3; ++r) {
      const std::string json = "fan" + std::to_string(valence) + "_" + std::to_string(r) + ".json";
      const Outcome o = run("--quiet --basis cc --mesh '" + std::string(IGA_SOURCE_DIR) + "/data/meshes/fan_" +
                            std::to_string(valence) + ".obj' --cc-boundary clamped --source "
                            "'2*pi^2*sin(pi*x)*sin(pi*y) - 2*x' --exact 'sin(pi*x)*sin(pi*y) + x*y^2' --threads 1 "
                            "--vtu none --refine " + std::to_string(r) + " " + extra + " --json " + json);
      EXPECT_EQ(o.code, 0) << o.err;
      if (o.code != 0) return 0.0;
      const nlohmann::json j = report(json);
      dofs.push_back(j["dofs"].get<double>());
      err.push_back(j["l2_error"].get<double>());
    }
    return iga::test::fitted_rate_in_dofs(dofs, err);
  };
  const double graded5 = rate(5, 2, ""), graded8 = rate(8, 2, ""), uniform5 = rate(5, 4, "--grade-evs 0");
  std::cout << "L2 rate in the dofs: graded valence 5 " << graded5 << ", valence 8 " << graded8
            << "; uniform valence 5 " << uniform5 << "\n";
  EXPECT_GE(graded5, 1.8);
  EXPECT_GE(graded8, 1.8);
  EXPECT_LE(uniform5, 1.2);
}

// --cc-boundary clamped alone takes the measured fastest path (README, "The defaults of --basis cc"): Nitsche's
// method and --refine + 3 graded levels, the same run as with both given; the natural rule stays strong and uniform.
TEST_F(IgaPoisson, ClampedCatmullClarkDefaultsToNitscheAndGrading) {
  const std::string base = "--quiet --basis cc --mesh '" + std::string(IGA_SOURCE_DIR) +
                           "/data/meshes/square_evs.obj' --problem sine --refine 1 --threads 1 --vtu none ";
  ASSERT_EQ(run(base + "--cc-boundary clamped --json defaults.json").code, 0);
  ASSERT_EQ(run(base + "--cc-boundary clamped --dirichlet-method nitsche --grade-evs 4 --json explicit.json").code, 0);
  ASSERT_EQ(run(base + "--json natural.json").code, 0);
  const nlohmann::json d = report("defaults.json"), e = report("explicit.json"), n = report("natural.json");
  EXPECT_EQ(d["graded_levels"], 4);
  EXPECT_EQ(d["settings"]["dirichlet-method"], "nitsche");
  EXPECT_EQ(d["dofs"], e["dofs"]);
  EXPECT_NEAR(d["l2_error"].get<double>(), e["l2_error"].get<double>(), 1e-12);
  EXPECT_EQ(n["settings"]["dirichlet-method"], "strong");
  EXPECT_FALSE(n.contains("graded_levels"));
  EXPECT_LT(d["l2_error"].get<double>(), 0.05 * n["l2_error"].get<double>());
}

// Adaptive Catmull–Clark on the L-shape whose reflex corner (vertex 41, (1, 1)) is kept as a corner of the limit
// domain (--cc-corners: 270°, tangent to the edges), so u = r^(2/3) sin(2φ/3) is singular there: uniform refinement
// is held to the singular rate (|e|_H1 ~ dofs^(-1/3): measured 0.29 at 1k..13k dofs), the adaptive loop reaches the
// optimal one (p/2 = 1.5 in the dofs; the issue asks >= 0.9 of it over the last 10 steps). Measured: slope 1.97 over
// steps 21..30 (8,134 dofs), 1.58 over steps 36..45 (231k dofs); efficiency index 2.8 .. 4.9 over 30 steps.
TEST_F(IgaPoisson, AdaptiveCatmullClarkReachesTheOptimalRateAtACornerVertex) {
  const std::string base = "--quiet --basis cc --mesh '" + std::string(IGA_SOURCE_DIR) +
                           "/data/meshes/l_shape.obj' --cc-boundary clamped --cc-corners 41 --problem corner "
                           "--dirichlet-method nitsche --threads 1 --vtu none ";
  const Outcome r = run(base + "--refine 1 --adaptive 30 --json adaptive.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json history = report("adaptive.json")["adaptive"]["history"];
  ASSERT_EQ(history.size(), 31u);
  std::vector<double> dofs, err;
  double lo = 1e300, hi = 0;
  for (std::size_t i = 0; i < history.size(); ++i) {
    const double eff = history[i]["efficiency_index"].get<double>();
    lo = std::min(lo, eff);
    hi = std::max(hi, eff);
    if (i + 10 >= history.size()) {
      dofs.push_back(history[i]["dofs"].get<double>());
      err.push_back(history[i]["energy_error"].get<double>());
    }
  }
  const double slope = iga::test::fitted_rate_in_dofs(dofs, err);
  std::cout << "adaptive cc at the corner: slope " << slope << " over the last 10 steps, efficiency " << lo << " .. " << hi << "\n";
  EXPECT_GE(slope, 1.35);
  EXPECT_GT(lo, 1.0);
  EXPECT_LT(hi / lo, 3.0);
  // Uniform refinement: the singular rate.
  std::vector<double> udofs, uerr;
  for (int k = 2; k <= 4; ++k) {
    ASSERT_EQ(run(base + "--refine " + std::to_string(k) + " --grade-evs 0 --json uniform.json").code, 0);
    const nlohmann::json u = report("uniform.json");
    udofs.push_back(u["dofs"].get<double>());
    uerr.push_back(u["h1_error"].get<double>());
  }
  EXPECT_NEAR(iga::test::fitted_rate_in_dofs(udofs, uerr), 1.0 / 3.0, 0.08);
}

// Half-box splines on the dual of a triangulation (a net the program reads; pentagons and heptagons inside):
// the affine solution is reproduced, the report names the backend and the .vtu has triangle cells whose
// element_kind codes include the half-box irregular ones (2·10000 + 1000 + 100 + n).
TEST_F(IgaPoisson, HalfBoxOnTheDualOfATriangulation) {
  iga::mesh::write_obj(iga::mesh::dual_net(iga::mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/tri_square.obj")),
                       (dir_ / "net.obj").string());
  const Outcome r = run("--quiet --basis halfbox --mesh net.obj --refine 1 --problem linear --quadrature tiles:4:16 --vtu-format linear");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  EXPECT_EQ(j["basis"], "halfbox");
  EXPECT_EQ(j["degree"], 3);
  EXPECT_EQ(j["quadrature"], "tiles:4:16");
  EXPECT_EQ(j["error_quadrature"], "tiles:6:16");  // two more points per direction for the error norms
  EXPECT_EQ(j["elements"], 512);  // 128 patches of the dual net, each split in four
  EXPECT_LT(j["l2_error_relative"].get<double>(), 1e-10);
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((dir_ / "result.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_GT(grid->GetNumberOfCells(), 0);
  EXPECT_EQ(grid->GetCellType(0), VTK_TRIANGLE);
  vtkDataArray* kinds = grid->GetCellData()->GetArray("element_kind");
  ASSERT_NE(kinds, nullptr);
  bool pentagon = false, heptagon = false;
  for (vtkIdType c = 0; c < kinds->GetNumberOfTuples(); ++c) {
    pentagon |= kinds->GetComponent(c, 0) == 21105;
    heptagon |= kinds->GetComponent(c, 0) == 21107;
  }
  EXPECT_TRUE(pentagon);
  EXPECT_TRUE(heptagon);
  // Values and gradients on the triangle cells: u = 1 + 2x − 3y and ∇u = (2, −3, 0) at every sample point.
  vtkDataArray* u = grid->GetPointData()->GetArray("u");
  vtkDataArray* grad = grid->GetPointData()->GetArray("grad_u");
  ASSERT_NE(u, nullptr);
  ASSERT_NE(grad, nullptr);
  ASSERT_EQ(grad->GetNumberOfComponents(), 3);
  double worst_u = 0, worst_grad = 0;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double x[3];
    grid->GetPoint(i, x);
    worst_u = std::max(worst_u, std::abs(u->GetComponent(i, 0) - (1 + 2 * x[0] - 3 * x[1])));
    worst_grad = std::max({worst_grad, std::abs(grad->GetComponent(i, 0) - 2.0), std::abs(grad->GetComponent(i, 1) + 3.0),
                           std::abs(grad->GetComponent(i, 2))});
  }
  EXPECT_LT(worst_u, 1e-9);
  EXPECT_LT(worst_grad, 1e-8);
  // Neumann data on part of the boundary (selected geometrically) keep the patch test. Sides of EF elements
  // that run into the EF corner get Gauss on their dyadic tile pieces (PerTile::side_rule), plain Gauss only on
  // the last piece [0, 2^-L]: the error falls like 2^-L (relative L2 7.4e-9, 2.9e-11, 1.7e-13 for L = 16,
  // 24, 32; 4.8e-4 with 4 Gauss points on the whole side).
  const Outcome n = run("--quiet --basis halfbox --mesh net.obj --refine 0 --problem linear --quadrature tiles:4:32 "
                        "--neumann-where 'x > 0.5' --vtu none --json neumann.json");
  ASSERT_EQ(n.code, 0) << n.err;
  const nlohmann::json jn = report("neumann.json");
  EXPECT_GT(jn["neumann_edges"].get<int>(), 0);
  EXPECT_GT(jn["dirichlet_edges"].get<int>(), 0);
  EXPECT_LT(jn["l2_error_relative"].get<double>(), 1e-10);
  // A quad net is not three-valent: one line naming a vertex.
  const Outcome bad = run("--basis halfbox --mesh '" + std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj' --vtu none --json none");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("square_evs.obj:0: vertex 3 has 5 edges; a half-box net must be three-valent"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

// --geometry square: the unit square as one polynomial patch (area 1, the linear patch test exact with the default
// rule), and the report names CHOLMOD's ordering (a small system: AMD, fem/solver.cpp).
TEST_F(IgaPoisson, UnitSquareGeometryAndSolverOrdering) {
  const Outcome r = run("--quiet --geometry square --degree 2 --refine 2 --problem linear --vtu none");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  EXPECT_NEAR(j["domain_measure"].get<double>(), 1.0, 1e-14);
  EXPECT_LT(j["l2_error"].get<double>(), 1e-12);
  EXPECT_EQ(j["solver_ordering"], "amd");
}

// Local refinement by refine-and-smooth: three steps halving interval 0 in both directions grade the mesh
// toward one corner: 2, 3, 4 intervals per direction (16 elements); the patch test stays exact. The annulus is a
// NURBS patch: a linear u is in its space, but the stiffness integrand is rational, so the patch test is exact only
// to the rule's error (3.6e-6 with the default gauss:4, 1e-15 with gauss:10, measured).
TEST_F(IgaPoisson, RefineIntervals) {
  const Outcome r = run("--quiet --refine 3 --refine-intervals 0 --problem linear --quadrature gauss:10 --vtu none");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  EXPECT_EQ(j["elements"], 16);
  EXPECT_LT(j["l2_error"].get<double>(), 1e-10);
  EXPECT_NE(run("--refine-intervals 0,x --vtu none --json none").code, 0);
}

// --coarse-split U,V inserts knots before refining: split 2,2 then 4 midpoint steps has the knots of 5 steps, so the
// same space and the same solution; 1,3 has 3 × 4^k elements. Malformed values are one line.
TEST_F(IgaPoisson, CoarseSplit) {
  ASSERT_EQ(run("--quiet --problem harmonic --refine 5 --vtu none --json five.json").code, 0);
  const Outcome r = run("--quiet --problem harmonic --refine 4 --coarse-split 2,2 --vtu none --json split.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json five = report("five.json"), split = report("split.json");
  EXPECT_EQ(split["dofs"], five["dofs"]);
  EXPECT_EQ(split["coarse_split"], nlohmann::json::array({2, 2}));
  EXPECT_NEAR(split["l2_error"].get<double>(), five["l2_error"].get<double>(), 1e-9 * five["l2_error"].get<double>());
  ASSERT_EQ(run("--quiet --refine 2 --coarse-split 1,3 --vtu none").code, 0);
  EXPECT_EQ(report()["elements"], 3 * 16);
  for (const char* bad : {"1,0", "3", "1,2,3", "1,x", "1,65", "-1,2"}) {
    const Outcome b = run(std::string("--vtu none --json none --coarse-split ") + bad);
    EXPECT_NE(b.code, 0) << bad;
    EXPECT_NE(b.err.find("--coarse-split: '" + std::string(bad) + "' is not U,V"), std::string::npos) << b.err;
    EXPECT_EQ(std::count(b.err.begin(), b.err.end(), '\n'), 1) << b.err;
  }
}

TEST_F(IgaPoisson, NoExactGivesNullErrors) {
  const Outcome r = run("--quiet --source 1 --dirichlet 0 --refine 2 --vtu none");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  EXPECT_TRUE(j["l2_error"].is_null());
  EXPECT_TRUE(j["h1_error"].is_null());
}

TEST_F(IgaPoisson, BadInputGivesOneClearLine) {
  std::ofstream(dir_ / "bad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 7\n";
  struct Case {
    std::string args, needle;
  };
  const std::vector<Case> cases = {
      {"--mesh bad.obj", "bad.obj:4:"},
      {"--source 'sin(x'", "--source"},
      {"--quadrature simpson:3", "simpson"},
      {"--problem nope", "nope"},
      {"--basis cc", "cc"},
      {"--neumann-boundary top", "top"},
      {"--degree 1", "degree"},
      // Options the backend does not take are errors, not silently ignored (basis/registry.hpp).
      {"--basis cc --mesh '" + std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj' --degree 5",
       "--degree is not an option of --basis cc"},
      {"--basis polyhedral --mesh '" + std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj' --refine-intervals 0",
       "--refine-intervals is not an option of --basis polyhedral"},
      {"--presubdivide 1", "--presubdivide is not an option of --basis bspline"},
      {"--basis cc --mesh '" + std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj' --coarse-split 1,2",
       "--coarse-split is not an option of --basis cc"},
  };
  for (const Case& c : cases) {
    const Outcome r = run("--vtu none --json none " + c.args);
    EXPECT_NE(r.code, 0) << c.args;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
  }
}

TEST_F(IgaPoisson, AdaptiveWritesASeriesAndTheHistory) {
  const Outcome r = run("--quiet --geometry l-shape --problem corner --degree 2 --refine 1 --adaptive 6 --theta 0.5 "
                        "--vtu ad.vtu --json ad.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report("ad.json");
  ASSERT_TRUE(j.contains("adaptive"));
  const nlohmann::json& a = j["adaptive"];
  EXPECT_EQ(a["stopped"], "steps");
  ASSERT_EQ(a["history"].size(), 7u);
  long previous = 0;
  for (const nlohmann::json& s : a["history"]) {
    for (const char* key : {"dofs", "elements", "levels", "estimate", "energy_error", "efficiency_index", "seconds"}) {
      EXPECT_TRUE(s.contains(key)) << key;
    }
    EXPECT_GT(s["dofs"].get<long>(), previous);  // every step refines
    previous = s["dofs"].get<long>();
    EXPECT_NEAR(s["efficiency_index"].get<double>(), s["estimate"].get<double>() / s["energy_error"].get<double>(), 1e-12);
  }
  EXPECT_EQ(j["dofs"], a["history"].back()["dofs"]);  // the top-level figures are the last step's
  // The rates over the steps against N^(-1/2): the report's equal the ones fitted here from its own history
  // (least squares of log e over log N^(-1/2)), and the energy error's is far above the 2/3 of uniform refinement
  // for the corner singularity (optimal for degree 2 is 2; these early steps fit 2.4).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(a["history"].size());
  for (const nlohmann::json& s : a["history"]) {
    const double x = std::log(1.0 / std::sqrt(s["dofs"].get<double>())), y = std::log(s["energy_error"].get<double>());
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double fitted = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(a["convergence"]["fitted_rates"]["energy_error"].get<double>(), fitted, 1e-12);
  EXPECT_GT(fitted, 1.5);
  EXPECT_EQ(a["history"].back()["levels"].get<int>(), 7);  // Dörfler marks the corner element every step
  // The .pvd lists the 7 files in order; each reads back with cell data level and indicator.
  vtkSmartPointer<vtkXMLDataElement> pvd;
  pvd.TakeReference(vtkXMLUtilities::ReadElementFromFile((dir_ / "ad.pvd").c_str()));
  ASSERT_NE(pvd, nullptr);
  EXPECT_STREQ(pvd->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = pvd->GetNestedElement(0);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 7);
  for (int k = 0; k < 7; ++k) {
    vtkXMLDataElement* set = collection->GetNestedElement(k);
    char expected[32];
    std::snprintf(expected, sizeof expected, "ad_step%03d.vtu", k);
    EXPECT_STREQ(set->GetAttribute("file"), expected);
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName((dir_ / expected).c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    EXPECT_EQ(grid->GetNumberOfCells(), a["history"][k]["elements"].get<long>());  // one Bézier cell per element
    vtkDataArray* level = grid->GetCellData()->GetArray("level");
    expect_finite_array(grid->GetCellData()->GetArray("indicator"), 1);
    ASSERT_NE(level, nullptr);
    double range[2];
    level->GetRange(range);
    EXPECT_EQ(range[1], a["history"][k]["levels"].get<int>() - 1);
  }
}

// Issue 38: --max-seconds stops the adaptive loop cleanly. A limit already spent after the first step (which always
// runs: nothing to predict it from) stops before the second with exit 0; the report, its top-level figures and the
// .pvd are those of the last complete step, and the report says why it stopped. Without --quiet one line says it.
TEST_F(IgaPoisson, AdaptiveStopsCleanlyAtTheTimeLimit) {
  const std::string args = "--geometry l-shape --problem corner --degree 2 --refine 1 --adaptive 40 --theta 1 "
                           "--max-seconds 0.001 --vtu ad.vtu --json ad.json";
  const Outcome r = run("--quiet " + args);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const nlohmann::json j = report("ad.json");
  const nlohmann::json& a = j["adaptive"];
  EXPECT_EQ(a["max_seconds"].get<double>(), 0.001);
  const std::string stopped = a["stopped"].get<std::string>();
  EXPECT_EQ(stopped.rfind("time limit: ", 0), 0u) << stopped;
  EXPECT_NE(stopped.find(" s used of --max-seconds 0.001"), std::string::npos) << stopped;
  ASSERT_EQ(a["history"].size(), 1u);  // of the 41 solves asked for
  EXPECT_EQ(j["dofs"], a["history"].back()["dofs"]);
  EXPECT_EQ(j["dofs"].get<long>(), 28);
  EXPECT_GT(a["history"].back()["wall_seconds"].get<double>(), 0.0);
  EXPECT_GT(a["history"].back()["predicted_next_seconds"].get<double>(), 0.0);
  EXPECT_TRUE(fs::exists(dir_ / "ad_step000.vtu"));
  EXPECT_FALSE(fs::exists(dir_ / "ad_step001.vtu"));
  vtkSmartPointer<vtkXMLDataElement> pvd;
  pvd.TakeReference(vtkXMLUtilities::ReadElementFromFile((dir_ / "ad.pvd").c_str()));
  ASSERT_NE(pvd, nullptr);
  EXPECT_EQ(pvd->GetNestedElement(0)->GetNumberOfNestedElements(), 1);
  const Outcome loud = run(args);
  ASSERT_EQ(loud.code, 0) << loud.err;
  EXPECT_NE(loud.err.find("\niga-poisson: adaptive loop stopped after step 0: time limit: "), std::string::npos) << loud.err;
  EXPECT_NE(loud.err.find("iga-poisson: step 0: 28 dofs, 1 levels, "), std::string::npos) << loud.err;
  EXPECT_NE(loud.err.find("; step 1 predicted "), std::string::npos) << loud.err;  // the progress line's forecast
  // A generous limit changes nothing: every step runs and the loop stops for the steps asked for.
  ASSERT_EQ(run("--quiet --geometry l-shape --problem corner --degree 2 --refine 1 --adaptive 2 --max-seconds 1000000 "
                "--vtu none --json ad.json").code, 0);
  EXPECT_EQ(report("ad.json")["adaptive"]["stopped"], "steps");
  EXPECT_EQ(report("ad.json")["adaptive"]["history"].size(), 3u);
}

// The same for --study: the first level runs, the next is not started once the limit is spent; the study's files
// hold the levels done and say why it stopped.
TEST_F(IgaPoisson, StudyStopsCleanlyAtTheTimeLimit) {
  const Outcome r = run("--quiet --study 1:5 --max-seconds 0.001 --study-output st --plots none --json st_report.json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const nlohmann::json j = report("st.json");
  const std::string stopped = j["study"]["stopped"].get<std::string>();
  EXPECT_EQ(stopped.rfind("time limit: ", 0), 0u) << stopped;
  ASSERT_EQ(j["series"].size(), 1u);
  ASSERT_EQ(j["series"][0]["levels"].size(), 1u);  // of the 5 asked for
  EXPECT_EQ(j["series"][0]["levels"][0]["refine"].get<int>(), 1);
  EXPECT_EQ(report("st_report.json")["study"]["stopped"], stopped);
  std::ifstream csv(dir_ / "st.csv");
  const std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2) << text;  // the header and level 1
  const Outcome without = run("--quiet --max-seconds 5 --vtu none --json none");
  EXPECT_EQ(without.code, 2);
  EXPECT_EQ(without.err, "iga-poisson: error: --max-seconds requires --adaptive or --study\n");
}

TEST_F(IgaPoisson, AdaptiveNeedsALocallyRefinableBasis) {
  const Outcome r = run("--quiet --basis polyhedral --mesh " + std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj --adaptive 2");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("has no local refinement"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// Issue 32: the corner solution given as a user's expression (with acos and ?:, as in the issue) reports the energy
// error of the built-in problem, whose gradient is in C++, at every adaptive step (within 1 %; measured: equal to 6
// digits). Before, the expression's gradient was a finite difference with step 2e-3 (1e-3 × the domain's size),
// and the finest elements here (10 levels from elements of about 0.1: about 2e-4) lie inside that stencil: its
// energy error grew with the steps while the estimate fell.
TEST_F(IgaPoisson, ExpressionGradientsAreExactNearASingularity) {
  const std::string corner =
      "'((x-1)^2+(y-1)^2)^(1/3)*sin(2/3*(y > 1 ? acos((x-1)/sqrt((x-1)^2+(y-1)^2)) - pi/2 : "
      "3*pi/2 - acos((x-1)/sqrt((x-1)^2+(y-1)^2))))'";
  const std::string common = "--quiet --geometry l-shape --degree 1 --adaptive 16 --theta 0.2 --vtu none ";
  const Outcome text = run(common + "--exact " + corner + " --source 0 --json text.json");
  ASSERT_EQ(text.code, 0) << text.err;
  const Outcome built_in = run(common + "--problem corner --json built_in.json");
  ASSERT_EQ(built_in.code, 0) << built_in.err;
  const nlohmann::json a = report("text.json"), b = report("built_in.json");
  EXPECT_EQ(a["error_derivatives"], "symbolic (GiNaC)");
  EXPECT_EQ(b["error_derivatives"], "closed form");
  EXPECT_EQ(a["error_quadrature"], b["error_quadrature"]);
  const nlohmann::json& ha = a["adaptive"]["history"];
  const nlohmann::json& hb = b["adaptive"]["history"];
  ASSERT_EQ(ha.size(), hb.size());
  ASSERT_GE(ha.back()["levels"].get<int>(), 10);
  for (std::size_t k = 0; k < ha.size(); ++k) {
    ASSERT_EQ(ha[k]["dofs"], hb[k]["dofs"]) << "step " << k;
    const double ea = ha[k]["energy_error"].get<double>(), eb = hb[k]["energy_error"].get<double>();
    EXPECT_NEAR(ea, eb, 0.01 * eb) << "step " << k;
  }
  // And the energy error falls with the estimate (at the rate of the estimate, about 1 per 1/h for degree 1).
  EXPECT_LT(ha.back()["energy_error"].get<double>(), 0.3 * ha.front()["energy_error"].get<double>());
}
