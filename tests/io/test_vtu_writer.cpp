// Tests of io::write_vtu (read back with VTK's own reader) and io::write_json.
#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "basis/space.hpp"
#include "core/error.hpp"
#include "fem/function.hpp"
#include "io/report.hpp"
#include "io/sampled_writer.hpp"
#include "io/vtu_writer.hpp"

namespace {

using iga::Index;
namespace basis = iga::basis;
namespace fs = std::filesystem;

/// Vertices of an nx × ny grid, vertex (i, j) has index i + j * (nx + 1).
Index vertex(Index nx, Index i, Index j) { return i + j * (nx + 1); }

/// Bilinear Lagrange functions on an nx × ny grid of elements; dofs on the grid vertices.
/// Element (i, j) has index i + j * nx; local functions in the order (0,0), (1,0), (1,1), (0,1).
class BilinearSpace : public basis::Space {
 public:
  BilinearSpace(Index nx, Index ny) : nx_(nx), ny_(ny) {
    for (Index j = 0; j < ny; ++j) {
      for (Index i = 0; i < nx; ++i) {
        dofs_.push_back(vertex(nx, i, j));
        dofs_.push_back(vertex(nx, i + 1, j));
        dofs_.push_back(vertex(nx, i + 1, j + 1));
        dofs_.push_back(vertex(nx, i, j + 1));
      }
    }
  }
  std::string name() const override { return "bilinear-test"; }
  Index num_dofs() const override { return (nx_ + 1) * (ny_ + 1); }
  Index num_elements() const override { return nx_ * ny_; }
  basis::ElementKind kind(Index) const override { return {basis::Shape::Quad, basis::Family::Regular, 4}; }
  std::span<const Index> dofs(Index e) const override {
    return std::span<const Index>(dofs_).subspan(static_cast<std::size_t>(4 * e), 4);
  }
  Index max_local_dofs() const override { return 4; }
  void evaluate(Index, const Eigen::Matrix2Xd& pts, int derivatives, basis::BasisValues& out) const override {
    const Index q = pts.cols();
    out.value.resize(4, q);
    if (derivatives >= 1) {
      out.du.resize(4, q);
      out.dv.resize(4, q);
    }
    for (Index k = 0; k < q; ++k) {
      const double u = pts(0, k), v = pts(1, k);
      out.value.col(k) << (1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v;
      if (derivatives >= 1) {
        out.du.col(k) << -(1 - v), 1 - v, v, -v;
        out.dv.col(k) << -(1 - u), -u, u, 1 - u;
      }
    }
  }
  std::vector<basis::BoundaryEdge> boundary_edges() const override { return {}; }
  std::vector<std::string> boundary_part_names() const override { return {"boundary"}; }

 private:
  Index nx_, ny_;
  std::vector<Index> dofs_;
};

/// Linear (P1) functions on the same grid, each square split into two triangles along its diagonal from
/// (i, j) to (i + 1, j + 1). Local functions 1 - u - v, u, v at the triangle's vertices a, b, c.
class LinearTriangleSpace : public basis::Space {
 public:
  LinearTriangleSpace(Index nx, Index ny) : nx_(nx), ny_(ny) {
    for (Index j = 0; j < ny; ++j) {
      for (Index i = 0; i < nx; ++i) {
        dofs_.insert(dofs_.end(), {vertex(nx, i, j), vertex(nx, i + 1, j), vertex(nx, i + 1, j + 1)});
        dofs_.insert(dofs_.end(), {vertex(nx, i, j), vertex(nx, i + 1, j + 1), vertex(nx, i, j + 1)});
      }
    }
  }
  std::string name() const override { return "p1-test"; }
  Index num_dofs() const override { return (nx_ + 1) * (ny_ + 1); }
  Index num_elements() const override { return 2 * nx_ * ny_; }
  basis::ElementKind kind(Index) const override { return {basis::Shape::Triangle, basis::Family::Regular, 6}; }
  std::span<const Index> dofs(Index e) const override {
    return std::span<const Index>(dofs_).subspan(static_cast<std::size_t>(3 * e), 3);
  }
  Index max_local_dofs() const override { return 3; }
  void evaluate(Index, const Eigen::Matrix2Xd& pts, int derivatives, basis::BasisValues& out) const override {
    const Index q = pts.cols();
    out.value.resize(3, q);
    if (derivatives >= 1) {
      out.du.resize(3, q);
      out.dv.resize(3, q);
    }
    for (Index k = 0; k < q; ++k) {
      out.value.col(k) << 1 - pts(0, k) - pts(1, k), pts(0, k), pts(1, k);
      if (derivatives >= 1) {
        out.du.col(k) << -1, 1, 0;
        out.dv.col(k) << -1, 0, 1;
      }
    }
  }
  std::vector<basis::BoundaryEdge> boundary_edges() const override { return {}; }
  std::vector<std::string> boundary_part_names() const override { return {}; }

