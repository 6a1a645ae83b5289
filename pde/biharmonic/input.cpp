#include "pde/biharmonic/input.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/problem.hpp"

namespace iga::pde {

namespace {

constexpr double kPi = std::numbers::pi;

// u = sin(πx) sin(πy) with its gradient and Hessian; Δ²u = 4π⁴ u.
std::shared_ptr<const fem::Function> sine_exact() {
  return fem::make_function(
      [](const Eigen::Vector3d& x) { return std::sin(kPi * x(0)) * std::sin(kPi * x(1)); },
      [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
        return {kPi * std::cos(kPi * x(0)) * std::sin(kPi * x(1)), kPi * std::sin(kPi * x(0)) * std::cos(kPi * x(1)), 0.0};
      },
      [](const Eigen::Vector3d& x) -> Eigen::Matrix3d {
        const double s = std::sin(kPi * x(0)) * std::sin(kPi * x(1)), c = std::cos(kPi * x(0)) * std::cos(kPi * x(1));
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        h(0, 0) = h(1, 1) = -kPi * kPi * s;
        h(0, 1) = h(1, 0) = kPi * kPi * c;
        return h;
      });
}

std::shared_ptr<const fem::Function> sine_source() {
  return fem::make_function([](const Eigen::Vector3d& x) {
    return 4.0 * std::pow(kPi, 4) * std::sin(kPi * x(0)) * std::sin(kPi * x(1));
  });
}

std::vector<std::string> part_names(const std::vector<int>& parts, const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (int p : parts) out.push_back(names[static_cast<std::size_t>(p)]);
  return out;
}

}  // namespace

std::vector<std::string> biharmonic_problem_names() { return {"sine", "plate"}; }

BiharmonicData biharmonic_data(const BiharmonicInput& in, const basis::Geometry& geometry, nlohmann::json& description) {
  const bool expressions = !in.source.empty() || !in.exact.empty() || !in.value.empty() || !in.slope.empty() ||
                           !in.moment.empty();
  if (!in.problem.empty() && expressions) {
    throw InputError("--problem " + in.problem + " brings its own source and boundary data: give either --problem or "
                     "--source/--exact/--value/--slope/--moment, not both");
  }
  if (in.problem.empty() && in.source.empty() && in.exact.empty() && expressions) {
    throw InputError("--value/--slope/--moment without --source: give the load f (and --exact for error norms), or use --problem");
  }
  const std::string problem = in.problem.empty() && !expressions ? std::string("sine") : in.problem;
  const std::vector<std::string>& names = geometry.space().boundary_part_names();
  const std::vector<int> simply = fem::parse_boundary_parts(in.simply_supported, names, "--simply-supported");
  std::vector<int> clamped;
  for (int p = 0; p < static_cast<int>(names.size()); ++p) {
    if (std::find(simply.begin(), simply.end(), p) == simply.end()) clamped.push_back(p);
  }
  BiharmonicData data;
  std::string source = in.source, exact = in.exact, value, slope, moment;
  if (problem == "sine") {
    data = biharmonic_data_from_exact(sine_exact(), sine_source(), simply);
    source = "4*pi^4*sin(pi*x)*sin(pi*y)";
    exact = "sin(pi*x)*sin(pi*y)";
  } else if (problem == "plate") {
    data.source = fem::constant_function(1.0);
    data.simply_supported = simply;
    source = "1";
  } else if (!problem.empty()) {
    std::string known;
    for (const std::string& n : biharmonic_problem_names()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("--problem: unknown problem '" + problem + "' (" + known + ")");
  } else {
    std::shared_ptr<const fem::Function> f;
    if (!in.source.empty()) f = std::make_shared<fem::Expression>(in.source, "--source");
    if (!in.exact.empty()) {
      auto u = std::make_shared<fem::Expression>(in.exact, "--exact");
      u->set_fd_step(fem::finite_difference_step(geometry));  // its derivatives: ∂u/∂n, Δu and the error norms
      data = biharmonic_data_from_exact(u, f, simply);
    } else {
      data.source = f;
      data.simply_supported = simply;
    }
    if (!in.value.empty()) data.value = std::make_shared<fem::Expression>(in.value, "--value");
    if (!in.slope.empty()) data.slope = std::make_shared<fem::Expression>(in.slope, "--slope", true);
    if (!in.moment.empty()) data.moment = std::make_shared<fem::Expression>(in.moment, "--moment");
  }
  data.nitsche_penalty = in.nitsche_penalty;
  // The texts in effect: an option's, else the exact solution's own data, else 0 ("").
  const std::string from_exact = exact.empty() ? "" : "from the exact solution";
  value = !in.value.empty() ? in.value : (exact.empty() ? "" : exact);
  slope = !in.slope.empty() ? in.slope : from_exact;
  moment = !in.moment.empty() ? in.moment : from_exact;
  description = {{"name", problem.empty() ? nlohmann::json(nullptr) : nlohmann::json(problem)},
                 {"source", source}, {"exact", exact}, {"value", value}, {"slope", slope}, {"moment", moment},
                 {"simply_supported", part_names(simply, names)}, {"clamped", part_names(clamped, names)},
                 {"nitsche_penalty", in.nitsche_penalty > 0 ? nlohmann::json(in.nitsche_penalty) : nlohmann::json(nullptr)}};
  return data;
}

}  // namespace iga::pde
