#pragma once
// Options that contradict each other or have no effect in the given combination (issue 38, class 7): ONE table
// for every program, checked after parsing. A rule names the programs it holds for (the same option can mean
// more in one program: iga-bem's --vtu-samples also samples the interior errors); an option the user did not
// give (its default) never triggers one. Header-only: programs link CLI11 themselves.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace iga::io {

struct OptionRule {
  enum class Kind {
    kRequires,  ///< `option` does something only with `other` given: "--theta requires --adaptive"
    kExcludes,  ///< `option` and `other` contradict each other: "--study excludes --refine"
    kNoEffect,  ///< `option` has no effect when `other` has one of `values` (as given, or by default)
    kRequiresOneOf,  ///< `option` does something only with one of the options `values`: "requires --a or --b"
  };
  Kind kind;
  std::string option, other;
  std::vector<std::string> values;  ///< kNoEffect: the values of `other` under which `option` does nothing;
                                    ///< kRequiresOneOf: the options of which one is needed
  std::string reason;               ///< kNoEffect: why, in the user's words
  std::vector<std::string> programs;  ///< the programs it holds for (the first runs `example` in the tests)
  std::string example;                ///< options that trigger the rule (the tests run every rule)
};

/// The table. Backend options given with another --basis are refused by the backend registry (io/discretisation),
/// a built-in problem on a geometry it does not belong to by fem::check_problem_domain.
inline const std::vector<OptionRule>& option_rules() {
  using K = OptionRule::Kind;
  static const std::vector<OptionRule> rules = {
      // Issue 32's rules, formerly CLI11's needs/excludes (the same words and exit code 2).
      {K::kRequires, "--theta", "--adaptive", {}, "", {"iga-poisson"}, "--theta 0.3"},
      {K::kRequires, "--mark", "--adaptive", {}, "", {"iga-poisson"}, "--mark max"},
      {K::kRequires, "--max-dofs", "--adaptive", {}, "", {"iga-poisson"}, "--max-dofs 1000"},
      {K::kRequires, "--admissibility", "--adaptive", {}, "", {"iga-poisson"}, "--admissibility 3"},
      {K::kRequires, "--degrees", "--study", {}, "", {"iga-poisson"}, "--degrees 2,3"},
      {K::kRequires, "--study-output", "--study", {}, "", {"iga-poisson"}, "--study-output s"},
      {K::kRequires, "--plots", "--study", {}, "", {"iga-poisson"}, "--plots png"},
      {K::kExcludes, "--study", "--refine", {}, "", {"iga-poisson"}, "--study 0:2 --refine 2"},
      {K::kExcludes, "--study", "--adaptive", {}, "", {"iga-poisson"}, "--study 0:2 --adaptive 2"},
      {K::kExcludes, "--degrees", "--degree", {}, "", {"iga-poisson"}, "--study 0:2 --degrees 2 --degree 3"},
      // Issue 38: options that do nothing in the combination given.
      {K::kNoEffect, "--nitsche-penalty", "--dirichlet-method", {"strong"},
       "strong conditions have no penalty; it belongs to --dirichlet-method nitsche", {"iga-poisson"},
       "--nitsche-penalty 100"},
      {K::kNoEffect, "--vtu-format", "--vtu", {"none"}, "no .vtu is written",
       {"iga-poisson", "iga-biharmonic", "iga-elasticity", "iga-shell"},
       "--vtu none --vtu-format linear"},
      {K::kNoEffect, "--vtu-samples", "--vtu", {"none"}, "no .vtu is written",
       {"iga-poisson", "iga-biharmonic", "iga-elasticity", "iga-shell"},
       "--vtu none --vtu-samples 8"},
      {K::kNoEffect, "--vtu-degree", "--vtu", {"none"}, "no .vtu is written",
       {"iga-poisson", "iga-biharmonic", "iga-elasticity", "iga-shell"},
       "--vtu none --vtu-degree 4"},
      {K::kNoEffect, "--vtu-samples", "--vtu-format", {"bezier"},
       "Bézier cells are written exactly, not sampled; the samples are for --vtu-format linear",
       {"iga-biharmonic", "iga-poisson", "iga-elasticity", "iga-shell"},
       "--vtu out.vtu --vtu-samples 8"},
      {K::kNoEffect, "--vtu-degree", "--vtu-format", {"linear"},
       "it is the degree of the Bézier cells of --vtu-format bezier", {"iga-biharmonic", "iga-poisson", "iga-elasticity", "iga-shell"},
       "--vtu out.vtu --vtu-format linear --vtu-degree 4"},
      {K::kNoEffect, "--gmres-tolerance", "--solver", {"lu"}, "LU solves directly", {"iga-bem"},
       "--solver lu --gmres-tolerance 1e-10"},
      {K::kRequires, "--max-seconds", "--grid", {}, "", {"iga-bem"}, "--max-seconds 10"},
      {K::kRequiresOneOf, "--max-seconds", "", {"--adaptive", "--study"}, "", {"iga-poisson"}, "--max-seconds 10"},
  };
  return rules;
}

namespace detail {
/// The option's value as given (the last one), else its default text.
inline std::string option_value(const CLI::Option& o) { return o.count() > 0 ? o.results().back() : o.get_default_str(); }
}  // namespace detail

/// The message of the first rule of `program` the command line breaks (empty: none); a rule whose options the
/// app does not have is skipped.
inline std::string broken_option_rule(const CLI::App& app, const std::string& program) {
  for (const OptionRule& r : option_rules()) {
    if (std::find(r.programs.begin(), r.programs.end(), program) == r.programs.end()) continue;
    const CLI::Option* option = app.get_option_no_throw(r.option);
    if (option == nullptr || option->count() == 0) continue;
    if (r.kind == OptionRule::Kind::kRequiresOneOf) {
      const bool any = std::any_of(r.values.begin(), r.values.end(), [&](const std::string& name) {
        const CLI::Option* o = app.get_option_no_throw(name);
        return o != nullptr && o->count() > 0;
      });
      if (!any) {
        std::string names;
        for (std::size_t k = 0; k < r.values.size(); ++k) {
          names += (k == 0 ? "" : k + 1 == r.values.size() ? " or " : ", ") + r.values[k];
        }
        return r.option + " requires " + names;
      }
      continue;
    }
    const CLI::Option* other = app.get_option_no_throw(r.other);
    if (other == nullptr) continue;
    switch (r.kind) {
      case OptionRule::Kind::kRequires:
        if (other->count() == 0) return r.option + " requires " + r.other;
        break;
      case OptionRule::Kind::kExcludes:
        if (other->count() > 0) return r.option + " excludes " + r.other;
        break;
      case OptionRule::Kind::kNoEffect: {
        const std::string v = detail::option_value(*other);
        if (std::find(r.values.begin(), r.values.end(), v) != r.values.end()) {
          return r.option + " has no effect with " + r.other + " " + v + " (" + r.reason + "): leave it out";
        }
        break;
      }
      case OptionRule::Kind::kRequiresOneOf:
        break;
    }
  }
  return std::string();
}

/// After parsing: 2 (a usage error, one line on stderr naming the option) when a rule is broken, else nullopt.
inline std::optional<int> check_option_rules(const CLI::App& app, const std::string& program) {
  const std::string message = broken_option_rule(app, program);
  if (message.empty()) return std::nullopt;
  std::cerr << program << ": error: " << message << std::endl;
  return 2;
}

}  // namespace iga::io
