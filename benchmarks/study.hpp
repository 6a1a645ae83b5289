#pragma once
// iga-poisson --study K0:K1: a convergence study in one process. Every level is one run of the program's own
// pipeline (the callbacks below), so a level's report is what `--refine K --json` writes; the study adds the mesh
// size, the rates between levels and fitted over all levels (fem::ConvergenceTable), a table on stderr,
// PREFIX.csv, PREFIX.json, a .vtu per level with a .pvd collection (--vtu), and the plots of plot_study.py.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iga::bench {

struct StudyLevels {
  int first = 0, last = 0;  ///< refinement levels first..last, inclusive
};
constexpr int kMinStudyLevels = 3;  ///< the fewest levels a fitted rate is asserted over (CONVENTIONS.md)
constexpr int kMaxStudyLevel = 14;  ///< as --refine

/// "" when text is "K0:K1" with 0 <= K0, K1 <= 14 and at least kMinStudyLevels levels; else the reason.
std::string check_levels(const std::string& text);
StudyLevels parse_levels(const std::string& text);  ///< InputError with check_levels' reason
/// "" when text is a comma-separated list of distinct degrees 1..12; else the reason.
std::string check_degrees(const std::string& text);
std::vector<int> parse_degrees(const std::string& text);  ///< InputError with check_degrees' reason

struct StudyOptions {
  StudyLevels levels;
  std::vector<int> degrees;       ///< empty: the run's own degree (one series)
  std::string output = "study";   ///< PREFIX of PREFIX.csv and PREFIX.json and the plots; "none": no files
  std::string vtu;                ///< "" or "none": no .vtu; else BASE(.vtu): BASE[_pP]_kK.vtu and BASE[_pP].pvd
  std::string json;               ///< "" or "none": only PREFIX.json; else the report here too ("-": stdout)
  std::string plots = "png,svg";  ///< png,svg | png | svg | none
  bool quiet = false;
  /// A time limit (0: none): before each level but the first its time is predicted (io::StepForecast, from the
  /// levels of the same degree done), and the study stops before a level predicted to end past the limit or once
  /// the time is spent; the report's study.stopped says why ("levels" when every level ran).
  double max_seconds = 0.0;
};

struct StudyHooks {
  /// Refuses (throws) a level predicted not to fit in memory, before any work. degree 0: the run's own.
  std::function<void(int degree, int refine)> check_size;
  /// Solves one level and returns its report (the keys of a single run's JSON); vtu: "" for none.
  std::function<nlohmann::json(int degree, int refine, const std::string& vtu)> solve;
};

/// Runs the study; returns the exit code (0). Throws InputError when a level has no error norms (no exact
/// solution) and for files that cannot be written. Plots that cannot be drawn because python3, matplotlib or the
/// script is missing are one line on stderr and "plots": {"drawn": false, "reason": ...} in the report, exit 0.
int run_study(const StudyOptions& options, const StudyHooks& hooks);

}  // namespace iga::bench
