// Tests of io::write_bezier (Bézier VTU output), read back with VTK's reader and evaluated with VTK's own Bézier
// cells: exact (1e-12 relative) on polynomial elements, no cracks (shared corner points) everywhere.
#include "support/paths.hpp"
#include <gtest/gtest.h>
#include <vtkBezierCurve.h>
#include <vtkBezierQuadrilateral.h>
#include <vtkBezierTriangle.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "io/bezier_layout.hpp"
#include "io/bezier_writer.hpp"
#include "io/net_writer.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"

namespace {

using iga::Index;
namespace basis = iga::basis;
namespace io = iga::io;
namespace fs = std::filesystem;

std::string temp_file(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("iga_test_bezier_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

iga::mesh::PolyMesh net(const std::string& file) {
  return iga::mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file);
}

basis::Geometry from_net(const std::string& backend, const iga::mesh::PolyMesh& m) {
  basis::BackendFacts facts;
  return basis::make_geometry(basis::backend(backend), &m, basis::BackendOptions{}, facts);
}

/// u_d = x_d² y_d (+ z_d) at the control points: a non-trivial field.
Eigen::VectorXd field(const basis::Geometry& g) {
  const Eigen::MatrixXd& cp = g.control_points();
  Eigen::VectorXd u(cp.rows());
  for (Index d = 0; d < cp.rows(); ++d) u(d) = cp(d, 0) * cp(d, 0) * cp(d, 1) + (g.dim() == 3 ? cp(d, 2) : 0.5);
  return u;
}

/// The library's x (3 × q) and u (q) on element e at reference points pts.
void library_values(const basis::Geometry& g, const Eigen::VectorXd& u, Index e, const Eigen::Matrix2Xd& pts,
                    Eigen::Matrix3Xd& x, Eigen::VectorXd& values) {
  basis::BasisValues bv;
  g.space().evaluate(e, pts, 0, bv);
  const auto dofs = g.space().dofs(e);
  x = Eigen::Matrix3Xd::Zero(3, pts.cols());
  values = Eigen::VectorXd::Zero(pts.cols());
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    for (Index k = 0; k < pts.cols(); ++k) {
      const double phi = bv.value(static_cast<Index>(a), k);
      x.col(k).head(g.dim()) += phi * g.control_points().row(dofs[a]).transpose();
      values(k) += phi * u(dofs[a]);
    }
  }
}

/// The cell's centre and side midpoints (polynomial elements) or its corners (all elements).
Eigen::Matrix2Xd check_points(basis::Shape shape, bool polynomial) {
  const int sides = basis::num_sides(shape);
  Eigen::Matrix2Xd pts(2, polynomial ? sides + 1 : sides);
  for (int s = 0; s < sides; ++s) pts.col(s) = basis::side_point(shape, s, polynomial ? 0.5 : 0.0);
  if (polynomial) pts.col(sides) = shape == basis::Shape::Quad ? Eigen::Vector2d(0.5, 0.5) : Eigen::Vector2d(1.0 / 3, 1.0 / 3);
  return pts;
}

/// Compares every cell of the file with the library at check_points(); returns the number of exact cells.
Index compare_cells(vtkUnstructuredGrid* grid, const basis::Geometry& g, const Eigen::VectorXd& u,
                    const std::vector<bool>& exact_cell) {
  const basis::Space& space = g.space();
  EXPECT_EQ(grid->GetNumberOfCells(), space.num_elements());
  vtkDataArray* u_array = grid->GetPointData()->GetArray("u");
  EXPECT_NE(u_array, nullptr);
  if (u_array == nullptr) return 0;
  const double x_scale = g.control_points().cwiseAbs().maxCoeff(), u_scale = u.cwiseAbs().maxCoeff();
  Index exact_cells = 0;
  std::vector<double> weights;
  for (Index e = 0; e < space.num_elements(); ++e) {
    const basis::Shape shape = space.kind(e).shape;
    const bool polynomial = exact_cell[static_cast<std::size_t>(e)];
    if (polynomial) {
      EXPECT_TRUE(space.polynomial_degree(e).has_value() || space.rational_form(e).has_value()) << "element " << e;
    }
    exact_cells += polynomial ? 1 : 0;
    vtkCell* cell = grid->GetCell(static_cast<vtkIdType>(e));
    EXPECT_EQ(cell->GetCellType(), shape == basis::Shape::Quad ? VTK_BEZIER_QUADRILATERAL : VTK_BEZIER_TRIANGLE);
    const Eigen::Matrix2Xd pts = check_points(shape, polynomial);
    Eigen::Matrix3Xd x;
    Eigen::VectorXd values;
    library_values(g, u, e, pts, x, values);
    weights.resize(static_cast<std::size_t>(cell->GetNumberOfPoints()));
    for (Index k = 0; k < pts.cols(); ++k) {
      double pcoords[3] = {pts(0, k), pts(1, k), 0.0}, xv[3];
      int sub = 0;
      cell->EvaluateLocation(sub, pcoords, xv, weights.data());
      double uv = 0.0;
      for (vtkIdType a = 0; a < cell->GetNumberOfPoints(); ++a) uv += weights[static_cast<std::size_t>(a)] * u_array->GetComponent(cell->GetPointId(a), 0);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(xv[c], x(c, k), 1e-12 * x_scale) << "element " << e << " point " << k;
      EXPECT_NEAR(uv, values(k), 1e-12 * u_scale) << "element " << e << " point " << k;
    }
  }
  return exact_cells;
}

/// Position of a VTK cell at reference point (u, v).
Eigen::Vector3d cell_point(vtkUnstructuredGrid* grid, Index c, const Eigen::Vector2d& ref) {
  vtkCell* cell = grid->GetCell(static_cast<vtkIdType>(c));
  std::vector<double> weights(static_cast<std::size_t>(cell->GetNumberOfPoints()));
  double pcoords[3] = {ref(0), ref(1), 0.0};
  Eigen::Vector3d x;
  int sub = 0;
  cell->EvaluateLocation(sub, pcoords, x.data(), weights.data());
  return x;
}

/// No cracks: along every interior edge of the space, both cells of the file give the same points (VTK's own
/// evaluation at s = 0, 1/4, 1/2, 3/4, 1 of the shared piece; 1e-12 of the domain's size), hanging sides included.
/// Counting sides by their
/// corner point ids: a side used by one cell only is on the domain boundary or a piece of a side that meets several
/// (polyhedral T-junctions: InteriorEdge with a sub-range). Returns the number of sides used by one cell only.
Index check_no_cracks(vtkUnstructuredGrid* grid, const basis::Space& space, double scale) {
  std::set<std::pair<Index, int>> partial;
  for (const basis::InteriorEdge& ie : space.interior_edges()) {
    const bool whole = std::abs(std::abs(ie.t1[0] - ie.t0[0]) - 1.0) < 1e-14 && std::abs(std::abs(ie.t1[1] - ie.t0[1]) - 1.0) < 1e-14;
    for (int i = 0; i < 2; ++i) {
      if (!whole) partial.insert({ie.element[i], ie.side[i]});
    }
    for (double s : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      Eigen::Vector3d x[2];
      for (int i = 0; i < 2; ++i) {
        const basis::Shape shape = space.kind(ie.element[i]).shape;
        x[i] = cell_point(grid, ie.element[i], basis::side_point(shape, ie.side[i], ie.t0[i] + s * (ie.t1[i] - ie.t0[i])));
      }
      EXPECT_LE((x[0] - x[1]).norm(), 1e-12 * scale) << "elements " << ie.element[0] << ", " << ie.element[1] << " s = " << s;
    }
  }
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  std::vector<std::pair<vtkIdType, vtkIdType>> side_key;
  for (Index e = 0; e < space.num_elements(); ++e) {
    vtkCell* cell = grid->GetCell(static_cast<vtkIdType>(e));
    const int corners = basis::num_sides(space.kind(e).shape);  // VTK lists the corners first, counter-clockwise
    for (int s = 0; s < corners; ++s) {
      const vtkIdType a = cell->GetPointId(s), b = cell->GetPointId((s + 1) % corners);
      EXPECT_NE(a, b) << "element " << e << " side " << s;
      side_key.push_back({std::min(a, b), std::max(a, b)});
      ++uses[side_key.back()];
    }
  }
  std::set<std::pair<Index, int>> boundary;
  for (const basis::BoundaryEdge& b : space.boundary_edges()) boundary.insert({b.element, b.side});
  Index open = 0, k = 0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    for (int s = 0; s < basis::num_sides(space.kind(e).shape); ++s, ++k) {
      const int n = uses[side_key[static_cast<std::size_t>(k)]];
      EXPECT_LE(n, 2) << "element " << e << " side " << s;
      if (n == 1) {
        EXPECT_TRUE(boundary.count({e, s}) == 1 || partial.count({e, s}) == 1) << "element " << e << " side " << s;
      } else {
        EXPECT_EQ(boundary.count({e, s}), 0u) << "element " << e << " side " << s;
      }
      open += n == 1 ? 1 : 0;
    }
  }
  return open;
}

