#include "bem/boundary_discretization.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace iga::bem {

namespace {

double checked_scale(const basis::CurveGeometry& curve) {
  if (!(curve.diameter() > 0.0) || !std::isfinite(curve.diameter())) {
    throw InputError("boundary discretization: the curve has no extent (diameter 0)");
  }
  return 0.5 / curve.diameter();
}

// The maximum of segment-local B-spline j of an open segment, by sampling its support and Newton steps on
// the derivative (degree >= 2; for degree 1 the hat's peak is its Greville abscissa).
double basis_maximum(const basis::SplineCurveSpace& space, Index segment, Index j, double greville) {
  const int p = space.degree();
  if (p == 1) return greville;
  const Index n = space.segments()[static_cast<std::size_t>(segment)].elements;
  const double lo = static_cast<double>(std::clamp<Index>(j - p, 0, n));
  const double hi = static_cast<double>(std::clamp<Index>(j + 1, 0, n));
  constexpr int kSamples = 64;
  double best = greville, best_value = -1.0;
  for (int k = 0; k <= kSamples; ++k) {
    const double s = lo + (hi - lo) * k / kSamples;
    const double v = space.function(segment, j, s)(0);
    if (v > best_value) {
      best_value = v;
      best = s;
    }
  }
  for (int it = 0; it < 30; ++it) {
    const Eigen::Vector3d f = space.function(segment, j, best);
    if (!(f(2) < 0.0)) break;  // at an end of the support (or a flat piece): keep the sample
    const double next = std::clamp(best - f(1) / f(2), lo, hi);
    if (std::abs(next - best) < 1e-15 * std::max(1.0, hi)) {
      best = next;
      break;
    }
    best = next;
  }
  return best;
}

}  // namespace

BoundaryDiscretization::BoundaryDiscretization(const basis::CurveGeometry& curve, std::vector<int> condition,
                                               const DiscretizationOptions& options)
    : options_(options),
      curve_(curve),
      scaled_(curve.space_ptr(), curve.control_points() * checked_scale(curve)),
      scale_(checked_scale(curve)) {
  if (static_cast<Index>(condition.size()) != curve.num_elements()) {
    throw InputError("boundary discretization: " + std::to_string(condition.size()) + " conditions for " +
                     std::to_string(curve.num_elements()) + " curve elements");
  }
  for (std::size_t e = 0; e < condition.size(); ++e) {
    if (condition[e] != kDirichlet && condition[e] != kNeumann) {
      throw InputError("boundary discretization: curve element " + std::to_string(e) + " has condition " +
                       std::to_string(condition[e]) + " (expected 0 Dirichlet or 1 Neumann)");
    }
  }
  if (options_.degree < 1) throw InputError("boundary discretization: degree " + std::to_string(options_.degree));
  if (options_.refine < 0 || options_.refine > 20) {
    throw InputError("boundary discretization: refine " + std::to_string(options_.refine) + " (expected 0..20)");
  }
  build_segments(condition);
  build_collocation();
}

