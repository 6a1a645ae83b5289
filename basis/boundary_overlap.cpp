#include "basis/boundary_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "basis/basis_values.hpp"

namespace iga::basis {
namespace {

constexpr int kSamples = 16;    // segments per boundary side
constexpr double kTouch = 1e-9;  // of the domain's diameter: closer non-neighbouring segments meet

struct Segment {
  Eigen::Vector2d a, b;
  std::size_t edge;  // the side (or net edge) it samples, for messages
};

Eigen::MatrixX2d local_points(const Geometry& g, Index e) { return g.element_points(e).leftCols<2>(); }

// Physical points of element e at reference points pts.
Eigen::Matrix2Xd map_points(const Geometry& g, Index e, const Eigen::Matrix2Xd& pts, BasisValues& f) {
  g.space().evaluate(e, pts, 0, f);
  return (f.value.transpose() * local_points(g, e)).transpose();
}

std::vector<Segment> boundary_segments(const Geometry& g, const std::vector<BoundaryEdge>& edges) {
  std::vector<Segment> segments;
  segments.reserve(edges.size() * kSamples);
  BasisValues f;
  Eigen::Matrix2Xd pts(2, kSamples + 1);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Shape shape = g.space().kind(edges[k].element).shape;
    for (int i = 0; i <= kSamples; ++i) pts.col(i) = side_point(shape, edges[k].side, static_cast<double>(i) / kSamples);
    const Eigen::Matrix2Xd x = map_points(g, edges[k].element, pts, f);
    for (int i = 0; i < kSamples; ++i) segments.push_back({x.col(i), x.col(i + 1), k});
  }
  return segments;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a(0) * b(1) - a(1) * b(0); }

double point_segment(const Eigen::Vector2d& p, const Segment& s) {
  const Eigen::Vector2d d = s.b - s.a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - s.a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (s.a + t * d - p).norm();
}

// Distance between two segments (0 when they cross), and a point where they are nearest.
double distance(const Segment& s, const Segment& r, Eigen::Vector2d& at) {
  const double d1 = cross(s.b - s.a, r.a - s.a), d2 = cross(s.b - s.a, r.b - s.a);
  const double d3 = cross(r.b - r.a, s.a - r.a), d4 = cross(r.b - r.a, s.b - r.a);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    at = r.a + (r.b - r.a) * (d1 / (d1 - d2));
    return 0.0;
  }
  double best = HUGE_VAL;
  for (const auto& [p, other] : {std::pair{&s.a, &r}, {&s.b, &r}, {&r.a, &s}, {&r.b, &s}}) {
    const double d = point_segment(*p, *other);
    if (d < best) {
      best = d;
      at = *p;
    }
  }
  return best;
}

// Where two segments meet (a point of the nearer pair), or nothing: neighbours (an end shared to tol) meet only
// when they turn back onto each other.
std::optional<Eigen::Vector2d> meeting(const Segment& s, const Segment& r, double tol) {
  const Eigen::Vector2d* shared = nullptr;
  const Eigen::Vector2d *qs = nullptr, *qr = nullptr;
  for (const auto* p : {&s.a, &s.b}) {
    for (const auto* q : {&r.a, &r.b}) {
      if ((*p - *q).norm() <= tol) {
        shared = p;
        qs = p == &s.a ? &s.b : &s.a;
        qr = q == &r.a ? &r.b : &r.a;
      }
    }
  }
  if (shared) {
    const Eigen::Vector2d d1 = *qs - *shared, d2 = *qr - *shared;
    const double n = d1.norm() * d2.norm();
    if (n > 0 && d1.dot(d2) > 0 && std::abs(cross(d1, d2)) <= 1e-9 * n) return *shared;  // a cusp
    return std::nullopt;
  }
  Eigen::Vector2d at;
  if (distance(s, r, at) <= tol) return at;
  return std::nullopt;
}

