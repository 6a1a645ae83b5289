#include "pde/elasticity/kirsch.hpp"

#include <cmath>

#include "core/error.hpp"

namespace iga::pde {

KirschSolution kirsch_solution(double tension, double radius, Lame lame) {
  if (!std::isfinite(tension) || !(radius > 0.0) || !std::isfinite(radius)) {
    throw InputError("Kirsch solution: the tension must be finite and the radius a finite number > 0");
  }
  const double t = tension, a = radius;
  const double kappa = (lame.lambda + 3 * lame.mu) / (lame.lambda + lame.mu);
  const double c = t * a / (8 * lame.mu);
  KirschSolution s;
  auto polar = [](const Eigen::Vector3d& x) { return std::make_pair(std::hypot(x(0), x(1)), std::atan2(x(1), x(0))); };
  // u_x = c (A1 r cos θ + A2 cos θ / r + A3 cos 3θ / r − A4 cos 3θ / r³), u_y alike with B1, B2 and sines.
  const double a1 = (kappa + 1) / a, a2 = 2 * a * (1 + kappa), a3 = 2 * a, a4 = 2 * a * a * a;
  const double b1 = (kappa - 3) / a, b2 = 2 * a * (1 - kappa);
  // ∂/∂x = cos θ ∂_r − sin θ / r ∂_θ, ∂/∂y = sin θ ∂_r + cos θ / r ∂_θ.
  auto cartesian = [](double r, double th, double dr, double dth) {
    return Eigen::Vector3d(std::cos(th) * dr - std::sin(th) / r * dth, std::sin(th) * dr + std::cos(th) / r * dth, 0);
  };
  s.displacement[0] = fem::make_function(
      [=](const Eigen::Vector3d& x) {
        const auto [r, th] = polar(x);
        return c * (a1 * r * std::cos(th) + a2 * std::cos(th) / r + a3 * std::cos(3 * th) / r -
                    a4 * std::cos(3 * th) / (r * r * r));
      },
      [=](const Eigen::Vector3d& x) {
        const auto [r, th] = polar(x);
        const double dr = c * (a1 * std::cos(th) - a2 * std::cos(th) / (r * r) - a3 * std::cos(3 * th) / (r * r) +
                               3 * a4 * std::cos(3 * th) / std::pow(r, 4));
        const double dth = c * (-a1 * r * std::sin(th) - a2 * std::sin(th) / r - 3 * a3 * std::sin(3 * th) / r +
                                3 * a4 * std::sin(3 * th) / (r * r * r));
        return cartesian(r, th, dr, dth);
      });
  s.displacement[1] = fem::make_function(
      [=](const Eigen::Vector3d& x) {
        const auto [r, th] = polar(x);
        return c * (b1 * r * std::sin(th) + b2 * std::sin(th) / r + a3 * std::sin(3 * th) / r -
                    a4 * std::sin(3 * th) / (r * r * r));
      },
      [=](const Eigen::Vector3d& x) {
        const auto [r, th] = polar(x);
        const double dr = c * (b1 * std::sin(th) - b2 * std::sin(th) / (r * r) - a3 * std::sin(3 * th) / (r * r) +
                               3 * a4 * std::sin(3 * th) / std::pow(r, 4));
        const double dth = c * (b1 * r * std::cos(th) + b2 * std::cos(th) / r + 3 * a3 * std::cos(3 * th) / r -
                                3 * a4 * std::cos(3 * th) / (r * r * r));
        return cartesian(r, th, dr, dth);
      });
  s.stress[0] = fem::make_function([=](const Eigen::Vector3d& x) {
    const auto [r, th] = polar(x);
    const double q2 = a * a / (r * r), q4 = q2 * q2;
    return t * (1 - q2 * (1.5 * std::cos(2 * th) + std::cos(4 * th)) + 1.5 * q4 * std::cos(4 * th));
  });
  s.stress[1] = fem::make_function([=](const Eigen::Vector3d& x) {
    const auto [r, th] = polar(x);
    const double q2 = a * a / (r * r), q4 = q2 * q2;
    return t * (-q2 * (0.5 * std::cos(2 * th) - std::cos(4 * th)) - 1.5 * q4 * std::cos(4 * th));
  });
  s.stress[2] = fem::make_function([=](const Eigen::Vector3d& x) {
    const auto [r, th] = polar(x);
    const double q2 = a * a / (r * r), q4 = q2 * q2;
    return t * (-q2 * (0.5 * std::sin(2 * th) + std::sin(4 * th)) + 1.5 * q4 * std::sin(4 * th));
  });
  return s;
}

}  // namespace iga::pde
