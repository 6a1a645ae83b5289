#include "io/forecast.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

#include "core/error.hpp"

namespace iga::io {

namespace {
constexpr double kFirstGrowth = 4.0;        // one refinement of every element of a planar or surface mesh
constexpr double kFitSeconds = 0.05;        // shorter steps are too noisy to fit an exponent to
constexpr double kLevelGrowth = 4.0;        // a Catmull–Clark level has 4 times the elements of the one above
}  // namespace

std::string seconds_text(double seconds) {
  std::ostringstream o;
  o << std::setprecision(3) << seconds;
  return o.str();
}

StepForecast::StepForecast(double max_seconds, std::string option, std::string step)
    : max_seconds_(max_seconds), option_(std::move(option)), step_(std::move(step)) {
  if (!(max_seconds >= 0.0) || !std::isfinite(max_seconds)) throw InputError(option_ + " must be a finite number >= 0");
}

double StepForecast::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - created_).count();
}

void StepForecast::done(double dofs, bool built_level, double now) {
  const double t = std::max(0.0, now - end_);
  end_ = now;
  dofs_.push_back(dofs);
  seconds_.push_back(t);
  if (built_level) level_seconds_ = t;
}

double StepForecast::predict(bool builds_level) const {
  const std::size_t n = dofs_.size();
  if (n == 0) return 0.0;
  const double t = seconds_[n - 1];
  double growth = kFirstGrowth, exponent = 1.0;
  if (n >= 2 && dofs_[n - 2] > 0.0) {
    growth = std::max(1.0, dofs_[n - 1] / dofs_[n - 2]);
    if (growth > 1.0 && t >= kFitSeconds && seconds_[n - 2] >= kFitSeconds) {
      exponent = std::clamp(std::log(t / seconds_[n - 2]) / std::log(growth), 1.0, 2.0);
    }
  }
  double p = t * std::pow(growth, exponent);
  if (builds_level && level_seconds_ >= 0.0) p = std::max(p, kLevelGrowth * level_seconds_);
  return p;
}

std::string StepForecast::stop_reason(const std::string& next, bool builds_level, double now) const {
  if (max_seconds_ <= 0.0) return std::string();
  if (now >= max_seconds_) {
    return "time limit: " + seconds_text(now) + " s used of " + option_ + " " + seconds_text(max_seconds_);
  }
  const double p = predict(builds_level);
  if (now + p <= max_seconds_) return std::string();
  return "time limit: " + step_ + " " + next + " predicted " + seconds_text(p) + " s, " + seconds_text(max_seconds_ - now) +
         " s left of " + option_ + " " + seconds_text(max_seconds_);
}

std::string StepForecast::progress(const std::string& next, bool builds_level) const {
  std::string text = seconds_text(last_seconds()) + " s (" + seconds_text(end_) + " s in all)";
  if (!next.empty()) text += "; " + step_ + " " + next + " predicted " + seconds_text(predict(builds_level)) + " s";
  return text;
}

}  // namespace iga::io
