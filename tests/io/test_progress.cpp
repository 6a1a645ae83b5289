// io::Progress: a phase longer than the threshold is announced (plain lines in a log) and closed with its time;
// a short one prints nothing; quiet prints nothing; the times add up per phase name and the table lists them.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <thread>

#include "io/progress.hpp"

namespace {

using namespace std::chrono_literals;

TEST(Progress, LongPhasesAreAnnouncedShortOnesAreNot) {
  std::ostringstream log;
  {
    iga::io::Progress p("prog", false, log, 0.2);
    p.phase("short", [] { std::this_thread::sleep_for(10ms); });
    p.phase("long", [] { std::this_thread::sleep_for(700ms); });
    const auto& phases = p.phases();
    ASSERT_EQ(phases.size(), 2u);
    EXPECT_EQ(phases[0].first, "short");
    EXPECT_EQ(phases[1].first, "long");
    EXPECT_GE(phases[1].second, 0.7);
    EXPECT_LT(phases[0].second, 0.2);
    const nlohmann::json j = p.json();
    EXPECT_GE(j["total"].get<double>(), phases[0].second + phases[1].second);
    const std::string table = p.table();
    EXPECT_NE(table.find("prog: time per phase"), std::string::npos) << table;
    EXPECT_NE(table.find("  long "), std::string::npos) << table;
    EXPECT_NE(table.find("  total"), std::string::npos) << table;
  }
  const std::string text = log.str();
  EXPECT_EQ(text.find("short"), std::string::npos) << text;
  EXPECT_EQ(text.rfind("prog: long ... ", 0), 0u) << text;  // announced at 0.2 s, 0.4 s (a log: plain lines)
  EXPECT_NE(text.find("prog: long done in 0."), std::string::npos) << text;
}

TEST(Progress, QuietPrintsNothingButKeepsTheTimes) {
  std::ostringstream log;
  iga::io::Progress p("prog", true, log, 0.05);
  p.phase("a", [] { std::this_thread::sleep_for(200ms); });
  p.phase("a", [] { std::this_thread::sleep_for(100ms); });
  p.print_table();
  EXPECT_EQ(log.str(), "");
  ASSERT_EQ(p.phases().size(), 1u);
  EXPECT_GE(p.phases()[0].second, 0.3);
}

TEST(Progress, AnExceptionEndsThePhase) {
  std::ostringstream log;
  iga::io::Progress p("prog", false, log, 10.0);
  EXPECT_THROW(p.phase("fails", []() -> int { throw std::runtime_error("x"); }), std::runtime_error);
  p.phase("next", [] {});
  EXPECT_EQ(p.phases().size(), 2u);
}

}  // namespace
