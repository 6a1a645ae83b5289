// iga-knots: refines a B-spline curve (JSON: degree, knots, control_points; standard convention) by knot
// insertion — Boehm, Oslo or the refine-and-smooth algorithm — and writes the refined curve (same keys).
// Thin: parses options, reads and checks the JSON, calls basis/bspline/ and refine/.
#include <CLI/CLI.hpp>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "basis/bspline/spline_curve.hpp"
#include "core/error.hpp"
#include "io/report.hpp"
#include "refine/refine_smooth.hpp"

namespace {

using iga::InputError;
using iga::basis::bspline::SplineCurve;

double number(const nlohmann::json& j, const std::string& where) {
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) {
    const std::string s = j.get<std::string>();
    if (s == "nan" || s == "NaN" || s == "inf" || s == "-inf" || s == "Infinity" || s == "-Infinity") {
      throw InputError(where + " is not a finite number (" + s + ")");
    }
  }
  if (j.is_null()) throw InputError(where + " is not a finite number (null)");
  throw InputError(where + " must be a number");
}

SplineCurve parse_curve(const std::string& text, const std::string& name) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text, nullptr, true, false);
  } catch (const nlohmann::json::exception& e) {
    // NaN written literally is not JSON: say so.
    if (text.find("NaN") != std::string::npos || text.find("nan") != std::string::npos) {
      throw InputError(name + ": a value is NaN (not a finite number)");
    }
    throw InputError(name + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  if (!j.is_object()) throw InputError(name + ": expected a JSON object with degree, knots, control_points");
  for (const char* key : {"degree", "knots", "control_points"}) {
    if (!j.contains(key)) throw InputError(name + ": missing key '" + key + "'");
  }
  SplineCurve c;
  if (!j["degree"].is_number_integer()) throw InputError(name + ": degree must be an integer");
  c.degree = j["degree"].get<int>();
  if (!j["knots"].is_array()) throw InputError(name + ": knots must be a list of numbers");
  for (std::size_t i = 0; i < j["knots"].size(); ++i) {
    c.knots.push_back(number(j["knots"][i], name + ": knot " + std::to_string(i)));
  }
  const auto& cps = j["control_points"];
  if (!cps.is_array() || cps.empty()) throw InputError(name + ": control_points must be a non-empty list of coordinate lists");
  const std::size_t dim = cps[0].is_array() ? cps[0].size() : 0;
  if (dim == 0) throw InputError(name + ": control point 0 must be a non-empty list of coordinates");
  c.control_points.resize(static_cast<iga::Index>(cps.size()), static_cast<iga::Index>(dim));
  for (std::size_t i = 0; i < cps.size(); ++i) {
    if (!cps[i].is_array() || cps[i].size() != dim) {
      throw InputError(name + ": control point " + std::to_string(i) + " must have " + std::to_string(dim) +
                       " coordinates");
    }
    for (std::size_t k = 0; k < dim; ++k) {
      c.control_points(static_cast<iga::Index>(i), static_cast<iga::Index>(k)) =
          number(cps[i][k], name + ": control point " + std::to_string(i) + " coordinate " + std::to_string(k));
    }
  }
  try {
    iga::basis::bspline::validate(c);
  } catch (const InputError& e) {
    throw InputError(name + ": " + e.what());
  }
  return c;
}

nlohmann::json to_json(const SplineCurve& c) {
  nlohmann::json j;
  j["degree"] = c.degree;
  j["knots"] = c.knots;
  nlohmann::json cps = nlohmann::json::array();
  for (iga::Index i = 0; i < c.control_points.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (iga::Index k = 0; k < c.control_points.cols(); ++k) row.push_back(c.control_points(i, k));
    cps.push_back(row);
  }
  j["control_points"] = cps;
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-knots: refine a B-spline curve by knot insertion (JSON in, JSON out)"};
  std::string input, out, algorithm = "refine-smooth";
  std::vector<double> insert;
  std::vector<long> intervals;
  app.add_option("input", input, "JSON B-spline {degree, knots, control_points} (standard convention), '-' = stdin")
      ->required();
  auto* ins = app.add_option("--insert", insert, "knots to insert (inside the domain)")->delimiter(',');
  auto* itv = app.add_option("--intervals", intervals,
                             "0-based indices, increasing, of the non-empty domain intervals to halve (default all)")
                  ->delimiter(',');
  ins->excludes(itv);
  app.add_option("--algorithm", algorithm, "boehm | oslo | refine-smooth")
      ->check(CLI::IsMember({"boehm", "oslo", "refine-smooth"}));
  app.add_option("--out", out, "output file (default stdout)");
  CLI11_PARSE(app, argc, argv);
  try {
    std::string text;
    if (input == "-") {
      text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
    } else {
      std::ifstream f(input);
      if (!f) throw InputError(input + ": cannot open");
      text.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    const SplineCurve curve = parse_curve(text, input == "-" ? "stdin" : input);
    std::vector<double> xs = insert;
    if (xs.empty()) {
      std::vector<iga::Index> chosen(intervals.begin(), intervals.end());
      xs = iga::basis::bspline::interval_midpoints(curve, chosen);
    }
    for (double x : xs) {
      if (!std::isfinite(x)) throw InputError("--insert: a knot is not a finite number");
    }
    SplineCurve fine;
    if (algorithm == "boehm") {
      fine = iga::basis::bspline::insert_knots_boehm(curve, xs);
    } else if (algorithm == "oslo") {
      fine = iga::basis::bspline::insert_knots_oslo(curve, xs);
    } else {
      fine = iga::refine::refine_smooth(curve, xs);
    }
    const std::string result = to_json(fine).dump(1) + "\n";
    iga::io::write_text(out.empty() ? "-" : out, result);  // every write checked (a full disk, /dev/full)
  } catch (const iga::Error& e) {
    std::cerr << "iga-knots: error: " << e.what() << std::endl;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "iga-knots: error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
