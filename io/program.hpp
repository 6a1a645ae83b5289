#pragma once
// What every iga-* program shares at its edges (CONVENTIONS.md, "Programs"): the command line is parsed so
// that a usage error is one line "PROGRAM: error: ..." and exit code 2; the run is wrapped so that every
// exception (a typed iga::Error, std::bad_alloc, anything else) is one line "PROGRAM: error: ..." and exit
// code 1; validators check options at parse time in the option's own words. Header-only: programs link
// CLI11 themselves.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "core/error.hpp"

namespace iga::io {

/// Parses argv. Returns an exit code when the program must stop now: 0 after --help, 2 (one line on stderr)
/// on a usage error; std::nullopt when the run goes on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const std::string& program) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ExtrasError&) {
    // CLI11 lists the extras in reverse; name them in the user's order.
    std::string extras;
    for (const std::string& a : app.remaining()) extras += (extras.empty() ? "" : " ") + a;
    std::cerr << program << ": error: unknown option or argument: " << extras << " (see --help)" << std::endl;
    return 2;
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    for (char& c : what) {
      if (c == '\n') c = ' ';
    }
    std::cerr << program << ": error: " << what << std::endl;
    return 2;
  }
  return std::nullopt;
}

/// Runs body() and turns every exception into one line on stderr and exit code 1.
template <class Body>
int run_program(const std::string& program, Body&& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    std::cerr << program << ": error: out of memory (an allocation failed; a smaller problem, fewer refinements "
                            "or fewer output samples would fit)" << std::endl;
  } catch (const std::exception& e) {
    std::string what = e.what();
    for (char& c : what) {
      if (c == '\n') c = ' ';
    }
    std::cerr << program << ": error: " << what << std::endl;
  } catch (...) {
    std::cerr << program << ": error: unknown failure" << std::endl;
  }
  return 1;
}

namespace detail {
inline std::string shortest(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
}  // namespace detail

/// A finite number in [lo, hi] (either bound may be ±infinity: then only that side is open). The message
/// names the bounds as the user would write them ("a finite number >= 0"), never 309 digits of DBL_MAX.
inline CLI::Validator finite_number(double lo, double hi = INFINITY) {
  std::string expected = "a finite number";
  if (std::isfinite(lo) && std::isfinite(hi)) {
    expected += " in [" + detail::shortest(lo) + ", " + detail::shortest(hi) + "]";
  } else if (std::isfinite(lo)) {
    expected += " >= " + detail::shortest(lo);
  } else if (std::isfinite(hi)) {
    expected += " <= " + detail::shortest(hi);
  }
  return CLI::Validator(
      [lo, hi, expected](std::string& text) -> std::string {
        double v = 0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || text.find_first_not_of(" \t", used) != std::string::npos) {
          return "'" + text + "' is not a number; expected " + expected;
        }
        if (!std::isfinite(v) || v < lo || v > hi) return "'" + text + "' is not " + expected;
        return std::string();
      },
      expected.substr(2));
}

/// A whole number in [lo, hi]: "'three' is not a whole number from 1 to 12" (CLI11's own Range would call
/// "three" out of range, and its conversion error names no range).
inline CLI::Validator whole_number(long long lo, long long hi) {
  const std::string expected = "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, expected](std::string& text) -> std::string {
        long long v = 0;
        std::size_t used = 0;
        try {
          v = std::stoll(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || v < lo || v > hi) return "'" + text + "' is not " + expected;
        return std::string();
      },
      std::to_string(lo) + ".." + std::to_string(hi));
}

/// A thread count from 1 to max(64, 4 × the machine's processors): more threads than that cannot help, and a
/// thousand of them exhaust the OpenMP runtime's stacks before any work is done.
inline CLI::Validator thread_count() {
  const unsigned procs = std::max(1u, std::thread::hardware_concurrency());
  const long most = std::max(64L, 4L * static_cast<long>(procs));
  return CLI::Validator(
      [most, procs](std::string& text) -> std::string {
        long v = 0;
        std::size_t used = 0;
        try {
          v = std::stol(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || v < 1 || v > most) {
          return "'" + text + "' is not a thread count from 1 to " + std::to_string(most) + " (this machine has " +
                 std::to_string(procs) + " processors)";
        }
        return std::string();
      },
      "1.." + std::to_string(most));
}

/// Text that must say something: an empty or blank value is an error, not "use the default".
inline CLI::Validator non_blank() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text.find_first_not_of(" \t\r\n") == std::string::npos) return "empty value";
        return std::string();
      },
      "TEXT");
}

}  // namespace iga::io
