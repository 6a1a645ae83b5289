#include "basis/fit_surface.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "basis/basis_values.hpp"
#include "core/error.hpp"

namespace iga::basis {

Eigen::Vector3d ExactSurface::at(double pa, double pb) const {
  if (kind == Kind::kCylinder) return {radius * std::sin(pa), pb, radius * std::cos(pa)};
  return radius * Eigen::Vector3d(std::cos(pb) * std::cos(pa), std::cos(pb) * std::sin(pa), std::sin(pb));
}

bool ExactSurface::periodic() const { return a[1] - a[0] >= 2 * std::numbers::pi * (1 - 1e-12); }

Eigen::Vector2d ExactSurface::parameters(const Eigen::Vector3d& x) const {
  double pa = kind == Kind::kCylinder ? std::atan2(x(0), x(2)) : std::atan2(x(1), x(0));
  double pb = kind == Kind::kCylinder ? x(1) : std::atan2(x(2), std::hypot(x(0), x(1)));
  if (periodic()) {
    while (pa < a[0]) pa += 2 * std::numbers::pi;
    while (pa >= a[0] + 2 * std::numbers::pi) pa -= 2 * std::numbers::pi;
  } else {
    // The angle nearest to the range (atan2's branch may lie a turn away from it).
    const double mid = 0.5 * (a[0] + a[1]);
    pa = mid + std::remainder(pa - mid, 2 * std::numbers::pi);
    pa = std::clamp(pa, a[0], a[1]);
  }
  return {pa, std::clamp(pb, b[0], b[1])};
}

Eigen::Vector3d ExactSurface::project(const Eigen::Vector3d& x, bool on_boundary) const {
  Eigen::Vector2d p = parameters(x);
  if (on_boundary) {
    // Distances along the surface to the four boundary curves: R Δa (times cos b on the sphere) and Δb (times R).
    const double scale_a = kind == Kind::kCylinder ? radius : radius * std::cos(p(1));
    const double scale_b = kind == Kind::kCylinder ? 1.0 : radius;
    double best = INFINITY;
    Eigen::Vector2d q = p;
    for (int side = 0; side < 4; ++side) {
      if (side < 2 && periodic()) continue;
      const bool in_a = side < 2;
      const double bound = in_a ? a[static_cast<std::size_t>(side)] : b[static_cast<std::size_t>(side - 2)];
      const double d = in_a ? scale_a * std::abs(p(0) - bound) : scale_b * std::abs(p(1) - bound);
      if (d < best) {
        best = d;
        q = p;
        q(in_a ? 0 : 1) = bound;
      }
    }
    p = q;
  }
  return at(p(0), p(1));
}

std::string ExactSurface::description() const {
  const double deg = 180 / std::numbers::pi;
  std::ostringstream out;
  out << (kind == Kind::kCylinder ? "cylinder" : "sphere") << " R = " << radius << ", "
      << (kind == Kind::kCylinder ? "a" : "longitude") << " in [" << a[0] * deg << ", " << a[1] * deg << "] degrees, ";
  if (kind == Kind::kCylinder) {
    out << "y in [" << b[0] << ", " << b[1] << "]";
  } else {
    out << "latitude in [" << b[0] * deg << ", " << b[1] * deg << "] degrees";
  }
  return out.str();
}

ExactSurface parse_exact_surface(const std::string& text, const std::string& what) {
  const std::string usage = what + " '" + text + "': expected 'cylinder; R; A0; A1; Y0; Y1' (about the y axis, x = R sin a, "
                            "z = R cos a, angles in degrees) or 'sphere; R; LON0; LON1; LAT0; LAT1' (degrees)";
  std::vector<std::string> f;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ';');) {
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    f.push_back(first == std::string::npos ? "" : item.substr(first, last - first + 1));
  }
  if (f.size() != 6 || (f[0] != "cylinder" && f[0] != "sphere")) throw InputError(usage);
  double v[5];
  for (int i = 0; i < 5; ++i) {
    std::size_t used = 0;
    try {
      v[i] = std::stod(f[static_cast<std::size_t>(i + 1)], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != f[static_cast<std::size_t>(i + 1)].size() || !std::isfinite(v[i])) throw InputError(usage);
  }
  const bool sphere = f[0] == "sphere";
  if (!(v[0] > 0)) throw InputError(what + " '" + text + "': the radius must be > 0");
  if (!(v[2] > v[1]) || v[2] - v[1] > 360) throw InputError(what + " '" + text + "': the angle range must be increasing and at most 360 degrees");
  if (!(v[4] > v[3])) throw InputError(what + " '" + text + "': the " + (sphere ? "latitude" : "y") + " range must be increasing");
  if (sphere && (v[3] < -90 || v[4] > 90)) throw InputError(what + " '" + text + "': latitudes lie in [-90, 90] degrees");
  const double deg = std::numbers::pi / 180, scale_b = sphere ? deg : 1.0;
  return {sphere ? ExactSurface::Kind::kSphere : ExactSurface::Kind::kCylinder, v[0], {v[1] * deg, v[2] * deg},
          {v[3] * scale_b, v[4] * scale_b}};
}

