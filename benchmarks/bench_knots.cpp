// bench-knots: control points refined per second by Boehm's insertion (one backward sweep), the Oslo
// algorithm and the refine-and-smooth algorithm (both variants; the §5 blocked in-place variant on one thread and on
// all threads), one new knot in every interval of a uniform clamped degree-d curve in 3D. Median of --repeat
// runs, each with freshly mapped output memory (as a caller gets it; see --memory for the arithmetic alone).
// JSON on stdout (and --json FILE).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <nlohmann/json.hpp>
#include <random>
#include <vector>

#include "basis/bspline/spline_curve.hpp"
#include "fem/threads.hpp"
#include "io/report.hpp"
#include "refine/refine_smooth.hpp"

int main(int argc, char** argv) {
  CLI::App app{"bench-knots: knot insertion speed, Boehm vs Oslo vs refine-and-smooth"};
  long points = 1000000;
  int min_degree = 2, max_degree = 7, repeat = 5, threads = 0;
  std::string json, memory = "fresh";
  app.add_option("--points", points, "control points of the curve")->capture_default_str();
  app.add_option("--min-degree", min_degree)->capture_default_str();
  app.add_option("--max-degree", max_degree)->capture_default_str();
  app.add_option("--repeat", repeat, "runs per measurement (the median counts)")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "threads for the parallel §5 variant (0: OpenMP default)")->check(CLI::NonNegativeNumber);
  app.add_option("--memory", memory,
                 "fresh: every allocation of 1 MiB or more on newly mapped pages (as a caller gets it); "
                 "process: the allocator as configured (with GLIBC_TUNABLES keeping freed memory: the "
                 "arithmetic alone)")
      ->check(CLI::IsMember({"fresh", "process"}))
      ->capture_default_str();
  app.add_option("--json", json, "write the report here too");
  CLI11_PARSE(app, argc, argv);
#ifdef __GLIBC__
  // A fixed threshold (glibc adapts it to freed sizes otherwise, so whether an output faults in fresh pages
  // would depend on what the process freed before).
  if (memory == "fresh") mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  try {
    using namespace iga;
    if (threads > 0) fem::set_num_threads(threads);
    const int all_threads = fem::num_threads();
    nlohmann::json report = {{"program", "bench-knots"}, {"control_points", points}, {"repeat", repeat},
                             {"threads", all_threads}, {"memory", memory}};
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    for (int d = min_degree; d <= max_degree; ++d) {
      basis::bspline::SplineCurve c;
      c.degree = d;
      const long intervals = points - d;
      for (int i = 0; i < d; ++i) c.knots.push_back(0.0);
      for (long i = 0; i <= intervals; ++i) c.knots.push_back(static_cast<double>(i));
      for (int i = 0; i < d; ++i) c.knots.push_back(static_cast<double>(intervals));
      c.control_points.resize(points, 3);
      for (long i = 0; i < points; ++i) c.control_points.row(i) << coord(rng), coord(rng), coord(rng);
      const std::vector<double> xs = basis::bspline::interval_midpoints(c, {});
      auto time = [&](auto&& f) {
        std::vector<double> rates;
        basis::bspline::SplineCurve out;
        for (int r = 0; r < repeat; ++r) {
          const auto t0 = std::chrono::steady_clock::now();
          out = f();
          const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          rates.push_back(static_cast<double>(out.num_control_points()) / s);
        }
        std::sort(rates.begin(), rates.end());
        return std::make_pair(rates[rates.size() / 2], out);
      };
      const auto boehm = time([&] { return basis::bspline::insert_knots_boehm(c, xs); });
      const auto oslo = time([&] { return basis::bspline::insert_knots_oslo(c, xs); });
      long long count = 0;
      const auto rs3 = time([&] {
        count = 0;
        return refine::refine_smooth(c, xs, refine::RefineSmoothVariant::levels, &count);
      });
      fem::set_num_threads(1);
      const auto rs5_one = time([&] { return refine::refine_smooth(c, xs, refine::RefineSmoothVariant::constant_memory, nullptr); });
      fem::set_num_threads(all_threads);
      const auto rs5 = time([&] { return refine::refine_smooth(c, xs, refine::RefineSmoothVariant::constant_memory, nullptr); });
      const double diff = std::max((rs5.second.control_points - boehm.second.control_points).cwiseAbs().maxCoeff(),
                                   (rs3.second.control_points - boehm.second.control_points).cwiseAbs().maxCoeff());
      report["degrees"][std::to_string(d)] = {{"boehm_points_per_second", boehm.first},
                                              {"oslo_points_per_second", oslo.first},
                                              {"refine_smooth_levels_points_per_second", rs3.first},
                                              {"refine_smooth_sweep_one_thread_points_per_second", rs5_one.first},
                                              {"refine_smooth_sweep_points_per_second", rs5.first},
                                              {"affine_combinations", count},
                                              {"max_difference_to_boehm", diff}};
      std::cerr << "bench-knots: degree " << d << " done" << std::endl;
    }
    std::cout << report.dump(2) << std::endl;
    if (!json.empty()) io::write_json(json, report);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench-knots: error: " << e.what() << std::endl;
    return 1;
  }
}
