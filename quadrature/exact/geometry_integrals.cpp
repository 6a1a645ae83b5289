#include "quadrature/exact/geometry_integrals.hpp"

#include <map>
#include <mutex>

#include "basis/catmull_clark/space.hpp"
#include "core/error.hpp"
#include "quadrature/exact/irregular_integrals.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/tensor_rule.hpp"

namespace iga::quadrature::exact {

namespace {

using basis::catmull_clark::CatmullClarkSpace;
using basis::catmull_clark::IrregularConfig;
using basis::catmull_clark::IrregularElement;

const CatmullClarkSpace& cc_space(const basis::Geometry& g, int dim, const char* what) {
  const auto* cc = dynamic_cast<const CatmullClarkSpace*>(&g.space());
  if (cc == nullptr) throw InputError(std::string(what) + ": the geometry is not on a Catmull–Clark space");
  if (g.dim() != dim) {
    throw InputError(std::string(what) + ": needs a " + (dim == 2 ? "planar (dim 2)" : "3D surface (dim 3)") +
                     " geometry, got dim " + std::to_string(g.dim()));
  }
  return *cc;
}

Eigen::MatrixXd local_coordinates(const basis::Geometry& g, Index e) {
  const auto dofs = g.space().dofs(e);
  Eigen::MatrixXd x(static_cast<Eigen::Index>(dofs.size()), g.dim());
  for (std::size_t i = 0; i < dofs.size(); ++i) x.row(static_cast<Eigen::Index>(i)) = g.control_points().row(dofs[i]);
  return x;
}

// ∫ ∂u φ_a ∂v φ_b (dofs × dofs) of a boundary-EV element: level-0 tiles (area 1/4, derivative factor 2 each)
// plus levels l >= 1 (tiles E_k A^(l-1) A0 G, area 4^-(l+1), factor 2^(l+1) each): both products are 1.
Eigen::MatrixXd irregular_duv(const IrregularElement& el, std::map<const IrregularConfig*, Eigen::MatrixXd>& cache) {
  const Eigen::MatrixXd g01 = tile_gram(0, 1);
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(el.level1.cols(), el.level1.cols());
  for (const auto& t : el.level0) d.noalias() += t.transpose() * g01 * t;
  auto it = cache.find(el.config.get());
  if (it == cache.end()) {
    const IrregularConfig& c = *el.config;
    it = cache.emplace(el.config.get(), level_series(c.tile_ops[0], c.subdivision, c.limit, 0, 1)).first;
  }
  d.noalias() += el.level1.transpose() * it->second * el.level1;
  return d;
}

// ∫ φ_a ∂u φ_b ∂v φ_c of a boundary-EV element (factors 1/4 · 2 · 2 = 1 on every level).
Tensor3 irregular_triple(const IrregularElement& el) {
  const Tensor3 t16 = tile_triple(-1, 0, 1);
  Tensor3 t(static_cast<std::size_t>(el.level1.cols()), Eigen::MatrixXd::Zero(el.level1.cols(), el.level1.cols()));
  auto add = [&](const Tensor3& s) {
    for (std::size_t i = 0; i < t.size(); ++i) t[i] += s[i];
  };
  for (const auto& m : el.level0) add(contract(t16, m, m, m));
  const IrregularConfig& c = *el.config;
  add(contract(level_series_triple(c.tile_ops[0], c.subdivision, c.limit, -1, 0, 1), el.level1, el.level1, el.level1));
  return t;
}

const Tensor3& stam_triple(int n) {
  static std::mutex mutex;
  static std::map<int, Tensor3> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, triple(n, -1, 0, 1)).first;
  return it->second;
}

double triple_form(const Tensor3& t, const Eigen::VectorXd& z, const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  double s = 0;
  for (std::size_t a = 0; a < t.size(); ++a) {
    const double za = z(static_cast<Eigen::Index>(a));
    if (za != 0.0) s += za * (x.dot(t[a] * y) - y.dot(t[a] * x));
  }
  return s;
}

double gauss_sum(const basis::Geometry& g, Index e, const Rule& rule, bool volume) {
  basis::GeometryValues gv;
  g.evaluate(e, rule.points, gv);
  double s = 0;
  for (Eigen::Index q = 0; q < rule.size(); ++q) {
    const double det = gv.xu(0, q) * gv.xv(1, q) - gv.xu(1, q) * gv.xv(0, q);
    s += rule.weights(q) * det * (volume ? gv.x(2, q) : 1.0);
  }
  return s;
}

}  // namespace

double exact_area(const basis::Geometry& g) {
  const CatmullClarkSpace& cc = cc_space(g, 2, "exact_area");
  const Rule1D g3 = gauss_legendre(3);
  const Rule rule = tensor_rule(g3, g3);
  std::map<const IrregularConfig*, Eigen::MatrixXd> cache;
  double area = 0;
  for (Index e = 0; e < cc.num_elements(); ++e) {
    if (cc.kind(e).family == basis::Family::Regular) {
      area += gauss_sum(g, e, rule, false);
      continue;
    }
    const Eigen::MatrixXd xy = local_coordinates(g, e);
    if (const auto* st = cc.stam(e)) {
      const Eigen::MatrixXd& d = irregular_integrals(st->valence()).d[0][1];
      const Eigen::VectorXd x = cc.stam_map(e) * xy.col(0), y = cc.stam_map(e) * xy.col(1);
      area += x.dot(d * y) - y.dot(d * x);
    } else if (const auto* el = cc.irregular(e)) {
      const Eigen::MatrixXd d = irregular_duv(*el, cache);
      area += xy.col(0).dot(d * xy.col(1)) - xy.col(1).dot(d * xy.col(0));
    } else {
      throw UnsupportedError("exact_area: element " + std::to_string(e) + " has no exact integration data");
    }
  }
  return area;
}

double exact_volume(const basis::Geometry& g) {
  const CatmullClarkSpace& cc = cc_space(g, 3, "exact_volume");
  const Rule1D g5 = gauss_legendre(5);
  const Rule rule = tensor_rule(g5, g5);
  double volume = 0;
  for (Index e = 0; e < cc.num_elements(); ++e) {
    if (cc.kind(e).family == basis::Family::Regular) {
      volume += gauss_sum(g, e, rule, true);
      continue;
    }
    const Eigen::MatrixXd p = local_coordinates(g, e);
    if (const auto* st = cc.stam(e)) {
      const Eigen::MatrixXd loc = cc.stam_map(e) * p;
      volume += triple_form(stam_triple(st->valence()), loc.col(2), loc.col(0), loc.col(1));
    } else if (const auto* el = cc.irregular(e)) {
      volume += triple_form(irregular_triple(*el), p.col(2), p.col(0), p.col(1));
    } else {
      throw UnsupportedError("exact_volume: element " + std::to_string(e) + " has no exact integration data");
    }
  }
  return volume;
}

}  // namespace iga::quadrature::exact