 private:
  Index nx_, ny_;
  std::vector<Index> dofs_;
};

/// Control points of the grid vertices on [0,2] × [0,1]; `perturb` moves interior vertices (still a valid,
/// orientation-preserving map).
Eigen::MatrixXd grid_points(Index nx, Index ny, bool perturb = false) {
  Eigen::MatrixXd cp((nx + 1) * (ny + 1), 2);
  for (Index j = 0; j <= ny; ++j) {
    for (Index i = 0; i <= nx; ++i) {
      double x = 2.0 * static_cast<double>(i) / static_cast<double>(nx);
      double y = static_cast<double>(j) / static_cast<double>(ny);
      if (perturb && i > 0 && i < nx && j > 0 && j < ny) {
        x += 0.1 / static_cast<double>(nx) * std::sin(3.0 * static_cast<double>(i + 2 * j));
        y += 0.1 / static_cast<double>(ny) * std::cos(5.0 * static_cast<double>(i + j));
      }
      cp(vertex(nx, i, j), 0) = x;
      cp(vertex(nx, i, j), 1) = y;
    }
  }
  return cp;
}

double linear(const Eigen::Vector3d& x) { return 1.0 + 2.0 * x(0) + 3.0 * x(1); }

/// Coefficients of the nodal interpolant of `linear` (exact for bilinear and P1 elements).
Eigen::VectorXd interpolate_linear(const Eigen::MatrixXd& cp) {
  Eigen::VectorXd u(cp.rows());
  for (Index i = 0; i < cp.rows(); ++i) u(i) = linear(Eigen::Vector3d(cp(i, 0), cp(i, 1), 0.0));
  return u;
}

std::shared_ptr<const iga::fem::Function> linear_function() {
  return iga::fem::make_function(linear, [](const Eigen::Vector3d&) { return Eigen::Vector3d(2.0, 3.0, 0.0); });
}

/// A fresh file name in a fresh temporary directory, removed by the destructor.
class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    std::ostringstream name;
    name << "iga_test_io_" << ::getpid() << "_" << counter++;
    dir_ = fs::temp_directory_path() / name.str();
    fs::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  return grid;
}

/// Checks the point data of a grid written for u = 1 + 2x + 3y with the exact solution.
void check_linear_point_data(vtkUnstructuredGrid* grid) {
  vtkDataArray* u = grid->GetPointData()->GetArray("u");
  vtkDataArray* grad = grid->GetPointData()->GetArray("grad_u");
  vtkDataArray* exact = grid->GetPointData()->GetArray("exact");
  vtkDataArray* error = grid->GetPointData()->GetArray("error");
  ASSERT_NE(u, nullptr);
  ASSERT_NE(grad, nullptr);
  ASSERT_NE(exact, nullptr);
  ASSERT_NE(error, nullptr);
  EXPECT_EQ(u->GetNumberOfComponents(), 1);
  EXPECT_EQ(grad->GetNumberOfComponents(), 3);
  EXPECT_EQ(exact->GetNumberOfComponents(), 1);
  EXPECT_EQ(error->GetNumberOfComponents(), 1);
  const vtkIdType n = grid->GetNumberOfPoints();
  ASSERT_EQ(u->GetNumberOfTuples(), n);
  ASSERT_EQ(grad->GetNumberOfTuples(), n);
  ASSERT_EQ(exact->GetNumberOfTuples(), n);
  ASSERT_EQ(error->GetNumberOfTuples(), n);
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    grid->GetPoint(i, p);
    const double expected = 1.0 + 2.0 * p[0] + 3.0 * p[1];
    ASSERT_TRUE(std::isfinite(u->GetComponent(i, 0)));
    ASSERT_TRUE(std::isfinite(exact->GetComponent(i, 0)));
    ASSERT_TRUE(std::isfinite(error->GetComponent(i, 0)));
    EXPECT_EQ(p[2], 0.0);
    EXPECT_NEAR(u->GetComponent(i, 0), expected, 1e-12) << "point " << i;
    EXPECT_NEAR(exact->GetComponent(i, 0), expected, 1e-12) << "point " << i;
    EXPECT_NEAR(error->GetComponent(i, 0), 0.0, 1e-12) << "point " << i;
    for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(grad->GetComponent(i, c)));
    EXPECT_NEAR(grad->GetComponent(i, 0), 2.0, 1e-12) << "point " << i;
    EXPECT_NEAR(grad->GetComponent(i, 1), 3.0, 1e-12) << "point " << i;
    EXPECT_NEAR(grad->GetComponent(i, 2), 0.0, 1e-12) << "point " << i;
  }
}

