#include "io/bv.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <type_traits>
#include <vector>

#include "core/error.hpp"

namespace iga::io {

namespace {

void check_patch(const BvPatch& p, std::size_t index) {
  const Eigen::Index expected = p.triangle ? triangle_size(p.degree_u)
                                           : static_cast<Eigen::Index>(p.degree_u + 1) * (p.degree_v + 1);
  if (p.degree_u < 1 || (!p.triangle && p.degree_v < 1) || p.points.rows() != expected || p.points.cols() != 3) {
    const std::string degree = p.triangle ? "triangle degree " + std::to_string(p.degree_u)
                                          : "degree (" + std::to_string(p.degree_u) + ", " + std::to_string(p.degree_v) + ")";
    throw InputError("write_bv: patch " + std::to_string(index) + " has " + std::to_string(p.points.rows()) + " × " +
                     std::to_string(p.points.cols()) + " points for " + degree + " (expected " +
                     std::to_string(expected) + " × 3)");
  }
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

/// Integers or doubles of one line; false if a token is not a number of that type.
template <typename T>
bool numbers(const std::string& line, std::vector<T>& out) {
  out.clear();
  std::istringstream in(line);
  std::string tok;
  while (in >> tok) {
    std::size_t used = 0;
    try {
      if constexpr (std::is_same_v<T, int>) {
        const long v = std::stol(tok, &used);
        if (v < -1000000 || v > 1000000) return false;
        out.push_back(static_cast<int>(v));
      } else {
        out.push_back(std::stod(tok, &used));
      }
    } catch (const std::exception&) {
      return false;
    }
    if (used != tok.size()) return false;
  }
  return true;
}

}  // namespace

void write_bv(std::ostream& out, const std::vector<BvPatch>& patches) {
  for (std::size_t k = 0; k < patches.size(); ++k) check_patch(patches[k], k);
  out << std::setprecision(17);
  for (const BvPatch& p : patches) {
    if (!p.group.empty()) out << p.group << '\n';
    if (p.triangle) {  // the stored order is the file's (bv.hpp)
      out << "3\n" << p.degree_u << '\n';
      for (Eigen::Index r = 0; r < p.points.rows(); ++r) {
        out << p.points(r, 0) << ' ' << p.points(r, 1) << ' ' << p.points(r, 2) << '\n';
      }
      continue;
    }
    out << "5\n" << p.degree_u << ' ' << p.degree_v << '\n';
    for (int i = 0; i <= p.degree_u; ++i) {
      for (int j = 0; j <= p.degree_v; ++j) {
        const auto r = p.points.row(j * (p.degree_u + 1) + i);
        out << r(0) << ' ' << r(1) << ' ' << r(2) << '\n';
      }
    }
  }
}

void write_bv(const std::string& path, const std::vector<BvPatch>& patches) {
  for (std::size_t k = 0; k < patches.size(); ++k) check_patch(patches[k], k);
  std::ofstream out(path);
  if (!out) throw InputError(path, 0, "cannot write file");
  write_bv(out, patches);
  out.flush();
  if (!out) throw InputError(path, 0, "cannot write file");
}

std::vector<BvPatch> read_bv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open file");
  return parse_bv(in, path);
}

std::vector<BvPatch> parse_bv(std::istream& in, const std::string& name) {
  std::vector<BvPatch> patches;
  std::string group;
  std::string raw;
  long line_no = 0;
  // Next non-blank line (trimmed); false at the end of the file.
  auto next = [&](std::string& line) {
    while (std::getline(in, raw)) {
      ++line_no;
      line = trim(raw);
      if (!line.empty()) return true;
    }
    return false;
  };
  std::string line;
  while (next(line)) {
    if (line.rfind("Group", 0) == 0) {
      group = line;
      continue;
    }
    std::vector<int> ints;
    if (!numbers(line, ints) || ints.size() != 1) {
      throw InputError(name, line_no, "expected a patch kind (a single integer, e.g. 5) or a Group line, got '" + line + "'");
    }
    const int kind = ints[0];
    if (kind != 3 && kind != 4 && kind != 5) {
      const std::string what = kind == 1 ? " (polyhedron)" : kind == 8 ? " (rational patch)" : kind == 9 ? " (PN triangle)" : "";
      throw InputError(name, line_no, "patch kind " + std::to_string(kind) + what + " is not supported (supported: 3, 4, 5)");
    }
    const long kind_line = line_no;
    if (!next(line)) throw InputError(name, line_no, "end of file after patch kind " + std::to_string(kind) + " (line " + std::to_string(kind_line) + ")");
    const std::size_t want = kind == 5 ? 2 : 1;
    if (!numbers(line, ints) || ints.size() != want) {
      throw InputError(name, line_no, kind != 5 ? "expected one degree for a kind-" + std::to_string(kind) + " patch, got '" + line + "'"
                                                : "expected two degrees 'deg_u deg_v' for a kind-5 patch, got '" + line + "'");
    }
    BvPatch p;
    p.group = group;
    p.triangle = kind == 3;
    p.degree_u = ints[0];
    p.degree_v = kind == 5 ? ints[1] : ints[0];
    if (p.degree_u < 1 || p.degree_u > 30 || p.degree_v < 1 || p.degree_v > 30) {
      throw InputError(name, line_no, "patch degrees must be in 1..30, got '" + line + "'");
    }
    const int count = p.triangle ? triangle_size(p.degree_u) : (p.degree_u + 1) * (p.degree_v + 1);
    p.points.resize(count, 3);
    std::vector<double> xyz;
    for (int k = 0; k < count; ++k) {
      if (!next(line)) {
        throw InputError(name, line_no, "end of file inside the patch of line " + std::to_string(kind_line) + ": " +
                                            std::to_string(k) + " of " + std::to_string(count) + " control points read");
      }
      if (!numbers(line, xyz) || xyz.size() != 3) {
        throw InputError(name, line_no, "expected a control point 'x y z', got '" + line + "'");
      }
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
        throw InputError(name, line_no, "control point is not finite: '" + line + "'");
      }
      if (p.triangle) {  // stored in the file's order
        p.points.row(k) << xyz[0], xyz[1], xyz[2];
        continue;
      }
      const int i = k / (p.degree_v + 1), j = k % (p.degree_v + 1);  // u-major in the file
      p.points.row(j * (p.degree_u + 1) + i) << xyz[0], xyz[1], xyz[2];
    }
    patches.push_back(std::move(p));
  }
  return patches;
}

}  // namespace iga::io
