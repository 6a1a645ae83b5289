#include "basis/bspline/patches.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "basis/bspline/rational_space.hpp"
#include "core/error.hpp"

namespace iga::basis::bspline {

namespace {
// Degree elevation of Bézier control points (rows) from degree q to q+1:
// Q_i = i/(q+1) P_{i-1} + (1 - i/(q+1)) P_i.
Eigen::MatrixXd elevate(const Eigen::MatrixXd& p) {
  const Eigen::Index q = p.rows() - 1;
  Eigen::MatrixXd out(q + 2, p.cols());
  for (Eigen::Index i = 0; i <= q + 1; ++i) {
    const double a = static_cast<double>(i) / static_cast<double>(q + 1);
    out.row(i).setZero();
    if (i >= 1) out.row(i) += a * p.row(i - 1);
    if (i <= q) out.row(i) += (1.0 - a) * p.row(i);
  }
  return out;
}
Eigen::MatrixXd elevate_to(Eigen::MatrixXd p, int degree) {
  while (p.rows() - 1 < degree) p = elevate(p);
  return p;
}
}  // namespace

Geometry make_patch(KnotVector u, KnotVector v, Eigen::MatrixXd control_points) {
  auto space = std::make_shared<const TensorSpace>(std::move(u), std::move(v));
  return Geometry(space, std::move(control_points));
}

Geometry make_quarter_annulus(int degree, double r_inner, double r_outer) {
  if (degree < 2) {
    throw InputError("quarter annulus: the arc is quadratic, degree " + std::to_string(degree) +
                     " cannot represent it; use degree >= 2 or give a mesh");
  }
  if (!(r_inner > 0.0 && r_outer > r_inner)) throw InputError("quarter annulus: need 0 < r_inner < r_outer");
  // The quarter circle as a rational quadratic Bézier curve (The NURBS Book, §7.3): points (1,0), (1,1), (0,1)
  // with weights 1, cos 45°, 1; raised to degree p in homogeneous coordinates (w x, w y, w).
  const double c = std::sqrt(0.5);
  Eigen::MatrixXd arc(3, 3);
  arc << 1.0, 0.0, 1.0, c, c, c, 0.0, 1.0, 1.0;
  const Eigen::MatrixXd arc_p = elevate_to(arc, degree);  // (p+1) × 3, along v
  Eigen::MatrixXd radius(2, 1);
  radius << r_inner, r_outer;
  const Eigen::MatrixXd radius_p = elevate_to(radius, degree);  // (p+1) × 1, along u
  const int n = degree + 1;
  Eigen::MatrixXd cp(n * n, 2);
  Eigen::VectorXd weights(n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      cp.row(i + n * j) = radius_p(i, 0) * arc_p.block(j, 0, 1, 2) / arc_p(j, 2);
      weights(i + n * j) = arc_p(j, 2);
    }
  }
  return make_rational_patch(KnotVector::uniform(degree, 1), KnotVector::uniform(degree, 1), cp, weights);
}

Geometry make_cylinder_patch(int degree, double radius, double length, double theta0, double theta1) {
  if (degree < 2) {
    throw InputError("cylinder patch: the arc is quadratic, degree " + std::to_string(degree) +
                     " cannot represent it; use degree >= 2");
  }
  const double span = theta1 - theta0;
  if (!(radius > 0.0 && length > 0.0) || !std::isfinite(radius) || !std::isfinite(length)) {
    throw InputError("cylinder patch: need a radius and a length > 0");
  }
  if (!(span > 0.0 && span < std::numbers::pi)) throw InputError("cylinder patch: need 0 < theta1 - theta0 < pi");
  // The arc in the (x, z) plane as a rational quadratic Bézier curve in homogeneous coordinates (w x, w z, w).
  const double half = 0.5 * span, mid = theta0 + half, w = std::cos(half), far = radius / w;
  Eigen::MatrixXd arc(3, 3);
  arc << radius * std::sin(theta0), radius * std::cos(theta0), 1.0,  //
      w * far * std::sin(mid), w * far * std::cos(mid), w,              //
      radius * std::sin(theta1), radius * std::cos(theta1), 1.0;
  const Eigen::MatrixXd arc_p = elevate_to(arc, degree);
  Eigen::MatrixXd axis(2, 1);
  axis << 0.0, length;
  const Eigen::MatrixXd axis_p = elevate_to(axis, degree);
  const int n = degree + 1;
  Eigen::MatrixXd cp(n * n, 3);
  Eigen::VectorXd weights(n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      cp.row(i + n * j) << arc_p(i, 0) / arc_p(i, 2), axis_p(j, 0), arc_p(i, 1) / arc_p(i, 2);
      weights(i + n * j) = arc_p(i, 2);
    }
  }
  return make_rational_patch(KnotVector::uniform(degree, 1), KnotVector::uniform(degree, 1), cp, weights);
}