/// Writes both formats, checks the Bézier file, prints the sizes; returns the open sides.
Index check_geometry(const std::string& name, const basis::Geometry& g) {
  const Eigen::VectorXd u = field(g);
  const std::string bezier = temp_file(name + ".vtu"), linear = temp_file(name + "_linear.vtu");
  io::write_bezier(bezier, g, &u);
  io::write_vtu(linear, g, u);
  auto grid = read_vtu(bezier);
  const Index exact_cells = compare_cells(grid, g, u, io::bezier_mesh(g, &u).exact_cell);
  const Index open = check_no_cracks(grid, g.space(), g.control_points().cwiseAbs().maxCoeff());
  auto outline = read_vtu(io::outline_path(bezier));
  EXPECT_GT(outline->GetNumberOfCells(), 0);
  for (vtkIdType c = 0; c < outline->GetNumberOfCells(); ++c) EXPECT_EQ(outline->GetCellType(c), VTK_BEZIER_CURVE);
  std::cout << name << ": " << g.space().num_elements() << " elements (" << exact_cells << " exact), "
            << grid->GetNumberOfPoints() << " points; bezier " << fs::file_size(bezier) << " bytes (+ outline "
            << fs::file_size(io::outline_path(bezier)) << "), linear (5 samples) " << fs::file_size(linear)
            << " bytes\n";
  return open;
}