/// Checks the cell data: cells_per_element consecutive cells per element, of the given VTK type and code.
void check_cell_data(vtkUnstructuredGrid* grid, Index elements, Index cells_per_element, int vtk_type, int code) {
  ASSERT_EQ(grid->GetNumberOfCells(), elements * cells_per_element);
  auto* element = vtkIdTypeArray::SafeDownCast(grid->GetCellData()->GetArray("element"));
  auto* kind = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("element_kind"));
  ASSERT_NE(element, nullptr);
  ASSERT_NE(kind, nullptr);
  ASSERT_EQ(element->GetNumberOfTuples(), grid->GetNumberOfCells());
  ASSERT_EQ(kind->GetNumberOfTuples(), grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    EXPECT_EQ(grid->GetCellType(c), vtk_type) << "cell " << c;
    EXPECT_EQ(element->GetValue(c), c / cells_per_element) << "cell " << c;
    EXPECT_EQ(kind->GetValue(c), code) << "cell " << c;
  }
}

TEST(VtuWriter, BilinearElementsReproduceLinearFunction) {
  const Index nx = 2, ny = 1;  // unit-square elements covering [0,2] × [0,1]
  auto space = std::make_shared<BilinearSpace>(nx, ny);
  const Eigen::MatrixXd cp = grid_points(nx, ny);
  const basis::Geometry geometry(space, cp);
  const Eigen::VectorXd u = interpolate_linear(cp);
  TempDir tmp;
  const std::string path = tmp.file("bilinear.vtu");
  iga::io::VtuOptions options;
  options.samples = 5;
  options.exact = linear_function();
  iga::io::write_vtu(path, geometry, u, options);

  auto grid = read_vtu(path);
  ASSERT_NE(grid, nullptr);
  const Index elements = nx * ny;
  EXPECT_EQ(grid->GetNumberOfPoints(), elements * 25);
  check_linear_point_data(grid);
  check_cell_data(grid, elements, 16, VTK_QUAD, basis::kind_code({basis::Shape::Quad, basis::Family::Regular, 4}));

  // Points are duplicated per element and cover the reference square with both ends included:
  // element 0 spans [0,1] × [0,1], element 1 spans [1,2] × [0,1].
  double p[3];
  grid->GetPoint(0, p);
  EXPECT_DOUBLE_EQ(p[0], 0.0);
  EXPECT_DOUBLE_EQ(p[1], 0.0);
  grid->GetPoint(24, p);
  EXPECT_DOUBLE_EQ(p[0], 1.0);
  EXPECT_DOUBLE_EQ(p[1], 1.0);
  grid->GetPoint(25, p);
  EXPECT_DOUBLE_EQ(p[0], 1.0);
  EXPECT_DOUBLE_EQ(p[1], 0.0);
  grid->GetPoint(49, p);
  EXPECT_DOUBLE_EQ(p[0], 2.0);
  EXPECT_DOUBLE_EQ(p[1], 1.0);
}

TEST(VtuWriter, PerturbedGridAndOtherSampleCounts) {
  const Index nx = 4, ny = 3;
  auto space = std::make_shared<BilinearSpace>(nx, ny);
  const Eigen::MatrixXd cp = grid_points(nx, ny, /*perturb=*/true);
  const basis::Geometry geometry(space, cp);
  const Eigen::VectorXd u = interpolate_linear(cp);
  TempDir tmp;
  for (int samples : {2, 3, 7}) {
    const std::string path = tmp.file("perturbed_" + std::to_string(samples) + ".vtu");
    iga::io::write_vtu(path, geometry, u, {samples, linear_function()});
    auto grid = read_vtu(path);
    EXPECT_EQ(grid->GetNumberOfPoints(), nx * ny * samples * samples);
    check_linear_point_data(grid);
    check_cell_data(grid, nx * ny, (samples - 1) * (samples - 1), VTK_QUAD, 4);
  }
}