namespace {
// The circular arc of unit radius from angle a0 to a1 (< π apart) as a rational quadratic Bézier curve in homogeneous
// coordinates (w cos, w sin, w), raised to degree p.
Eigen::MatrixXd unit_arc(double a0, double a1, int degree) {
  const double half = 0.5 * (a1 - a0), mid = a0 + half, w = std::cos(half), far = 1.0 / w;
  Eigen::MatrixXd arc(3, 3);
  arc << std::cos(a0), std::sin(a0), 1.0, w * far * std::cos(mid), w * far * std::sin(mid), w, std::cos(a1),
      std::sin(a1), 1.0;
  return elevate_to(arc, degree);
}
}  // namespace

Geometry make_sphere_patch(int degree, double radius, double lambda0, double lambda1, double phi0, double phi1) {
  if (degree < 2) {
    throw InputError("sphere patch: the arcs are quadratic, degree " + std::to_string(degree) +
                     " cannot represent them; use degree >= 2");
  }
  if (!(radius > 0.0) || !std::isfinite(radius)) throw InputError("sphere patch: need a radius > 0");
  const double half_pi = 0.5 * std::numbers::pi;
  if (!(lambda1 - lambda0 > 0.0 && lambda1 - lambda0 < std::numbers::pi) || !(phi1 - phi0 > 0.0) ||
      !(phi0 >= -half_pi && phi1 <= half_pi)) {
    throw InputError("sphere patch: need 0 < lambda1 - lambda0 < pi and -pi/2 <= phi0 < phi1 <= pi/2");
  }
  const Eigen::MatrixXd parallel = unit_arc(lambda0, lambda1, degree), meridian = unit_arc(phi0, phi1, degree);
  const int n = degree + 1;
  Eigen::MatrixXd cp(n * n, 3);
  Eigen::VectorXd weights(n * n);
  for (int j = 0; j < n; ++j) {
    // Meridian point j: distance from the axis r = cos φ, height z = sin φ (homogeneous: divided by its weight).
    const double r = meridian(j, 0) / meridian(j, 2), z = meridian(j, 1) / meridian(j, 2);
    for (int i = 0; i < n; ++i) {
      cp.row(i + n * j) << radius * r * parallel(i, 0) / parallel(i, 2), radius * r * parallel(i, 1) / parallel(i, 2),
          radius * z;
      weights(i + n * j) = parallel(i, 2) * meridian(j, 2);
    }
  }
  return make_rational_patch(KnotVector::uniform(degree, 1), KnotVector::uniform(degree, 1), cp, weights);
}

