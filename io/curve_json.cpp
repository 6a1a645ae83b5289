#include "io/curve_json.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string_view>

#include "core/error.hpp"
#include "core/json_text.hpp"

namespace iga::io {

namespace {

using nlohmann::json;
using basis::bspline::SplineCurve;
using json_text::kind;
using json_text::shown;

// Inputs above this size are refused before they are read: a curve of 64 MiB of text has millions of knots, and
// the parsed JSON takes several times the text's memory.
constexpr std::uintmax_t kMaxBytes = std::uintmax_t{64} << 20;

double read_number(const json& j, const std::string& what) { return json_text::number(j, what); }

int read_degree(const json& d, std::size_t num_knots, const std::string& name) {
  double value = 0.0;
  if (d.is_number_unsigned()) {
    value = static_cast<double>(d.get<std::uint64_t>());
  } else if (d.is_number()) {
    value = d.get<double>();
  }
  if (!d.is_number() || !std::isfinite(value) || value != std::floor(value)) {
    throw InputError(name + ": degree must be an integer, got " + kind(d));
  }
  if (value < 1) throw InputError(name + ": degree must be >= 1, got " + shown(d));
  if (value > static_cast<double>(std::numeric_limits<int>::max()) || value + 2 > static_cast<double>(num_knots)) {
    throw InputError(name + ": degree " + shown(d) + " needs at least degree + 2 knots, " +
                     std::to_string(num_knots) + " given");
  }
  return static_cast<int>(value);
}


Eigen::MatrixXd read_control_points(const json& cps, const std::string& name) {
  if (!cps.is_array() || cps.empty()) {
    throw InputError(name + ": control_points must be a non-empty list of coordinate lists, got " + kind(cps));
  }
  // Every row is checked before anything is allocated: rows x (size of the first row) must be the text's size.
  for (std::size_t i = 0; i < cps.size(); ++i) {
    const std::string at = name + ": control_points[" + std::to_string(i) + "]";
    if (!cps[i].is_array()) throw InputError(at + " must be a list of coordinates, got " + kind(cps[i]));
    if (cps[i].empty()) throw InputError(at + " has no coordinates");
    if (cps[i].size() != cps[0].size()) {
      const auto coordinates = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " coordinate" : " coordinates"); };
      throw InputError(at + " has " + coordinates(cps[i].size()) + ", control_points[0] has " +
                       coordinates(cps[0].size()));
    }
  }
  Eigen::MatrixXd points(static_cast<Index>(cps.size()), static_cast<Index>(cps[0].size()));
  for (std::size_t i = 0; i < cps.size(); ++i) {
    for (std::size_t k = 0; k < cps[i].size(); ++k) {
      points(static_cast<Index>(i), static_cast<Index>(k)) =
          read_number(cps[i][k], name + ": control_points[" + std::to_string(i) + "][" + std::to_string(k) + "]");
    }
  }
  return points;
}

}  // namespace

SplineCurve parse_curve_json(const std::string& text_in, const std::string& name) {
  const json j = json_text::parse(text_in, name);
  if (!j.is_object()) {
    throw InputError(name + ": expected a JSON object {\"degree\", \"knots\", \"control_points\"}, got " + kind(j));
  }
  for (const auto& item : j.items()) {
    if (item.key() != "degree" && item.key() != "knots" && item.key() != "control_points") {
      // The key as decoded may hold line ends ("\n" in the file) and be long: escaped and cut, one short line.
      throw InputError(name + ": unknown key '" + json_text::key_text(item.key()) + "' (a curve has degree, knots, control_points)");
    }
  }
  for (const char* key : {"degree", "knots", "control_points"}) {
    if (!j.contains(key)) throw InputError(name + ": missing key '" + key + "'");
  }
  const json& knots = j["knots"];
  if (!knots.is_array()) throw InputError(name + ": knots must be a list of numbers, got " + kind(knots));
  SplineCurve c;
  c.degree = read_degree(j["degree"], knots.size(), name);
  c.knots.reserve(knots.size());
  for (std::size_t i = 0; i < knots.size(); ++i) {
    c.knots.push_back(read_number(knots[i], name + ": knots[" + std::to_string(i) + "]"));
  }
  c.control_points = read_control_points(j["control_points"], name);
  // Knot insertion divides by knot differences: a span beyond the largest double overflows them (±1e308 knots
  // gave null or wrong control points with exit 0).
  if (!c.knots.empty() && !std::isfinite(c.knots.back() - c.knots.front())) {
    throw InputError(name + ": the knots run from " + shown(knots.front()) + " to " + shown(knots.back()) +
                     ": their differences overflow a double; rescale them (the curve does not change)");
  }
  try {
    basis::bspline::validate(c);
  } catch (const InputError& e) {
    throw InputError(name + ": " + e.what());
  }
  return c;
}

SplineCurve read_curve_json(const std::string& path) {
  return parse_curve_json(json_text::read_input(path, kMaxBytes, "curve"), path == "-" ? "stdin" : path);
}

}  // namespace iga::io