// B-splines (the L-shape) and NURBS (the default quarter annulus, written as rational Bézier cells with VTK's
// RationalWeights) of degrees 2 and 3: every cell exact.
TEST(BezierWriter, BsplineAndNurbsDegreesTwoAndThreeAreExact) {
  for (const std::string geometry : {"l-shape", ""}) {
    for (int degree : {2, 3}) {
      basis::BackendOptions options;
      options.degree = degree;
      options.geometry = geometry;
      basis::BackendFacts facts;
      const basis::Backend& b = basis::backend("bspline");
      const basis::Geometry g = basis::make_refined_geometry(b, nullptr, options, 2, facts).geometry;
      for (Index e = 0; e < g.space().num_elements(); ++e) {
        if (geometry.empty()) {
          ASSERT_TRUE(g.space().rational_form(e).has_value());
          EXPECT_EQ(g.space().rational_form(e)->degree, degree);
        } else {
          EXPECT_EQ(g.space().polynomial_degree(e), degree);
        }
      }
      const std::string name = (geometry.empty() ? "nurbs" : "bspline") + std::to_string(degree);
      const Index open = check_geometry(name, g);
      EXPECT_EQ(open, static_cast<Index>(g.space().boundary_edges().size()));
      const Eigen::VectorXd u = field(g);
      const io::BezierMesh mesh = io::bezier_mesh(g, &u);
      EXPECT_EQ(mesh.num_polynomial, g.space().num_elements()) << name;
      EXPECT_EQ(mesh.weights.size() > 0, geometry.empty()) << name;
    }
  }
}

/// Every third element refined locally, twice (admissibility class 2).
basis::Geometry refined_locally(basis::Geometry g) {
  for (int round = 0; round < 2; ++round) {
    std::vector<Index> marked;
    for (Index e = 0; e < g.space().num_elements(); e += 3) marked.push_back(e);
    basis::BackendFacts facts;
    g = basis::refine_marked(g, marked, 2, facts, false).geometry;
  }
  return g;
}

