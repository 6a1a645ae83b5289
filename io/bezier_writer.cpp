#include "io/bezier_writer.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

#include "basis/basis_values.hpp"
#include "core/error.hpp"
#include "io/bezier_hanging.hpp"
#include "io/bezier_layout.hpp"
#include "io/vtk_file.hpp"
#include "io/vtu_cell_data.hpp"

namespace iga::io {

namespace {

/// Points merged by a spatial hash: a point within `tol` (max norm) of an earlier mergeable point whose payload
/// (the u coefficient) is within `payload_tol` is that point.
class PointMerger {
 public:
  PointMerger(const Eigen::Vector3d& lo, double tol, double payload_tol) : lo_(lo), tol_(tol), payload_tol_(payload_tol) {}

  Index insert(const Eigen::Vector3d& x, double payload, double weight, bool mergeable) {
    const Key key = key_of(x);
    if (mergeable) {
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const auto it = grid_.find({key[0] + dx, key[1] + dy, key[2] + dz});
            if (it == grid_.end()) continue;
            for (const Index id : it->second) {
              if ((points_[static_cast<std::size_t>(id)] - x).lpNorm<Eigen::Infinity>() <= tol_ &&
                  std::abs(payload_[static_cast<std::size_t>(id)] - payload) <= payload_tol_ &&
                  std::abs(weight_[static_cast<std::size_t>(id)] - weight) <= 1e-12 * std::abs(weight)) {
                return id;
              }
            }
          }
        }
      }
    }
    const auto id = static_cast<Index>(points_.size());
    points_.push_back(x);
    payload_.push_back(payload);
    weight_.push_back(weight);
    if (mergeable) grid_[key].push_back(id);
    return id;
  }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }

 private:
  using Key = std::array<long long, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
    }
  };
  Key key_of(const Eigen::Vector3d& x) const {
    Key k{};
    for (int c = 0; c < 3; ++c) k[static_cast<std::size_t>(c)] = static_cast<long long>(std::floor((x(c) - lo_(c)) / tol_));
    return k;
  }
  Eigen::Vector3d lo_;
  double tol_, payload_tol_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<double> payload_, weight_;
  std::unordered_map<Key, std::vector<Index>, KeyHash> grid_;
};

/// Lower corner and merge tolerance from the control points' bounding box (3D, z = 0 when planar).
std::pair<Eigen::Vector3d, double> merge_frame(const basis::Geometry& geometry, double relative) {
  const Eigen::MatrixXd& cp = geometry.control_points();
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (cp.rows() > 0) {
    lo.head(cp.cols()) = cp.colwise().minCoeff().transpose();
    hi.head(cp.cols()) = cp.colwise().maxCoeff().transpose();
  }
  const double diag = (hi - lo).norm();
  const double tol = relative * (diag > 0.0 ? diag : 1.0);
  return {lo - Eigen::Vector3d::Constant(2.0 * tol), tol};
}

/// The sampled fields at the nodes (at field_points, vtu_writer.hpp): nodes × their components, in order.
Eigen::MatrixXd field_values(Index e, const basis::Geometry& geometry, const Eigen::Matrix2Xd& nodes,
                             const std::vector<SampledField>& fields) {
  Eigen::Index components = 0;
  for (const SampledField& f : fields) components += f.components;
  Eigen::MatrixXd out(nodes.cols(), components);
  // What the fields read, by derivatives asked for (1 or 2): evaluated once each, where field_points says.
  basis::BasisValues bv[2];
  basis::GeometryValues gv[2];
  bool evaluated[2] = {false, false};
  Eigen::MatrixXd values;
  Eigen::Index column = 0;
  for (const SampledField& f : fields) {
    const int d = std::clamp(f.derivatives, 1, 2), i = d - 1;
    if (!evaluated[i]) {
      geometry.space().evaluate(e, field_points(geometry.space(), e, nodes, d), d, bv[i]);
      geometry.evaluate(e, bv[i], gv[i], /*check=*/false, d);
      evaluated[i] = true;
    }
    f.values(e, bv[i], gv[i], values);
    if (values.rows() != f.components || values.cols() != out.rows()) {
      throw Error("Bézier output: field '" + f.name + "' gave " + std::to_string(values.rows()) + " × " +
                  std::to_string(values.cols()) + " values for " + std::to_string(f.components) + " × " +
                  std::to_string(out.rows()));
    }
    out.middleCols(column, f.components) = values.transpose();
    column += f.components;
  }
  return out;
}

