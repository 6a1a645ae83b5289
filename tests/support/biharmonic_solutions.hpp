#pragma once
// Manufactured solutions of the biharmonic equation shared by the tests, with closed-form gradients and Hessians.
#include <cmath>
#include <memory>
#include <numbers>

#include "fem/function.hpp"

namespace iga::test {

// u = sin²(πx) sin²(πy): zero with its normal derivative on the unit square's boundary.
inline std::shared_ptr<fem::Function> bump() {
  auto s = [](double t) { return std::pow(std::sin(std::numbers::pi * t), 2); };
  auto s1 = [](double t) { return std::numbers::pi * std::sin(2 * std::numbers::pi * t); };
  auto s2 = [](double t) { return 2 * std::numbers::pi * std::numbers::pi * std::cos(2 * std::numbers::pi * t); };
  return fem::make_function(
      [=](const Eigen::Vector3d& x) { return s(x(0)) * s(x(1)); },
      [=](const Eigen::Vector3d& x) { return Eigen::Vector3d(s1(x(0)) * s(x(1)), s(x(0)) * s1(x(1)), 0); },
      [=](const Eigen::Vector3d& x) {
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        h(0, 0) = s2(x(0)) * s(x(1));
        h(0, 1) = h(1, 0) = s1(x(0)) * s1(x(1));
        h(1, 1) = s(x(0)) * s2(x(1));
        return h;
      });
}
inline std::shared_ptr<fem::Function> bump_source() {
  auto s = [](double t) { return std::pow(std::sin(std::numbers::pi * t), 2); };
  auto s2 = [](double t) { return 2 * std::numbers::pi * std::numbers::pi * std::cos(2 * std::numbers::pi * t); };
  auto s4 = [](double t) { return -8 * std::pow(std::numbers::pi, 4) * std::cos(2 * std::numbers::pi * t); };
  return fem::make_function([=](const Eigen::Vector3d& x) {
    return s4(x(0)) * s(x(1)) + 2 * s2(x(0)) * s2(x(1)) + s(x(0)) * s4(x(1));
  });
}

}  // namespace iga::test