Geometry make_plate_with_hole(int degree, double radius, double side) {
  if (degree < 2) {
    throw InputError("plate with a hole: the hole is quadratic, degree " + std::to_string(degree) +
                     " cannot represent it; use degree >= 2");
  }
  if (!(radius > 0.0 && side > radius) || !std::isfinite(side)) {
    throw InputError("plate with a hole: need 0 < radius < side");
  }
  const int p = degree;
  const double w = std::cos(std::numbers::pi / 8), t = std::tan(std::numbers::pi / 8), c = std::sqrt(0.5);
  // Per half h (0: θ in [0°, 45°], 1: [45°, 90°]) the hole's and the outer side's rational quadratic Bézier
  // control points in homogeneous coordinates (w x, w y, w).
  auto half = [&](int h, double r, bool outer) {
    Eigen::MatrixXd b(3, 3);
    Eigen::Vector2d p0, p1, p2;
    if (h == 0) {
      p0 = {r, 0.0};
      p1 = {r, r * t};
      p2 = outer ? Eigen::Vector2d(r, r) : Eigen::Vector2d(r * c, r * c);
    } else {
      p0 = outer ? Eigen::Vector2d(r, r) : Eigen::Vector2d(r * c, r * c);
      p1 = {r * t, r};
      p2 = {0.0, r};
    }
    b << p0(0), p0(1), 1.0, w * p1(0), w * p1(1), w, p2(0), p2(1), 1.0;
    return elevate_to(b, p);  // (p+1) × 3
  };
  Eigen::MatrixXd linear(2, 1);
  linear << 0.0, 1.0;
  const Eigen::MatrixXd s = elevate_to(linear, p);  // the radial blend at the p+1 Bézier points
  const int nu = p + 1, nv = 2 * p + 1;
  Eigen::MatrixXd cp(nu * nv, 2);
  Eigen::VectorXd weights(nu * nv);
  for (int h = 0; h < 2; ++h) {
    const Eigen::MatrixXd hole = half(h, radius, false), out = half(h, side, true);
    for (int j = 0; j <= p; ++j) {
      const int row = h * p + j;  // the shared point of the two halves is written twice, alike
      for (int i = 0; i < nu; ++i) {
        const Eigen::RowVector2d x = (1 - s(i, 0)) * hole.block(j, 0, 1, 2) / hole(j, 2) +
                                     s(i, 0) * out.block(j, 0, 1, 2) / out(j, 2);
        cp.row(i + nu * row) = x;
        weights(i + nu * row) = hole(j, 2);
      }
    }
  }
  std::vector<double> v(static_cast<std::size_t>(p + 1), 0.0);
  v.insert(v.end(), static_cast<std::size_t>(p), 0.5);
  v.insert(v.end(), static_cast<std::size_t>(p + 1), 1.0);
  return make_rational_patch(KnotVector::uniform(p, 1), KnotVector(p, v), cp, weights);
}

Geometry make_rectangle(int degree, double x0, double x1, double y0, double y1) {
  if (!(x1 > x0 && y1 > y0)) throw InputError("rectangle: need x0 < x1 and y0 < y1");
  const int n = degree + 1;
  Eigen::MatrixXd cp(n * n, 2);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      cp(i + n * j, 0) = x0 + (x1 - x0) * i / degree;  // Greville abscissae of a Bézier patch
      cp(i + n * j, 1) = y0 + (y1 - y0) * j / degree;
    }
  }
  return make_patch(KnotVector::uniform(degree, 1), KnotVector::uniform(degree, 1), cp);
}

Geometry make_l_shape(int degree) {
  if (degree < 1) throw InputError("L-shape: degree must be >= 1");
  const int p = degree;
  // Corners of the two bilinear pieces: piece[k][a + 2b] = P(u = a, v = b) of piece k.
  const Eigen::Vector2d piece[2][4] = {{{2, 1}, {1, 1}, {2, 0}, {0, 0}}, {{1, 1}, {1, 2}, {0, 0}, {0, 2}}};
  std::vector<double> u(static_cast<std::size_t>(p + 1), 0.0), v(static_cast<std::size_t>(p + 1), 0.0);
  u.insert(u.end(), static_cast<std::size_t>(p), 0.5);
  u.insert(u.end(), static_cast<std::size_t>(p + 1), 1.0);
  v.insert(v.end(), static_cast<std::size_t>(p + 1), 1.0);
  const int nu = 2 * p + 1, nv = p + 1;
  Eigen::MatrixXd cp(nu * nv, 2);
  // With a knot of multiplicity p the B-spline coefficients are the Bézier points of each piece; a bilinear
  // piece raised to degree p has the bilinear map at (a/p, b/p) as Bézier points.
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const int k = i < p ? 0 : 1;
      const double s = static_cast<double>(i - k * p) / p, t = static_cast<double>(j) / p;
      const Eigen::Vector2d* c = piece[k];
      cp.row(i + nu * j) = ((1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + (1 - s) * t * c[2] + s * t * c[3]).transpose();
    }
  }
  return make_patch(KnotVector(p, u), KnotVector(p, v), cp);
}