/// Control points of element e (CellControl, bezier_hanging.hpp) in the layout's order.
void cell_control(Index e, const basis::Geometry& geometry, const Eigen::VectorXd* u, const BezierOptions& options,
                  const BezierLayout& layout, CellControl& out) {
  const basis::Space& space = geometry.space();
  const fem::Function* exact = options.exact.get();
  basis::BasisValues bv;
  space.evaluate(e, layout.nodes, 0, bv);
  const auto dofs = space.dofs(e);
  const auto n = static_cast<Eigen::Index>(dofs.size());
  Eigen::MatrixXd local_cp(n, 3);
  local_cp.setZero();
  Eigen::VectorXd local_u(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    local_cp.row(a).head(geometry.dim()) = geometry.control_points().row(dofs[static_cast<std::size_t>(a)]);
    if (u != nullptr) local_u(a) = (*u)(dofs[static_cast<std::size_t>(a)]);
  }
  Eigen::MatrixXd x_nodes = bv.value.transpose() * local_cp;  // nodes × 3
  Eigen::VectorXd u_nodes = u != nullptr ? Eigen::VectorXd(bv.value.transpose() * local_u) : Eigen::VectorXd();
  Eigen::VectorXd exact_nodes;
  if (exact != nullptr) exact->values(x_nodes.transpose(), exact_nodes);
  Eigen::MatrixXd field_nodes = field_values(e, geometry, layout.nodes, options.fields);  // nodes × components
  // A NURBS element: W = Σ w_j N_j is 1 / Σ_i R_i / w_i at the nodes (since Σ N_i = 1), and W, W x, W u are
  // polynomials of the cell's degree: their Bernstein coefficients are the weights and the weighted points.
  const std::optional<basis::RationalForm> rational = space.rational_form(e);
  Eigen::VectorXd w_nodes;
  if (rational) {
    w_nodes = (bv.value.transpose() * rational->weights.cwiseInverse()).cwiseInverse();
    x_nodes = w_nodes.asDiagonal() * x_nodes;
    if (u != nullptr) u_nodes = w_nodes.cwiseProduct(u_nodes);
    if (exact != nullptr) exact_nodes = w_nodes.cwiseProduct(exact_nodes);
    field_nodes = w_nodes.asDiagonal() * field_nodes;
    out.weights = layout.collocation.solve(w_nodes);
  } else {
    out.weights.resize(0);
  }
  const Eigen::VectorXd inv = rational ? Eigen::VectorXd(out.weights.cwiseInverse()) : Eigen::VectorXd();
  out.x = layout.collocation.solve(x_nodes);
  if (rational) out.x = inv.asDiagonal() * out.x;
  if (u != nullptr) out.u = layout.collocation.solve(u_nodes);
  if (u != nullptr && rational) out.u = inv.cwiseProduct(out.u);
  if (exact != nullptr) out.exact = layout.collocation.solve(exact_nodes);
  if (exact != nullptr && rational) out.exact = inv.cwiseProduct(out.exact);
  out.fields = field_nodes.cols() > 0 ? Eigen::MatrixXd(layout.collocation.solve(field_nodes)) : Eigen::MatrixXd();
  if (field_nodes.cols() > 0 && rational) out.fields = inv.asDiagonal() * out.fields;
}

