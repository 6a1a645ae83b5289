// iga-fit-quadrature: fits moment-fitting quadrature rules for Catmull–Clark elements at an extraordinary
// vertex (thesis §4.2.4) and writes them as tables (format in quadrature/moment_fit/table.hpp).
//
// For each valence n: q = n + start, n + start + 1, ... until a rule converges (||Φw − b|| <= tolerance,
// weights > 0, points in [lower, 1]²); prints every q tried with its success count over the random starts and
// writes the first converged rule of the smallest q to <output>/cc_<space>_n<N>[_sym].txt.
// --first-points/--last-points give the q range directly (the mass and stiffness spaces need far more points
// than n + 4). --rank prints instead the numerical rank of the space's functions (SVD of their values at
// random points on every tile level), which bounds the points a rule needs from below (3q >= rank).
#include <CLI/CLI.hpp>
#include <Eigen/SVD>

#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>

#include "core/error.hpp"
#include "io/program.hpp"
#include "quadrature/moment_fit/fit.hpp"
#include "quadrature/moment_fit/table.hpp"
#include "quadrature/per_tile.hpp"

namespace mf = iga::quadrature::moment_fit;

namespace {

bool quiet = false;  // --quiet

// What the fit found, on stderr (the iga-* convention: stdout carries only a report asked for with '-').
__attribute__((format(printf, 1, 2))) void say(const char* format, ...) {
  if (quiet) return;
  va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
}

struct Settings {
  int min_valence = 3, max_valence = 8;
  int start = 4, max_extra = 6;
  int first_points = 0, last_points = 0;  // absolute q range; 0: from start / max_extra
  int step = 1;                           // q increment
  bool rank = false;
  std::vector<int> eliminate;  // P L: node elimination from tiled_rule(P, L) instead of random starts
  std::string space = "phi";
  std::string output;
  bool survey = false;
  bool symmetric = false;
  double time_limit = 120.0;  // per valence, seconds
  mf::FitOptions fit;
};

// Tries one (n, q[, diagonal points]) and prints one line.
mf::FitResult try_fit(int n, int q, int diagonal, const Settings& s, std::chrono::steady_clock::time_point deadline) {
  mf::FitOptions o = s.fit;
  o.deadline = deadline;  // --time-limit holds inside a fit too (NLopt's maxtime, no new attempt after it)
  o.space = mf::parse_space(s.space);
  o.symmetric = s.symmetric;
  o.diagonal_points = diagonal;
  o.stop_at_first = !s.survey;
  const auto t0 = std::chrono::steady_clock::now();
  mf::FitResult r = mf::fit_rule(n, q, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double best = r.attempts.front().residual;
  for (const auto& a : r.attempts) best = std::min(best, a.residual);
  say("n=%2d q=%2d%s successes %2d/%2d  best residual %.2e  %s  (%.1f s)\n", n, q,
              s.symmetric ? (" diag=" + std::to_string(r.diagonal_points)).c_str() : "", r.successes(),
              static_cast<int>(r.attempts.size()), best, r.converged ? "CONVERGED" : "-", seconds);
  std::fflush(stdout);
  return r;
}

// Numerical rank of the functions of the space: singular values of F (functions × points) at 4 (functions)
// points, a quarter uniform in [0,1]², the others uniform in [0, 2^-k]² for k = 1..12 (the tiles near the EV).
// rank = #{σ_i > 1e-10 σ_1}; prints the singular values either side of the cut so the gap can be judged.
void print_rank(int n, const Settings& s) {
  const mf::Space space = mf::parse_space(s.space);
  const int m = mf::num_functions(n, space);
  const int count = 4 * m;
  std::mt19937 gen(s.fit.seed);
  auto uniform = [&] { return (static_cast<double>(gen()) + 0.5) / 4294967296.0; };
  Eigen::Matrix2Xd pts(2, count);
  for (int i = 0; i < count; ++i) {
    const double scale = i < count / 4 ? 1.0 : std::ldexp(1.0, -(1 + i % 12));
    pts.col(i) << scale * uniform(), scale * uniform();
  }
  Eigen::MatrixXd f;
  mf::evaluate_functions(n, space, pts, f);
  // Rows scaled to unit norm so that no function dominates the cut.
  for (Eigen::Index r = 0; r < f.rows(); ++r) f.row(r) /= std::max(f.row(r).norm(), 1e-300);
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(f);
  const Eigen::VectorXd sv = svd.singularValues();
  int rank = 0;
  while (rank < sv.size() && sv(rank) > 1e-10 * sv(0)) ++rank;
  say("n=%2d space=%s functions %d rank %d (sigma[rank-1] = %.2e, sigma[rank] = %.2e relative) -> q >= %d;"
              " count of sigma_i/sigma_1 above", n, s.space.c_str(), m, rank, sv(rank - 1) / sv(0),
              rank < sv.size() ? sv(rank) / sv(0) : 0.0, (rank + 2) / 3);
  for (const double cut : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14}) {
    int k = 0;
    while (k < sv.size() && sv(k) > cut * sv(0)) ++k;
    say(" %.0e: %d", cut, k);
  }
  say("\n");
  std::fflush(stdout);
}

// Node elimination from the per-tile rule; writes the smallest converged rule.
void run_elimination(int n, const Settings& s) {
  mf::FitOptions o = s.fit;
  o.space = mf::parse_space(s.space);
  const auto t0 = std::chrono::steady_clock::now();
  o.deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(s.time_limit));
  const iga::quadrature::Rule start = iga::quadrature::tiled_rule(s.eliminate[0], s.eliminate[1]);
  const mf::FitResult r = mf::eliminate_points(n, start, o, std::max(1, s.first_points));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  say("n=%2d space=%s elimination from tiles:%d:%d (%d points): %s q=%d residual %.2e min weight %.3e "
              "(||b|| = %.2e; %d removal steps tried, %.1f s)\n", n, s.space.c_str(), s.eliminate[0], s.eliminate[1],
              static_cast<int>(start.size()), r.converged ? "CONVERGED" : "start not exact", r.points, r.residual,
              r.rule.weights.minCoeff(), mf::moments(n, o.space).norm(), std::max(0, static_cast<int>(r.attempts.size()) - 1), seconds);
  if (std::chrono::steady_clock::now() >= *o.deadline) say("n=%2d: time limit reached (--time-limit %g s): the rule above is the smallest found by then\n", n, s.time_limit);
  std::fflush(stdout);
  if (r.converged && !s.output.empty()) {
    mf::Table t;
    t.valence = n;
    t.space = r.space;
    t.residual = r.residual;
    t.rule = r.rule;
    t.note = "node elimination from tiles:" + std::to_string(s.eliminate[0]) + ":" + std::to_string(s.eliminate[1]) +
             " (iga-fit-quadrature --eliminate " + std::to_string(s.eliminate[0]) + " " +
             std::to_string(s.eliminate[1]) + "); seed 0 attempt 0: deterministic";
    const auto path = std::filesystem::path(s.output) / mf::table_file_name(n, r.space, false);
    mf::write_table(path.string(), t);
    say("  wrote %s\n", path.string().c_str());
  }
}

