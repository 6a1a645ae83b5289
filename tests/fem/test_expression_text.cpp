// fem::Expression on hostile text, the findings of tests/fuzz/fuzz_expression.cpp (libFuzzer): every refusal is
// an InputError of one line.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "fem/expression.hpp"

namespace {

std::string error_of(const std::string& text) {
  try {
    const iga::fem::Expression f(text, "--source");
  } catch (const iga::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExpressionText, ControlCharactersAreRefusedInOneLine) {
  // The fuzzer's input "x==\x01x==y && y&..\n.." was quoted whole in muparser's error: a message of two lines.
  EXPECT_EQ(error_of(std::string("x==\x01x==y && y&\xA1|\n\0", 18)),
            "--source: control character (byte 0x01) at position 4 of the expression");
  EXPECT_EQ(error_of("sin(x)\n+1"), "--source: control character (byte 0x0A) at position 7 of the expression");
  EXPECT_EQ(error_of("x\x7F"), "--source: control character (byte 0x7F) at position 2 of the expression");
  EXPECT_EQ(error_of("x +\ty"), "");  // a tab is a blank
}

// muparser counts positions from 0 ("found at position 4." for the fifth character); the message counts from 1, as
// the control-character check does, and ends without muparser's full stop (issue 32).
TEST(ExpressionText, PositionsCountFromOne) {
  EXPECT_EQ(error_of("sin(t)"), "--source: 'sin(t)': Unexpected token \"t\" found at position 5");
  EXPECT_EQ(error_of("x+*y"), "--source: 'x+*y': Unexpected operator \"*\" found at position 3");
}
