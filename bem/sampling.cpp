#include "bem/sampling.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "bem/errors.hpp"
#include "bem/interior.hpp"

namespace iga::bem {

double side_parameter(basis::Shape shape, int side, const Eigen::Vector2d& p, double tol) {
  const double u = p.x(), v = p.y();
  double off = 0.0, t = 0.0;
  if (shape == basis::Shape::Triangle) {
    switch (side) {
      case 0: off = v, t = u; break;
      case 1: off = 1.0 - u - v, t = v; break;
      default: off = u, t = 1.0 - v; break;
    }
  } else {
    switch (side) {
      case 0: off = v, t = u; break;
      case 1: off = 1.0 - u, t = v; break;
      case 2: off = 1.0 - v, t = 1.0 - u; break;
      default: off = u, t = 1.0 - v; break;
    }
  }
  return std::abs(off) <= tol ? std::clamp(t, 0.0, 1.0) : -1.0;
}

std::vector<Eigen::VectorXd> sample_on_geometry(const basis::Geometry& geometry, const basis::TraceSpace& trace,
                                                const BoundaryDiscretization& d, const Solution& solution,
                                                const std::function<Eigen::Matrix2Xd(basis::Shape)>& ref_points,
                                                std::vector<std::vector<char>>* on_boundary) {
  const basis::Space& space = geometry.space();
  std::multimap<Index, std::pair<int, Index>> sides;  // element → (side, trace element)
  for (Index k = 0; k < trace.num_elements(); ++k) sides.emplace(trace.edge(k).element, std::make_pair(trace.edge(k).side, k));
  const Index ne = space.num_elements();
  std::vector<Eigen::VectorXd> values(static_cast<std::size_t>(ne));
  if (on_boundary) on_boundary->assign(static_cast<std::size_t>(ne), {});
  std::vector<std::pair<Index, Index>> pending;  // (element, point) not on a boundary side of their element
  std::vector<Eigen::Vector2d> pending_x;
  // Boundary values by position, for points that lie on the boundary without being on a boundary side of their
  // element (an element that touches the boundary at a corner only).
  const double tol = 1e-12 * d.curve().diameter();
  std::map<std::pair<long long, long long>, std::vector<std::pair<Eigen::Vector2d, double>>> known;
  auto key = [&](const Eigen::Vector2d& x) {
    return std::make_pair(static_cast<long long>(std::floor(x.x() / (16 * tol))), static_cast<long long>(std::floor(x.y() / (16 * tol))));
  };
  basis::BasisValues bv;
  basis::GeometryValues gv;
  for (Index e = 0; e < ne; ++e) {
    const Eigen::Matrix2Xd ref = ref_points(space.kind(e).shape);
    space.evaluate(e, ref, 1, bv);
    geometry.evaluate(e, bv, gv, /*check=*/false);  // sample points include corners (EVs: no derivatives)
    Eigen::VectorXd& out = values[static_cast<std::size_t>(e)];
    out.setZero(ref.cols());
    if (on_boundary) (*on_boundary)[static_cast<std::size_t>(e)].assign(static_cast<std::size_t>(ref.cols()), 0);
    const auto range = sides.equal_range(e);
    for (Index k = 0; k < ref.cols(); ++k) {
      bool done = false;
      for (auto it = range.first; it != range.second && !done; ++it) {
        const double t = side_parameter(space.kind(e).shape, it->second.first, ref.col(k));
        if (t < 0.0) continue;
        const auto [be, bt] = d.locate(it->second.second, t);
        out(k) = evaluate_u(d, solution, be, bt);
        if (on_boundary) (*on_boundary)[static_cast<std::size_t>(e)][static_cast<std::size_t>(k)] = 1;
        known[key(gv.x.col(k).head<2>())].emplace_back(gv.x.col(k).head<2>(), out(k));
        done = true;
      }
      if (!done) {
        pending.emplace_back(e, k);
        pending_x.push_back(gv.x.col(k).head<2>());
      }
    }
  }
  std::vector<std::pair<Index, Index>> inside;
  std::vector<Eigen::Vector2d> inside_x;
  for (std::size_t m = 0; m < pending.size(); ++m) {
    const auto [e, k] = pending[m];
    const auto [kx, ky] = key(pending_x[m]);
    bool found = false;
    for (long long dx = -1; dx <= 1 && !found; ++dx) {
      for (long long dy = -1; dy <= 1 && !found; ++dy) {
        const auto it = known.find({kx + dx, ky + dy});
        if (it == known.end()) continue;
        for (const auto& [x, value] : it->second) {
          if ((x - pending_x[m]).norm() > tol) continue;
          values[static_cast<std::size_t>(e)](k) = value;
          if (on_boundary) (*on_boundary)[static_cast<std::size_t>(e)][static_cast<std::size_t>(k)] = 1;
          found = true;
          break;
        }
      }
    }
    if (!found) {
      inside.emplace_back(e, k);
      inside_x.push_back(pending_x[m]);
    }
  }
  Eigen::Matrix2Xd pts(2, static_cast<Index>(inside_x.size()));
  for (std::size_t k = 0; k < inside_x.size(); ++k) pts.col(static_cast<Index>(k)) = inside_x[k];
  const Eigen::VectorXd u = evaluate_interior(d, solution, pts);
  for (std::size_t k = 0; k < inside.size(); ++k) {
    values[static_cast<std::size_t>(inside[k].first)](inside[k].second) = u(static_cast<Index>(k));
  }
  return values;
}

}  // namespace iga::bem
