// iga-fit-quadrature: fits moment-fitting quadrature rules for Catmull–Clark elements at an extraordinary
// vertex (thesis §4.2.4) and writes them as tables (format in quadrature/moment_fit/table.hpp).
//
// For each valence n: q = n + start, n + start + 1, ... until a rule converges (||Φw − b|| <= tolerance,
// weights > 0, points in [lower, 1]²); prints every q tried with its success count over the random starts and
// writes the first converged rule of the smallest q to <output>/cc_<space>_n<N>[_sym].txt.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "core/error.hpp"
#include "quadrature/moment_fit/fit.hpp"
#include "quadrature/moment_fit/table.hpp"

namespace mf = iga::quadrature::moment_fit;

namespace {

struct Settings {
  int min_valence = 3, max_valence = 8;
  int start = 4, max_extra = 6;
  std::string space = "phi";
  std::string output;
  bool survey = false;
  bool symmetric = false;
  double time_limit = 120.0;  // per valence, seconds
  mf::FitOptions fit;
};

// Tries one (n, q[, diagonal points]) and prints one line.
mf::FitResult try_fit(int n, int q, int diagonal, const Settings& s) {
  mf::FitOptions o = s.fit;
  o.space = mf::parse_space(s.space);
  o.symmetric = s.symmetric;
  o.diagonal_points = diagonal;
  o.stop_at_first = !s.survey;
  const auto t0 = std::chrono::steady_clock::now();
  mf::FitResult r = mf::fit_rule(n, q, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double best = r.attempts.front().residual;
  for (const auto& a : r.attempts) best = std::min(best, a.residual);
  std::printf("n=%2d q=%2d%s successes %2d/%2d  best residual %.2e  %s  (%.1f s)\n", n, q,
              s.symmetric ? (" diag=" + std::to_string(r.diagonal_points)).c_str() : "", r.successes(),
              static_cast<int>(r.attempts.size()), best, r.converged ? "CONVERGED" : "-", seconds);
  std::fflush(stdout);
  return r;
}

void run_valence(int n, const Settings& s) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int q = std::max(1, n + s.start); q <= n + 4 + s.max_extra; ++q) {
    std::vector<int> diagonals{-1};
    if (s.symmetric) {
      diagonals.clear();
      for (int d = q % 2; d <= q; d += 2) diagonals.push_back(d);
    }
    for (const int d : diagonals) {
      const mf::FitResult r = try_fit(n, q, d, s);
      if (r.converged) {
        if (!s.output.empty()) {
          mf::Table t;
          t.valence = n;
          t.space = r.space;
          t.residual = r.residual;
          t.seed = r.seed;
          t.attempt = r.best_attempt;
          t.symmetric = r.symmetric;
          t.rule = r.rule;
          const auto path = std::filesystem::path(s.output) / mf::table_file_name(n, r.space, r.symmetric);
          mf::write_table(path.string(), t);
          std::printf("  wrote %s (residual %.2e, min weight %.3e)\n", path.string().c_str(), r.residual,
                      r.rule.weights.minCoeff());
        }
        return;
      }
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > s.time_limit) {
        std::printf("n=%2d: time limit reached, no rule\n", n);
        return;
      }
    }
  }
  std::printf("n=%2d: no rule up to q = %d\n", n, n + 4 + s.max_extra);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit moment-fitting quadrature rules for Catmull-Clark elements at an extraordinary vertex"};
  Settings s;
  app.add_option("--min-valence", s.min_valence, "smallest valence (3..16)");
  app.add_option("--max-valence", s.max_valence, "largest valence (3..16)");
  app.add_option("--start", s.start, "first q = n + start");
  app.add_option("--max-extra", s.max_extra, "last q = n + 4 + max-extra");
  app.add_option("--space", s.space, "phi | mass | stiffness");
  app.add_option("--output", s.output, "directory for the tables (none: do not write)");
  app.add_flag("--survey", s.survey, "run every random start (success rates) instead of stopping at the first");
  app.add_flag("--symmetric", s.symmetric, "only rules symmetric about u = v (all diagonal point counts)");
  app.add_option("--time-limit", s.time_limit, "seconds per valence");
  app.add_option("--attempts", s.fit.attempts, "random starts per q");
  app.add_option("--seed", s.fit.seed, "random seed (attempt k uses seed + k)");
  app.add_option("--algorithm", s.fit.algorithm, "NLopt first stage: LD_LBFGS, LD_SLSQP, LD_MMA, LN_BOBYQA, none");
  app.add_option("--max-evaluations", s.fit.max_evaluations, "NLopt evaluations per start");
  app.add_option("--polish-iterations", s.fit.polish_iterations, "Levenberg-Marquardt iterations per start");
  app.add_option("--tolerance", s.fit.tolerance, "convergence: ||Phi w - b|| <= tolerance");
  app.add_option("--lower-bound", s.fit.lower_bound, "u, v >= lower bound");
  CLI11_PARSE(app, argc, argv);
  try {
    mf::parse_space(s.space);
    for (int n = s.min_valence; n <= s.max_valence; ++n) run_valence(n, s);
  } catch (const iga::Error& e) {
    std::cerr << "iga-fit-quadrature: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
