#pragma once
// A forecast of the next step of a loop of growing steps (adaptive refinement, the levels of a study) and the
// time limit of --max-seconds: before each step its time is predicted from the steps done, and a step that would
// end past the limit is not started, so the last result written is the last complete step's.
#include <chrono>
#include <string>
#include <vector>

namespace iga::io {

/// The prediction (every figure in seconds of wall time). Step k's time t_k is the time from the end of step k − 1
/// (from the start of the run for step 0) to the end of step k, so it includes everything the step does: the
/// refinement that made its mesh, the solve, the estimate and its output. With N_k its dofs, the next step is
///   t_next = t_k · g^a,  g = N_k / N_{k−1} (the last growth of the dofs; 4 after one step: a refinement that splits
///                        every element in four, the most one step of a planar or surface mesh can add),
///   a = log(t_k / t_{k−1}) / log(g) of the last two steps, within [1, 2], when both took at least 0.05 s and
///       the dofs grew (1 otherwise: time proportional to the dofs),
/// and, for a step that builds a new level of a hierarchy whose levels are built whole (Catmull–Clark: 4 times the
/// elements of the level above), at least 4 t_d, t_d the time of the last step that built a level.
class StepForecast {
 public:
  /// max_seconds: the limit (0: none); option: its name in the reasons ("--max-seconds"); step: what one is called
  /// ("step", "level").
  StepForecast(double max_seconds, std::string option = "--max-seconds", std::string step = "step");

  /// Records a step that ended `now` seconds after the start: its dofs, whether it built a new level.
  void done(double dofs, bool built_level, double now);
  /// Forgets the steps done (a new series of steps starting small again); the clock and the time limit go on.
  void restart() {
    dofs_.clear();
    seconds_.clear();
  }
  /// The predicted seconds of the next step (0 before any step is done).
  double predict(bool builds_level) const;
  /// "" when the next step (called `next`) may start at `now`; else why not, for the report: "time limit: step 7
  /// predicted 12.3 s, 3.1 s left of --max-seconds 20", or "time limit: 21.4 s used of --max-seconds 20" when the
  /// time is already spent (the limit is honoured within one step).
  std::string stop_reason(const std::string& next, bool builds_level, double now) const;
  /// The progress text of the step done last: "0.82 s (1.90 s in all); step 4 predicted 1.6 s" (or without the
  /// prediction when `next` is "").
  std::string progress(const std::string& next, bool builds_level) const;

  /// Seconds since construction (the `now` of a run that made its forecast at its start).
  double elapsed() const;
  double max_seconds() const { return max_seconds_; }
  int steps_done() const { return static_cast<int>(dofs_.size()); }
  double last_seconds() const { return seconds_.empty() ? 0.0 : seconds_.back(); }

 private:
  double max_seconds_;
  std::chrono::steady_clock::time_point created_ = std::chrono::steady_clock::now();
  std::string option_, step_;
  std::vector<double> dofs_, seconds_;
  double end_ = 0.0;             // when the last step ended
  double level_seconds_ = -1.0;  // time of the last step that built a level (< 0: none yet)
};

/// Seconds to three significant figures ("12.3", "0.0412", "1530"), for the reasons and progress lines.
std::string seconds_text(double seconds);

}  // namespace iga::io