Geometry geometry_from_quad_grid(const mesh::PolyMesh& m, int degree, const std::string& name) {
  auto fail = [&](const std::string& why) -> void {
    throw InputError(name, 0, "not a structured quad grid for a B-spline patch: " + why);
  };
  for (Index f = 0; f < m.num_faces(); ++f) {
    if (m.face_size(f) != 4) fail("face " + std::to_string(f + 1) + " has " + std::to_string(m.face_size(f)) + " vertices");
  }
  if (m.is_closed()) fail("the mesh is closed");
  if (m.boundary_loops().size() != 1) fail("the mesh has " + std::to_string(m.boundary_loops().size()) + " boundary loops");
  // Start at a corner (a boundary vertex with one face): the first boundary half-edge leaving it.
  const std::vector<Index>& loop = m.boundary_loops()[0];
  Index start = -1;
  for (Index h : loop) {
    if (m.num_vertex_faces(m.half_edge(h).origin) == 1) {
      start = h;
      break;
    }
  }
  if (start < 0) fail("the boundary has no corner (a vertex with a single face)");
  // Walk rows: row j's half-edges run along u; the next row is twin(next(next(h))) of each.
  std::vector<Index> row;
  {
    // The bottom row: boundary half-edges from the corner to the next corner.
    std::size_t k = 0;
    while (loop[k] != start) ++k;
    for (std::size_t s = 0; s < loop.size(); ++s) {
      const Index h = loop[(k + s) % loop.size()];
      row.push_back(h);
      if (m.num_vertex_faces(m.half_edge_target(h)) == 1) break;
    }
  }
  const Index nu = static_cast<Index>(row.size()) + 1;
  std::vector<Index> grid;  // vertex indices, i + nu * j
  for (Index h : row) grid.push_back(m.half_edge(h).origin);
  grid.push_back(m.half_edge_target(row.back()));
  Index nv = 1;
  while (true) {
    std::vector<Index> up;
    bool any = false, all = true;
    for (Index h : row) {
      const Index opp = m.half_edge(m.half_edge(h).next).next;  // c -> d in the quad a b c d
      const Index t = m.half_edge(opp).twin;
      up.push_back(opp);
      if (t >= 0) any = true; else all = false;
    }
    // The top row of vertices: opp runs from (i+1, j+1) to (i, j+1).
    std::vector<Index> verts(static_cast<std::size_t>(nu));
    for (std::size_t i = 0; i < up.size(); ++i) {
      const Index opp = up[i];
      verts[i] = m.half_edge_target(opp);
      verts[i + 1] = m.half_edge(opp).origin;
    }
    // Consistency: neighbouring quads in a row share the vertical edge.
    for (std::size_t i = 0; i + 1 < up.size(); ++i) {
      if (m.half_edge_target(up[i + 1]) != m.half_edge(up[i]).origin) fail("rows do not line up");
    }
    grid.insert(grid.end(), verts.begin(), verts.end());
    ++nv;
    if (!any) break;
    if (!all) fail("a row of quads ends before the others (the net is not a rectangle of quads)");
    std::vector<Index> next_row;
    for (Index opp : up) next_row.push_back(m.half_edge(opp).twin);
    row = std::move(next_row);
    if (nv > m.num_vertices()) fail("rows do not close");
  }
  if ((nu - 1) * (nv - 1) != m.num_faces()) {
    fail(std::to_string(m.num_faces()) + " faces, but the grid from a corner has " + std::to_string(nu - 1) +
         " × " + std::to_string(nv - 1));
  }
  std::vector<char> seen(static_cast<std::size_t>(m.num_vertices()), 0);
  for (Index v : grid) {
    if (seen[static_cast<std::size_t>(v)]) fail("vertex " + std::to_string(v + 1) + " appears twice in the grid");
    seen[static_cast<std::size_t>(v)] = 1;
  }
  if (nu < degree + 1 || nv < degree + 1) {
    throw InputError(name, 0, "the grid has " + std::to_string(nu) + " × " + std::to_string(nv) +
                                  " control points; degree " + std::to_string(degree) + " needs at least " +
                                  std::to_string(degree + 1) + " in each direction");
  }
  const int dim = m.is_planar() ? 2 : 3;
  Eigen::MatrixXd cp(nu * nv, dim);
  for (Index k = 0; k < nu * nv; ++k) cp.row(k) = m.point(grid[static_cast<std::size_t>(k)]).head(dim).transpose();
  return make_patch(KnotVector::uniform(degree, nu - degree), KnotVector::uniform(degree, nv - degree), cp);
}

}  // namespace iga::basis::bspline
