// --config / --export-config (io/config_file.hpp, io/program.hpp; issue 38): a value written by --export-config
// reads back as it was, whatever characters a path holds (#, =, quotes, spaces, a backslash, a leading [, line
// breaks), for a CLI11 app built as the programs build theirs and end to end through iga-knots and iga-poisson;
// a config line that is not one of the program's options is an error naming the file and line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/program.hpp"
#include "support/paths.hpp"
#include "support/program_run.hpp"

namespace {

namespace fs = std::filesystem;

// File names with every character a config file gives a meaning to; each is a valid Linux file name.
const std::vector<std::string> kHostile = {
    "[k] #1=2 \"q\" 'r' \\s;t.json",  // a leading [ (a section, or a list), a comment, '=', both quotes, '\'
    "[[x]]",                            // a TOML table array
    "a  b,c.json",                      // spaces (CLI11 splits a bare value there) and a comma (a list separator)
    " lead and trail ",                 // blanks the reader trims
    "tab\tline\nbreak\rcr.json",        // control characters
    "\\\\server\\share\\u0041.json",    // backslashes, one before 'u' (an escape in a basic string)
    "'single'",                         // a literal string's quotes
    "\"double\"",                       // a basic string's quotes
    "# not a comment",
    "; not a comment",
    "=",
    "true",                             // a word the writer leaves bare: the same text back
    "1e-3",
    "\xc3\xbc\xe2\x82\xac.json",        // UTF-8
};

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// An argument as the shell reads it back: in single quotes, a quote as '\''.
std::string sq(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The options of a small program, built the way the programs build theirs.
struct Toy {
  CLI::App app{"toy"};
  iga::io::CommonOptions common{"toy"};
  std::string out, source = "1";
  int refine = 4;
  std::vector<double> insert;
  bool flag = false;
  Toy() {
    app.add_option("--out", out, "output");
    app.add_option("--source", source, "text")->capture_default_str();
    app.add_option("--refine", refine, "level")->capture_default_str();
    app.add_option("--insert", insert, "list")->delimiter(',');
    app.add_flag("--flag", flag, "a flag");
    iga::io::add_common_options(app, common);
  }
  std::optional<int> parse(std::vector<std::string> args) {
    args.insert(args.begin(), "toy");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    return iga::io::parse_command_line(app, static_cast<int>(argv.size()), argv.data(), common);
  }
};

}  // namespace

TEST(ConfigFile, EveryValueReadsBackAsWritten) {
  std::vector<std::string> values = kHostile;
  std::string every_byte;
  for (int c = 1; c < 256; ++c) every_byte += static_cast<char>(c);
  values.push_back(every_byte);
  values.push_back("");
  for (const std::string& v : values) {
    std::string error;
    const auto lines = iga::io::parse_config_text("name = " + iga::io::detail::config_value_text(v) + "  # note\n", error);
    ASSERT_EQ(error, "") << v;
    ASSERT_EQ(lines.size(), 1u) << v;
    EXPECT_EQ(lines[0].values, std::vector<std::string>{v}) << v;
  }
  std::string error;
  const auto list = iga::io::parse_config_text("name = " + iga::io::detail::config_values_text(kHostile), error);
  ASSERT_EQ(error, "");
  EXPECT_EQ(list.at(0).values, kHostile);
}

TEST(ConfigFile, ExportThenConfigRoundTripsInAnApp) {
  const fs::path dir = fresh_dir("iga_config_app");
  for (const std::string& name : kHostile) {
    const std::string cfg = (dir / "run.toml").string();
    Toy first;
    ASSERT_EQ(first.parse({"--out", name, "--source", name, "--refine", "1", "--insert", "0.25,0.5", "--flag",
                           "--export-config", cfg}),
              std::nullopt);
    Toy second;
    ASSERT_EQ(second.parse({"--config", cfg}), std::nullopt) << slurp(cfg);
    EXPECT_EQ(second.out, name) << slurp(cfg);
    EXPECT_EQ(second.source, name);
    EXPECT_EQ(second.refine, 1);
    EXPECT_EQ(second.insert, (std::vector<double>{0.25, 0.5}));
    EXPECT_TRUE(second.flag);
  }
}

TEST(ConfigFile, UnknownNamesAndSectionsNameTheFileAndLine) {
  const fs::path dir = fresh_dir("iga_config_errors");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"# meant refine\nrefin = 1\n", ":2: unknown option 'refin' (did you mean 'refine'?)"},
      {"out = \"x\"\n\n[section]\nrefine = 1\n",
       ":3: a section '[section]': the options have no sections (write name = value lines only)"},
      {"totally_else = 1\n", ":1: unknown option 'totally_else' (the options are those of --help, without dashes)"},
      {"refine = 1\nrefine = 2\n", ":2: 'refine' is set again (first on line 1)"},
      {"config = \"other.toml\"\n", ":1: 'config' cannot be set in a config file (give it on the command line)"},
      {"out = \"a\\qb\"\n", ":1: unknown escape '\\q' in a \"quoted\" value (write \\\\ for a backslash, or use "
                            "'single quotes')"},
      {"out = 'open\n", ":1: the quote ' is not closed on this line"},
      {"insert = [0.25, 0.5\n", ":1: the list is not closed with ']' on this line"},
      {"source = a b\n", ":1: 'source' takes one value, got 2 (text with spaces or commas goes in quotes: \"...\")"},
      {"refine 1\n", ":1: expected 'name = value', got 'refine 1'"},
  };
  for (const auto& [text, message] : cases) {
    const fs::path cfg = dir / "c.toml";
    std::ofstream(cfg) << text;
    Toy toy;
    EXPECT_EQ(iga::io::check_config_file(toy.app, cfg.string()), cfg.string() + message) << text;
    testing::internal::CaptureStderr();
    EXPECT_EQ(toy.parse({"--config", cfg.string()}), 1) << text;
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "toy: error: " + cfg.string() + message + "\n");
  }
  // What CLI11 also accepts reads as before: a flag's bare name, dashes, INI comments, CRLF, a byte-order mark.
  const fs::path cfg = dir / "ok.toml";
  std::ofstream(cfg) << "\xEF\xBB\xBF; INI comment\r\nflag\r\n--refine = 2\r\ninsert = 0.25, 0.75\r\nout = 'C:\\x'\r\n";
  Toy toy;
  ASSERT_EQ(toy.parse({"--config", cfg.string()}), std::nullopt);
  EXPECT_TRUE(toy.flag);
  EXPECT_EQ(toy.refine, 2);
  EXPECT_EQ(toy.insert, (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(toy.out, "C:\\x");
}

// iga-knots: the input curve and the output under every hostile name; --export-config, the output removed,
// then --config alone writes the same curve to the same name.
TEST(ConfigFile, IgaKnotsRoundTripsHostileNames) {
  const fs::path dir = fresh_dir("iga_config_knots");
  for (const std::string& name : kHostile) {
    const std::string in = "in " + name, out = "out " + name;
    std::ofstream(dir / in) << R"({"degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "control_points": [[0], [1], [2], [3]]})";
    auto r = iga::test::run_program(dir, IGA_KNOTS_EXE,
                                    sq(in) + " --insert 0.5,1.5 --out " + sq(out) + " --export-config run.toml");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string first = slurp(dir / out);
    ASSERT_FALSE(first.empty());
    fs::remove(dir / out);
    r = iga::test::run_program(dir, IGA_KNOTS_EXE, "--config run.toml");
    EXPECT_EQ(r.code, 0) << r.err << slurp(dir / "run.toml");
    EXPECT_EQ(slurp(dir / out), first) << name << "\n" << slurp(dir / "run.toml");
    fs::remove(dir / out);
    fs::remove(dir / in);
  }
}

