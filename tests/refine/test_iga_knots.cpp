// iga-knots end to end: a round trip (file in, --out file, read back, compared with the library's Boehm) and
// one clear line with a non-zero exit code for each kind of invalid input.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>

#include "basis/bspline/spline_curve.hpp"

namespace {

namespace fs = std::filesystem;

struct ProgramRun {
  int code = 0;
  std::string err;
};

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

ProgramRun run_program(const std::string& args, const std::string& stdin_text = "") {
  const fs::path dir = fs::temp_directory_path() / ("iga_knots_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string cmd = std::string(IGA_KNOTS_EXE) + " " + args + " 2> " + (dir / "err").string() + " > " +
                    (dir / "out").string();
  if (!stdin_text.empty()) {
    std::ofstream(dir / "in") << stdin_text;
    cmd += " < " + (dir / "in").string();
  }
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "err")};
}

const char* const curve = R"({"degree": 3, "knots": [0, 0, 0, 0, 1, 2, 2, 4, 4, 4, 4],
  "control_points": [[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [7, 1]]})";

}  // namespace

TEST(IgaKnots, RoundTripMatchesTheLibrary) {
  const fs::path dir = fs::temp_directory_path() / ("iga_knots_rt_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "in.json") << curve;
  iga::basis::bspline::SplineCurve c;
  c.degree = 3;
  c.knots = {0, 0, 0, 0, 1, 2, 2, 4, 4, 4, 4};
  c.control_points.resize(7, 2);
  c.control_points << 0, 0, 1, 2, 2, 3, 4, 3, 5, 1, 6, 0, 7, 1;
  // Intervals 0 and 2.
  const iga::basis::bspline::SplineCurve ref = iga::basis::bspline::insert_knots_boehm(c, {0.5, 3.0});
  for (const char* algorithm : {"boehm", "oslo", "refine-smooth"}) {
    const ProgramRun r = run_program((dir / "in.json").string() + " --intervals 0,2 --algorithm " + algorithm + " --out " +
                      (dir / "out.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(dir / "out.json"));
    EXPECT_EQ(j["degree"].get<int>(), 3);
    EXPECT_EQ(j["knots"].get<std::vector<double>>(), ref.knots);
    ASSERT_EQ(j["control_points"].size(), static_cast<std::size_t>(ref.control_points.rows()));
    for (std::size_t i = 0; i < j["control_points"].size(); ++i)
      for (std::size_t k = 0; k < 2; ++k)
        EXPECT_NEAR(j["control_points"][i][k].get<double>(),
                    ref.control_points(static_cast<long>(i), static_cast<long>(k)), 1e-12);
  }
  // stdin, default (all intervals), refined twice through the program equals inserting every midpoint.
  const ProgramRun r = run_program("- --insert 0.5,1.5", curve);
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST(IgaKnots, InvalidInputGivesOneLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"degree": 2, "knots": [0,0,0,1,0.5,2,2], "control_points": [[0],[1],[2],[3]]})", "decrease"},
      {R"({"degree": 2, "knots": [0,0,0,1,2,2,2], "control_points": [[0],[1],[2]]})", "number of control points"},
      {R"({"degree": 1, "knots": [0,0,1,1,1,2,2], "control_points": [[0],[1],[2],[3],[4]]})", "multiplicity"},
      {R"({"degree": 2, "knots": [0,0,0,1,2,2,2], "control_points": [[0],[NaN],[2],[3]]})", "NaN"},
      {R"({"degree": 2, "knots": [0,0,0,"nan",2,2,2], "control_points": [[0],[1],[2],[3]]})", "finite"},
  };
  for (const auto& [text, word] : cases) {
    const ProgramRun r = run_program("-", text);
    EXPECT_NE(r.code, 0) << text;
    EXPECT_NE(r.err.find(word), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const ProgramRun r = run_program("- --insert 9", curve);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("outside the domain"), std::string::npos) << r.err;
}

TEST(IgaKnots, FailedWritesAreErrors) {
  // Issue 14, class 6: a write that fails (a full device) is one line naming the file, exit 1, not exit 0.
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const ProgramRun r = run_program("- --out /dev/full", curve);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("/dev/full:0: cannot write file"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(IgaKnots, InputThatIsNotAFile) {
  // Issue 14: a directory read as an empty string ("not valid JSON ([json.exception.parse_error.101] ...").
  const std::string dir = fs::temp_directory_path().string();
  const ProgramRun r = run_program(dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "iga-knots: error: " + dir + ": cannot read (is a directory)\n");
  const ProgramRun empty = run_program("-", " \n");
  EXPECT_EQ(empty.code, 1);
  EXPECT_EQ(empty.err, "iga-knots: error: stdin: empty input\n");
}