// The first pair of segments that meet, found through a grid of cells about a segment long; name(edge) names a
// segment's side in messages.
std::string self_meeting(const std::string& subject, const std::vector<Segment>& segments,
                         const std::function<std::string(std::size_t)>& name, double diameter) {
  if (segments.empty()) return {};
  const double tol = kTouch * diameter;
  Eigen::Vector2d lo = segments[0].a, hi = lo;
  double length = 0;
  for (const Segment& s : segments) {
    lo = lo.cwiseMin(s.a.cwiseMin(s.b));
    hi = hi.cwiseMax(s.a.cwiseMax(s.b));
    length += (s.b - s.a).norm();
  }
  const double cell = std::max({length / static_cast<double>(segments.size()), (hi - lo).maxCoeff() / 2048, 1e-300});
  std::unordered_map<long long, std::vector<std::size_t>> cells;
  auto index = [&](double v, double base) { return static_cast<long long>(std::floor((v - base) / cell)); };
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Eigen::Vector2d a = segments[i].a.cwiseMin(segments[i].b).array() - tol;
    const Eigen::Vector2d b = segments[i].a.cwiseMax(segments[i].b).array() + tol;
    for (long long x = index(a(0), lo(0)); x <= index(b(0), lo(0)); ++x) {
      for (long long y = index(a(1), lo(1)); y <= index(b(1), lo(1)); ++y) cells[x * 4099 + y].push_back(i);
    }
  }
  for (const auto& [key, members] : cells) {
    for (std::size_t p = 0; p < members.size(); ++p) {
      for (std::size_t q = p + 1; q < members.size(); ++q) {
        const Segment &s = segments[members[p]], &r = segments[members[q]];
        if (s.edge == r.edge && (members[q] == members[p] + 1 || members[p] == members[q] + 1)) continue;
        if (const auto at = meeting(s, r, tol)) {
          std::ostringstream m;
          Eigen::Vector2d p = *at;
          for (int c = 0; c < 2; ++c) {
            if (std::abs(p(c)) < 1e-12 * diameter) p(c) = 0;  // round-off of a point on an axis
          }
          m << std::setprecision(6) << subject << " meets itself at (" << p(0) << ", " << p(1) << ") ("
            << name(s.edge) << " and " << name(r.edge)
            << "): a slit, a crack or a net that overlaps itself; the domain must be bounded by simple closed curves "
               "(a crack is not supported: leave a gap between its sides)";
          return m.str();
        }
      }
    }
  }
  return {};
}

// A domain of no area at all (every point on one line) is degenerate rather than cracked: the geometry's own guards
// name it (and iga-geometry still draws it, with a warning).
bool encloses_nothing(const std::vector<Segment>& segments, double diameter) {
  double area = 0;
  for (const Segment& s : segments) area += 0.5 * cross(s.a, s.b);
  return std::abs(area) <= 1e-10 * diameter * diameter;
}

}  // namespace

std::string boundary_overlap(const Geometry& geometry) {
  if (geometry.dim() != 2) return {};
  const std::vector<BoundaryEdge> edges = geometry.space().boundary_edges();
  if (edges.empty()) return {};
  const std::vector<Segment> segments = boundary_segments(geometry, edges);
  Eigen::Vector2d lo = segments[0].a, hi = lo;
  for (const Segment& s : segments) {
    lo = lo.cwiseMin(s.a.cwiseMin(s.b));
    hi = hi.cwiseMax(s.a.cwiseMax(s.b));
  }
  const double diameter = (hi - lo).norm();
  if (!std::isfinite(diameter)) return {};  // overflowing maps are named by Geometry::evaluate's guards
  if (encloses_nothing(segments, diameter)) return {};
  const auto name = [&](std::size_t k) {
    return "element " + std::to_string(edges[k].element) + " side " + std::to_string(edges[k].side);
  };
  return self_meeting("the boundary", segments, name, diameter);
}

std::string net_boundary_overlap(const mesh::PolyMesh& net) {
  if (!net.is_planar()) return {};
  std::vector<Segment> segments;
  std::vector<Index> half_edges;
  for (const auto& loop : net.boundary_loops()) {
    for (Index h : loop) {
      const Eigen::Vector3d a = net.point(net.half_edge(h).origin), b = net.point(net.half_edge_target(h));
      segments.push_back({a.head<2>(), b.head<2>(), half_edges.size()});
      half_edges.push_back(h);
    }
  }
  if (segments.empty()) return {};
  Eigen::Vector2d lo = segments[0].a, hi = lo;
  for (const Segment& s : segments) {
    lo = lo.cwiseMin(s.a.cwiseMin(s.b));
    hi = hi.cwiseMax(s.a.cwiseMax(s.b));
  }
  const double diameter = (hi - lo).norm();
  if (!std::isfinite(diameter)) return {};
  if (encloses_nothing(segments, diameter)) return {};
  const auto name = [&](std::size_t k) {
    const Index h = half_edges[k], face = net.half_edge(h).face;
    const long line = net.face_line(face);
    return "net edge " + std::to_string(net.half_edge(h).origin + 1) + "-" + std::to_string(net.half_edge_target(h) + 1) +
           " of face " + std::to_string(face + 1) + (line > 0 ? " (line " + std::to_string(line) + ")" : std::string());
  };
  return self_meeting("the net's boundary", segments, name, diameter);
}

}  // namespace iga::basis
