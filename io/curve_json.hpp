#pragma once
// B-spline curves as JSON, the format iga-knots reads and writes:
//   {"degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]}
// (standard convention: as many control points as knots - degree - 1, each a list of 1 or more coordinates).
#include <string>

#include "basis/bspline/spline_curve.hpp"

namespace iga::io {

/// Parses a curve from JSON text; `name` is the file named in messages ("stdin" for standard input).
/// Every refusal is an InputError of one line:
/// - text that is not JSON: "NAME:LINE:COLUMN: reason" (1-based line and column of the offending token,
///   lines ending at LF, CRLF or a lone CR, columns counting characters), e.g. "expected ',' or ']', found
///   '3'", "unexpected end of input", "NaN is not a finite number"; binary data (a control character
///   outside tab, CR, LF) as "binary data (byte 0x00)"; an input without JSON as "NAME: empty input";
/// - JSON that is not a curve: "NAME: reason" naming the key, with 0-based list positions as in the JSON
///   (knots[3], control_points[2][1]); degree must be an integer >= 1 (2.0 is read as 2; 2.5, "2", true and
///   integers too large for the knots given are refused), every number finite, unknown or repeated keys are
///   refused, and finally basis::bspline::validate() (its "knot i" is the same 0-based position).
/// A UTF-8 byte-order mark is skipped. Memory is proportional to the text: control points are allocated only
/// after every one has been checked to have as many coordinates as the first.
basis::bspline::SplineCurve parse_curve_json(const std::string& text, const std::string& name);

/// Reads a curve from the file `path`, or standard input for "-" (named "stdin"). InputError
/// "PATH: cannot read (is a directory)", "PATH: cannot open", "PATH: read error", and what parse_curve_json
/// throws.
basis::bspline::SplineCurve read_curve_json(const std::string& path);

}  // namespace iga::io