/// Every cell's layout and control points, hanging sides of non-polynomial elements followed (bezier_hanging.hpp);
/// exact[e]: the cell is exact (polynomial element, no side that follows a coarser non-polynomial one).
void all_cells(const basis::Geometry& geometry, const Eigen::VectorXd* u, const BezierOptions& options,
               std::vector<const BezierLayout*>& layout, std::vector<CellControl>& control, std::vector<bool>& exact) {
  const basis::Space& space = geometry.space();
  const auto ne = static_cast<std::size_t>(space.num_elements());
  std::vector<int> degree(ne);
  exact.assign(ne, false);
  for (std::size_t e = 0; e < ne; ++e) {
    const std::optional<int> d = space.polynomial_degree(static_cast<Index>(e));
    const std::optional<basis::RationalForm> rational = d ? std::nullopt : space.rational_form(static_cast<Index>(e));
    degree[e] = d ? *d : rational ? rational->degree : options.degree;
    exact[e] = d.has_value() || rational.has_value();
  }
  const std::vector<HangingSide> hanging = hanging_sides(space, degree);
  layout.resize(ne);
  control.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    layout[e] = &bezier_layout(space.kind(static_cast<Index>(e)).shape, degree[e]);
    cell_control(static_cast<Index>(e), geometry, u, options, *layout[e], control[e]);
  }
  for (const HangingSide& h : hanging) {
    follow_coarse_side(h, layout, control);
    exact[static_cast<std::size_t>(h.fine)] = false;
  }
}

}  // namespace

BezierMesh bezier_mesh(const basis::Geometry& geometry, const Eigen::VectorXd* u, const BezierOptions& options) {
  const basis::Space& space = geometry.space();
  if (u != nullptr && u->size() != space.num_dofs()) {
    throw InputError("Bézier output: the solution has " + std::to_string(u->size()) + " coefficients, the space has " +
                     std::to_string(space.num_dofs()) + " functions");
  }
  bezier_layout(basis::Shape::Quad, options.degree);  // checks the degree
  const auto [lo, tol] = merge_frame(geometry, options.merge_tolerance);
  const double u_scale = u != nullptr && u->size() > 0 ? u->cwiseAbs().maxCoeff() : 0.0;
  PointMerger merger(lo, tol, options.merge_tolerance * u_scale);

  std::vector<const BezierLayout*> layout;
  std::vector<CellControl> control;
  std::vector<bool> exact_cell;
  all_cells(geometry, u, options, layout, control, exact_cell);
  BezierMesh mesh;
  std::vector<double> u_values, exact_values, weights;
  std::vector<Eigen::VectorXd> point_fields;  // per point: all fields' components
  const bool any_rational = std::any_of(control.begin(), control.end(), [](const CellControl& c) { return c.weights.size() > 0; });
  for (Index e = 0; e < space.num_elements(); ++e) {
    const BezierLayout& l = *layout[static_cast<std::size_t>(e)];
    const CellControl& c = control[static_cast<std::size_t>(e)];
    for (int k = 0; k < l.num_points(); ++k) {
      const double uk = u != nullptr ? c.u(k) : 0.0;
      const double wk = c.weights.size() > 0 ? c.weights(k) : 1.0;
      const Index id = merger.insert(c.x.row(k).transpose(), uk, wk, l.on_side[static_cast<std::size_t>(k)]);
      if (id == static_cast<Index>(u_values.size())) {
        u_values.push_back(uk);
        weights.push_back(wk);
        exact_values.push_back(options.exact ? c.exact(k) : 0.0);
        if (!options.fields.empty()) point_fields.emplace_back(c.fields.row(k).transpose());
      }
      mesh.connectivity.push_back(id);
    }
    mesh.offsets.push_back(static_cast<Index>(mesh.connectivity.size()));
    mesh.degree.push_back(l.degree);
    mesh.shape.push_back(l.shape);
    mesh.exact_cell.push_back(exact_cell[static_cast<std::size_t>(e)]);
    if (exact_cell[static_cast<std::size_t>(e)]) ++mesh.num_polynomial;
  }
  const auto& pts = merger.points();
  mesh.points.resize(3, static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) mesh.points.col(static_cast<Eigen::Index>(i)) = pts[i];
  if (u != nullptr) mesh.u = Eigen::Map<const Eigen::VectorXd>(u_values.data(), static_cast<Eigen::Index>(u_values.size()));
  if (options.exact) {
    mesh.exact = Eigen::Map<const Eigen::VectorXd>(exact_values.data(), static_cast<Eigen::Index>(exact_values.size()));
  }
  if (any_rational) mesh.weights = Eigen::Map<const Eigen::VectorXd>(weights.data(), static_cast<Eigen::Index>(weights.size()));
  Eigen::Index column = 0;
  for (const SampledField& f : options.fields) {
    Eigen::MatrixXd values(f.components, static_cast<Eigen::Index>(point_fields.size()));
    for (std::size_t i = 0; i < point_fields.size(); ++i) {
      values.col(static_cast<Eigen::Index>(i)) = point_fields[i].segment(column, f.components);
    }
    mesh.fields.emplace_back(f.name, std::move(values));
    column += f.components;
  }
  return mesh;
}

