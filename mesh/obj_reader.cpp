#include "mesh/obj_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace iga::mesh {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : rest_(text) {}
  std::string_view next() {
    std::size_t i = 0;
    while (i < rest_.size() && is_blank(rest_[i])) {
      ++i;
    }
    std::size_t j = i;
    while (j < rest_.size() && !is_blank(rest_[j])) {
      ++j;
    }
    const std::string_view token = rest_.substr(i, j - i);
    rest_.remove_prefix(j);
    return token;
  }

 private:
  std::string_view rest_;
};

// A token as quoted in a message: at most 40 characters, so that a 10-million-digit number still gives one
// short line.
std::string shown(std::string_view token) {
  return token.size() <= 40 ? std::string(token) : std::string(token.substr(0, 37)) + "...";
}

// Error for the current line of the current file.
struct Where {
  const std::string& name;
  long line;
  [[noreturn]] void fail(const std::string& reason) const { throw InputError(name, line, reason); }
};

double parse_number(std::string_view token, const Where& where) {
  std::string_view digits = token;
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) {
    where.fail("number '" + shown(token) + "' is out of range");
  }
  if (ec != std::errc{} || end != digits.data() + digits.size()) {
    where.fail("malformed number '" + shown(token) + "'");
  }
  return value;
}

// Parses an integer field of a face vertex; false if it is not a plain (signed) integer.
bool parse_integer(std::string_view text, Index& value) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') {
    text.remove_prefix(1);
  }
  if (text.empty()) {
    return false;
  }
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc{} && end == text.data() + text.size();
}

// One face vertex token (i, i/j, i//k, i/j/k): returns the 0-based vertex index it refers to.
Index parse_face_vertex(std::string_view token, Index num_vertices, const Where& where) {
  const auto malformed = [&] { where.fail("malformed face vertex '" + shown(token) + "'"); };
  const std::size_t slash = token.find('/');
  const std::string_view vertex_part = token.substr(0, slash);
  Index unused = 0;
  if (slash != std::string_view::npos) {
    const std::string_view rest = token.substr(slash + 1);
    const std::size_t slash2 = rest.find('/');
    if (slash2 == std::string_view::npos) {
      if (!parse_integer(rest, unused)) {  // i/j
        malformed();
      }
    } else {
      const std::string_view texture_part = rest.substr(0, slash2);
      const std::string_view normal_part = rest.substr(slash2 + 1);
      if ((!texture_part.empty() && !parse_integer(texture_part, unused)) || !parse_integer(normal_part, unused)) {
        malformed();  // i/j/k or i//k
      }
    }
  }
  Index index = 0;
  if (!parse_integer(vertex_part, index)) {
    malformed();
  }
  if (index == 0) {
    where.fail("vertex index 0 is invalid (OBJ indices start at 1)");
  }
  const Index resolved = index > 0 ? index - 1 : num_vertices + index;
  if (resolved < 0 || resolved >= num_vertices) {
    where.fail("vertex index " + std::to_string(index) + " out of range (" + std::to_string(num_vertices) +
               " vertices defined)");
  }
  return resolved;
}

// The rest of a `v` statement: x y z [w ...] (only x y z kept).
Eigen::Vector3d parse_vertex(Tokens& tokens, const Where& where) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
    const double value = parse_number(t, where);
    if (count < 3) {
      if (!std::isfinite(value)) {
        where.fail("non-finite coordinate '" + shown(t) + "'");
      }
      p[count] = value;
    }
    ++count;
  }
  if (count < 3) {
    where.fail("vertex has " + std::to_string(count) + " coordinates; a vertex needs x y z");
  }
  return p;
}

// The rest of an `f` statement: at least 3 distinct vertices among the num_vertices defined so far.
std::vector<Index> parse_face(Tokens& tokens, Index num_vertices, std::vector<Index>& sorted, const Where& where) {
  std::vector<Index> face;
  for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
    face.push_back(parse_face_vertex(t, num_vertices, where));
  }
  if (face.size() < 3) {
    where.fail("face has " + std::to_string(face.size()) + " vertices; a face needs at least 3");
  }
  sorted.assign(face.begin(), face.end());
  std::sort(sorted.begin(), sorted.end());
  if (const auto dup = std::adjacent_find(sorted.begin(), sorted.end()); dup != sorted.end()) {
    where.fail("vertex " + std::to_string(*dup + 1) + " appears more than once in the face");
  }
  return face;
}

