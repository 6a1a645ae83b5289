#include "fem/problems.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace iga::fem {

namespace {
using V = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;
}  // namespace

std::vector<std::string> manufactured_problem_names() { return {"sine", "harmonic", "linear", "poly"}; }

ManufacturedProblem manufactured_problem(const std::string& name, double c) {
  ManufacturedProblem p;
  p.name = name;
  if (name == "sine") {
    p.description = "u = sin(pi x) sin(pi y)";
    p.exact = make_function([](const V& x) { return std::sin(kPi * x(0)) * std::sin(kPi * x(1)); },
                            [](const V& x) -> V {
                              return {kPi * std::cos(kPi * x(0)) * std::sin(kPi * x(1)),
                                      kPi * std::sin(kPi * x(0)) * std::cos(kPi * x(1)), 0.0};
                            });
    p.source = make_function([c](const V& x) { return (2 * kPi * kPi + c) * std::sin(kPi * x(0)) * std::sin(kPi * x(1)); });
  } else if (name == "harmonic") {
    p.description = "u = exp(x) sin(y) (harmonic)";
    p.exact = make_function([](const V& x) { return std::exp(x(0)) * std::sin(x(1)); },
                            [](const V& x) -> V {
                              return {std::exp(x(0)) * std::sin(x(1)), std::exp(x(0)) * std::cos(x(1)), 0.0};
                            });
    p.source = make_function([c](const V& x) { return c * std::exp(x(0)) * std::sin(x(1)); });
  } else if (name == "linear") {
    p.description = "u = 1 + 2x - 3y (patch test)";
    p.exact = make_function([](const V& x) { return 1 + 2 * x(0) - 3 * x(1); },
                            [](const V&) -> V { return {2.0, -3.0, 0.0}; });
    p.source = make_function([c](const V& x) { return c * (1 + 2 * x(0) - 3 * x(1)); });
  } else if (name == "poly") {
    p.description = "u = x^2 y + y^3 - x y";
    p.exact = make_function([](const V& x) { return x(0) * x(0) * x(1) + x(1) * x(1) * x(1) - x(0) * x(1); },
                            [](const V& x) -> V {
                              return {2 * x(0) * x(1) - x(1), x(0) * x(0) + 3 * x(1) * x(1) - x(0), 0.0};
                            });
    p.source = make_function([c](const V& x) {
      return -8 * x(1) + c * (x(0) * x(0) * x(1) + x(1) * x(1) * x(1) - x(0) * x(1));
    });
  } else {
    std::string known;
    for (const auto& n : manufactured_problem_names()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("problem '" + name + "': unknown (known: " + known + ")");
  }
  return p;
}

}  // namespace iga::fem
