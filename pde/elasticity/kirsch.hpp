#pragma once
// Kirsch's infinite plate with a circular hole of radius a under uniaxial tension T along x (Kirsch 1898), the
// classic test of isogeometric elasticity (Hughes, Cottrell and Bazilevs 2005, §4.1): in polar coordinates (r, θ)
// about the hole's centre,
//   σ_xx = T (1 − a²/r² (3/2 cos 2θ + cos 4θ) + 3a⁴/(2r⁴) cos 4θ)
//   σ_yy = T (−a²/r² (1/2 cos 2θ − cos 4θ) − 3a⁴/(2r⁴) cos 4θ)
//   σ_xy = T (−a²/r² (1/2 sin 2θ + sin 4θ) + 3a⁴/(2r⁴) sin 4θ)
//   u_x = T a/(8μ) (r/a (κ + 1) cos θ + 2a/r ((1 + κ) cos θ + cos 3θ) − 2a³/r³ cos 3θ)
//   u_y = T a/(8μ) (r/a (κ − 3) sin θ + 2a/r ((1 − κ) sin θ + sin 3θ) − 2a³/r³ sin 3θ)
// with κ = (λ + 3μ)/(λ + μ) of the in-plane Lamé constants (3 − 4ν plane strain, (3 − ν)/(1 + ν) plane stress).
// σ_xx = 3T at (0, a), the stress concentration.
#include <array>
#include <memory>

#include "fem/function.hpp"
#include "pde/elasticity/forms.hpp"

namespace iga::pde {

struct KirschSolution {
  std::array<std::shared_ptr<const fem::Function>, 2> displacement;  ///< with closed-form gradients
  std::array<std::shared_ptr<const fem::Function>, 3> stress;        ///< σ_xx, σ_yy, σ_xy
};

/// InputError for a radius or a tension that is not finite, or a radius <= 0.
KirschSolution kirsch_solution(double tension, double radius, Lame lame);

}  // namespace iga::pde
