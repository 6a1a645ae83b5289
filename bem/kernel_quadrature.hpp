#pragma once
// Quadrature of the Laplace kernels against smooth functions on one piece [a, b] of a curve element, for a
// source point P anywhere (thesis §4.3.3):
//  - P on the piece (at curve parameter t0 ∈ [a, b], or at one of its end points): the piece is split at t0;
//    on each side t = t0 ± L s, s ∈ [0, 1], ln|x(t) − P| = ln s + ln(|x(t) − P| / s) with the second term
//    smooth: ∫ f ln s ds by quadrature::log_gauss_rule (4.51), the rest and the (bounded) double layer by
//    Gauss–Legendre;
//  - P off the piece: Gauss–Legendre when the distance from P to the piece (sampled at its ends and
//    midpoint) is at least `admissibility` times the piece's length, otherwise the piece is halved and each
//    half treated the same way (adaptive subdivision towards the nearest point; the nearly singular case).
// The nodes carry the kernels already multiplied by weight and speed (ds = speed dt in the curve's units), so
// ∫ φ v ds ≈ Σ_k single[k] φ(t_k) and ∫ φ ∂v/∂n ds ≈ Σ_k dbl[k] φ(t_k) for any smooth φ on the piece.
#include <Eigen/Core>
#include <vector>

#include "basis/curve/curve_geometry.hpp"

namespace iga::bem {

struct KernelNodes {
  std::vector<double> t;       ///< curve-element parameters
  std::vector<double> single;  ///< weight × speed × v(P, x(t)) (log part included)
  std::vector<double> dbl;     ///< weight × speed × ∂v/∂n_Q(P, x(t))
  bool hit_point = false;      ///< the subdivision reached P off its declared position (P on the boundary)
  bool at_end_point = false;   ///< P was found at an end point of the piece (t0 not given): P is on Γ
  void clear() {
    t.clear();
    single.clear();
    dbl.clear();
    hit_point = false;
    at_end_point = false;
  }
  std::size_t size() const { return t.size(); }
};

struct KernelQuadratureOptions {
  int regular_order = 14;    ///< Gauss points per admissible piece
  int singular_order = 16;   ///< Gauss and log-Gauss points per side of P
  double admissibility = 1.25;
  int max_depth = 48;        ///< halvings before a piece is declared to contain P
};

/// Appends the nodes of piece [a, b] of `element` for source point p (in the curve's coordinates). t0: P's
/// parameter on this element when P is known to lie on it, NaN otherwise (P is then still detected at the
/// piece's end points, to 1e-13 of the curve's diameter: corners and element joints).
void append_kernel_nodes(const basis::CurveGeometry& curve, Index element, double a, double b,
                         const Eigen::Vector2d& p, double t0, KernelNodes& out,
                         const KernelQuadratureOptions& options = {});

/// Whether Gauss with `regular_order` points on all of [a, b] is admissible for p (the test used above),
/// from the piece's end points, midpoint and a length estimate.
bool admissible(const Eigen::Vector2d& xa, const Eigen::Vector2d& xm, const Eigen::Vector2d& xb, double length,
                const Eigen::Vector2d& p, double admissibility);

}  // namespace iga::bem
