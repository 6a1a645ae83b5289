// io::StepForecast (iga-poisson --max-seconds): the next step's time from the steps done (t_k · g^a), the level
// rule for hierarchies that build whole levels, and the reasons a step is not started, with times given explicitly.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "io/forecast.hpp"

namespace {

using iga::io::StepForecast;

TEST(StepForecast, GrowthOfTheDofsTimesTheLastStep) {
  StepForecast f(20.0);
  EXPECT_EQ(f.predict(false), 0.0);  // nothing done: nothing to predict from
  f.done(100, false, 1.0);
  EXPECT_EQ(f.predict(false), 4.0);  // one step: growth 4 (every element split in four), time ~ dofs
  EXPECT_EQ(f.stop_reason("1", false, 1.0), "");
  EXPECT_EQ(f.progress("1", false), "1 s (1 s in all); step 1 predicted 4 s");
  f.done(400, false, 3.0);           // 2 s for 4 times the dofs: the fitted exponent 0.5 is raised to 1
  EXPECT_EQ(f.predict(false), 8.0);
  EXPECT_EQ(f.stop_reason("2", false, 3.0), "");
  f.done(1600, false, 11.0);         // 8 s: exponent 1, the next 32 s would end at 43 s
  EXPECT_EQ(f.predict(false), 32.0);
  EXPECT_EQ(f.stop_reason("3", false, 11.0), "time limit: step 3 predicted 32 s, 9 s left of --max-seconds 20");
  EXPECT_EQ(f.stop_reason("3", false, 21.4), "time limit: 21.4 s used of --max-seconds 20");
  EXPECT_EQ(f.progress("", false), "8 s (11 s in all)");
  EXPECT_EQ(f.steps_done(), 3);
}

TEST(StepForecast, TheExponentIsFittedWithinOneAndTwo) {
  StepForecast f(0.0, "--max-seconds", "level");
  f.done(100, false, 0.1);
  f.done(200, false, 0.5);   // 4 times the time for twice the dofs: exponent 2
  EXPECT_NEAR(f.predict(false), 0.4 * 4.0, 1e-12);
  f.done(400, false, 6.9);   // 16 times: exponent 4, taken as 2
  EXPECT_NEAR(f.predict(false), 6.4 * 4.0, 1e-12);
  EXPECT_EQ(f.stop_reason("9", false, 1e6), "");  // 0: no limit
  StepForecast short_steps(1.0);
  short_steps.done(100, false, 0.01);
  short_steps.done(400, false, 0.05);  // steps under 0.05 s are not fitted: time ~ dofs
  EXPECT_NEAR(short_steps.predict(false), 0.04 * 4.0, 1e-12);
}

TEST(StepForecast, AStepThatBuildsALevelTakesFourTimesTheLastOneThatDid) {
  StepForecast f(10.0, "--max-seconds", "level");
  f.done(100, false, 1.0);
  f.done(120, true, 3.0);  // 2 s for 1.2 times the dofs (exponent 2 at most): 2.88 s without a level
  EXPECT_NEAR(f.predict(false), 2.88, 1e-12);
  EXPECT_EQ(f.predict(true), 8.0);
  EXPECT_EQ(f.stop_reason("5", true, 3.0), "time limit: level 5 predicted 8 s, 7 s left of --max-seconds 10");
  EXPECT_EQ(f.stop_reason("5", false, 3.0), "");
  f.restart();  // a new series: nothing to predict from, but the clock goes on
  EXPECT_EQ(f.predict(false), 0.0);
  EXPECT_EQ(f.stop_reason("0", false, 9.0), "");
  EXPECT_EQ(f.stop_reason("0", false, 10.0), "time limit: 10 s used of --max-seconds 10");
}

TEST(StepForecast, ALimitMustBeFiniteAndNotNegative) {
  for (const double bad : {-1.0, std::nan(""), static_cast<double>(INFINITY)}) {
    EXPECT_THROW(StepForecast f(bad), iga::InputError) << bad;
  }
}

}  // namespace
