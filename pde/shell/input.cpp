#include "pde/shell/input.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/problem.hpp"

namespace iga::pde {

namespace {

int component_of(const std::string& c, const std::string& what) {
  if (c == "x") return 0;
  if (c == "y") return 1;
  if (c == "z") return 2;
  throw InputError(what + ": component '" + c + "' is not x, y or z");
}

// "X, Y, Z" → a point, each a finite number.
Eigen::Vector3d vector_of(const std::string& text, const std::string& what) {
  const std::vector<std::string> f = fem::item_fields(text, ',');
  Eigen::Vector3d out;
  bool ok = f.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) {
    std::size_t used = 0;
    try {
      out(static_cast<Index>(i)) = std::stod(f[i], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    ok = used > 0 && used == f[i].size() && std::isfinite(out(static_cast<Index>(i)));
  }
  if (!ok) throw InputError(what + ": '" + text + "' is not three finite numbers X, Y, Z");
  return out;
}

std::array<std::shared_ptr<const fem::Function>, 3> triple_of(const std::string& text, const std::string& what,
                                                              double fd_step) {
  const std::vector<std::string> f = fem::item_fields(text);
  if (f.size() != 3 || f[0].empty() || f[1].empty() || f[2].empty()) {
    throw InputError(what + " '" + text + "': expected FX; FY; FZ (three expressions separated by ';')");
  }
  std::array<std::shared_ptr<const fem::Function>, 3> out;
  for (int c = 0; c < 3; ++c) {
    auto e = std::make_shared<fem::Expression>(f[static_cast<std::size_t>(c)], what + " " + "xyz"[c]);
    e->set_fd_step(fd_step);
    out[static_cast<std::size_t>(c)] = e;
  }
  return out;
}

// A built-in problem's items, as a user would give them, and its material and reference points.
struct Builtin {
  double young, poisson, thickness;
  ShellInput items;
  std::vector<ShellPoint> points;
};

Builtin builtin(const std::string& name) {
  const double deg = std::numbers::pi / 180;
  Builtin b{};
  if (name == "scordelis-lo-roof") {
    // Scordelis and Lo 1964 as set in Belytschko et al. 1985: self-weight 90 per area, rigid diaphragms at the ends
    // y = 0, 50 (v0, v1), free straight edges; one axial bearing at the crown of the first diaphragm.
    b = {4.32e8, 0.0, 0.25, {}, {}};
    b.items.area_load = "0; 0; -90";
    b.items.support = {"x; v0, v1", "z; v0, v1"};
    b.items.point_support = {"0, 0, 25; y"};
    b.points = {{"free edge midpoint", {25 * std::sin(40 * deg), 25.0, 25 * std::cos(40 * deg)}, 2, -0.3006,
                 "0.3006 (Kirchhoff-Love; 0.3024 shear-deformable): Belytschko et al. 1985, Kiendl et al. 2009"}};
  } else if (name == "pinched-cylinder") {
    // R = 300, L = 600, t = 3, E = 3e6, ν = 0.3, rigid diaphragms, P = 1 at the top and bottom of the middle section:
    // the octant x, z >= 0, 0 <= y <= 300 with the diaphragm at y = 0 (v0) and symmetry planes x = 0 (u0), z = 0 (u1),
    // y = 300 (v1), P/4 at (0, 300, 300).
    b = {3e6, 0.3, 3.0, {}, {}};
    b.items.support = {"x; v0", "z; v0"};
    b.items.symmetry = {"x; u0", "z; u1", "y; v1"};
    b.items.point_load = {"0, 300, 300; 0, 0, -0.25"};
    b.points = {{"under the load", {0.0, 300.0, 300.0}, 2, -1.8248e-5, "1.8248e-5: Belytschko et al. 1985"}};
  } else if (name == "pinched-hemisphere") {
    // R = 10, t = 0.04, E = 6.825e7, ν = 0.3, an 18° hole, loads 2 (outward along x, inward along y) on the whole
    // hemisphere: the quarter 0 <= λ <= 90° with symmetry planes y = 0 (u0), x = 0 (u1), the quarter's share 1 of
    // each load, held vertically at the middle of the hole's edge.
    b = {6.825e7, 0.3, 0.04, {}, {}};
    b.items.symmetry = {"y; u0", "x; u1"};
    const double rc = 10 * std::cos(72 * deg), z = 10 * std::sin(72 * deg);
    std::ostringstream top;
    top.precision(17);
    top << rc * std::sqrt(0.5) << ", " << rc * std::sqrt(0.5) << ", " << z << "; z";
    b.items.point_support = {top.str()};
    b.items.point_load = {"10, 0, 0; 1, 0, 0", "0, 10, 0; 0, -1, 0"};
    b.points = {{"load A", {10.0, 0.0, 0.0}, 0, 0.0924,
                 "0.0924: Belytschko et al. 1985 (MacNeal and Harder 1985: 0.094); 0.0924 is the hemisphere without a "
                 "hole (Morley and Morris 1978), the Kirchhoff-Love limit with the 18 degree hole is 0.09352 (README)"}};
  } else {
    throw InputError("--problem: unknown problem '" + name + "' (scordelis-lo-roof, pinched-cylinder, pinched-hemisphere)");
  }
  return b;
}

template <class T>
void append(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

void add_supports(const ShellInput& in, const std::vector<std::string>& names, ShellData& data, nlohmann::json& out);
void add_points(const ShellInput& in, ShellSetUp& s, nlohmann::json& out);

}  // namespace

std::vector<std::string> shell_problem_names() { return {"scordelis-lo-roof", "pinched-cylinder", "pinched-hemisphere"}; }

std::string shell_problem_geometry(const std::string& problem) {
  builtin(problem);  // InputError for an unknown name
  return problem;
}

ShellSetUp shell_setup(const ShellInput& given, const basis::Geometry& geometry, nlohmann::json& description) {
  ShellInput in = given;
  ShellSetUp s;
  if (!in.problem.empty()) {
    const Builtin b = builtin(in.problem);
    // The reference values hold for the problem as set: not when the material, a load or a support is changed (the
    // geometry may be another discretisation of the same surface: a net of the roof).
    const auto same = [](double given, double own) { return std::isnan(given) || given == own; };
    const bool as_set = same(in.young, b.young) && same(in.poisson, b.poisson) && same(in.thickness, b.thickness) &&
                        in.area_load.empty() && in.pressure.empty() && in.line_load.empty() && in.support.empty() &&
                        in.symmetry.empty() && in.clamped.empty() && in.point_load.empty() && in.point_support.empty();
    if (std::isnan(in.young)) in.young = b.young;
    if (std::isnan(in.poisson)) in.poisson = b.poisson;
    if (std::isnan(in.thickness)) in.thickness = b.thickness;
    if (in.area_load.empty()) in.area_load = b.items.area_load;
    in.support.insert(in.support.begin(), b.items.support.begin(), b.items.support.end());
    in.symmetry.insert(in.symmetry.begin(), b.items.symmetry.begin(), b.items.symmetry.end());
    in.point_support.insert(in.point_support.begin(), b.items.point_support.begin(), b.items.point_support.end());
    append(in.point_load, b.items.point_load);
    s.points = b.points;
    if (!as_set) {
      for (ShellPoint& p : s.points) p.component = -1;  // reported without the reference
    }
  }
  if (std::isnan(in.poisson)) in.poisson = 0.3;
  if (std::isnan(in.young)) throw InputError("--young: Young's modulus is needed (no --problem gives it)");
  if (std::isnan(in.thickness)) throw InputError("--thickness: the shell's thickness is needed (no --problem gives it)");
  s.data.material = {in.young, in.poisson, in.thickness};
  const double fd_step = fem::finite_difference_step(geometry);
  if (!in.area_load.empty()) s.data.area_load = triple_of(in.area_load, "--area-load", fd_step);
  if (!in.pressure.empty()) s.data.pressure = std::make_shared<fem::Expression>(in.pressure, "--pressure");
  const std::vector<std::string>& names = geometry.space().boundary_part_names();
  nlohmann::json loads = nlohmann::json::array(), supports = nlohmann::json::array(), points = nlohmann::json::array();
  if (!in.area_load.empty()) loads.push_back({{"area load", in.area_load}});
  if (!in.pressure.empty()) loads.push_back({{"pressure", in.pressure}});
  for (const std::string& item : in.line_load) {
    const std::vector<std::string> f = fem::item_fields(item);
    if (f.size() != 4) throw InputError("--line-load '" + item + "': expected PARTS; QX; QY; QZ (e.g. 'u1; 0; 0; -2')");
    ShellLineLoad l;
    l.parts = fem::parse_boundary_parts(f[0], names, "--line-load '" + item + "'");
    for (int c = 0; c < 3; ++c) {
      l.load[static_cast<std::size_t>(c)] =
          std::make_shared<fem::Expression>(f[static_cast<std::size_t>(c) + 1], std::string("--line-load ") + "xyz"[c], true);
    }
    s.data.line_loads.push_back(l);
    loads.push_back({{"line load", f[1] + "; " + f[2] + "; " + f[3]}, {"parts", f[0]}});
  }
  for (const std::string& item : in.point_load) {
    const std::vector<std::string> f = fem::item_fields(item);
    if (f.size() != 2) throw InputError("--point-load '" + item + "': expected X, Y, Z; FX, FY, FZ");
    s.data.point_loads.push_back({vector_of(f[0], "--point-load '" + item + "'"), vector_of(f[1], "--point-load '" + item + "'")});
    loads.push_back({{"point load", f[1]}, {"at", f[0]}});
  }
  if (!in.problem.empty()) {
    // The problem's own supports first: they name the parts of its built-in surface.
    const Builtin b = builtin(in.problem);
    try {
      add_supports(b.items, names, s.data, supports);
    } catch (const InputError& e) {
      throw InputError("--problem " + in.problem + ": its supports name the parts of its built-in surface, which this "
                       "geometry does not have (" + std::string(e.what()) + "): give the loads and supports for it");
    }
    in.support.erase(in.support.begin(), in.support.begin() + static_cast<std::ptrdiff_t>(b.items.support.size()));
    in.symmetry.erase(in.symmetry.begin(), in.symmetry.begin() + static_cast<std::ptrdiff_t>(b.items.symmetry.size()));
    in.point_support.erase(in.point_support.begin(),
                           in.point_support.begin() + static_cast<std::ptrdiff_t>(b.items.point_support.size()));
  }
  add_supports(in, names, s.data, supports);
  add_points(in, s, points);
  description = {{"name", in.problem.empty() ? nlohmann::json(nullptr) : nlohmann::json(in.problem)},
                 {"young", in.young}, {"poisson_ratio", in.poisson}, {"thickness", in.thickness},
                 {"formulation", "linear Kirchhoff-Love (Kiendl et al. 2009)"},
                 {"loads", loads}, {"supports", supports}, {"points", points}};
  return s;
}

namespace {

void add_supports(const ShellInput& in, const std::vector<std::string>& names, ShellData& data, nlohmann::json& out) {
  for (const std::string& item : in.support) {
    const std::vector<std::string> f = fem::item_fields(item);
    const std::string what = "--support '" + item + "'";
    if (f.size() < 2 || f.size() > 3) throw InputError(what + ": expected C; PARTS[; value|slope|value+slope]");
    ShellSupport s;
    s.component = component_of(f[0], what);
    s.parts = fem::parse_boundary_parts(f[1], names, what);
    const std::string hold = f.size() == 3 ? f[2] : "value";
    if (hold == "value") {
      s.hold = Hold::kValue;
    } else if (hold == "slope") {
      s.hold = Hold::kSlope;
    } else if (hold == "value+slope") {
      s.hold = Hold::kValueAndSlope;
    } else {
      throw InputError(what + ": '" + hold + "' is not value, slope or value+slope");
    }
    data.supports.push_back(s);
    out.push_back({{"support", f[0]}, {"parts", f[1]}, {"holds", hold}});
  }
  for (const std::string& item : in.symmetry) {
    const std::vector<std::string> f = fem::item_fields(item);
    const std::string what = "--symmetry '" + item + "'";
    if (f.size() != 2) throw InputError(what + ": expected AXIS; PARTS (the plane normal to AXIS, e.g. 'x; u0')");
    const int c = component_of(f[0], what);
    const std::vector<int> parts = fem::parse_boundary_parts(f[1], names, what);
    data.supports.push_back({c, parts, nullptr, Hold::kValue});
    for (int o = 0; o < 3; ++o) {
      if (o != c) data.supports.push_back({o, parts, nullptr, Hold::kSlope});
    }
    out.push_back({{"symmetry plane normal to", f[0]}, {"parts", f[1]}});
  }
  for (const std::string& item : in.clamped) {
    const std::string what = "--clamped '" + item + "'";
    const std::vector<int> parts = fem::parse_boundary_parts(item, names, what);
    for (int c = 0; c < 3; ++c) data.supports.push_back({c, parts, nullptr, Hold::kValueAndSlope});
    out.push_back({{"clamped", item}});
  }
  for (const std::string& item : in.point_support) {
    const std::vector<std::string> f = fem::item_fields(item);
    const std::string what = "--point-support '" + item + "'";
    if (f.size() != 2) throw InputError(what + ": expected X, Y, Z; C");
    data.point_supports.push_back({vector_of(f[0], what), component_of(f[1], what)});
    out.push_back({{"point support", f[1]}, {"at", f[0]}});
  }
}

void add_points(const ShellInput& in, ShellSetUp& s, nlohmann::json& out) {
  for (const std::string& item : in.point) {
    const std::vector<std::string> f = fem::item_fields(item);
    if (f.size() != 2 || f[0].empty()) throw InputError("--point '" + item + "': expected NAME; X, Y, Z");
    s.points.push_back({f[0], vector_of(f[1], "--point '" + item + "'"), -1, 0.0, ""});
  }
  for (const ShellPoint& p : s.points) {
    nlohmann::json j = {{"name", p.name}, {"at", {p.at(0), p.at(1), p.at(2)}}};
    if (p.component >= 0) {
      j["reference"] = {{"component", std::string(1, "xyz"[p.component])}, {"value", p.reference}, {"source", p.source}};
    }
    out.push_back(j);
  }
}

}  // namespace

}  // namespace iga::pde
