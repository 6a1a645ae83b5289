#include "core/json_text.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <vector>

#include "core/error.hpp"

namespace iga::json_text {

using nlohmann::json;

namespace {

// "NAME:LINE:COLUMN: " for a 0-based byte offset in text: lines end at LF, CRLF or a lone CR; the column counts
// characters (UTF-8 continuation bytes are not counted), both 1-based.
std::string position(std::string_view text, std::size_t offset, const std::string& name) {
  long line = 1, column = 1;
  offset = std::min(offset, text.size());
  for (std::size_t k = 0; k < offset; ++k) {
    const char c = text[k];
    if (c == '\n' || (c == '\r' && (k + 1 >= text.size() || text[k + 1] != '\n'))) {
      ++line;
      column = 1;
    } else if (c != '\r' && (static_cast<unsigned char>(c) & 0xC0U) != 0x80U) {
      ++column;
    }
  }
  return name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

// JSON is text: a control character other than tab, CR and LF is binary data (outside strings nlohmann would call
// it an invalid literal, inside one an unescaped control character).
void check_text(std::string_view text, const std::string& name) {
  for (std::size_t k = 0; k < text.size(); ++k) {
    const auto byte = static_cast<unsigned char>(text[k]);
    if (byte < 0x20U && byte != '\t' && byte != '\n' && byte != '\r') {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", byte);
      throw InputError(position(text, k, name) + "binary data (byte " + hex + "); JSON is text");
    }
  }
}

bool word_char(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '+' || c == '-' ||
         c == '.';
}

// The start of the token that ends at `end` (nlohmann reports the last character it read): a word (number or
// literal), a quoted string, or one character.
std::size_t token_start(std::string_view text, std::size_t end) {
  if (end >= text.size()) return text.size();
  std::size_t start = end;
  if (word_char(text[end])) {
    while (start > 0 && word_char(text[start - 1])) --start;
  } else if (text[end] == '"' && end > 0) {
    start = end - 1;
    while (start > 0 && (text[start] != '"' || text[start - 1] == '\\')) --start;
  }
  return start;
}

// The token at `start`, quoted for a message (at most 20 characters).
std::string token_text(std::string_view text, std::size_t start) {
  if (start >= text.size()) return "end of input";
  std::size_t end = start + 1;
  if (word_char(text[start])) {
    while (end < text.size() && word_char(text[end])) ++end;
  } else if (text[start] == '"') {
    while (end < text.size() && text[end] != '"' && text[end] != '\n' && text[end] != '\r') end += text[end] == '\\' ? 2 : 1;
    end = std::min(end + 1, text.size());
  }
  std::string token;
  for (const char c : text.substr(start, std::min<std::size_t>(end - start, 20))) {
    if (static_cast<unsigned char>(c) < 0x20U) {  // a line end or tab: shown escaped, the message stays one line
      token += c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t" : "?";
    } else {
      token += c;
    }
  }
  if (end - start > 20) token += "...";
  return "'" + token + "'";
}

// What nlohmann expected, from the part of its message that names the construct ("while parsing array").
std::string expectation(const std::string& what) {
  if (what.find("while parsing array") != std::string::npos) return "expected ',' or ']'";
  if (what.find("while parsing object separator") != std::string::npos) return "expected ':' after the key";
  if (what.find("while parsing object key") != std::string::npos) return "expected a quoted key";
  if (what.find("while parsing object") != std::string::npos) return "expected ',' or '}'";
  return "expected a value";
}

bool is_nan_or_infinity(std::string_view word) {
  if (word.starts_with('-') || word.starts_with('+')) word.remove_prefix(1);
  for (const char* w : {"NaN", "nan", "NAN", "Infinity", "infinity", "inf", "Inf", "INF"}) {
    if (word == w) return true;
  }
  return false;
}

// One line in plain words for a JSON syntax error, at the start of the offending token.
[[noreturn]] void fail_syntax(const json::parse_error& e, std::string_view text, const std::string& name) {
  const std::string what = e.what();
  const std::size_t dash = what.find(" - ");
  const std::string detail = dash == std::string::npos ? what : what.substr(dash + 3);
  std::size_t end = e.byte == 0 ? 0 : static_cast<std::size_t>(e.byte - 1);
  const bool bad_word = detail.starts_with("invalid literal") || detail.starts_with("invalid number");
  // For "tru}" nlohmann has read one past the word; "~" fails on its first character.
  if (bad_word && end < text.size() && end > 0 && !word_char(text[end]) && word_char(text[end - 1])) --end;
  const std::size_t start = detail.starts_with("invalid string") ? std::min(end, text.size()) : token_start(text, end);
  const std::string where = position(text, start, name);
  const std::string found = token_text(text, start);
  std::string reason;
  if (detail.starts_with("unexpected end of input") || start >= text.size()) {
    reason = "unexpected end of input; " + expectation(what);
  } else if (detail.find("expected end of input") != std::string::npos) {
    reason = "unexpected text after the JSON value: " + found;
  } else if (detail.starts_with("unexpected")) {
    reason = expectation(what) + ", found " + found;
  } else if (bad_word && is_nan_or_infinity(found.substr(1, found.size() - 2))) {
    reason = found.substr(1, found.size() - 2) + " is not a finite number (JSON has no NaN or Infinity)";
  } else if (bad_word) {
    reason = std::string(detail.starts_with("invalid number") ? "invalid number " : "invalid literal ") + found;
  } else if (detail.find("control character") != std::string::npos) {
    reason = "line break or tab inside a quoted string (write \\n or \\t)";
  } else if (detail.find("UTF-8") != std::string::npos) {
    reason = "invalid UTF-8 inside a quoted string";
  } else if (detail.find("missing closing quote") != std::string::npos) {
    reason = "a quoted string is not closed";
  } else if (detail.starts_with("invalid string")) {
    reason = "invalid escape sequence in a quoted string";
  } else {
    reason = "invalid JSON";
  }
  throw InputError(where + reason);
}

// nlohmann's number overflow ("number overflow parsing '1e999'") at the number's first occurrence.
[[noreturn]] void fail_overflow(const json::out_of_range& e, std::string_view text, const std::string& name) {
  const std::string what = e.what();
  const std::size_t quote = what.find('\'');
  const std::string number = quote == std::string::npos ? "" : what.substr(quote + 1, what.rfind('\'') - quote - 1);
  const std::size_t at = number.empty() ? std::string_view::npos : text.find(number);
  if (at == std::string_view::npos) throw InputError(name + ": a number is out of range");
  throw InputError(position(text, at, name) + "number " + number + " is out of range");
}


}  // namespace

json parse(std::string_view text, const std::string& name) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) throw InputError(name + ": empty input");
  check_text(text, name);
  // Repeated keys: nlohmann keeps the last one silently; they are refused here, per object.
  std::vector<std::set<std::string>> keys;
  const json::parser_callback_t check_keys = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.empty() && !keys.back().insert(parsed.get<std::string>()).second) {
      throw InputError(name + ": key '" + key_text(parsed.get<std::string>()) + "' appears more than once");
    }
    return true;
  };
  try {
    return json::parse(text, check_keys, true, false);
  } catch (const json::parse_error& e) {
    fail_syntax(e, text, name);
  } catch (const json::out_of_range& e) {
    fail_overflow(e, text, name);
  } catch (const json::exception&) {
    throw InputError(name + ": invalid JSON");
  }
}