// iga-poisson: --json and --vtu under hostile names; the report read back from the config run records the same
// settings.
TEST(ConfigFile, IgaPoissonRoundTripsHostileNames) {
  const fs::path dir = fresh_dir("iga_config_poisson");
  const std::string json = "[k] #1=2 \"q\" 'r' \\s;t.json", vtu = "a  b,c\tline\nbreak = 'x'.vtu";
  auto r = iga::test::run_program(dir, IGA_POISSON_EXE,
                                  "--degree 2 --refine 1 --source " + sq("2*(x + y)") + " --json " + sq(json) +
                                      " --vtu " + sq(vtu) + " --quiet --export-config run.toml");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto first = nlohmann::json::parse(slurp(dir / json));
  ASSERT_TRUE(fs::exists(dir / vtu));
  fs::remove(dir / json);
  fs::remove(dir / vtu);
  r = iga::test::run_program(dir, IGA_POISSON_EXE, "--config run.toml");
  ASSERT_EQ(r.code, 0) << r.err << slurp(dir / "run.toml");
  ASSERT_TRUE(fs::exists(dir / json)) << slurp(dir / "run.toml");
  EXPECT_TRUE(fs::exists(dir / vtu));
  const auto second = nlohmann::json::parse(slurp(dir / json));
  EXPECT_EQ(second["settings"], first["settings"]);
  EXPECT_EQ(second["settings"]["json"], json);
  EXPECT_EQ(second["settings"]["source"], "2*(x + y)");
}