SurfaceFit fit_to_surface(const Geometry& g, const ExactSurface& shape, int rounds) {
  if (g.dim() != 3) throw InputError("fit_to_surface: the geometry is planar; a shape is fitted by a surface in 3D");
  const Space& space = g.space();
  struct Sample {
    Index element;
    Eigen::Vector2d uv;
    bool boundary;
  };
  std::vector<Sample> samples;
  const int k = 5;
  for (Index e = 0; e < space.num_elements(); ++e) {
    // k × k cell centres of the unit square; of a triangle, the k(k + 1)/2 points ((i + 1/3)/k, (j + 1/3)/k), i + j < k.
    const bool triangle = space.kind(e).shape == Shape::Triangle;
    const double offset = triangle ? 1.0 / 3 : 0.5;
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < (triangle ? k - j : k); ++i) {
        samples.push_back({e, Eigen::Vector2d((i + offset) / k, (j + offset) / k), false});
      }
    }
  }
  for (const BoundaryEdge& e : space.boundary_edges()) {
    for (int i = 0; i <= 2 * k; ++i) samples.push_back({e.element, side_point(space.kind(e.element).shape, e.side, double(i) / (2 * k)), true});
  }
  std::vector<Eigen::Triplet<double>> entries;
  BasisValues bv;
  Eigen::Matrix2Xd at(2, 1);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    at.col(0) = samples[s].uv;
    space.evaluate(samples[s].element, at, 0, bv);
    const auto dofs = space.dofs(samples[s].element);
    for (std::size_t a = 0; a < dofs.size(); ++a) {
      entries.emplace_back(static_cast<Index>(s), dofs[a], bv.value(static_cast<Index>(a), 0));
    }
  }
  Eigen::SparseMatrix<double> phi(static_cast<Index>(samples.size()), space.num_dofs());
  phi.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> phi_t = phi.transpose();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> normal(phi_t * phi);
  if (normal.info() != Eigen::Success) {
    throw InputError("fit_to_surface: the least-squares system is singular (a function without samples)");
  }
  Eigen::MatrixXd p = g.control_points();
  Eigen::MatrixXd target(phi.rows(), 3);
  double distance = 0.0;
  for (int round = 0; round <= rounds; ++round) {
    const Eigen::MatrixXd x = phi * p;
    distance = 0.0;
    for (Index s = 0; s < x.rows(); ++s) {
      const Eigen::Vector3d xs = x.row(s).transpose();
      target.row(s) = shape.project(xs, samples[static_cast<std::size_t>(s)].boundary).transpose();
      distance = std::max(distance, (target.row(s) - x.row(s)).norm());
    }
    if (round == rounds) break;  // the last round measures
    p = normal.solve(phi_t * target);
  }
  return {Geometry(g.space_ptr(), p), distance};
}

}  // namespace iga::basis
