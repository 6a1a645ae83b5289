#pragma once
// What every iga-* program shares at its edges (CONVENTIONS.md, "Programs"): the command line is parsed so
// that a usage error is one line "PROGRAM: error: ..." and exit code 2; the run is wrapped so that every
// exception (a typed iga::Error, std::bad_alloc, anything else) is one line "PROGRAM: error: ..." and exit
// code 1; validators check options at parse time in the option's own words; every program has --version,
// --quiet, --config FILE and --export-config FILE (add_common_options) and records what ran in its report
// (run_info). Header-only: programs link CLI11 themselves.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <cstdlib>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/config_file.hpp"
#include "io/report.hpp"
#include "io/run_program.hpp"
#include "io/version.hpp"

namespace iga::io {

namespace detail {
/// Set when an input file named on the command line is missing or not a file: parse_command_line then exits 1 (bad
/// input), not 2 (a usage error).
inline bool& input_file_missing() {
  static bool missing = false;
  return missing;
}
/// What is wrong with an input file's path ("no such file: X", "a folder, not a file: X"), or "" ("-" is stdin).
inline std::string input_file_problem(const std::string& path) {
  if (path == "-") return std::string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) return "a folder, not a file: " + path;
  if (!std::filesystem::exists(status)) return "no such file: " + path;
  return std::string();
}
}  // namespace detail

/// The options every iga-* program has (README, "Conventions of every program").
struct CommonOptions {
  explicit CommonOptions(std::string name) : program(std::move(name)) {}
  std::string program;        ///< "iga-poisson", ...
  bool quiet = false;         ///< --quiet: nothing on stderr but errors
  std::string export_config;  ///< --export-config FILE ("-": standard output)
};

/// "iga-poisson 0.1.0 (git 0123456789ab)": what --version prints and the report records.
inline std::string version_line(const std::string& program) {
  return program + " " + version() + " (git " + git_revision() + ")";
}

/// Adds --version, --quiet, --config FILE (`name = value`, option names without dashes, io/config_file.hpp; command-
/// line options override the file) and --export-config FILE. A config file's unknown name or [section] is an error
/// naming the file and line (parse_command_line), and the values written by --export-config are quoted so that any
/// path reads back as it was (ProgramConfig).
inline void add_common_options(CLI::App& app, CommonOptions& common) {
  app.config_formatter(std::make_shared<ProgramConfig>());
  app.allow_config_extras(CLI::config_extras_mode::error);  // check_config_file has said which line already
  app.set_version_flag("--version", version_line(common.program), "print the program's version and git revision");
  app.set_config("--config", "", "read options from a TOML/INI file (name = value, names without dashes; a name that "
                                 "is not an option is an error); options given on the command line override it");
  app.add_option("--export-config", common.export_config,
                 "write this run's options as a --config file ('-': standard output) and go on; options left at their "
                 "defaults are listed as comments")
      ->configurable(false)
      ->check(CLI::Validator(
          [](std::string& t) { return t.find_first_not_of(" \t") == std::string::npos ? "empty value" : ""; }, "FILE"));
  app.add_flag("--quiet", common.quiet, "nothing on stderr but errors (no progress, notes or summary)");
}

namespace detail {
// An option's long name, or "" for options without one (positionals) and the ones that only steer the run
// (help, version, config, export-config).
inline std::string setting_name(const CLI::Option* opt) {
  if (opt->get_lnames().empty()) return std::string();
  const std::string& name = opt->get_lnames().front();
  for (const char* skip : {"help", "help-all", "version", "config", "export-config"}) {
    if (name == skip) return std::string();
  }
  return name;
}
}  // namespace detail

/// The effective configuration as a --config file (TOML): the options that were set (on the command line or in
/// a --config file) as ProgramConfig writes them (text quoted and escaped), then the others with their defaults as
/// comments.
inline std::string export_config_text(const CLI::App& app, const std::string& program) {
  std::string text = "# " + version_line(program) + ": options of one run (read back with --config FILE)\n";
  text += app.config_to_str(false, false);
  std::string defaults;
  for (const CLI::Option* opt : app.get_options()) {
    const std::string name = detail::setting_name(opt);
    if (name.empty() || opt->count() > 0) continue;
    const std::string d = opt->get_expected_min() == 0 ? "false" : opt->get_default_str();
    defaults += "# " + name + " = " +
                (d.empty() ? std::string("(not set: the program's default)") : detail::config_value_text(d)) + "\n";
  }
  if (!defaults.empty()) text += "# left at their defaults:\n" + defaults;
  return text;
}

