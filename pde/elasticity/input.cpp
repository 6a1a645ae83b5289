#include "pde/elasticity/input.hpp"

#include <sstream>

#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/problem.hpp"
#include "pde/elasticity/kirsch.hpp"

namespace iga::pde {

namespace {

// "BX; BY" → two expressions named "<what> x" and "<what> y".
std::array<std::shared_ptr<const fem::Function>, 2> pair_of(const std::string& text, const std::string& what,
                                                            const std::string& form, double fd_step) {
  const std::vector<std::string> f = fem::item_fields(text);
  if (f.size() != 2 || f[0].empty() || f[1].empty()) {
    throw InputError(what + " '" + text + "': expected " + form + " (two expressions separated by ';')");
  }
  std::array<std::shared_ptr<const fem::Function>, 2> out;
  for (int c = 0; c < 2; ++c) {
    auto e = std::make_shared<fem::Expression>(f[static_cast<std::size_t>(c)], what + " " + (c == 0 ? "x" : "y"));
    e->set_fd_step(fd_step);
    out[static_cast<std::size_t>(c)] = e;
  }
  return out;
}

// The --displacement and --traction items into data; their description into conditions (an array).
void add_conditions(const std::vector<std::string>& displacement, const std::vector<std::string>& traction,
                    const std::vector<std::string>& names, Lame material, ElasticityData& data, nlohmann::json& conditions);

}  // namespace

std::vector<std::string> elasticity_problem_names() { return {"kirsch"}; }

ElasticityData elasticity_data(const ElasticityInput& in, const basis::Geometry& geometry, nlohmann::json& description) {
  if (in.model != "strain" && in.model != "stress") throw InputError("--model: '" + in.model + "' is not strain or stress");
  ElasticityData data;
  data.young = in.young;
  data.poisson = in.poisson;
  data.model = in.model == "strain" ? PlaneModel::kStrain : PlaneModel::kStress;
  const Lame material = lame(in.young, in.poisson, data.model);  // InputError for E, ν out of range
  const std::vector<std::string>& names = geometry.space().boundary_part_names();
  const double fd_step = fem::finite_difference_step(geometry);
  std::vector<std::string> displacement = in.displacement, traction = in.traction;
  if (!in.problem.empty()) {
    if (in.problem != "kirsch") throw InputError("--problem: unknown problem '" + in.problem + "' (kirsch)");
    if (!in.body_force.empty() || !in.exact.empty()) {
      throw InputError("--problem kirsch brings its own exact solution and no body force: leave out --body-force and --exact");
    }
    data.exact = kirsch_solution(in.tension, 1.0, material).displacement;
    if (displacement.empty()) displacement = {"x; v1", "y; v0"};
    if (traction.empty()) traction = {"u1"};
  } else {
    if (!in.body_force.empty()) data.body_force = pair_of(in.body_force, "--body-force", "BX; BY", fd_step);
    if (!in.exact.empty()) data.exact = pair_of(in.exact, "--exact", "UX; UY", fd_step);
  }
  const bool kirsch_parts = in.problem == "kirsch" && in.displacement.empty() && in.traction.empty();
  try {
    add_conditions(displacement, traction, names, material, data, description);
  } catch (const InputError& e) {
    if (!kirsch_parts) throw;
    throw InputError("--problem kirsch: its default conditions (--displacement 'x; v1' --displacement 'y; v0' --traction "
                     "u1) name the parts of the built-in plate-with-hole geometry, which this one does not have (" +
                     std::string(e.what()) + "): give --displacement and --traction for it");
  }
  const nlohmann::json conditions = description;
  description = {{"name", in.problem.empty() ? nlohmann::json(nullptr) : nlohmann::json(in.problem)},
                 {"young", in.young}, {"poisson_ratio", in.poisson}, {"model", "plane " + in.model},
                 {"lambda", material.lambda}, {"mu", material.mu},
                 {"body_force", in.body_force}, {"exact", in.problem == "kirsch" ? "kirsch" : in.exact},
                 {"conditions", conditions}};
  if (in.problem == "kirsch") description["tension"] = in.tension;
  return data;
}

namespace {

void add_conditions(const std::vector<std::string>& displacement, const std::vector<std::string>& traction,
                    const std::vector<std::string>& names, Lame material, ElasticityData& data, nlohmann::json& conditions) {
  conditions = nlohmann::json::array();
  for (const std::string& item : displacement) {
    const std::vector<std::string> f = fem::item_fields(item);
    if (f.size() < 2 || f.size() > 3 || (f[0] != "x" && f[0] != "y")) {
      throw InputError("--displacement '" + item + "': expected C; PARTS[; VALUE] with C x or y (e.g. 'x; v1' or 'y; v0; 0.01*x')");
    }
    DisplacementCondition d;
    d.component = f[0] == "x" ? 0 : 1;
    d.parts = fem::parse_boundary_parts(f[1], names, "--displacement '" + item + "'");
    if (f.size() == 3) {
      d.value = std::make_shared<fem::Expression>(f[2], "--displacement " + f[0]);
    } else {
      d.value = data.exact[static_cast<std::size_t>(d.component)];  // null without one: 0
    }
    data.displacement.push_back(d);
    conditions.push_back({{"displacement", f[0]}, {"parts", f[1]},
                          {"value", f.size() == 3 ? f[2] : (data.exact[0] ? "the exact solution's" : "0")}});
  }
  for (const std::string& item : traction) {
    const std::vector<std::string> f = fem::item_fields(item);
    if (f.size() != 1 && f.size() != 3) throw InputError("--traction '" + item + "': expected PARTS[; TX; TY] (e.g. 'u1; 10; 0')");
    TractionCondition t;
    t.parts = fem::parse_boundary_parts(f[0], names, "--traction '" + item + "'");
    if (f.size() == 3) {
      for (int c = 0; c < 2; ++c) {
        t.traction[static_cast<std::size_t>(c)] = std::make_shared<fem::Expression>(
            f[static_cast<std::size_t>(c) + 1], std::string("--traction ") + (c == 0 ? "x" : "y"), true);
      }
    } else {
      if (!data.exact[0]) throw InputError("--traction '" + item + "': without TX; TY it is the exact solution's, and no --exact is given");
      t.traction = traction_of(data.exact, material);
    }
    data.traction.push_back(t);
    conditions.push_back({{"traction", f.size() == 3 ? f[1] + "; " + f[2] : "the exact solution's"}, {"parts", f[0]}});
  }
}

}  // namespace


}  // namespace iga::pde