TEST(BezierWriter, HierarchicalSpacesWithHangingSides) {
  // THB splines (bspline, p = 2) and hierarchical Catmull–Clark on the torus: elements of several levels; a coarse
  // side against two finer ones is one cell side against two (check_no_cracks compares them along the pieces).
  basis::BackendOptions options;
  options.degree = 2;
  options.geometry = "l-shape";  // THB refines B-spline patches (not NURBS)
  basis::BackendFacts facts;
  const basis::Geometry thb = refined_locally(
      basis::make_refined_geometry(basis::backend("bspline"), nullptr, options, 1, facts).geometry);
  int deepest = 0;
  for (Index e = 0; e < thb.space().num_elements(); ++e) {
    EXPECT_EQ(thb.space().polynomial_degree(e), 2);
    deepest = std::max(deepest, thb.space().level(e));
  }
  EXPECT_EQ(deepest, 2);
  check_geometry("thb2", thb);
  const basis::Geometry cc = refined_locally(from_net("cc", net("torus_evs.obj")));
  for (Index e = 0; e < cc.space().num_elements(); ++e) {
    const bool regular = cc.space().kind(e).family == basis::Family::Regular;
    EXPECT_EQ(cc.space().polynomial_degree(e), regular ? std::optional<int>(3) : std::nullopt);
  }
  check_geometry("cc_torus_hierarchical", cc);  // sides used once: only the pieces of hanging sides (no boundary)
  // A coarse element at an extraordinary vertex against finer ones is one degree-6 interpolating cell; the finer cells
  // along that side take its side curve (so they are not exact there): the crack check above passes at 1e-12.
  const Eigen::VectorXd u = field(cc);
  const io::BezierMesh mesh = io::bezier_mesh(cc, &u);
  Index followers = 0;
  for (Index e = 0; e < cc.space().num_elements(); ++e) {
    followers += cc.space().polynomial_degree(e).has_value() && !mesh.exact_cell[static_cast<std::size_t>(e)] ? 1 : 0;
  }
  EXPECT_GT(followers, 0);
}

TEST(BezierWriter, LinearWriterWithoutSolution) {
  const basis::Geometry g = from_net("polyhedral", net("square_evs.obj"));
  const std::string path = temp_file("linear_geometry.vtu");
  io::write_vtu(path, g, io::VtuOptions{});
  auto grid = read_vtu(path);
  EXPECT_EQ(grid->GetNumberOfCells(), g.space().num_elements() * 16);
  EXPECT_EQ(grid->GetPointData()->GetArray("u"), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetArray("grad_u"), nullptr);
  EXPECT_NE(grid->GetCellData()->GetArray("element_kind"), nullptr);
}

TEST(BezierWriter, PolyhedralSquareWithExtraordinaryVerticesHasNoCracks) {
  const basis::Geometry g = from_net("polyhedral", net("square_evs.obj"));
  for (Index e = 0; e < g.space().num_elements(); ++e) EXPECT_EQ(g.space().polynomial_degree(e), 3);
  check_geometry("polyhedral_square_evs", g);
}

// Regular elements are cubic, elements at extraordinary vertices or faces not polynomial; the net has some of those.
void expect_cubic_where_regular(const basis::Geometry& g) {
  Index irregular = 0;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    const bool regular = g.space().kind(e).family == basis::Family::Regular;
    EXPECT_EQ(g.space().polynomial_degree(e), regular ? std::optional<int>(3) : std::nullopt);
    irregular += regular ? 0 : 1;
  }
  EXPECT_GT(irregular, 0);
}

TEST(BezierWriter, ClosedCatmullClarkTorusHasNoBoundary) {
  const basis::Geometry g = from_net("cc", net("torus_evs.obj"));
  expect_cubic_where_regular(g);
  EXPECT_EQ(check_geometry("cc_torus_evs", g), 0);
}

TEST(BezierWriter, ClosedHalfBoxSphereHasNoBoundary) {
  const basis::Geometry g = from_net("halfbox", iga::mesh::dual_net(net("tri_sphere.obj")));
  expect_cubic_where_regular(g);
  EXPECT_EQ(check_geometry("halfbox_sphere", g), 0);
}

TEST(BezierWriter, PlanarHalfBoxAndCatmullClarkSquares) {
  check_geometry("halfbox_square", from_net("halfbox", iga::mesh::dual_net(net("tri_square.obj"))));
  check_geometry("cc_square_evs", from_net("cc", net("square_evs.obj")));
}