TEST(VtuWriter, WithoutExactSolution) {
  auto space = std::make_shared<BilinearSpace>(2, 1);
  const basis::Geometry geometry(space, grid_points(2, 1));
  TempDir tmp;
  const std::string path = tmp.file("no_exact.vtu");
  iga::io::write_vtu(path, geometry, Eigen::VectorXd::Ones(space->num_dofs()));
  auto grid = read_vtu(path);
  EXPECT_EQ(grid->GetNumberOfPoints(), 2 * 25);
  EXPECT_EQ(grid->GetNumberOfCells(), 2 * 16);
  ASSERT_NE(grid->GetPointData()->GetArray("u"), nullptr);
  ASSERT_NE(grid->GetPointData()->GetArray("grad_u"), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetArray("exact"), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetArray("error"), nullptr);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    EXPECT_NEAR(grid->GetPointData()->GetArray("u")->GetComponent(i, 0), 1.0, 1e-14);
  }
}

TEST(VtuWriter, TriangleElementsUseTriangularLattice) {
  const Index nx = 2, ny = 2;
  auto space = std::make_shared<LinearTriangleSpace>(nx, ny);
  const Eigen::MatrixXd cp = grid_points(nx, ny, /*perturb=*/true);
  const basis::Geometry geometry(space, cp);
  const Eigen::VectorXd u = interpolate_linear(cp);
  TempDir tmp;
  for (int samples : {2, 4, 5}) {
    const std::string path = tmp.file("triangles_" + std::to_string(samples) + ".vtu");
    iga::io::write_vtu(path, geometry, u, {samples, linear_function()});
    auto grid = read_vtu(path);
    const Index elements = space->num_elements();
    EXPECT_EQ(grid->GetNumberOfPoints(), elements * samples * (samples + 1) / 2);
    check_linear_point_data(grid);
    check_cell_data(grid, elements, (samples - 1) * (samples - 1), VTK_TRIANGLE,
                    basis::kind_code({basis::Shape::Triangle, basis::Family::Regular, 6}));
    // The triangles of each element tile it: their areas add up to the element's area (twice the
    // area of the reference triangle times the constant Jacobian of the affine map).
    double area = 0.0;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
      vtkIdType npts = 0;
      const vtkIdType* ids = nullptr;
      grid->GetCellPoints(c, npts, ids);
      ASSERT_EQ(npts, 3);
      double a[3], b[3], d[3];
      grid->GetPoint(ids[0], a);
      grid->GetPoint(ids[1], b);
      grid->GetPoint(ids[2], d);
      const double signed_area = 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
      EXPECT_GT(signed_area, 0.0) << "cell " << c;  // counter-clockwise like the reference triangle
      area += signed_area;
    }
    EXPECT_NEAR(area, 2.0, 1e-12);  // the domain [0,2] × [0,1]
  }
}

TEST(VtuWriter, MissingDirectoryThrowsInputError) {
  auto space = std::make_shared<BilinearSpace>(2, 1);
  const basis::Geometry geometry(space, grid_points(2, 1));
  TempDir tmp;
  const std::string path = tmp.file("no/such/directory/out.vtu");
  try {
    iga::io::write_vtu(path, geometry, Eigen::VectorXd::Zero(space->num_dofs()));
    FAIL() << "expected InputError";
  } catch (const iga::InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.reason(), "cannot write file");
  }
}

TEST(VtuWriter, BadArgumentsThrowInputError) {
  auto space = std::make_shared<BilinearSpace>(2, 1);
  const basis::Geometry geometry(space, grid_points(2, 1));
  TempDir tmp;
  const std::string path = tmp.file("bad.vtu");
  EXPECT_THROW(iga::io::write_vtu(path, geometry, Eigen::VectorXd::Zero(space->num_dofs() + 1)), iga::InputError);
  EXPECT_THROW(iga::io::write_vtu(path, geometry, Eigen::VectorXd::Zero(0)), iga::InputError);
  EXPECT_THROW(iga::io::write_vtu(path, geometry, Eigen::VectorXd::Zero(space->num_dofs()), {1, nullptr}),
               iga::InputError);
  EXPECT_FALSE(fs::exists(path));
}

