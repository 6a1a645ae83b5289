#pragma once
// The --config / --export-config files of every iga-* program (io/program.hpp): a TOML subset, one `name = value`
// per line, that says what it did. Reading: every line is a blank line, a comment (`#`, `;`), or `name = value`
// (or a flag's bare `name`); a value is a TOML basic string ("..." with the escapes \" \\ \b \t \n \f \r \uXXXX
// \UXXXXXXXX), a literal string ('...', no escapes), a list [a, b] of those, or a bare word (a number, true/false;
// a bare value is split at commas, else at spaces, as CLI11's own reader does). A name that is not one of the
// program's options, a [section], a name given twice, a quote not closed, text after a quoted value: each is an
// error naming the file and line, before anything runs (check_config_file). Writing: every text value is a basic
// string with escapes, so that any path (`#`, `=`, quotes, spaces, `\`, a leading `[`) reads back as it was.
// Header-only, like program.hpp.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/json_text.hpp"

namespace iga::io {

/// One `name = value` line of a config file.
struct ConfigLine {
  std::size_t line = 0;             ///< 1-based
  std::string key;                  ///< as decoded (quotes removed)
  std::vector<std::string> values;  ///< decoded; a flag's bare name gives {"true"}
  bool bare = false;                ///< the value was a bare word, not quoted and not a list
};

namespace detail {

/// One value as a config file writes it: true, false and plain numbers bare, everything else a TOML basic string
/// with `"`, `\` and control characters escaped.
inline std::string config_value_text(const std::string& v) {
  static const std::regex number(R"([-+]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][-+]?[0-9]+)?)");
  if (v == "true" || v == "false" || std::regex_match(v, number)) return v;
  std::string out = "\"";
  for (const char c : v) {
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\t': out += "\\t"; break;
      case '\n': out += "\\n"; break;
      case '\f': out += "\\f"; break;
      case '\r': out += "\\r"; break;
      default:
        if (u < 0x20U || u == 0x7fU) {
          char hex[8];
          std::snprintf(hex, sizeof hex, "\\u%04X", u);
          out += hex;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

/// An option's values as a config file writes them: one value, or a list [a, b].
inline std::string config_values_text(const std::vector<std::string>& values) {
  if (values.size() == 1) return config_value_text(values.front());
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + config_value_text(values[i]);
  return out + "]";
}

/// Appends code point cp as UTF-8.
inline void append_utf8(std::string& out, unsigned long cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

/// One escape of a basic string, s[i] the character after the backslash; returns the error or "" (i advanced past
/// the escape).
inline std::string read_escape(const std::string& s, std::size_t& i, std::string& out) {
  static const std::string simple = "btnfr\"\\";
  static const std::string meaning = "\b\t\n\f\r\"\\";
  const char e = s[i];
  if (const auto k = simple.find(e); k != std::string::npos) {
    out += meaning[k];
    ++i;
    return std::string();
  }
  if (e == 'u' || e == 'U') {
    const std::size_t n = e == 'u' ? 4 : 8;
    const std::string hex = s.substr(i + 1, n);
    if (hex.size() != n || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
      return std::string("\\") + e + " needs " + std::to_string(n) + " hexadecimal digits";
    }
    const unsigned long cp = std::stoul(hex, nullptr, 16);
    if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return "\\" + std::string(1, e) + hex + " is not a character";
    append_utf8(out, cp);
    i += n + 1;
    return std::string();
  }
  return "unknown escape '\\" + json_text::key_text(std::string(1, e)) +
         "' in a \"quoted\" value (write \\\\ for a backslash, or use 'single quotes')";
}

/// A quoted string starting at s[i] (a " or '); returns the error or "" (i past the closing quote).
inline std::string read_quoted(const std::string& s, std::size_t& i, std::string& out) {
  const char q = s[i++];
  while (i < s.size() && s[i] != q) {
    if (q == '"' && s[i] == '\\') {
      ++i;
      if (i >= s.size()) break;
      if (std::string e = read_escape(s, i, out); !e.empty()) return e;
    } else {
      out += s[i++];
    }
  }
  if (i >= s.size()) return std::string("the quote ") + q + " is not closed on this line";
  ++i;
  return std::string();
}

inline void skip_blanks(const std::string& s, std::size_t& i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
}

inline std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return std::string();
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

/// A bare value: up to a `#` comment, split at commas, else at spaces (as CLI11 reads it).
inline std::vector<std::string> split_bare(const std::string& text) {
  std::vector<std::string> parts;
  const bool commas = text.find(',') != std::string::npos;
  std::stringstream in(text);
  for (std::string part; commas ? static_cast<bool>(std::getline(in, part, ',')) : static_cast<bool>(in >> part);) {
    parts.push_back(trimmed(part));
  }
  return parts;
}

/// After a quoted value or a list: blanks, then nothing or a comment.
inline std::string expect_end(const std::string& s, std::size_t i) {
  skip_blanks(s, i);
  if (i < s.size() && s[i] != '#') return "unexpected text after the value: '" + json_text::key_text(s.substr(i)) + "'";
  return std::string();
}

/// A list [a, "b", 'c'] starting at s[i] == '['.
inline std::string read_list(const std::string& s, std::size_t i, ConfigLine& entry) {
  ++i;
  skip_blanks(s, i);
  if (i < s.size() && s[i] == ']') return expect_end(s, i + 1);
  while (i < s.size()) {
    skip_blanks(s, i);
    std::string item;
    if (i < s.size() && (s[i] == '"' || s[i] == '\'')) {
      if (std::string e = read_quoted(s, i, item); !e.empty()) return e;
    } else {
      const std::size_t end = s.find_first_of(",]#", i);
      item = trimmed(s.substr(i, end == std::string::npos ? std::string::npos : end - i));
      i = end == std::string::npos ? s.size() : end;
      if (item.empty()) return "an empty item in the list";
    }
    entry.values.push_back(item);
    skip_blanks(s, i);
    if (i < s.size() && s[i] == ']') return expect_end(s, i + 1);
    if (i >= s.size() || s[i] != ',') break;
    ++i;
  }
  return "the list is not closed with ']' on this line";
}

/// The value after `=`, s[i] its first character.
inline std::string read_value(const std::string& s, std::size_t i, ConfigLine& entry) {
  skip_blanks(s, i);
  if (i >= s.size() || s[i] == '#') return "no value after '=' (an empty text is written \"\")";
  if (s[i] == '[') return read_list(s, i, entry);
  if (s[i] == '"' || s[i] == '\'') {
    std::string v;
    if (std::string e = read_quoted(s, i, v); !e.empty()) return e;
    entry.values.push_back(v);
    return expect_end(s, i);
  }
  entry.bare = true;
  entry.values = split_bare(trimmed(s.substr(i, s.find('#', i) - i)));
  return std::string();
}

/// One line (trimmed, not blank, not a comment); returns the error or "".
inline std::string read_config_line(const std::string& s, ConfigLine& entry) {
  if (s.front() == '[') {
    return "a section '" + json_text::key_text(s) + "': the options have no sections (write name = value lines only)";
  }
  std::size_t i = 0;
  if (s.front() == '"' || s.front() == '\'') {
    if (std::string e = read_quoted(s, i, entry.key); !e.empty()) return e;
    skip_blanks(s, i);
    if (i < s.size() && s[i] != '=' && s[i] != '#') return "expected '=' after the name";
  } else {
    i = std::min(s.find('='), s.find('#'));
    entry.key = trimmed(s.substr(0, i));
    if (entry.key.empty()) return "no name before '='";
    if (entry.key.find_first_of(" \t") != std::string::npos) {
      return "expected 'name = value', got '" + json_text::key_text(s) + "'";
    }
  }
  if (i >= s.size() || s[i] == '#') {  // a flag's bare name
    entry.values = {"true"};
    return std::string();
  }
  return read_value(s, i + 1, entry);
}

}  // namespace detail

/// The lines of a config file's text; an error as "LINE: reason" in `error` (then `lines` holds those before it).
inline std::vector<ConfigLine> parse_config_text(std::string text, std::string& error) {
  std::vector<ConfigLine> lines;
  error.clear();
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a UTF-8 byte-order mark
  std::size_t number = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::string s = text.substr(at, end - at);
    at = end + 1;
    ++number;
    if (!s.empty() && s.back() == '\r') s.pop_back();
    const auto bad = std::find_if(s.begin(), s.end(), [](char c) {
      const auto u = static_cast<unsigned char>(c);
      return (u < 0x20U && c != '\t') || u == 0x7fU;
    });
    std::string e;
    if (bad != s.end()) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(*bad)));
      e = std::string("a control character (byte ") + hex + "); not a text file?";
    }
    s = detail::trimmed(s);
    if (e.empty() && (s.empty() || s.front() == '#' || s.front() == ';')) continue;
    ConfigLine entry;
    entry.line = number;
    if (e.empty()) e = detail::read_config_line(s, entry);
    if (!e.empty()) {
      error = std::to_string(number) + ": " + e;
      return lines;
    }
    lines.push_back(std::move(entry));
  }
  return lines;
}

namespace detail {

inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// "(did you mean 'refine'?)" for the configurable option nearest to `key`, or where the names are.
inline std::string nearest_option_hint(const CLI::App& app, const std::string& key) {
  std::string best;
  std::size_t best_distance = 3;  // at most two edits (a letter missing, '_' for '-', ...)
  for (const CLI::Option* opt : app.get_options()) {
    if (!opt->get_configurable()) continue;
    const std::string name = opt->get_single_name();
    const std::size_t d = edit_distance(key, name);
    if (d < best_distance && d < std::max<std::size_t>(name.size(), 2)) {
      best = name;
      best_distance = d;
    }
  }
  if (!best.empty()) return "(did you mean '" + best + "'?)";
  return "(the options are those of --help, without dashes)";
}

/// The option a config key sets, found as CLI11 finds it (App::_parse_single_config): the long name, a one-letter
/// short name, or a positional's name.
inline const CLI::Option* config_option(const CLI::App& app, const std::string& key) {
  const CLI::Option* opt = app.get_option_no_throw("--" + key);
  if (opt == nullptr && key.size() == 1) opt = app.get_option_no_throw("-" + key);
  if (opt == nullptr) opt = app.get_option_no_throw(key);
  return opt;
}

/// What is wrong with one entry for this app, or "".
inline std::string config_entry_problem(const CLI::App& app, const ConfigLine& entry,
                                        std::map<const CLI::Option*, std::size_t>& seen) {
  const std::string key = json_text::key_text(entry.key);
  const CLI::Option* opt = config_option(app, entry.key);
  if (opt == nullptr) return "unknown option '" + key + "' " + nearest_option_hint(app, entry.key);
  if (!opt->get_configurable()) return "'" + key + "' cannot be set in a config file (give it on the command line)";
  if (const auto it = seen.find(opt); it != seen.end()) {
    return "'" + key + "' is set again (first on line " + std::to_string(it->second) + ")";
  }
  seen[opt] = entry.line;
  if (entry.values.size() > 1 && opt->get_items_expected_max() <= 1) {
    return "'" + key + "' takes one value, got " + std::to_string(entry.values.size()) +
           (entry.bare ? " (text with spaces or commas goes in quotes: \"...\")" : "");
  }
  return std::string();
}

}  // namespace detail

/// Reads the config file at `path` and checks every line against the app's options: "" when it is fine, else the
/// one line "PATH:LINE: reason" (an unknown option with the nearest name, a [section], a name given twice, a
/// value that does not parse), or "PATH: ..." when the file cannot be read or is too large for a config file.
inline std::string check_config_file(const CLI::App& app, const std::string& path) {
  constexpr std::size_t kMaxBytes = std::size_t{1} << 20;
  std::ifstream in(path, std::ios::binary);
  if (!in) return path + ": cannot open";
  std::string text(kMaxBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) return path + ": read error";
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxBytes) return path + ": larger than 1 MiB; not a config file";
  std::string error;
  const std::vector<ConfigLine> lines = parse_config_text(text, error);
  if (!error.empty()) return path + ":" + error;
  std::map<const CLI::Option*, std::size_t> seen;
  for (const ConfigLine& entry : lines) {
    const std::string problem = detail::config_entry_problem(app, entry, seen);
    if (!problem.empty()) return path + ":" + std::to_string(entry.line) + ": " + problem;
  }
  return std::string();
}

