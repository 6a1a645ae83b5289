// io::parse_curve_json / read_curve_json: the curve iga-knots reads, and one clear line per kind of bad input
// (issue 14: out-of-range or non-integer degrees, nlohmann's exception ids, a missing comma called NaN,
// directories, empty input, repeated and unknown keys, absurd allocations). Messages are compared exactly.
#include "io/curve_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"

namespace {

using iga::InputError;

// The message parse_curve_json throws for text named "c.json" ("" if it parses).
std::string error_of(const std::string& text) {
  try {
    (void)iga::io::parse_curve_json(text, "c.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A valid curve with `degree`, `knots` and `points` spliced in.
std::string curve(const std::string& degree = "2", const std::string& knots = "[0,0,0,1,2,2,2]",
                  const std::string& points = "[[0],[1],[2],[3]]") {
  return R"({"degree": )" + degree + R"(, "knots": )" + knots + R"(, "control_points": )" + points + "}";
}

}  // namespace

TEST(CurveJson, ReadsTheReadmeCurve) {
  const auto c = iga::io::parse_curve_json(
      "\xEF\xBB\xBF{\"degree\": 2.0,\r\n \"knots\": [0,0,0,1,2,2,2],\r \"control_points\": [[0,0],[1,2],[3,2],[4,0]]}",
      "c.json");
  EXPECT_EQ(c.degree, 2);
  EXPECT_EQ(c.knots.size(), 7U);
  EXPECT_EQ(c.control_points.rows(), 4);
  EXPECT_EQ(c.control_points.cols(), 2);
  EXPECT_EQ(c.control_points(2, 1), 2.0);
}

TEST(CurveJson, DegreeMustBeAnIntegerInRange) {
  // 4294967298 = 2^32 + 2 was read as 2 (nlohmann's get<int> wraps).
  EXPECT_EQ(error_of(curve("4294967298")), "c.json: degree 4294967298 needs at least degree + 2 knots, 7 given");
  EXPECT_EQ(error_of(curve("-1")), "c.json: degree must be >= 1, got -1");
  EXPECT_EQ(error_of(curve("2.5")), "c.json: degree must be an integer, got 2.5");
  EXPECT_EQ(error_of(curve("\"2\"")), "c.json: degree must be an integer, got \"2\"");
  EXPECT_EQ(error_of(curve("true")), "c.json: degree must be an integer, got true");
  EXPECT_EQ(error_of(curve("6")), "c.json: degree 6 needs at least degree + 2 knots, 7 given");
}

TEST(CurveJson, SyntaxErrorsArePositionsInPlainWords) {
  // Was "not valid JSON ([json.exception.parse_error.101] parse error at line 2, column 19: ...)".
  EXPECT_EQ(error_of("{\"degree\": 2,\n \"knots\": [0,0,0,1 2,2,2]}"), "c.json:2:20: expected ',' or ']', found '2'");
  EXPECT_EQ(error_of("{\"degree\" 2}"), "c.json:1:11: expected ':' after the key, found '2'");
  EXPECT_EQ(error_of("{\"degree\": 2 \"knots\": []}"), "c.json:1:14: expected ',' or '}', found '\"knots\"'");
  EXPECT_EQ(error_of("{\"degree\": 2,}"), "c.json:1:14: expected a quoted key, found '}'");
  EXPECT_EQ(error_of("{\"knots\": [1,]}"), "c.json:1:14: expected a value, found ']'");
  EXPECT_EQ(error_of("{\"knots\": [1,2"), "c.json:1:15: unexpected end of input; expected ',' or ']'");
  EXPECT_EQ(error_of("{\"degree\": tru}"), "c.json:1:12: invalid literal 'tru'");
  EXPECT_EQ(error_of("{} x"), "c.json:1:4: unexpected text after the JSON value: 'x'");
  // Lines end at LF, CRLF or a lone CR, as an editor counts them.
  EXPECT_EQ(error_of("{\r\n\"degree\":\r\r 2 3}"), "c.json:4:4: expected ',' or '}', found '3'");
}

TEST(CurveJson, NaNIsNamedOnlyWhenItIsThere) {
  // A missing comma in a file that mentions NaN elsewhere was reported as "a value is NaN".
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1 2,2,2]", "[[0],[1],[2],[3]], \"note\": \"nan\"")),
            "c.json:1:33: expected ',' or ']', found '2'");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1,2,2,2]", "[[0],[NaN],[2],[3]]")),
            "c.json:1:65: NaN is not a finite number (JSON has no NaN or Infinity)");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1,2,2,-Infinity]")),
            "c.json:1:37: -Infinity is not a finite number (JSON has no NaN or Infinity)");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,\"nan\",2,2,2]")), "c.json: knots[3] is not a finite number (\"nan\")");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1e999,2,2,2]")), "c.json:1:31: number 1e999 is out of range");
}