TEST(BezierWriter, ArraysDegreesAndGeometryOnly) {
  basis::BackendFacts facts;
  const basis::Geometry g = from_net("cc", net("torus_evs.obj"));
  io::BezierOptions options;
  options.degree = 4;
  options.exact = iga::fem::make_function([](const Eigen::Vector3d& x) { return x(0); },
                                          [](const Eigen::Vector3d&) { return Eigen::Vector3d(1.0, 0.0, 0.0); });
  const std::string path = temp_file("arrays.vtu");
  io::write_bezier(path, g, nullptr, options, {{"indicator", Eigen::VectorXd::LinSpaced(g.space().num_elements(), 0, 1)}});
  auto grid = read_vtu(path);
  EXPECT_EQ(grid->GetPointData()->GetArray("u"), nullptr);  // geometry alone: no u, no error
  EXPECT_EQ(grid->GetPointData()->GetArray("error"), nullptr);
  vtkDataArray* exact = grid->GetPointData()->GetArray("exact");
  ASSERT_NE(exact, nullptr);
  vtkDataArray* degrees = grid->GetCellData()->GetHigherOrderDegrees();
  ASSERT_NE(degrees, nullptr);
  for (const char* name : {"element", "element_kind", "level", "indicator"}) {
    EXPECT_NE(grid->GetCellData()->GetArray(name), nullptr) << name;
  }
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    const int d = g.space().polynomial_degree(e).value_or(4);
    EXPECT_EQ(degrees->GetComponent(e, 0), d);
    EXPECT_EQ(grid->GetCell(static_cast<vtkIdType>(e))->GetNumberOfPoints(), (d + 1) * (d + 1));
  }
  // "exact" is the interpolant of x: on the points (Bernstein coefficients of the map's x) it is exactly x where the
  // cell is polynomial of degree >= 1, i.e. everywhere here up to round-off.
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) EXPECT_NEAR(exact->GetComponent(p, 0), grid->GetPoint(p)[0], 1e-12);
  io::BezierOptions bad;
  bad.degree = 0;
  EXPECT_THROW(io::bezier_mesh(g, nullptr, bad), iga::InputError);
  const Eigen::VectorXd wrong = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(io::bezier_mesh(g, &wrong), iga::InputError);
}

/// The polygons of a control-net file lie at their net face's vertices.
Index check_net_file(const std::string& path, const basis::Geometry& g, const iga::mesh::PolyMesh& m) {
  io::write_control_net_vtu(path, g, &m);
  auto grid = read_vtu(path);
  EXPECT_EQ(grid->GetNumberOfPoints(), g.space().num_dofs());
  vtkDataArray* face = grid->GetCellData()->GetArray("net_face");
  EXPECT_NE(face, nullptr);
  if (face == nullptr) return 0;
  Index polygons = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    if (grid->GetCellType(c) == VTK_VERTEX) continue;
    EXPECT_EQ(grid->GetCellType(c), VTK_POLYGON);
    const auto f = static_cast<Index>(face->GetComponent(c, 0));
    vtkCell* cell = grid->GetCell(c);
    EXPECT_EQ(cell->GetNumberOfPoints(), m.face_size(f));
    for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k) {
      const Eigen::Vector3d x(grid->GetPoint(cell->GetPointId(k)));
      EXPECT_LE((x - m.point(m.face(f)[static_cast<std::size_t>(k)])).norm(), 1e-12);
    }
    ++polygons;
  }
  EXPECT_EQ(grid->GetNumberOfCells(), g.space().num_dofs() + polygons);
  return polygons;
}

TEST(BezierWriter, ControlNetHasTheNetFacesAtTheDofs) {
  const std::string path = temp_file("net.vtu");
  // Polyhedral: the dofs are the net's vertices that some patch uses; the faces around them are drawn.
  const iga::mesh::PolyMesh square = net("square_evs.obj");
  const basis::Geometry p = from_net("polyhedral", square);
  EXPECT_GT(check_net_file(path, p, square), 0);
  // Catmull–Clark on a net that needs no global step: every face; on the torus (one global step: the dofs are the
  // refined net's vertices) only points where the refined net's vertices coincide with the given net's.
  const iga::mesh::PolyMesh torus = net("torus_evs.obj");
  const basis::Geometry t = from_net("cc", torus);
  const Index torus_polygons = check_net_file(path, t, torus);
  if (t.space().num_dofs() == torus.num_vertices()) {
    EXPECT_EQ(torus_polygons, torus.num_faces());
  }
}

}  // namespace

