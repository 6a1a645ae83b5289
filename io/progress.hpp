#pragma once
// Progress of a program's long phases and the time table at its end (deal.II's TimerOutput summary).
#include <chrono>
#include <condition_variable>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace iga::io {

/// Times named phases (refinement, pattern, element loop, factorisation, output, ...) of one program run.
///
/// While a phase runs longer than `after` (2 s), a ticker says so on the stream: on a terminal one line
/// "PROGRAM: PHASE ... 7 s" updated in place every second and closed with the phase's time; in a log (not a
/// terminal) plain lines "PROGRAM: PHASE ... 4 s", at 2, 4, 8, 16, ... s, then "PROGRAM: PHASE done in 9.3 s". A
/// phase shorter than `after` prints nothing. Quiet: nothing is printed, the times are still kept. Phases of
/// the same name add up; their order is that of their first start.
class Progress {
 public:
  Progress(std::string program, bool quiet, std::ostream& stream, double after_seconds = 2.0);
  Progress(std::string program, bool quiet);  ///< on std::cerr; a terminal when stderr is one
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Runs body() as phase `name` and returns what it returns (an exception ends the phase and goes on).
  template <class Body>
  auto phase(const std::string& name, Body&& body) -> decltype(body()) {
    start(name);
    struct Stop {
      Progress* p;
      ~Stop() { p->stop(); }
    } stop_at_exit{this};
    return body();
  }
  void start(const std::string& name);
  void stop();

  /// Seconds per phase, in the order of first start.
  const std::vector<std::pair<std::string, double>>& phases() const { return seconds_; }
  /// Seconds since construction.
  double total_seconds() const;
  /// The table: one row per phase (seconds and share of the total), "(other)" for the time outside the phases,
  /// and the total, as text lines.
  std::string table() const;
  /// {"PHASE": seconds, ..., "total": seconds}, for the report's "phase_seconds".
  nlohmann::json json() const;
  /// Prints table() on the stream unless quiet.
  void print_table() const;
  /// Whether the stream is treated as a terminal (one updating line).
  bool terminal() const { return terminal_; }

 private:
  void tick();  // the ticker thread's loop
  std::string program_;
  bool quiet_;
  std::ostream& out_;
  bool terminal_;
  double after_;
  using Clock = std::chrono::steady_clock;
  Clock::time_point created_, phase_start_;
  std::string current_;  // the running phase ("" when none)
  bool printed_ = false;  // the ticker has said something of the running phase
  double next_plain_ = 0.0;
  std::vector<std::pair<std::string, double>> seconds_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool ending_ = false;
  std::thread ticker_;
};

}  // namespace iga::io