/// CLI11's config formatter for the programs: reads with parse_config_text (check_config_file has refused a bad
/// file before CLI11 reads it; should one get here, its error is a CLI::ConfigError) and writes every option set
/// as `name = value` with config_values_text, so that every value reads back as it was.
class ProgramConfig : public CLI::ConfigBase {
 public:
  std::string to_config(const CLI::App* app, bool default_also, bool /*write_description*/,
                        std::string prefix) const override {
    std::string out;
    for (const CLI::Option* opt : app->get_options()) {
      if (!opt->get_configurable()) continue;
      std::vector<std::string> values = opt->reduced_results();
      if (values.empty() && default_also && !opt->get_default_str().empty()) values = {opt->get_default_str()};
      if (values.empty()) continue;
      out += prefix + opt->get_single_name() + " = " + detail::config_values_text(values) + "\n";
    }
    return out;
  }
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override {
    std::stringstream text;
    text << input.rdbuf();
    std::string error;
    const std::vector<ConfigLine> lines = parse_config_text(text.str(), error);
    if (!error.empty()) throw CLI::ConfigError("line " + error);
    std::vector<CLI::ConfigItem> items;
    for (const ConfigLine& line : lines) {
      CLI::ConfigItem item;
      item.name = line.key;
      item.inputs = line.values;
      items.push_back(std::move(item));
    }
    return items;
  }
};

}  // namespace iga::io
