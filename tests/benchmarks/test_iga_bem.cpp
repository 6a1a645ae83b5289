// iga-bem end to end: the boundary and interior .vtu read back with VTK, the JSON report, agreement with the FEM
// on the same geometry, one clear error line on bad input.
#include "support/paths.hpp"
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
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
};

class IgaBem : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("iga_bem_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  Outcome run(const std::string& args) {
    const fs::path err = dir_ / "stderr.txt";
    const std::string cmd = "cd '" + dir_.string() + "' && '" + IGA_BEM_EXE + "' " + args + " 2> '" + err.string() + "' > /dev/null";
    const int status = std::system(cmd.c_str());
    std::ifstream in(err);
    std::stringstream ss;
    ss << in.rdbuf();
    return {WEXITSTATUS(status), ss.str()};
  }
  nlohmann::json report(const std::string& name = "bem.json") {
    std::ifstream in(dir_ / name);
    return nlohmann::json::parse(in);
  }
  vtkSmartPointer<vtkUnstructuredGrid> read(const std::string& name) {
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName((dir_ / name).c_str());
    reader->Update();
    return reader->GetOutput();
  }
  fs::path dir_;
};

std::string mesh(const std::string& file) { return std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file; }

}  // namespace

TEST_F(IgaBem, DefaultRunAgreesWithTheFem) {
  // The embedded quarter annulus, u = e^x cos y on the whole boundary (Dirichlet). The FEM on the same geometry
  // (its default refinement) is the less accurate of the two here: the difference is within its error.
  const Outcome r = run("--quiet --compare-fem");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  for (const char* key : {"dofs", "elements", "collocation_points", "flux_l2_error", "u_l2_error", "max_interior_error",
                          "assembly_seconds", "solve_seconds", "condition_estimate", "scale", "boundary", "interior"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["dofs"], j["collocation_points"]);
  EXPECT_EQ(j["boundary"]["loops"], 1);
  EXPECT_EQ(j["boundary"]["corners"], 4);
  EXPECT_TRUE(j["problem"]["exact_is_default"].get<bool>());
  EXPECT_LT(j["max_interior_error"].get<double>(), 1e-5);
  EXPECT_GT(j["condition_estimate"].get<double>(), 1.0);
  const nlohmann::json& c = j["compare_fem"];
  EXPECT_LE(c["max_difference"].get<double>(), 1.1 * c["fem_max_error"].get<double>());
  // Boundary output: one polyline per BEM element with u, q and their exact values.
  const auto b = read("bem_boundary.vtu");
  ASSERT_EQ(b->GetNumberOfCells(), j["elements"].get<long>());
  EXPECT_EQ(b->GetCellType(0), VTK_POLY_LINE);
  for (const char* name : {"u", "q", "exact_u", "exact_q", "error_u", "error_q", "normal"}) {
    ASSERT_NE(b->GetPointData()->GetArray(name), nullptr) << name;
  }
  double worst = 0.0;
  vtkDataArray* eq = b->GetPointData()->GetArray("error_q");
  for (vtkIdType i = 0; i < eq->GetNumberOfTuples(); ++i) worst = std::max(worst, std::abs(eq->GetComponent(i, 0)));
  EXPECT_LT(worst, 1e-2);
  // Interior output on the geometry's sampling: u close to the exact values.
  const auto g = read("bem.vtu");
  ASSERT_EQ(g->GetNumberOfPoints(), j["interior"]["points"].get<long>());
  vtkDataArray* err = g->GetPointData()->GetArray("error");
  ASSERT_NE(err, nullptr);
  worst = 0.0;
  for (vtkIdType i = 0; i < err->GetNumberOfTuples(); ++i) worst = std::max(worst, std::abs(err->GetComponent(i, 0)));
  EXPECT_LT(worst, 1e-4);
}

TEST_F(IgaBem, CatmullClarkDomainWithHolesMixed) {
  // Three holes, corners, Neumann on x = 1: the BEM converges (p = 3; errors drop by > 6 per refinement) and
  // agrees with the FEM on the same geometry within the FEM's error.
  double previous = 0.0;
  for (int k : {0, 1, 2}) {
    const Outcome r = run("--quiet --basis cc --mesh '" + mesh("square_three_holes.obj") +
                          "' --degree 3 --refine " + std::to_string(k) +
                          " --exact 'x^2 - y^2' --neumann-where 'x > 0.999' --compare-fem --vtu none --boundary-vtu none");
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json j = report();
    EXPECT_EQ(j["boundary"]["loops"], 4);
    EXPECT_GT(j["boundary"]["neumann_edges"].get<int>(), 0);
    const double e = j["flux_l2_error"].get<double>();
    if (k > 0) {
      EXPECT_LT(e, previous / 6.0) << k;
    }
    previous = e;
    EXPECT_LE(j["compare_fem"]["max_difference"].get<double>(), 1.1 * j["compare_fem"]["fem_max_error"].get<double>());
  }
}

TEST_F(IgaBem, GridOutputMarksTheInside) {
  const Outcome r = run("--quiet --geometry l-shape --grid 20 --boundary-vtu none");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = report();
  // [0,2]² minus (1,2]²: three quarters of the 400 cell centres are inside.
  EXPECT_EQ(j["interior"]["inside_points"], 300);
  EXPECT_LT(j["max_interior_error"].get<double>(), 1e-4);
  const auto g = read("bem.vtu");
  EXPECT_EQ(g->GetNumberOfPoints(), 400);
  ASSERT_NE(g->GetPointData()->GetArray("inside"), nullptr);
}

TEST_F(IgaBem, BadInputGetsOneLine) {
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"--basis cc --mesh '" + mesh("torus_evs.obj") + "'", "surface in 3D"},
      {"--neumann '1'", "--neumann needs --neumann-boundary or --neumann-where"},
      {"--neumann-boundary nope", "no boundary part 'nope'"},
      {"--exact 'x +'", "--exact"},
  };
  for (const Case& c : cases) {
    const Outcome r = run("--quiet " + c.args);
    EXPECT_EQ(r.code, 1) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}
