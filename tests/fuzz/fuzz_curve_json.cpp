// libFuzzer target: io::parse_curve_json on arbitrary bytes; a curve that parses is refined as iga-knots does
// (every non-empty interval halved) with Boehm, Oslo and refine-and-smooth, bounded in size (degree <= 12, at
// most 200 knots) so that one input stays fast. Refusal with an iga::Error of one line is fine; a crash, a
// sanitizer report, any other exception or a hang is a finding, and so is a refined curve without one new
// control point per inserted knot.
#include <cstddef>
#include <cstdint>
#include <string>

#include "basis/bspline/spline_curve.hpp"
#include "io/curve_json.hpp"
#include "refine/refine_smooth.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace bs = iga::basis::bspline;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const bs::SplineCurve curve =
        iga::io::parse_curve_json(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    if (curve.degree > 12 || curve.knots.size() > 200) return 0;
    const std::vector<double> xs = bs::interval_midpoints(curve, {});
    const auto expected = curve.num_control_points() + static_cast<iga::Index>(xs.size());
    if (bs::insert_knots_boehm(curve, xs).num_control_points() != expected) std::abort();
    if (bs::insert_knots_oslo(curve, xs).num_control_points() != expected) std::abort();
    if (iga::refine::refine_smooth(curve, xs).num_control_points() != expected) std::abort();
  } catch (const iga::Error& e) {
    iga::fuzz::check_one_line(e);
  }
  return 0;
}