namespace {

/// A sampled field (x, y, z, u) of 4 components from what the writer evaluated: its Bernstein coefficients must be the
/// file's points and "u" (the same interpolation), on exact, rational, interpolating and hanging-side cells alike. The
/// same field asking for second derivatives is evaluated 1e-6 of the element inside at the nodes of cells that are not
/// polynomial (io::field_points): within `moved` (relative) of them there. The linear writer's fields alike.
void expect_field_is_points_and_u(const std::string& name, const basis::Geometry& g, double moved) {
  const Eigen::VectorXd u = field(g);
  io::BezierOptions options;
  const auto values = [&](Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv, Eigen::MatrixXd& out) {
    const auto dofs = g.space().dofs(e);
    Eigen::VectorXd local(static_cast<Eigen::Index>(dofs.size()));
    for (std::size_t a = 0; a < dofs.size(); ++a) local(static_cast<Eigen::Index>(a)) = u(dofs[a]);
    out.resize(4, gv.x.cols());
    out.topRows(3) = gv.x;
    out.row(3) = (bv.value.transpose() * local).transpose();
  };
  const auto values2 = [&](Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv, Eigen::MatrixXd& out) {
    EXPECT_EQ(bv.duu.cols(), gv.x.cols());  // the field asked for second derivatives
    values(e, bv, gv, out);
  };
  options.fields = {{"xyzu", 4, values, 1}, {"xyzu2", 4, values2, 2}};
  const std::string path = temp_file(name + "_fields.vtu"), linear = temp_file(name + "_fields_linear.vtu");
  io::write_bezier(path, g, &u, options);
  io::VtuOptions linear_options;
  linear_options.fields = options.fields;
  io::write_vtu(linear, g, u, linear_options);  // the sampled writer: values at its points, the same rule
  for (const std::string& file : {path, io::outline_path(path), linear}) {
    auto grid = read_vtu(file);
    for (const auto& [array, tol] : {std::pair{"xyzu", 1e-11}, std::pair{"xyzu2", moved}}) {
      vtkDataArray* f = grid->GetPointData()->GetArray(array);
      vtkDataArray* uu = grid->GetPointData()->GetArray("u");
      ASSERT_NE(f, nullptr) << file;
      ASSERT_NE(uu, nullptr) << file;
      ASSERT_EQ(f->GetNumberOfComponents(), 4);
      const double x_scale = g.control_points().cwiseAbs().maxCoeff(), u_scale = u.cwiseAbs().maxCoeff();
      double worst_x = 0.0, worst_u = 0.0;
      for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
        double p[3];
        grid->GetPoint(i, p);
        for (int c = 0; c < 3; ++c) worst_x = std::max(worst_x, std::abs(f->GetComponent(i, c) - p[c]));
        worst_u = std::max(worst_u, std::abs(f->GetComponent(i, 3) - uu->GetComponent(i, 0)));
      }
      std::cout << name << " " << array << ": coefficients within " << worst_x / x_scale << " (x), " << worst_u / u_scale
                << " (u), relative\n";
      EXPECT_LT(worst_x, tol * x_scale) << file << " " << array;
      EXPECT_LT(worst_u, tol * u_scale) << file << " " << array;
    }
  }
}

}  // namespace

TEST(BezierWriter, SampledFieldsAreInterpolatedLikeTheSolution) {
  basis::BackendOptions options;
  options.degree = 2;
  basis::BackendFacts facts;
  const basis::Geometry nurbs = basis::make_refined_geometry(basis::backend("bspline"), nullptr, options, 2, facts).geometry;
  expect_field_is_points_and_u("nurbs2", nurbs, 1e-11);  // rational cells: never moved
  // Measured 1.3e-5 and 8e-8 (the moved evaluation amplified by the degree-6 interpolation).
  expect_field_is_points_and_u("cc_torus_hierarchical", refined_locally(from_net("cc", net("torus_evs.obj"))), 1e-4);
  expect_field_is_points_and_u("halfbox_sphere", from_net("halfbox", iga::mesh::dual_net(net("tri_sphere.obj"))), 1e-4);
}