// A JSON value in a message: its text, at most 30 characters.
std::string shown(const json& j) {
  std::string s = j.dump(-1, ' ', false, json::error_handler_t::replace);
  if (s.size() > 30) s = s.substr(0, 27) + "...";
  return s;
}

std::string kind(const json& j) {
  if (j.is_object()) return "an object";
  if (j.is_array()) return "a list";
  return shown(j);
}

std::string key_text(const std::string& key) {
  std::string out;
  for (const char c : key.substr(0, 40)) {
    out += c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t" : static_cast<unsigned char>(c) < 0x20U ? "?" : std::string(1, c);
  }
  if (key.size() > 40) out += "...";
  return out;
}

double number(const json& j, const std::string& what) {
  if (j.is_number()) {
    return j.is_number_unsigned() ? static_cast<double>(j.get<std::uint64_t>()) : j.get<double>();
  }
  if (j.is_string() && is_nan_or_infinity(j.get<std::string>())) {
    throw InputError(what + " is not a finite number (" + shown(j) + ")");
  }
  if (j.is_null()) throw InputError(what + " is not a finite number (null)");
  throw InputError(what + " must be a number, got " + kind(j));
}

std::string read_input(const std::string& path, std::uintmax_t max_bytes, const std::string& what) {
  const std::string name = path == "-" ? "stdin" : path;
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot read (is a directory)");
  std::ifstream file;
  if (path != "-") {
    file.open(path, std::ios::binary);
    if (!file.is_open()) throw InputError(path + ": cannot open");
  }
  std::istream& in = path == "-" ? std::cin : file;
  std::string text;
  std::vector<char> block(1 << 16);
  while (in && text.size() <= max_bytes) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    text.append(block.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(name + ": read error");
  if (text.size() > max_bytes) {
    throw InputError(name + ": input larger than " + std::to_string(max_bytes >> 20) + " MiB; not a " + what);
  }
  return text;
}

}  // namespace iga::json_text