TEST(VtuWriter, ElementFieldIsWrittenAtTheSamplePoints) {
  // A field given point by point: u = x + 2y at the physical points, which must be the sample_points() of each
  // element mapped (so the field sees the same points as the file's).
  auto space = std::make_shared<BilinearSpace>(2, 1);
  const basis::Geometry geometry(space, grid_points(2, 1, /*perturb=*/true));
  TempDir tmp;
  const std::string path = tmp.file("field.vtu");
  Index calls = 0;
  const iga::io::ElementField field = [&](Index e, const Eigen::Matrix2Xd& ref, const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) {
    ++calls;
    EXPECT_TRUE(ref.isApprox(iga::io::sample_points(basis::Shape::Quad, 3))) << e;
    out = (x.row(0) + 2.0 * x.row(1)).transpose();
  };
  iga::io::write_vtu(path, geometry, field, {3, nullptr});
  EXPECT_EQ(calls, 2);
  auto grid = read_vtu(path);
  ASSERT_EQ(grid->GetNumberOfPoints(), 2 * 9);
  EXPECT_EQ(grid->GetPointData()->GetArray("grad_u"), nullptr);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    EXPECT_NEAR(grid->GetPointData()->GetArray("u")->GetComponent(i, 0), p[0] + 2.0 * p[1], 1e-14);
  }
  const Eigen::Matrix2Xd tri = iga::io::sample_points(basis::Shape::Triangle, 4);
  EXPECT_EQ(tri.cols(), 10);
  EXPECT_THROW(iga::io::sample_points(basis::Shape::Quad, 1), iga::InputError);
}

TEST(VtuWriter, SampledFieldsOfSeveralComponents) {
  // A 3-component field (x, 2y, x y) and a 6-component one at the physical sample points; a field of the wrong size
  // is refused naming it.
  auto space = std::make_shared<BilinearSpace>(2, 1);
  const basis::Geometry geometry(space, grid_points(2, 1, /*perturb=*/true));
  TempDir tmp;
  iga::io::VtuOptions options;
  options.samples = 3;
  options.fields = {{"vector", 3, [](Index, const basis::BasisValues&, const basis::GeometryValues& gv, Eigen::MatrixXd& o) {
                       o.resize(3, gv.x.cols());
                       o.row(0) = gv.x.row(0);
                       o.row(1) = 2 * gv.x.row(1);
                       o.row(2) = gv.x.row(0).cwiseProduct(gv.x.row(1));
                     }},
                    {"tensor", 6, [](Index e, const basis::BasisValues&, const basis::GeometryValues& gv, Eigen::MatrixXd& o) {
                       o = Eigen::MatrixXd::Constant(6, gv.x.cols(), static_cast<double>(e));
                     }}};
  const std::string path = tmp.file("fields.vtu");
  iga::io::write_vtu(path, geometry, options);
  auto grid = read_vtu(path);
  vtkDataArray* v = grid->GetPointData()->GetArray("vector");
  vtkDataArray* t = grid->GetPointData()->GetArray("tensor");
  ASSERT_NE(v, nullptr);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(v->GetNumberOfComponents(), 3);
  EXPECT_EQ(t->GetNumberOfComponents(), 6);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    EXPECT_NEAR(v->GetComponent(i, 0), p[0], 1e-14);
    EXPECT_NEAR(v->GetComponent(i, 1), 2 * p[1], 1e-14);
    EXPECT_NEAR(v->GetComponent(i, 2), p[0] * p[1], 1e-14);
    EXPECT_EQ(t->GetComponent(i, 5), i < 9 ? 0.0 : 1.0);  // element 0's 9 samples first
  }
  options.fields[0].components = 2;
  try {
    iga::io::write_vtu(tmp.file("bad.vtu"), geometry, options);
    FAIL() << "a field of the wrong size was written";
  } catch (const iga::Error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'vector'"), std::string::npos) << e.what();
  }
}