void BoundaryDiscretization::build_segments(const std::vector<int>& condition) {
  const Index split = Index{1} << options_.refine;
  const int p = options_.degree;
  const double d2 = curve_.diameter() * curve_.diameter();
  if (!(curve_.signed_area() > 0.0)) {
    throw InputError("boundary discretization: the boundary encloses a signed area of " +
                     std::to_string(curve_.signed_area()) +
                     ": the domain must lie to the left of the curve (outer loops counter-clockwise, holes clockwise)");
  }
  for (std::size_t l = 0; l < curve_.loops().size(); ++l) {
    const basis::CurveLoop& loop = curve_.loops()[l];
    if (!loop.closed) {
      throw InputError("boundary discretization: the boundary is not closed (an open chain starts at curve element " +
                       std::to_string(loop.elements.front()) + ")");
    }
    // A loop that encloses no area runs along the same curve twice (a slit, e.g. two sides of non-conforming
    // patches that the geometry reports as boundary): its collocation points would lie on the other side.
    if (std::abs(curve_.loop_area(l)) <= 1e-10 * d2) {
      throw InputError("boundary discretization: boundary loop " + std::to_string(l) + " (from curve element " +
                       std::to_string(loop.elements.front()) +
                       ") encloses no area: a slit, where the geometry's boundary runs along the same curve twice; "
                       "the BEM needs simple closed boundary curves");
    }
    const std::vector<Index>& els = loop.elements;
    const std::size_t m = els.size();
    std::vector<std::size_t> cuts;  // positions k: a segment ends after els[k]
    for (std::size_t k = 0; k < m; ++k) {
      const Index e = els[k], f = els[(k + 1) % m];
      if (options_.joints == Joints::Split || curve_.corner_at_end(e, options_.corner_tolerance) ||
          condition[static_cast<std::size_t>(e)] != condition[static_cast<std::size_t>(f)]) {
        cuts.push_back(k);
      }
    }
    if (cuts.empty()) {
      BemSegment s;
      s.curve_elements = els;
      s.closed = static_cast<Index>(m) * split >= p + 1;
      s.condition = condition[static_cast<std::size_t>(els.front())];
      segments_.push_back(std::move(s));
      continue;
    }
    // Start after the first cut; close a segment after every cut.
    BemSegment s;
    for (std::size_t r = 0; r < m; ++r) {
      const std::size_t k = (cuts.front() + 1 + r) % m;
      s.curve_elements.push_back(els[k]);
      if (std::find(cuts.begin(), cuts.end(), k) != cuts.end()) {
        s.condition = condition[static_cast<std::size_t>(els[k])];
        segments_.push_back(std::move(s));
        s = BemSegment{};
      }
    }
  }
  std::vector<basis::SplineSegment> spline_segments;
  first_bem_element_.assign(static_cast<std::size_t>(curve_.num_elements()), -1);
  for (const BemSegment& s : segments_) {
    spline_segments.push_back({static_cast<Index>(s.curve_elements.size()) * split, s.closed});
    for (Index ce : s.curve_elements) {
      first_bem_element_[static_cast<std::size_t>(ce)] = static_cast<Index>(elements_.size());
      for (Index k = 0; k < split; ++k) {
        elements_.push_back({ce, static_cast<double>(k) / static_cast<double>(split),
                             static_cast<double>(k + 1) / static_cast<double>(split)});
      }
    }
  }
  space_ = std::make_shared<basis::SplineCurveSpace>(p, std::move(spline_segments));
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    for (Index j = 0; j < space_->segment_dofs(static_cast<Index>(k)); ++j) {
      dof_condition_.push_back(segments_[k].condition);
    }
  }
}

void BoundaryDiscretization::build_collocation() {
  for (Index k = 0; k < space_->num_segments(); ++k) {
    const basis::SplineSegment& seg = space_->segments()[static_cast<std::size_t>(k)];
    Eigen::VectorXd s = space_->greville(k);
    const Index nd = s.size();
    if (options_.collocation == Collocation::Maxima && !seg.closed) {
      // Periodic uniform B-splines peak at their centres, which are their Greville abscissae.
      for (Index j = 0; j < nd; ++j) s(j) = basis_maximum(*space_, k, j, s(j));
    }
    if (!seg.closed) {
      const double f = nd == 2 ? 1.0 / 3.0 : 0.5;
      s(0) += f * (s(1) - s(0));
      s(nd - 1) -= f * (s(nd - 1) - s(nd - 2));
    }
    const double n = static_cast<double>(seg.elements);
    for (Index j = 0; j < nd; ++j) {
      const double sj = seg.closed ? std::fmod(s(j) + n, n) : std::clamp(s(j), 0.0, n);
      const Index i = std::min<Index>(static_cast<Index>(std::floor(sj)), seg.elements - 1);
      CollocationPoint c;
      c.element = space_->first_element(k) + i;
      c.t = sj - static_cast<double>(i);
      const BemElement& el = element(c.element);
      c.curve_element = el.curve_element;
      c.curve_t = el.a + c.t * (el.b - el.a);
      c.x = curve_.point(c.curve_element, c.curve_t);
      points_.push_back(c);
    }
  }
}

std::pair<Index, double> BoundaryDiscretization::locate(Index curve_element, double t) const {
  const Index split = Index{1} << options_.refine;
  const double u = std::clamp(t, 0.0, 1.0) * static_cast<double>(split);
  const Index k = std::min<Index>(static_cast<Index>(std::floor(u)), split - 1);
  return {first_bem_element_[static_cast<std::size_t>(curve_element)] + k, u - static_cast<double>(k)};
}

}  // namespace iga::bem