namespace {

vtkSmartPointer<vtkDoubleArray> point_array(const char* name, const Eigen::VectorXd& values) {
  auto a = make_double_array(name, 1, values.size());
  std::copy(values.data(), values.data() + values.size(), a->GetPointer(0));
  return a;
}

/// The grid's points and point data ("u", "exact", "error" as the mesh has them).
vtkNew<vtkUnstructuredGrid> grid_with_points(const BezierMesh& mesh) {
  vtkNew<vtkUnstructuredGrid> grid;
  auto coords = make_double_array("Points", 3, mesh.points.cols());
  std::copy(mesh.points.data(), mesh.points.data() + mesh.points.size(), coords->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coords);
  grid->SetPoints(points);
  if (mesh.u.size() > 0) {
    grid->GetPointData()->AddArray(point_array("u", mesh.u));
    grid->GetPointData()->SetActiveScalars("u");
  }
  if (mesh.exact.size() > 0) {
    grid->GetPointData()->AddArray(point_array("exact", mesh.exact));
    if (mesh.u.size() > 0) grid->GetPointData()->AddArray(point_array("error", mesh.u - mesh.exact));
  }
  if (mesh.weights.size() > 0) grid->GetPointData()->SetRationalWeights(point_array("RationalWeights", mesh.weights));
  for (const auto& [name, values] : mesh.fields) {
    auto a = make_double_array(name.c_str(), static_cast<int>(values.rows()), values.cols());
    std::copy(values.data(), values.data() + values.size(), a->GetPointer(0));
    grid->GetPointData()->AddArray(a);
  }
  return grid;
}


}  // namespace

void write_bezier_vtu(const std::string& path, const basis::Space& space, const BezierMesh& mesh,
                      const ElementData& element_data, const Pieces& pieces) {
  if (mesh.num_cells() != space.num_elements()) {
    throw InputError("Bézier output: " + std::to_string(mesh.num_cells()) + " cells for " +
                     std::to_string(space.num_elements()) + " elements");
  }
  check_element_data(space, element_data);
  auto grid = grid_with_points(mesh);
  std::vector<unsigned char> types;
  vtkNew<vtkIntArray> degrees;
  degrees->SetName("HigherOrderDegrees");
  degrees->SetNumberOfComponents(3);
  degrees->SetNumberOfTuples(static_cast<vtkIdType>(mesh.num_cells()));
  std::vector<Index> element_of_cell;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const int d = mesh.degree[static_cast<std::size_t>(c)];
    types.push_back(bezier_layout(mesh.shape[static_cast<std::size_t>(c)], d).vtk_type());
    degrees->SetTypedTuple(static_cast<vtkIdType>(c), std::array<int, 3>{d, d, 0}.data());
    element_of_cell.push_back(c);
  }
  set_cells(grid, mesh.offsets, mesh.connectivity, types);
  grid->GetCellData()->SetHigherOrderDegrees(degrees);
  add_element_cell_data(grid, space, element_of_cell, element_data);
  write_vtk_grid(path, grid, pieces);
}

