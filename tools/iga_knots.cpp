// iga-knots: refines a B-spline curve (JSON: degree, knots, control_points; standard convention) by knot
// insertion — Boehm, Oslo or the refine-and-smooth algorithm — and writes the refined curve (same keys).
// Thin: parses options, reads the curve with io/curve_json.hpp, calls basis/bspline/ and refine/.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "basis/bspline/spline_curve.hpp"
#include "core/error.hpp"
#include "io/curve_json.hpp"
#include "io/program.hpp"
#include "io/report.hpp"
#include "refine/refine_smooth.hpp"

namespace {

using iga::InputError;
using iga::basis::bspline::SplineCurve;

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
  app.add_option("--out", out, "output file (default or '-': stdout; 'none': no output)")->check(iga::io::non_blank());
  iga::io::CommonOptions common{"iga-knots"};
  iga::io::add_common_options(app, common);
  if (const auto code = iga::io::parse_command_line(app, argc, argv, common)) return *code;
  return iga::io::run_program("iga-knots", [&] {
    const SplineCurve curve = iga::io::read_curve_json(input);  // one line naming the file and position
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
    if (!fine.control_points.allFinite()) {
      throw iga::NumericalError("the refined control points are not finite (the knots' scale overflows); rescale the knots");
    }
    const std::string result = to_json(fine).dump(1) + "\n";
    if (out != "none") iga::io::write_text(out.empty() ? "-" : out, result);  // every write checked (a full disk, /dev/full)
    return 0;
  });
}