/// What ran, for the report: program, version, git_revision, schema_version and `settings`, every option by its
/// long name with its effective value (as given; the default when not given; null when neither; flags true/false).
inline nlohmann::json run_info(const CLI::App& app, const std::string& program) {
  nlohmann::json settings = nlohmann::json::object();
  for (const CLI::Option* opt : app.get_options()) {
    const std::string name = detail::setting_name(opt);
    if (name.empty()) continue;
    if (opt->get_expected_min() == 0) {
      settings[name] = opt->count() > 0;
    } else if (opt->count() > 0) {
      const std::vector<std::string>& r = opt->results();
      settings[name] = r.size() == 1 ? nlohmann::json(r.front()) : nlohmann::json(r);
    } else {
      const std::string d = opt->get_default_str();
      settings[name] = d.empty() ? nlohmann::json(nullptr) : nlohmann::json(d);
    }
  }
  return {{"program", program}, {"version", version()}, {"git_revision", git_revision()},
          {"schema_version", kReportSchemaVersion}, {"settings", settings}};
}

namespace detail {
/// CLI11's own phrases in the programs' words: "--mesh: 1 required TEXT:FILE missing" (a value is missing), "--json:
/// At Most 1 required but received 3" (an option given more than once), "Could not convert: --x = v".
inline std::string plain_cli_message(const std::string& what) {
  static const std::regex missing(R"(^(\S+): [0-9]+ required \S+ missing$)");
  static const std::regex at_most(R"(^(\S+): At Most ([0-9]+) required but received ([0-9]+)$)");
  static const std::regex convert(R"(^Could not convert: (\S+) = (.*)$)");
  std::smatch m;
  if (std::regex_match(what, m, missing)) return m[1].str() + ": its value is missing";
  if (std::regex_match(what, m, at_most)) {
    return m[1].str() + " takes " + (m[2].str() == "1" ? std::string("one value") : m[2].str() + " values") +
           ", got " + m[3].str() + " (is it given more than once?)";
  }
  if (std::regex_match(what, m, convert)) return m[1].str() + ": cannot read '" + m[2].str() + "' as its value";
  return what;
}

/// This process's rank as the MPI launcher set it (Open MPI, PMIx, MPICH's PMI), 0 outside a launcher.
inline int launcher_rank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    if (const char* value = std::getenv(name)) return std::atoi(value);
  }
  return 0;
}
}  // namespace detail

/// Parses argv. Returns an exit code when the program must stop now: 0 after --help or --version, 2 (one line on
/// stderr) on a usage error (CLI11's own codes mapped), 1 (one line) for an input file or --config file that is not
/// there or is a folder, 1 for a --config file with a line that is not one of the program's options
/// ("FILE:LINE: unknown option 'refin' (did you mean 'refine'?)", a [section], a value that does not parse), 1 when
/// --export-config cannot be written; std::nullopt when the run goes on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const CommonOptions& common) {
  const std::string& program = common.program;
  // Under mpirun every rank reads the same arguments: rank 0 alone speaks (a parallel session mutes the others
  // again), so a usage error is one line, not one per rank interleaved.
  if (detail::launcher_rank() > 0) {
    std::cerr.setstate(std::ios::failbit);
    std::cout.setstate(std::ios::failbit);
  }
  // --config FILE: a file that is not there is bad input, said in the words of input_file().
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    std::string file;
    if (arg == "--config" && i + 1 < argc) file = argv[i + 1];
    if (arg.rfind("--config=", 0) == 0) file = arg.substr(9);
    const std::string problem = file.empty() ? std::string() : detail::input_file_problem(file);
    if (!problem.empty()) {
      std::cerr << program << ": error: --config: " << problem << std::endl;
      return 1;
    }
    // Every line of it is one of this program's options, said before CLI11 reads it (which would skip the others).
    const std::string wrong = file.empty() || file == "-" ? std::string() : check_config_file(app, file);
    if (!wrong.empty()) {
      std::cerr << program << ": error: " << wrong << std::endl;
      return 1;
    }
  }
  try {
    app.parse(argc, argv);
    if (!common.export_config.empty() && common.export_config != "none") {
      write_text(common.export_config, export_config_text(app, program));
    }
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << std::endl;
    return 0;
  } catch (const iga::Error& e) {
    std::cerr << program << ": error: --export-config: " << e.what() << std::endl;
    return 1;
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
    std::cerr << program << ": error: " << detail::plain_cli_message(what) << std::endl;
    // A file that is not there (an input option's, or --config's) is bad input, not a usage error.
    const bool missing_file = detail::input_file_missing() || dynamic_cast<const CLI::FileError*>(&e) != nullptr;
    return missing_file ? 1 : 2;
  }
  return std::nullopt;
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

/// An input file that exists and is a file, or "-" for standard input (the iga-* convention). One that is not there
/// is bad input: exit code 1, like a file that cannot be read.
inline CLI::Validator input_file() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::string what = detail::input_file_problem(text);
        if (!what.empty()) detail::input_file_missing() = true;
        return what;
      },
      "FILE");
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
