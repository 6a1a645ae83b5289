#include "quadrature/moment_fit/table.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "basis/element_kind.hpp"
#include "core/error.hpp"

namespace iga::quadrature::moment_fit {

std::string table_file_name(int valence, Space space, bool symmetric) {
  return "cc_" + to_string(space) + "_n" + std::to_string(valence) + (symmetric ? "_sym" : "") + ".txt";
}

void write_table(const std::string& path, const Table& t) {
  std::ofstream out(path);
  if (!out) throw InputError(path, 0, "cannot write file");
  out << "# iga fitted quadrature rule for a Catmull-Clark element with an extraordinary vertex at (0,0)\n"
      << "# (moment fitting, thesis 4.2.4): sum_i w_i f(u_i, v_i) = integral of f over [0,1]^2 for every f of the\n"
      << "# space (phi: the 2n+8 subdivision splines; mass: their pairwise products; stiffness: grad phi_a . grad\n"
      << "# phi_b). Written by iga-fit-quadrature; format in quadrature/moment_fit/table.hpp. Data lines: u v w.\n";
  if (!t.note.empty()) out << "# " << t.note << "\n";
  out << "valence " << t.valence << "\n"
      << "space " << to_string(t.space) << "\n"
      << "points " << t.rule.size() << "\n";
  out << std::setprecision(3) << std::scientific << "residual " << t.residual << "\n";
  out << "seed " << t.seed << " attempt " << t.attempt << "\n"
      << "symmetric " << (t.symmetric ? 1 : 0) << "\n"
      << "data\n";
  out << std::setprecision(16) << std::scientific;
  for (Eigen::Index i = 0; i < t.rule.size(); ++i) {
    out << t.rule.points(0, i) << " " << t.rule.points(1, i) << " " << t.rule.weights(i) << "\n";
  }
  out.flush();  // a full disk shows only when the buffer goes out
  if (!out) throw InputError(path, 0, "cannot write file");
}

namespace {
template <class T>
T read_value(std::istringstream& in, const std::string& path, long line, const std::string& what) {
  T value{};
  if (!(in >> value)) throw InputError(path, line, "expected " + what);
  return value;
}
void expect_end(std::istringstream& in, const std::string& path, long line) {
  std::string extra;
  if (in >> extra) throw InputError(path, line, "unexpected '" + extra + "'");
}
}  // namespace

Table load_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open");
  Table t;
  std::map<std::string, bool> seen;
  long line_no = 0;
  std::string line;
  long points = -1;
  bool data = false;
  Eigen::Index k = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ls(line);
    if (data) {
      if (k >= points) throw InputError(path, line_no, "more than " + std::to_string(points) + " data lines");
      const double u = read_value<double>(ls, path, line_no, "u v w");
      const double v = read_value<double>(ls, path, line_no, "u v w");
      const double w = read_value<double>(ls, path, line_no, "u v w");
      expect_end(ls, path, line_no);
      if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0) || std::max(u, v) <= 0.0) {
        throw InputError(path, line_no, "point outside (0,1]^2 or at the extraordinary vertex");
      }
      if (!(w > 0.0 && std::isfinite(w))) throw InputError(path, line_no, "weight must be positive");
      t.rule.points.col(k) << u, v;
      t.rule.weights(k) = w;
      ++k;
      continue;
    }
    std::string key;
    ls >> key;
    if (key == "data") {
      expect_end(ls, path, line_no);
      for (const char* required : {"valence", "space", "points", "residual", "seed", "symmetric"}) {
        if (!seen[required]) throw InputError(path, line_no, std::string("missing header '") + required + "' before data");
      }
      data = true;
      t.rule.points.resize(2, points);
      t.rule.weights.resize(points);
      continue;
    }
    if (seen[key]) throw InputError(path, line_no, "duplicate header '" + key + "'");
    seen[key] = true;
    if (key == "valence") {
      t.valence = read_value<int>(ls, path, line_no, "valence N");
      if (t.valence < 3 || t.valence > 16) throw InputError(path, line_no, "valence must be 3..16");
    } else if (key == "space") {
      const auto s = read_value<std::string>(ls, path, line_no, "space name");
      try {
        t.space = parse_space(s);
      } catch (const InputError& e) {
        throw InputError(path, line_no, e.reason());
      }
    } else if (key == "points") {
      points = read_value<long>(ls, path, line_no, "points Q");
      if (points < 1 || points > 100000) throw InputError(path, line_no, "points must be 1..100000");
    } else if (key == "residual") {
      t.residual = read_value<double>(ls, path, line_no, "residual R");
    } else if (key == "seed") {
      t.seed = read_value<unsigned>(ls, path, line_no, "seed S attempt K");
      if (read_value<std::string>(ls, path, line_no, "seed S attempt K") != "attempt") {
        throw InputError(path, line_no, "expected seed S attempt K");
      }
      t.attempt = read_value<int>(ls, path, line_no, "seed S attempt K");
    } else if (key == "symmetric") {
      const int s = read_value<int>(ls, path, line_no, "symmetric 0|1");
      if (s != 0 && s != 1) throw InputError(path, line_no, "symmetric must be 0 or 1");
      t.symmetric = s == 1;
    } else {
      throw InputError(path, line_no, "unknown header '" + key + "'");
    }
    expect_end(ls, path, line_no);
  }
  if (!data) throw InputError(path, line_no, "no 'data' line");
  if (k != points) {
    throw InputError(path, line_no, "expected " + std::to_string(points) + " data lines, found " + std::to_string(k));
  }
  return t;
}

Rule load_rule(const std::string& path) { return load_table(path).rule; }

Fitted::Fitted(const std::string& directory, Space space)
    : directory_(directory), space_(space), gauss_(4), tiled_(tiled_rule(4, 12)), rules_(17), sides_(4, 12) {
  if (!std::filesystem::is_directory(directory)) throw InputError(directory, 0, "fitted quadrature: not a directory");
  for (int n = 3; n <= 16; ++n) {
    for (const bool symmetric : {false, true}) {
      const auto path = std::filesystem::path(directory) / table_file_name(n, space_, symmetric);
      if (!std::filesystem::exists(path)) continue;
      Table t = load_table(path.string());
      if (t.valence != n || t.space != space_ || t.symmetric != symmetric) {
        throw InputError(path.string(), 0,
                         "table does not hold the " + to_string(space_) + " rule of valence " + std::to_string(n));
      }
      auto& slot = rules_[static_cast<std::size_t>(n)];
      if (slot.size() == 0 || t.rule.size() < slot.size()) slot = std::move(t.rule);
    }
  }
}

const Rule& Fitted::rule(const basis::ElementKind& kind) const {
  if (is_catmull_clark_irregular(kind)) {
    if (kind.boundary) return tiled_;
    const int n = kind.valence;
    if (n < 0 || n > 16 || rules_[static_cast<std::size_t>(n)].size() == 0) {
      throw UnsupportedError("fitted quadrature: no " + to_string(space_) + " table for valence " + std::to_string(n) +
                             " in '" + directory_ + "' (expected " + table_file_name(n, space_) + ")");
    }
    return rules_[static_cast<std::size_t>(n)];
  }
  return polynomial_rule(gauss_, kind, name());
}

std::vector<int> Fitted::valences() const {
  std::vector<int> out;
  for (int n = 3; n <= 16; ++n) {
    if (rules_[static_cast<std::size_t>(n)].size() > 0) out.push_back(n);
  }
  return out;
}

std::unique_ptr<RuleProvider> make_fitted(const std::string& directory, Space space) {
  return std::make_unique<Fitted>(directory, space);
}

}  // namespace iga::quadrature::moment_fit
