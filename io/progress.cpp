#include "io/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace iga::io {

namespace {
std::string seconds_text(double s, int precision) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(precision) << s;
  return o.str();
}
}  // namespace

Progress::Progress(std::string program, bool quiet, std::ostream& stream, double after_seconds)
    : program_(std::move(program)),
      quiet_(quiet),
      out_(stream),
      terminal_(&stream == &std::cerr && ::isatty(STDERR_FILENO) == 1),
      after_(after_seconds),
      created_(Clock::now()) {
  if (!quiet_) ticker_ = std::thread([this] { tick(); });
}

Progress::Progress(std::string program, bool quiet) : Progress(std::move(program), quiet, std::cerr) {}

Progress::~Progress() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ending_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
}

void Progress::start(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  current_ = name;
  phase_start_ = Clock::now();
  printed_ = false;
  next_plain_ = after_;
  if (std::none_of(seconds_.begin(), seconds_.end(), [&](const auto& p) { return p.first == name; })) {
    seconds_.emplace_back(name, 0.0);
  }
}

void Progress::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (current_.empty()) return;
  const double s = std::chrono::duration<double>(Clock::now() - phase_start_).count();
  for (auto& p : seconds_) {
    if (p.first == current_) p.second += s;
  }
  if (printed_ && !quiet_) {
    if (terminal_) {
      out_ << "\r\033[K" << program_ << ": " << current_ << " done in " << seconds_text(s, 1) << " s" << std::endl;
    } else {
      out_ << program_ << ": " << current_ << " done in " << seconds_text(s, 1) << " s" << std::endl;
    }
  }
  current_.clear();
}

void Progress::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!ending_) {
    wake_.wait_for(lock, std::chrono::milliseconds(terminal_ ? 250 : 500));
    if (ending_ || current_.empty()) continue;
    const double s = std::chrono::duration<double>(Clock::now() - phase_start_).count();
    if (s < after_) continue;
    if (terminal_) {
      out_ << "\r\033[K" << program_ << ": " << current_ << " ... " << seconds_text(s, 0) << " s" << std::flush;
      printed_ = true;
    } else if (s >= next_plain_) {
      out_ << program_ << ": " << current_ << " ... " << seconds_text(next_plain_, 0) << " s" << std::endl;
      printed_ = true;
      next_plain_ *= 2.0;
    }
  }
}

double Progress::total_seconds() const { return std::chrono::duration<double>(Clock::now() - created_).count(); }

std::string Progress::table() const {
  std::lock_guard<std::mutex> lock(mutex_);
  const double total = total_seconds();
  std::size_t width = 5;
  for (const auto& p : seconds_) width = std::max(width, p.first.size());
  std::ostringstream t;
  t << program_ << ": time per phase\n";
  auto row = [&](const std::string& name, double s) {
    t << "  " << std::left << std::setw(static_cast<int>(width)) << name << std::right << std::setw(10)
      << seconds_text(s, 3) << " s" << std::setw(7) << seconds_text(total > 0 ? 100.0 * s / total : 0.0, 1) << " %\n";
  };
  double timed = 0.0;
  for (const auto& p : seconds_) {
    row(p.first, p.second);
    timed += p.second;
  }
  if (total > timed) row("(other)", total - timed);
  row("total", total);
  return t.str();
}

nlohmann::json Progress::json() const {
  nlohmann::json j = nlohmann::json::object();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& p : seconds_) j[p.first] = p.second;
  }
  j["total"] = total_seconds();
  return j;
}

void Progress::print_table() const {
  if (quiet_) return;
  const std::string t = table();
  out_ << t << std::flush;
}

}  // namespace iga::io
