#pragma once
// JSON text as every program's input files read it: one clear line for every malformed input (nlohmann-json).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace iga::json_text {

/// Parses the JSON text of an input called `name` (a file name, "stdin"). A UTF-8 byte-order mark is skipped. Every
/// refusal is one InputError line: text that is not JSON as "NAME:LINE:COLUMN: reason" (1-based line and column of
/// the offending token, lines ending at LF, CRLF or a lone CR, columns counting characters), e.g. "expected ',' or
/// ']', found '3'", "unexpected end of input", "NaN is not a finite number"; binary data (a control character
/// outside tab, CR, LF) as "binary data (byte 0x00)"; no JSON at all as "NAME: empty input"; a key repeated in
/// one object; a number beyond the range of a double.
nlohmann::json parse(std::string_view text, const std::string& name);

/// The text of a file, or of standard input for "-" (named "stdin" in messages); InputError "PATH: cannot read (is a
/// directory)", "PATH: cannot open", "PATH: read error", or "PATH: input larger than N MiB; not a WHAT" (read in
/// blocks up to the cap: a device such as /dev/zero has no size to check first).
std::string read_input(const std::string& path, std::uintmax_t max_bytes, const std::string& what);

/// A JSON value in a message: its text, at most 30 characters.
std::string shown(const nlohmann::json& j);
/// "an object", "a list", or shown(j).
std::string kind(const nlohmann::json& j);
/// A key as decoded, for a message: line ends and tabs escaped, other control characters '?', cut at 40 characters.
std::string key_text(const std::string& key);
/// A finite number; InputError "WHAT is not a finite number (…)" or "WHAT must be a number, got …".
double number(const nlohmann::json& j, const std::string& what);

}  // namespace iga::json_text
