#include "basis/bspline/patch_file.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "basis/bspline/rational_space.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "core/error.hpp"
#include "core/json_text.hpp"

namespace iga::basis::bspline {
namespace {

using nlohmann::json;

// Reads one JSON patch, every failure an InputError "<name>: <path> ...".
class PatchReader {
 public:
  explicit PatchReader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

  const json& member(const json& root, const char* key) const {
    const auto it = root.find(key);
    if (it == root.end()) fail(std::string("no \"") + key + "\" (see the patch format in the README)");
    return *it;
  }

  double number(const json& v, const std::string& path) const { return json_text::number(v, name_ + ": " + path); }

  const json& array(const json& v, const std::string& path, std::size_t size) const {
    if (!v.is_array()) fail(path + " must be a list, got " + json_text::kind(v));
    if (size != 0 && v.size() != size) {
      fail(path + " has " + std::to_string(v.size()) + " entries, not " + std::to_string(size));
    }
    return v;
  }

  std::vector<double> numbers(const json& v, const std::string& path) const {
    array(v, path, 0);
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], path + "[" + std::to_string(i) + "]"));
    return out;
  }

  int degree(const json& v, const std::string& path) const {
    const double d = number(v, path);
    if (d != std::floor(d) || d < 1 || d > 20) fail(path + " is " + json_text::shown(v) + ": a degree is an integer 1..20");
    return static_cast<int>(d);
  }

  KnotVector knots(const json& v, int degree, const std::string& path) const {
    try {
      return KnotVector(degree, numbers(v, path));
    } catch (const InputError& e) {
      if (std::string(e.what()).rfind(name_ + ":", 0) == 0) throw;
      fail(path + " (degree " + std::to_string(degree) + "): " + e.what());
    }
  }

  Geometry read(const json& root) const {
    if (!root.is_object()) fail("expected a JSON object (the patch format in the README), got " + json_text::kind(root));
    static const std::set<std::string> known = {"format", "version", "degree", "knots", "control_points", "weights"};
    for (const auto& [key, value] : root.items()) {
      if (!known.count(key)) fail("unknown key \"" + json_text::key_text(key) + "\" (keys: format, version, degree, knots, control_points, weights)");
    }
    const json& format = member(root, "format");
    if (format != "iga-patch") fail("\"format\" is " + json_text::shown(format) + ", not \"iga-patch\"");
    const json& version = member(root, "version");
    if (version != 1) fail("\"version\" is " + json_text::shown(version) + ": this build reads version 1");
    const json& deg = array(member(root, "degree"), "degree", 2);
    const int pu = degree(deg[0], "degree[0]"), pv = degree(deg[1], "degree[1]");
    const json& kn = array(member(root, "knots"), "knots", 2);
    KnotVector u = knots(kn[0], pu, "knots[0]"), v = knots(kn[1], pv, "knots[1]");
    const Index n = u.num_basis() * v.num_basis();
    const json& cp = array(member(root, "control_points"), "control_points", static_cast<std::size_t>(n));
    const std::size_t dim = cp[0].is_array() ? cp[0].size() : 0;
    if (dim != 2 && dim != 3) fail("control_points[0] must be [x, y] or [x, y, z]");
    Eigen::MatrixXd points(n, static_cast<Eigen::Index>(dim));
    for (Index i = 0; i < n; ++i) {
      const std::string path = "control_points[" + std::to_string(i) + "]";
      const json& row = array(cp[static_cast<std::size_t>(i)], path, dim);
      for (std::size_t c = 0; c < dim; ++c) points(i, static_cast<Eigen::Index>(c)) = number(row[c], path + "[" + std::to_string(c) + "]");
    }
    const auto w = root.find("weights");
    if (w == root.end()) return Geometry(std::make_shared<const TensorSpace>(std::move(u), std::move(v)), std::move(points));
    array(*w, "weights", static_cast<std::size_t>(n));
    Eigen::VectorXd weights(n);
    for (Index i = 0; i < n; ++i) {
      const std::string path = "weights[" + std::to_string(i) + "]";
      weights(i) = number((*w)[static_cast<std::size_t>(i)], path);
      if (!(weights(i) > 0.0)) fail(path + " is " + json_text::shown((*w)[static_cast<std::size_t>(i)]) + ": weights must be positive");
    }
    return make_rational_patch(std::move(u), std::move(v), std::move(points), std::move(weights));
  }

 private:
  std::string name_;
};

json knot_array(const KnotVector& k) {
  json a = json::array();
  for (Index i = 0; i < k.size(); ++i) a.push_back(k[i]);
  return a;
}

}  // namespace

Geometry parse_patch(const std::string& text, const std::string& name) {
  return PatchReader(name).read(json_text::parse(text, name));
}

Geometry read_patch(const std::string& path) {
  // A patch of 64 MiB of text has millions of control points; the parsed JSON takes several times the text.
  return parse_patch(json_text::read_input(path, std::uintmax_t{64} << 20, "patch"), path == "-" ? "stdin" : path);
}

std::string patch_text(const Geometry& geometry) {
  const RationalSpace* rational = rational_space(geometry.space());
  const TensorSpace* tensor = rational ? &rational->base() : tensor_space(geometry.space());
  if (!tensor) throw UnsupportedError("patch files hold B-spline and NURBS patches, not a '" + geometry.space().name() + "' space");
  json root;
  root["format"] = "iga-patch";
  root["version"] = 1;
  root["degree"] = {tensor->knots_u().degree(), tensor->knots_v().degree()};
  root["knots"] = {knot_array(tensor->knots_u()), knot_array(tensor->knots_v())};
  json cp = json::array();
  for (Index i = 0; i < geometry.control_points().rows(); ++i) {
    json row = json::array();
    for (Index c = 0; c < geometry.dim(); ++c) row.push_back(geometry.control_points()(i, c));
    cp.push_back(std::move(row));
  }
  root["control_points"] = std::move(cp);
  if (rational) root["weights"] = std::vector<double>(rational->weights().data(), rational->weights().data() + rational->weights().size());
  return root.dump(1) + "\n";
}

void write_patch(const std::string& path, const Geometry& geometry) {
  const std::string text = patch_text(geometry);
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write the patch file");
  out << text;
  if (!out) throw InputError(path + ": writing the patch file failed");
}

bool is_patch_file(const std::string& geometry) {
  return geometry.size() > 5 && geometry.compare(geometry.size() - 5, 5, ".json") == 0;
}

}  // namespace iga::basis::bspline
