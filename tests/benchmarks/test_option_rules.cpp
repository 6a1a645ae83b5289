// Issue 38, class 7: every rule of the one table of contradicting or ineffective options (io/option_rules.hpp)
// is run in every program it names: its example is refused with one line naming the option (exit 2), and the
// example without the option is not refused by that rule.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>

#include "io/option_rules.hpp"
#include "support/paths.hpp"
#include "support/program_run.hpp"

namespace fs = std::filesystem;

namespace {
std::string exe(const std::string& program) {
  static const std::map<std::string, std::string> keys = {{"iga-poisson", "IGA_POISSON_EXE"},
                                                          {"iga-bem", "IGA_BEM_EXE"},
                                                          {"iga-biharmonic", "IGA_BIHARMONIC_EXE"},
                                                          {"iga-elasticity", "IGA_ELASTICITY_EXE"},
                                                          {"iga-shell", "IGA_SHELL_EXE"}};
  return iga::test::build_path(keys.at(program).c_str());
}

std::string expected_start(const iga::io::OptionRule& r, const std::string& program) {
  using K = iga::io::OptionRule::Kind;
  const std::string head = program + ": error: " + r.option + " ";
  switch (r.kind) {
    case K::kRequires: return head + "requires " + r.other;
    case K::kExcludes: return head + "excludes " + r.other;
    case K::kNoEffect: return head + "has no effect with " + r.other + " ";
    case K::kRequiresOneOf: return head + "requires " + r.values.front() + " or ";  // two alternatives here
  }
  return head;
}
}  // namespace

TEST(OptionRules, EveryRuleRefusesItsExampleByName) {
  const fs::path dir = fs::temp_directory_path() / ("iga_option_rules_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  ASSERT_GE(iga::io::option_rules().size(), 18u);
  for (const iga::io::OptionRule& r : iga::io::option_rules()) {
    ASSERT_FALSE(r.programs.empty()) << r.option;
    ASSERT_NE(r.example.find(r.option), std::string::npos) << r.option << ": the example does not give it";
    for (const std::string& program : r.programs) {
      const iga::test::Outcome o = iga::test::run_program(dir, exe(program), r.example + " --json none --quiet");
      EXPECT_EQ(o.code, 2) << program << " " << r.example << ": " << o.err;
      EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << program << " " << r.example << ": " << o.err;
      EXPECT_EQ(o.err.rfind(expected_start(r, program), 0), 0u) << program << " " << r.example << ": " << o.err;
      if (r.kind == iga::io::OptionRule::Kind::kNoEffect) {
        EXPECT_NE(o.err.find(": leave it out"), std::string::npos) << o.err;
      }
    }
  }
  fs::remove_all(dir);
}

// The message names the rule; an option left at its default never triggers one (the table's check sees only
// options given: iga-poisson's defaults --vtu-samples 4 with --vtu-format bezier, --nitsche-penalty 0 with strong).
TEST(OptionRules, DefaultsNeverTrigger) {
  const fs::path dir = fs::temp_directory_path() / ("iga_option_rules_defaults_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const iga::test::Outcome o = iga::test::run_program(dir, exe("iga-poisson"), "--refine 1 --vtu u.vtu --json none --quiet");
  EXPECT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.err, "");
  fs::remove_all(dir);
}