TEST(CurveJson, FuzzFindingsStayOneLine) {
  // libFuzzer (tests/fuzz/fuzz_curve_json.cpp): an invalid literal starting with '~' after a CR was reported as
  // "invalid literal '<CR>'" (the CR stepped back to, a two-line message); the '~' is the token.
  EXPECT_EQ(error_of("{\"degree\": 2.0,\r~\"control\": 1}"), "c.json:2:1: invalid literal '~'");
  EXPECT_EQ(error_of("{\"degree\": 2,\n\t}"), "c.json:2:2: expected a quoted key, found '}'");
  EXPECT_EQ(error_of("{\"a\": \"x\ty\"}"), "c.json:1:9: line break or tab inside a quoted string (write \\n or \\t)");
  // The 10-minute run: a key written with the escape \n decodes to a line break, which the "unknown key" message
  // quoted as it was (two lines). Escaped and cut at 40 characters now.
  EXPECT_EQ(error_of("{\"degree7]1]g\\no 04\": 3}"), "c.json: unknown key 'degree7]1]g\\no 04' (a curve has degree, knots, control_points)");
  EXPECT_EQ(error_of("{\"" + std::string(100, 'k') + "\": 3}"),
            "c.json: unknown key '" + std::string(40, 'k') + "...' (a curve has degree, knots, control_points)");
}

TEST(CurveJson, EmptyBinaryAndNotACurve) {
  EXPECT_EQ(error_of(""), "c.json: empty input");
  EXPECT_EQ(error_of(" \r\n\t"), "c.json: empty input");
  EXPECT_EQ(error_of(std::string("{\"degree\":\n 2\0}", 15)), "c.json:2:3: binary data (byte 0x00); JSON is text");
  EXPECT_EQ(error_of("[1, 2]"), "c.json: expected a JSON object {\"degree\", \"knots\", \"control_points\"}, got a list");
  EXPECT_EQ(error_of("{\"degree\": 2, \"knots\": []}"), "c.json: missing key 'control_points'");
}

TEST(CurveJson, RepeatedAndUnknownKeysAreRefused) {
  // nlohmann kept the last of two "degree" keys, and a "weights" key (a rational curve) was silently ignored.
  EXPECT_EQ(error_of("{\"degree\": 2, \"degree\": 3}"), "c.json: key 'degree' appears more than once");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1,2,2,2]", "[[0],[1],[2],[3]], \"weights\": [1,1,1,1]")),
            "c.json: unknown key 'weights' (a curve has degree, knots, control_points)");
}

TEST(CurveJson, ControlPointsAreCheckedBeforeAllocation) {
  // A first control point of 10^6 coordinates followed by 10^6 short ones allocated 10^12 doubles before the
  // size check; every row is checked first now.
  std::string wide = "[[";
  for (int k = 0; k < 1000000; ++k) wide += k ? ",0" : "0";
  wide += "]";
  for (int i = 0; i < 1000000; ++i) wide += ",[0]";
  wide += "]";
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1,2,2,2]", wide)),
            "c.json: control_points[1] has 1 coordinate, control_points[0] has 1000000 coordinates");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1,2,2,2]", "[[0],[],[2],[3]]")), "c.json: control_points[1] has no coordinates");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1,2,2,2]", "[[0],[\"a\"],[2],[3]]")),
            "c.json: control_points[1][0] must be a number, got \"a\"");
  EXPECT_EQ(error_of(curve("2", "[0,0,0,1,2,2,2]", "[[0],[1],[2]]")),
            "c.json: wrong number of control points: 3 given, 7 knots and degree 2 need 4");
}

TEST(CurveJson, FilesDirectoriesAndMissingFiles) {
  const std::string dir = testing::TempDir();
  try {
    (void)iga::io::read_curve_json(dir);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir + ": cannot read (is a directory)");
  }
  const std::string missing = dir + "iga_curve_json_missing.json";
  try {
    (void)iga::io::read_curve_json(missing);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open");
  }
  const std::string file = dir + "iga_curve_json_ok.json";
  std::ofstream(file) << curve();
  EXPECT_EQ(iga::io::read_curve_json(file).knots.size(), 7U);
  std::filesystem::remove(file);
}