TEST(SampledWriter, CurvesAreWrittenAsPolylines) {
  iga::io::CurveData c;
  c.points.resize(2, 5);
  c.points << 0, 1, 2, 2, 3, 0, 0, 0, 1, 1;
  c.offsets = {0, 3, 5};
  c.point_scalars = {{"u", Eigen::VectorXd::LinSpaced(5, 0.0, 4.0)}};
  c.point_vectors = {{"normal", Eigen::Matrix2Xd::Ones(2, 5)}};
  c.cell_scalars = {{"element", Eigen::Vector2d(0.0, 1.0)}};
  TempDir tmp;
  const std::string path = tmp.file("curves.vtu");
  iga::io::write_curves_vtu(path, c);
  auto grid = read_vtu(path);
  ASSERT_EQ(grid->GetNumberOfCells(), 2);
  EXPECT_EQ(grid->GetCellType(0), VTK_POLY_LINE);
  EXPECT_EQ(grid->GetCell(0)->GetNumberOfPoints(), 3);
  EXPECT_EQ(grid->GetCell(1)->GetNumberOfPoints(), 2);
  EXPECT_DOUBLE_EQ(grid->GetPointData()->GetArray("u")->GetComponent(4, 0), 4.0);
  EXPECT_EQ(grid->GetPointData()->GetArray("normal")->GetNumberOfComponents(), 3);
  EXPECT_DOUBLE_EQ(grid->GetCellData()->GetArray("element")->GetComponent(1, 0), 1.0);
  c.offsets = {0, 4, 5};  // a one-point cell
  EXPECT_THROW(iga::io::write_curves_vtu(path, c), iga::InputError);
  c.offsets = {0, 3};  // not ending at the last point
  EXPECT_THROW(iga::io::write_curves_vtu(path, c), iga::InputError);
  EXPECT_THROW(iga::io::write_curves_vtu(tmp.file("no/such/dir/c.vtu"), iga::io::CurveData{}), iga::InputError);
}

TEST(SampledWriter, GridIsWrittenAsQuads) {
  iga::io::GridData g;
  g.nx = 3;
  g.ny = 2;
  g.points.resize(2, 6);
  for (Index j = 0; j < 2; ++j) {
    for (Index i = 0; i < 3; ++i) g.points.col(i + 3 * j) = Eigen::Vector2d(i, j);
  }
  g.point_scalars = {{"u", Eigen::VectorXd::Ones(6)}};
  TempDir tmp;
  const std::string path = tmp.file("grid.vtu");
  iga::io::write_grid_vtu(path, g);
  auto grid = read_vtu(path);
  ASSERT_EQ(grid->GetNumberOfCells(), 2);
  EXPECT_EQ(grid->GetCellType(1), VTK_QUAD);
  g.point_scalars = {{"u", Eigen::VectorXd::Ones(5)}};
  EXPECT_THROW(iga::io::write_grid_vtu(path, g), iga::InputError);
  g.nx = 1;
  EXPECT_THROW(iga::io::write_grid_vtu(path, g), iga::InputError);
}

TEST(WriteJson, RoundTrip) {
  TempDir tmp;
  const std::string path = tmp.file("report.json");
  nlohmann::json report;
  report["backend"] = "bspline";
  report["dofs"] = 1234;
  report["errors"] = {{"l2", 1.5e-7}, {"h1", 3.25e-4}};
  report["rates"] = {2.0, 3.0, 1.0};
  report["converged"] = true;
  iga::io::write_json(path, report);

  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text.find("\n  \"backend\": \"bspline\""), std::string::npos);  // 2-space indent
  EXPECT_EQ(nlohmann::json::parse(text), report);
}

TEST(WriteJson, MissingDirectoryThrowsInputError) {
  TempDir tmp;
  const std::string path = tmp.file("no/such/dir/report.json");
  try {
    iga::io::write_json(path, nlohmann::json{{"a", 1}});
    FAIL() << "expected InputError";
  } catch (const iga::InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.reason(), "cannot write file");
  }
}

}  // namespace

TEST(Report, NonFiniteNumbersAreRefusedNotWrittenAsNull) {
  // Issue 14, class 3: nlohmann-json writes NaN and infinity as null, which in a report reads "not requested".
  const std::string path = ::testing::TempDir() + "/iga_nonfinite.json";
  std::remove(path.c_str());
  const nlohmann::json report = {{"dofs", 10}, {"errors", {{"l2", 1e-3}, {"h1", std::nan("")}}}};
  try {
    iga::io::write_json(path, report);
    FAIL() << "a NaN was written";
  } catch (const iga::NumericalError& e) {
    EXPECT_EQ(std::string(e.what()), "the result errors/h1 is not finite (nan); no report written to " + path);
  }
  EXPECT_FALSE(std::ifstream(path).good());
  EXPECT_THROW(iga::io::write_json(path, nlohmann::json{{"list", {1.0, INFINITY}}}), iga::NumericalError);
  EXPECT_NO_THROW(iga::io::write_json(path, nlohmann::json{{"l2_error", nullptr}, {"x", 1.5}}));
}