void run_valence(int n, const Settings& s) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(s.time_limit));
  const int first = s.first_points > 0 ? s.first_points : std::max(1, n + s.start);
  const int last = s.last_points > 0 ? s.last_points : n + 4 + s.max_extra;
  for (int q = first; q <= last; q += s.step) {
    std::vector<int> diagonals{-1};
    if (s.symmetric) {
      diagonals.clear();
      for (int d = q % 2; d <= q; d += 2) diagonals.push_back(d);
    }
    for (const int d : diagonals) {
      const mf::FitResult r = try_fit(n, q, d, s, deadline);
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
          say("  wrote %s (residual %.2e, min weight %.3e)\n", path.string().c_str(), r.residual,
                      r.rule.weights.minCoeff());
        }
        return;
      }
      if (std::chrono::steady_clock::now() >= deadline) {
        say("n=%2d: time limit reached, no rule\n", n);
        return;
      }
    }
  }
  say("n=%2d: no rule up to q = %d\n", n, last);
}

// What CLI11 cannot check option by option: the relations between options.
void check_settings(const Settings& s) {
  if (s.min_valence > s.max_valence) {
    throw iga::InputError("--min-valence " + std::to_string(s.min_valence) + " is above --max-valence " +
                          std::to_string(s.max_valence) + ": no valence to fit");
  }
  if (s.first_points > 0 && s.last_points > 0 && s.first_points > s.last_points) {
    throw iga::InputError("--first-points " + std::to_string(s.first_points) + " is above --last-points " +
                          std::to_string(s.last_points) + ": no point count to try");
  }
  if (!s.eliminate.empty() && (s.eliminate[0] < 1 || s.eliminate[0] > 64 || s.eliminate[1] < 1 || s.eliminate[1] > 50)) {
    throw iga::InputError("--eliminate P L: P must be 1..64 and L 1..50");
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit moment-fitting quadrature rules for Catmull-Clark elements at an extraordinary vertex"};
  Settings s;
  app.add_option("--min-valence", s.min_valence, "smallest valence (3..16)")->check(iga::io::whole_number(3, 16))->capture_default_str();
  app.add_option("--max-valence", s.max_valence, "largest valence (3..16)")->check(iga::io::whole_number(3, 16))->capture_default_str();
  app.add_option("--start", s.start, "first q = n + start")->check(iga::io::whole_number(0, 200))->capture_default_str();
  app.add_option("--max-extra", s.max_extra, "last q = n + 4 + max-extra")->check(iga::io::whole_number(0, 200))->capture_default_str();
  app.add_option("--first-points", s.first_points, "first q (overrides --start)")->check(iga::io::whole_number(1, 1000));
  app.add_option("--last-points", s.last_points, "last q (overrides --max-extra)")->check(iga::io::whole_number(1, 1000));
  app.add_option("--step", s.step, "q increment")->check(iga::io::whole_number(1, 1000))->capture_default_str();
  app.add_option("--eliminate", s.eliminate, "P L: node elimination from the per-tile rule tiles:P:L (then "
                 "--attempts = candidates tried per removal, --first-points = smallest q)")->expected(2);
  app.add_flag("--rank", s.rank, "print the numerical rank of the space per valence instead of fitting");
  app.add_option("--space", s.space, "phi | mass | stiffness")->check(CLI::IsMember({"phi", "mass", "stiffness"}))->capture_default_str();
  app.add_option("--output", s.output, "directory for the tables (default and none: do not write)")->check(iga::io::non_blank());
  app.add_flag("--survey", s.survey, "run every random start (success rates) instead of stopping at the first");
  app.add_flag("--symmetric", s.symmetric, "only rules symmetric about u = v (all diagonal point counts)");
  app.add_option("--time-limit", s.time_limit, "seconds per valence: no fit attempt or elimination step starts after it, and a running fit stops at it")->check(iga::io::finite_number(0))->capture_default_str();
  app.add_option("--attempts", s.fit.attempts, "random starts per q")->check(iga::io::whole_number(1, 100000))->capture_default_str();
  app.add_option("--seed", s.fit.seed, "random seed (attempt k uses seed + k)");
  app.add_option("--algorithm", s.fit.algorithm, "NLopt first stage")->check(CLI::IsMember({"LD_LBFGS", "LD_SLSQP", "LD_MMA", "LN_BOBYQA", "none"}))->capture_default_str();
  app.add_option("--max-evaluations", s.fit.max_evaluations, "NLopt evaluations per start")->check(iga::io::whole_number(1, 100000000))->capture_default_str();
  app.add_option("--polish-iterations", s.fit.polish_iterations, "Levenberg-Marquardt iterations per start")->check(iga::io::whole_number(0, 100000))->capture_default_str();
  app.add_option("--tolerance", s.fit.tolerance, "convergence: ||Phi w - b|| <= tolerance")->check(iga::io::finite_number(1e-300, 1.0))->capture_default_str();
  app.add_option("--lower-bound", s.fit.lower_bound, "u, v >= lower bound")->check(iga::io::finite_number(1e-16, 0.5))->capture_default_str();
  iga::io::CommonOptions common{"iga-fit-quadrature"};
  iga::io::add_common_options(app, common);
  if (const auto code = iga::io::parse_command_line(app, argc, argv, common)) return *code;
  quiet = common.quiet;
  if (s.output == "none") s.output.clear();
  return iga::io::run_program("iga-fit-quadrature", [&] {
    check_settings(s);
    for (int n = s.min_valence; n <= s.max_valence; ++n) {
      if (s.rank) {
        print_rank(n, s);
      } else if (!s.eliminate.empty()) {
        run_elimination(n, s);
      } else {
        run_valence(n, s);
      }
    }
    return 0;
  });
}
