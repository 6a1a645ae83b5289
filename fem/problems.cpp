#include "fem/problems.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"

namespace iga::fem {

namespace {
using V = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;
}  // namespace

std::vector<std::string> manufactured_problem_names() { return {"sine", "harmonic", "linear", "poly", "corner"}; }

ManufacturedProblem manufactured_problem(const std::string& name, double c) {
  ManufacturedProblem p;
  p.name = name;
  std::ostringstream cs;  // c exactly (17 significant digits) for the expressions
  cs.precision(17);
  cs << c;
  const std::string ct = cs.str();
  if (name == "sine") {
    p.description = "u = sin(pi x) sin(pi y)";
    p.exact = make_function([](const V& x) { return std::sin(kPi * x(0)) * std::sin(kPi * x(1)); },
                            [](const V& x) -> V {
                              return {kPi * std::cos(kPi * x(0)) * std::sin(kPi * x(1)),
                                      kPi * std::sin(kPi * x(0)) * std::cos(kPi * x(1)), 0.0};
                            });
    p.source = make_function([c](const V& x) { return (2 * kPi * kPi + c) * std::sin(kPi * x(0)) * std::sin(kPi * x(1)); });
    p.exact_expression = "sin(pi*x)*sin(pi*y)";
    p.source_expression = "(2*pi^2 + " + ct + ")*sin(pi*x)*sin(pi*y)";
  } else if (name == "harmonic") {
    p.description = "u = exp(x) sin(y) (harmonic)";
    p.exact = make_function([](const V& x) { return std::exp(x(0)) * std::sin(x(1)); },
                            [](const V& x) -> V {
                              return {std::exp(x(0)) * std::sin(x(1)), std::exp(x(0)) * std::cos(x(1)), 0.0};
                            });
    p.source = make_function([c](const V& x) { return c * std::exp(x(0)) * std::sin(x(1)); });
    p.exact_expression = "exp(x)*sin(y)";
    p.source_expression = ct + "*exp(x)*sin(y)";
  } else if (name == "linear") {
    p.description = "u = 1 + 2x - 3y (patch test)";
    p.exact = make_function([](const V& x) { return 1 + 2 * x(0) - 3 * x(1); },
                            [](const V&) -> V { return {2.0, -3.0, 0.0}; });
    p.source = make_function([c](const V& x) { return c * (1 + 2 * x(0) - 3 * x(1)); });
    p.exact_expression = "1 + 2*x - 3*y";
    p.source_expression = ct + "*(1 + 2*x - 3*y)";
  } else if (name == "poly") {
    p.description = "u = x^2 y + y^3 - x y";
    p.exact = make_function([](const V& x) { return x(0) * x(0) * x(1) + x(1) * x(1) * x(1) - x(0) * x(1); },
                            [](const V& x) -> V {
                              return {2 * x(0) * x(1) - x(1), x(0) * x(0) + 3 * x(1) * x(1) - x(0), 0.0};
                            });
    p.source = make_function([c](const V& x) {
      return -8 * x(1) + c * (x(0) * x(0) * x(1) + x(1) * x(1) * x(1) - x(0) * x(1));
    });
    p.exact_expression = "x^2*y + y^3 - x*y";
    p.source_expression = "-8*y + " + ct + "*(x^2*y + y^3 - x*y)";
  } else if (name == "corner") {
    // u = r^α sin(αφ), α = 2/3, in polar coordinates (r, θ) about (1, 1) with φ = θ − π/2 ∈ [0, 3π/2]: harmonic,
    // zero on the two edges at the corner; ∇u = α r^(α−1) (sin(αφ − θ), cos(αφ − θ)).
    p.description = "u = r^(2/3) sin(2 phi/3) about the reflex corner (1,1) of the L-shape [0,2]^2 minus (1,2]^2";
    // φ is taken in [−π/4, 7π/4): the branch cut is the notch's bisector (x = y > 1), so u stays harmonic across
    // the edges at the corner (a Catmull–Clark domain with the corner kept, --cc-corners, is tangent to them, not
    // equal). Elsewhere the cut can cross the domain (the quarter annulus: an L2 error of 18 %).
    p.domain = ProblemDomain{"the L-shape [0,2]^2 minus (1,2]^2 with its reentrant corner at (1, 1) (--geometry l-shape)",
                             {0.0, 0.0}, {2.0, 2.0}, {Eigen::Vector2d(1.0, 1.0)}};
    auto polar = [](const V& x, double& r, double& theta, double& phi) {
      r = std::hypot(x(0) - 1, x(1) - 1);
      theta = std::atan2(x(1) - 1, x(0) - 1);
      phi = theta - kPi / 2;
      if (phi < -kPi / 4) phi += 2 * kPi;
    };
    constexpr double a = 2.0 / 3.0;
    const std::string phi = "(atan2(y - 1, x - 1) < pi/4 ? atan2(y - 1, x - 1) + 3*pi/2 : atan2(y - 1, x - 1) - pi/2)";
    p.exact_expression = "((x - 1)^2 + (y - 1)^2)^(1/3)*sin(2/3*" + phi + ")";
    p.source_expression = ct + "*" + p.exact_expression;
    p.exact = make_function(
        [polar](const V& x) {
          double r, theta, phi;
          polar(x, r, theta, phi);
          return std::pow(r, a) * std::sin(a * phi);
        },
        [polar](const V& x) -> V {
          double r, theta, phi;
          polar(x, r, theta, phi);
          if (r == 0) return {0.0, 0.0, 0.0};
          const double g = a * std::pow(r, a - 1);
          return {g * std::sin(a * phi - theta), g * std::cos(a * phi - theta), 0.0};
        });
    auto exact = p.exact;
    p.source = make_function([c, exact](const V& x) {
      if (c == 0) return 0.0;
      Eigen::Matrix3Xd pt(3, 1);
      pt.col(0) = x;
      Eigen::VectorXd out;
      exact->values(pt, out);
      return c * out(0);
    });
  } else {
    std::string known;
    for (const auto& n : manufactured_problem_names()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("problem '" + name + "': unknown (known: " + known + ")");
  }
  return p;
}

namespace {
std::string short_number(double v) {
  std::ostringstream s;
  s.precision(4);
  s << (std::abs(v) < 1e-12 ? 0.0 : v);
  return s.str();
}
}  // namespace

void check_problem_domain(const ManufacturedProblem& problem, const basis::Geometry& geometry, const std::string& what) {
  if (!problem.domain || geometry.dim() != 2) return;
  const ProblemDomain& d = *problem.domain;
  const basis::Space& space = geometry.space();
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  std::vector<double> nearest(d.boundary_points.size(), INFINITY);
  basis::BasisValues bv;
  basis::GeometryValues gv;
  Eigen::Matrix2Xd t(2, 9);
  for (const basis::BoundaryEdge& e : space.boundary_edges()) {
    for (int k = 0; k < 9; ++k) t.col(k) = basis::side_point(space.kind(e.element).shape, e.side, k / 8.0);
    space.evaluate(e.element, t, 1, bv);
    geometry.evaluate(e.element, bv, gv, false);
    for (Eigen::Index k = 0; k < gv.x.cols(); ++k) {
      const Eigen::Vector2d x = gv.x.col(k).head<2>();
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
      for (std::size_t i = 0; i < nearest.size(); ++i) nearest[i] = std::min(nearest[i], (x - d.boundary_points[i]).norm());
    }
  }
  const double tol = 1e-6 * (d.hi - d.lo).norm();
  std::string wrong;
  if ((lo - d.lo).cwiseAbs().maxCoeff() > tol || (hi - d.hi).cwiseAbs().maxCoeff() > tol) {
    std::ostringstream span;
    span << "the geometry given spans [" << short_number(lo(0)) << ", " << short_number(hi(0)) << "] x ["
         << short_number(lo(1)) << ", " << short_number(hi(1)) << "]";
    wrong = span.str();
  }
  for (std::size_t i = 0; i < nearest.size(); ++i) {
    if (nearest[i] <= tol) continue;
    std::ostringstream point;
    point << (wrong.empty() ? "the geometry given does not have (" : " and does not have (") << short_number(d.boundary_points[i](0))
          << ", " << short_number(d.boundary_points[i](1)) << ") on its boundary";
    wrong += point.str();
  }
  if (!wrong.empty()) {
    std::ostringstream msg;
    msg << what << " belongs to " << d.description << "; " << wrong;
    throw InputError(msg.str());
  }
}

}  // namespace iga::fem
