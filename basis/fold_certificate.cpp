#include "basis/fold_certificate.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/subdivision_view.hpp"

namespace iga::basis {
namespace {

// A coefficient above −kRoundOff × the element's scale (max |x_u| max |x_v| of its coefficients, times max W³ for
// NURBS) counts as of the right sign; a value (a corner coefficient, or the value at the least coefficient's
// Greville point) below it is a fold.
constexpr double kRoundOff = 1e-10;
constexpr int kMaxDepth = 8;     // boxes down to 2^-8 of the element per direction
constexpr int kMaxBoxes = 4096;  // per element: a bound on the work where det J touches zero
constexpr int kMaxLayers = 60;   // subdivision layers towards an extraordinary vertex
constexpr double kLayerConverged = 1e-7;

// Tensor Bernstein coefficients: rows the u index, columns the v index.
using Coeffs = Eigen::MatrixXd;

double binomial(int n, int k) {
  double b = 1;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

// Interpolation of degree n at the Chebyshev–Lobatto nodes t_i = (1 − cos(iπ/n))/2: A(i, k) = B_k^n(t_i). Only the
// map's own degree is interpolated (its condition number stays below 1e4 to degree 15); det J's coefficients are
// products of these, formed exactly.
struct BernsteinGrid {
  explicit BernsteinGrid(int degree) : n(degree), t(degree + 1) {
    Eigen::MatrixXd a(n + 1, n + 1);
    for (int i = 0; i <= n; ++i) t(i) = 0.5 * (1.0 - std::cos(M_PI * i / n));
    for (int i = 0; i <= n / 2; ++i) t(n - i) = 1.0 - t(i);
    for (int i = 0; i <= n; ++i) {
      for (int k = 0; k <= n; ++k) a(i, k) = binomial(n, k) * std::pow(t(i), k) * std::pow(1.0 - t(i), n - k);
    }
    lu.compute(a);
  }
  int n;
  Eigen::VectorXd t;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
};

const BernsteinGrid& grid(int degree) {
  thread_local std::map<int, std::unique_ptr<BernsteinGrid>> grids;
  auto& g = grids[degree];
  if (!g) g = std::make_unique<BernsteinGrid>(degree);
  return *g;
}

Coeffs diff_u(const Coeffs& p) {
  const Eigen::Index a = p.rows() - 1;
  return static_cast<double>(a) * (p.bottomRows(a) - p.topRows(a));
}
Coeffs diff_v(const Coeffs& p) { return diff_u(p.transpose()).transpose(); }

Coeffs multiply(const Coeffs& p, const Coeffs& q) {
  const int a1 = static_cast<int>(p.rows()) - 1, a2 = static_cast<int>(p.cols()) - 1;
  const int b1 = static_cast<int>(q.rows()) - 1, b2 = static_cast<int>(q.cols()) - 1;
  Coeffs c = Coeffs::Zero(a1 + b1 + 1, a2 + b2 + 1);
  for (int k = 0; k <= a1; ++k) {
    for (int r = 0; r <= b1; ++r) {
      const double wu = binomial(a1, k) * binomial(b1, r) / binomial(a1 + b1, k + r);
      for (int l = 0; l <= a2; ++l) {
        for (int s = 0; s <= b2; ++s) {
          c(k + r, l + s) += wu * binomial(a2, l) * binomial(b2, s) / binomial(a2 + b2, l + s) * p(k, l) * q(r, s);
        }
      }
    }
  }
  return c;
}

// De Casteljau at 1/2 in u: the coefficients of the halves [0, 1/2] and [1/2, 1].
void split_u(const Coeffs& p, Coeffs& left, Coeffs& right) {
  const Eigen::Index n = p.rows() - 1;
  left.resize(p.rows(), p.cols());
  right.resize(p.rows(), p.cols());
  Coeffs work = p;
  for (Eigen::Index r = 0; r <= n; ++r) {
    left.row(r) = work.row(0);
    right.row(n - r) = work.row(n - r);
    for (Eigen::Index i = 0; i < n - r; ++i) work.row(i) = 0.5 * (work.row(i) + work.row(i + 1));
  }
}

double evaluate(const Coeffs& p, double u, double v) {
  auto basis = [](Eigen::Index n, double t) {
    Eigen::VectorXd b(n + 1);
    for (Eigen::Index k = 0; k <= n; ++k) {
      b(k) = binomial(static_cast<int>(n), static_cast<int>(k)) * std::pow(t, k) * std::pow(1.0 - t, n - k);
    }
    return b;
  };
  return basis(p.rows() - 1, u).dot(p * basis(p.cols() - 1, v));
}

// The map on the unit square as X, Y (and W for NURBS: x = X/W) in Bernstein form, and the numerator of its det J.
struct BernsteinMap {
  Coeffs x, y, w;  // w empty for polynomial maps; x and y relative to origin
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Coeffs det;      // det J (polynomial) or det J W³ (rational), times the orientation
  double scale = 0;
  Eigen::Vector2d point(double u, double v) const {
    const double weight = w.size() ? evaluate(w, u, v) : 1.0;
    return origin + Eigen::Vector2d(evaluate(x, u, v), evaluate(y, u, v)) / weight;
  }
  double det_j(double u, double v, double orientation) const {
    const double weight = w.size() ? evaluate(w, u, v) : 1.0;
    return orientation * evaluate(det, u, v) / (weight * weight * weight);
  }
};

// values: 3 × (n+1)² samples (X, Y, W) at the nodes (t_i, t_j), point i + (n+1) j.
BernsteinMap bernstein_map(const Eigen::Matrix3Xd& values, int n, bool rational, double orientation) {
  const BernsteinGrid& b = grid(n);
  auto coeffs = [&](int row) {
    const Eigen::MatrixXd v = values.row(row).reshaped(n + 1, n + 1);
    return Coeffs(b.lu.solve(b.lu.solve(v).transpose()).transpose());
  };
  BernsteinMap m;
  m.x = coeffs(0);
  m.y = coeffs(1);
  Coeffs xu = diff_u(m.x), xv = diff_v(m.x), yu = diff_u(m.y), yv = diff_v(m.y);
  const auto largest = [](const Coeffs& a, const Coeffs& b) { return std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()); };
  if (!rational) {
    m.det = orientation * (multiply(xu, yv) - multiply(xv, yu));
    m.scale = largest(xu, yu) * largest(xv, yv);
    return m;
  }
  // det [X X_u X_v; Y Y_u Y_v; W W_u W_v] = det J W³ (each term of degree 3n − 1 per direction), with x taken
  // relative to the element's first corner (X − c W), so that the scale below does not grow with the distance from
  // the origin.
  m.w = coeffs(2);
  m.origin = Eigen::Vector2d(m.x(0, 0), m.y(0, 0)) / m.w(0, 0);
  m.x -= m.origin(0) * m.w;
  m.y -= m.origin(1) * m.w;
  xu = diff_u(m.x), xv = diff_v(m.x), yu = diff_u(m.y), yv = diff_v(m.y);
  const Coeffs wu = diff_u(m.w), wv = diff_v(m.w);
  m.det = orientation * (multiply(m.x, multiply(yu, wv) - multiply(yv, wu)) -
                         multiply(m.y, multiply(xu, wv) - multiply(xv, wu)) +
                         multiply(m.w, multiply(xu, yv) - multiply(xv, yu)));
  const double wmax = m.w.cwiseAbs().maxCoeff();
  m.scale = largest(xu, yu) * largest(xv, yv) * wmax;  // X_u ~ W x_u: |X_u| |Y_v| W is det J W³'s scale
  return m;
}

struct Finding {
  Eigen::Vector2d x;
  double det = 0;
  bool sampled = false;  // a value of the wrong sign (else: undecided at the deepest box)
  double size = 0;       // about the element's size: coordinates below 1e-12 of it are printed as 0
};

struct Box {
  Coeffs c;
  double u0, u1, v0, v1;
  int depth;
};

// The sign of m.det on the unit square: nullopt when every coefficient of some subdivision is of the right sign.
std::optional<Finding> check_map(const BernsteinMap& m, double orientation) {
  // A map whose coefficients overflow is left to Geometry::evaluate's guards (they name the overflow).
  if (!std::isfinite(m.scale) || !m.det.allFinite()) return std::nullopt;
  const double floor = -kRoundOff * m.scale;
  std::vector<Box> boxes{{m.det, 0, 1, 0, 1, 0}};
  int visited = 0;
  Coeffs left, right, ll, lr, rl, rr;
  while (!boxes.empty()) {
    Box box = std::move(boxes.back());
    boxes.pop_back();
    Eigen::Index ci = 0, cj = 0;
    if (box.c.minCoeff(&ci, &cj) >= floor) continue;
    const Eigen::Index nu = box.c.rows() - 1, nv = box.c.cols() - 1;
    // The least coefficient's Greville point, and the corners (whose coefficients are values).
    const double gu = static_cast<double>(ci) / static_cast<double>(nu), gv = static_cast<double>(cj) / static_cast<double>(nv);
    for (const auto& [su, sv] : {std::pair{gu, gv}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}}) {
      if (evaluate(box.c, su, sv) < floor) {
        const double u = box.u0 + (box.u1 - box.u0) * su, v = box.v0 + (box.v1 - box.v0) * sv;
        return Finding{m.point(u, v), m.det_j(u, v, orientation), true, std::sqrt(m.scale)};
      }
    }
    if (box.depth == kMaxDepth || ++visited > kMaxBoxes) {
      const double u = box.u0 + (box.u1 - box.u0) * gu, v = box.v0 + (box.v1 - box.v0) * gv;
      return Finding{m.point(u, v), m.det_j(u, v, orientation), false, std::sqrt(m.scale)};
    }
    const double um = 0.5 * (box.u0 + box.u1), vm = 0.5 * (box.v0 + box.v1);
    const int d = box.depth + 1;
    split_u(box.c, left, right);
    split_u(left.transpose(), ll, lr);
    split_u(right.transpose(), rl, rr);
    boxes.push_back({ll.transpose(), box.u0, um, box.v0, vm, d});
    boxes.push_back({lr.transpose(), box.u0, um, vm, box.v1, d});
    boxes.push_back({rl.transpose(), um, box.u1, box.v0, vm, d});
    boxes.push_back({rr.transpose(), um, box.u1, vm, box.v1, d});
  }
  return std::nullopt;
}

// The nodes of degree n on the unit square, point i + (n+1) j at (t_i, t_j).
Eigen::Matrix2Xd nodes(int n) {
  const BernsteinGrid& b = grid(n);
  Eigen::Matrix2Xd pts(2, (n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) pts.col(i + (n + 1) * j) << b.t(i), b.t(j);
  }
  return pts;
}

// X, Y, W at the points from functions f (values, r × q) and points (r × 2); w the weights of rational functions
// (R_i = w_i N_i / W, and Σ N_i = 1 gives 1/W = Σ R_i / w_i).
Eigen::Matrix3Xd homogeneous(const Eigen::MatrixXd& f, const Eigen::MatrixX2d& points, const Eigen::VectorXd* w) {
  Eigen::Matrix3Xd out(3, f.cols());
  out.topRows(2) = (f.transpose() * points).transpose();
  for (Eigen::Index k = 0; k < f.cols(); ++k) {
    const double weight = w ? 1.0 / f.col(k).cwiseQuotient(*w).sum() : 1.0;
    out.col(k).head(2) *= weight;
    out(2, k) = weight;
  }
  return out;
}

Eigen::MatrixX2d local_points(const Geometry& g, Index e) { return g.element_points(e).leftCols<2>(); }

std::optional<Finding> check_polynomial_element(const Geometry& g, Index e, int degree, const Eigen::VectorXd* w) {
  BasisValues f;
  g.space().evaluate(e, nodes(degree), 0, f);
  const BernsteinMap m = bernstein_map(homogeneous(f.value, local_points(g, e), w), degree, w != nullptr, g.orientation());
  return check_map(m, g.orientation());
}

// One polynomial tile of a subdivision element: the regular patch's functions on its domain with these points.
std::optional<Finding> check_tile(const SubdivisionView& view, const PatchTile& tile, const Eigen::MatrixX2d& points,
                                  double orientation) {
  const double sign = tile.jacobian.determinant() > 0 ? 1.0 : -1.0;  // det J = det(dx/dt) det(dt/dx)
  BasisValues f;
  view.patch_functions(nodes(view.patch_degree), 0, f);
  const BernsteinMap m = bernstein_map(homogeneous(f.value, points, nullptr), view.patch_degree, false, orientation * sign);
  auto found = check_map(m, orientation * sign);
  if (found) found->det *= tile.jacobian.determinant() * sign;  // det(dx/dt) · det(dt/dx), the element's det J
  return found;
}

std::optional<Finding> check_subdivision_element(const Geometry& g, Index e, const SubdivisionElement& s) {
  const SubdivisionView& view = *s.view;
  if (view.patch_shape != Shape::Quad) return std::nullopt;  // triangle tiles: sampled only
  const Eigen::MatrixX2d local = local_points(g, e);
  for (const PatchTile& tile : s.explicit_tiles) {
    if (auto f = check_tile(view, tile, tile.points * local, g.orientation())) return f;
  }
  // Layers towards the vertex: points A^(l-1) P with the limit point taken out (A fixes constants, so the
  // difference iterates without cancellation) and normalised (det J's sign does not see a positive scale).
  const Eigen::MatrixX2d first = s.to_points * local;
  const Eigen::RowVector2d limit = view.limit.transpose() * first;
  Eigen::MatrixX2d d = first.rowwise() - limit;
  double magnitude = 1;  // the layer's points are limit + magnitude * d
  for (int layer = 1; layer <= kMaxLayers; ++layer) {
    const double size = d.cwiseAbs().maxCoeff();
    if (!(size > 0)) break;
    d /= size;
    magnitude *= size;
    for (const PatchTile& tile : view.tiles) {
      if (auto f = check_tile(view, tile, tile.points * d, g.orientation())) {
        f->x = limit.transpose() + magnitude * f->x;
        f->size *= magnitude;
        f->det *= magnitude * magnitude;
        return f;
      }
    }
    Eigen::MatrixX2d next = view.subdivision * d;
    const double change = (next / std::max(next.cwiseAbs().maxCoeff(), 1e-300) - d).cwiseAbs().maxCoeff();
    d.swap(next);
    if (layer > 3 && change < kLayerConverged) break;  // every further layer is this one scaled
  }
  return std::nullopt;
}

std::string message(Index e, Finding f, int orientation) {
  for (int c = 0; c < 2; ++c) {
    if (std::abs(f.x(c)) < 1e-12 * f.size) f.x(c) = 0;  // round-off of a point at 0 (a corner)
  }
  std::ostringstream m;
  m << "element " << e << ": ";
  if (f.sampled) {
    m << "det J = " << std::setprecision(3) << f.det << (orientation > 0 ? " < 0" : " > 0");
  } else {
    m << "det J's Bernstein coefficients stay " << (orientation > 0 ? "negative" : "positive")
      << " down to 1/256 of the element (det J = " << std::setprecision(3) << f.det << " there)";
  }
  m << " where most of the domain has det J " << (orientation > 0 ? "> 0" : "< 0") << ": the geometry map folds over"
    << (f.sampled ? "" : " or is degenerate") << std::setprecision(6) << " at (" << f.x(0) << ", " << f.x(1) << ")";
  return m.str();
}

}  // namespace

std::string fold_certificate(const Geometry& geometry) {
  if (geometry.dim() != 2) return {};
  const Space& space = geometry.space();
  for (Index e = 0; e < space.num_elements(); ++e) {
    if (space.kind(e).shape != Shape::Quad) continue;
    std::optional<Finding> found;
    if (const auto rational = space.rational_form(e)) {
      found = check_polynomial_element(geometry, e, rational->degree, &rational->weights);
    } else if (const auto degree = space.polynomial_degree(e)) {
      found = check_polynomial_element(geometry, e, *degree, nullptr);
    } else if (const auto sub = space.subdivision_element(e)) {
      found = check_subdivision_element(geometry, e, *sub);
    }
    if (found) return message(e, *found, geometry.orientation());
  }
  return {};
}

}  // namespace iga::basis