namespace {

/// The sides of the cells, each once (by its set of point ids): VTK_BEZIER_CURVE connectivity in mesh point ids,
/// and the element and side of each curve.
struct Outline {
  std::vector<Index> offsets{0}, connectivity, element, side;
};

Outline outline_of(const BezierMesh& mesh) {
  Outline o;
  std::map<std::vector<Index>, bool> seen;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const BezierLayout& layout = bezier_layout(mesh.shape[static_cast<std::size_t>(c)], mesh.degree[static_cast<std::size_t>(c)]);
    const Index* ids = mesh.connectivity.data() + mesh.offsets[static_cast<std::size_t>(c)];
    for (int s = 0; s < basis::num_sides(layout.shape); ++s) {
      const std::vector<int> along = layout.side_points(s);
      std::vector<Index> key;
      for (const int k : along) key.push_back(ids[k]);
      std::sort(key.begin(), key.end());
      if (!seen.emplace(key, true).second) continue;
      for (std::size_t k = 0; k < along.size(); ++k) {
        o.connectivity.push_back(ids[along[static_cast<std::size_t>(curve_point_order(layout.degree, static_cast<int>(k)))]]);
      }
      o.offsets.push_back(static_cast<Index>(o.connectivity.size()));
      o.element.push_back(c);
      o.side.push_back(s);
    }
  }
  return o;
}

/// The mesh's points (and point data) that the outline uses, renumbered in o.connectivity.
BezierMesh outline_points(const BezierMesh& mesh, Outline& o) {
  std::vector<Index> new_id(static_cast<std::size_t>(mesh.points.cols()), -1), old_id;
  for (Index& id : o.connectivity) {
    Index& n = new_id[static_cast<std::size_t>(id)];
    if (n < 0) {
      n = static_cast<Index>(old_id.size());
      old_id.push_back(id);
    }
    id = n;
  }
  BezierMesh points;
  const auto count = static_cast<Eigen::Index>(old_id.size());
  points.points.resize(3, count);
  if (mesh.u.size() > 0) points.u.resize(count);
  if (mesh.exact.size() > 0) points.exact.resize(count);
  if (mesh.weights.size() > 0) points.weights.resize(count);
  for (const auto& [name, values] : mesh.fields) points.fields.emplace_back(name, Eigen::MatrixXd(values.rows(), count));
  for (Eigen::Index i = 0; i < count; ++i) {
    const Index from = old_id[static_cast<std::size_t>(i)];
    points.points.col(i) = mesh.points.col(from);
    if (mesh.u.size() > 0) points.u(i) = mesh.u(from);
    if (mesh.exact.size() > 0) points.exact(i) = mesh.exact(from);
    if (mesh.weights.size() > 0) points.weights(i) = mesh.weights(from);
    for (std::size_t f = 0; f < mesh.fields.size(); ++f) points.fields[f].second.col(i) = mesh.fields[f].second.col(from);
  }
  return points;
}

}  // namespace

void write_bezier_outline_vtu(const std::string& path, const BezierMesh& mesh, const Pieces& pieces) {
  Outline o = outline_of(mesh);
  auto grid = grid_with_points(outline_points(mesh, o));
  set_cells(grid, o.offsets, o.connectivity, std::vector<unsigned char>(o.element.size(), VTK_BEZIER_CURVE));
  for (const auto& [name, values] : {std::pair{"element", &o.element}, std::pair{"side", &o.side}}) {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(static_cast<vtkIdType>(values->size()));
    std::copy(values->begin(), values->end(), a->GetPointer(0));
    grid->GetCellData()->AddArray(a);
  }
  write_vtk_grid(path, grid, pieces);
}

std::string outline_path(const std::string& vtu_path) {
  const std::string ext = ".vtu";
  const bool has_ext = vtu_path.size() > ext.size() && vtu_path.compare(vtu_path.size() - ext.size(), ext.size(), ext) == 0;
  return (has_ext ? vtu_path.substr(0, vtu_path.size() - ext.size()) : vtu_path) + "_outline.vtu";
}

void write_bezier(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd* u,
                  const BezierOptions& options, const ElementData& element_data, const Pieces& pieces) {
  const BezierMesh mesh = bezier_mesh(geometry, u, options);
  write_bezier_vtu(path, geometry.space(), mesh, element_data, pieces);
  write_bezier_outline_vtu(outline_path(path), mesh, pieces);
}

}  // namespace iga::io