// The next line of `in` without its end: lines end at "\n", "\r\n" or a lone "\r" (old Mac files), counted as
// an editor counts them. False at the end of the input.
bool next_line(std::streambuf& in, std::string& line) {
  line.clear();
  int c = in.sbumpc();
  if (c == std::char_traits<char>::eof()) {
    return false;
  }
  while (c != std::char_traits<char>::eof() && c != '\n' && c != '\r') {
    line.push_back(static_cast<char>(c));
    c = in.sbumpc();
  }
  if (c == '\r' && in.sgetc() == '\n') {
    in.sbumpc();
  }
  return true;
}

// Refuses bytes that never occur in text: control characters other than tab, vertical tab and form feed (line
// ends are already gone), and DEL. The column counts characters (UTF-8 continuation bytes are not counted).
void check_text(std::string_view line, const Where& where) {
  long column = 0;
  for (const char ch : line) {
    const auto byte = static_cast<unsigned char>(ch);
    if ((byte & 0xC0U) != 0x80U) {
      ++column;
    }
    if ((byte < 0x20U && byte != '\t' && byte != '\v' && byte != '\f') || byte == 0x7FU) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", byte);
      where.fail("binary data (byte " + std::string(hex) + " at column " + std::to_string(column) +
                 "); an OBJ file is text");
    }
  }
}

// The first line of the file: a UTF-8 byte-order mark is dropped; UTF-16 (whose every other byte is NUL) is
// named as such.
void strip_byte_order_mark(std::string& line, const Where& where) {
  if (line.starts_with("\xEF\xBB\xBF")) {
    line.erase(0, 3);
  } else if (line.starts_with("\xFF\xFE") || line.starts_with("\xFE\xFF")) {
    where.fail("file is UTF-16 text; save it as UTF-8 or ASCII");
  }
}

}  // namespace

PolyMesh read_obj(const std::string& path) {
  if (path == "-") return parse_obj(std::cin, "stdin");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path, 0, "cannot read (is a directory)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) {
    throw InputError(path, 0, "cannot open file");
  }
  return parse_obj(in, path);
}

PolyMesh parse_obj(std::istream& in, const std::string& name) {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<Index>> faces;
  std::vector<long> face_lines, vertex_lines;
  std::vector<Index> sorted;
  std::string line;
  long line_number = 0;

  while (next_line(*in.rdbuf(), line)) {
    ++line_number;
    const Where where{name, line_number};
    if (line_number == 1) {
      strip_byte_order_mark(line, where);
    }
    check_text(line, where);
    std::string_view text(line);
    if (const std::size_t hash = text.find('#'); hash != std::string_view::npos) {
      text = text.substr(0, hash);
    }
    Tokens tokens(text);
    const std::string_view keyword = tokens.next();

    if (keyword == "v") {
      points.push_back(parse_vertex(tokens, where));
      vertex_lines.push_back(line_number);
    } else if (keyword == "f") {
      faces.push_back(parse_face(tokens, static_cast<Index>(points.size()), sorted, where));
      face_lines.push_back(line_number);
    }
    // Every other statement (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) is not needed for the mesh.
  }
  if (line_number == 0) {
    throw InputError(name, 0, "file is empty");
  }
  if (points.empty()) {
    throw InputError(name, 0, "file has no vertices");
  }
  if (faces.empty()) {
    throw InputError(name, 0, "file has no faces");
  }
  try {
    PolyMesh mesh = PolyMesh::build(std::move(points), std::move(faces));
    mesh.set_source_lines(std::move(vertex_lines), std::move(face_lines));
    return mesh;
  } catch (const TopologyError& e) {
    const Index f = e.face();
    const long at_line = (f >= 0 && f < static_cast<Index>(face_lines.size())) ? face_lines[static_cast<std::size_t>(f)] : 0;
    throw InputError(name, at_line, e.describe(1));
  }
}

}  // namespace iga::mesh
