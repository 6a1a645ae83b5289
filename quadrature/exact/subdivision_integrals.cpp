#include "quadrature/exact/subdivision_integrals.hpp"

#include <Eigen/LU>
#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <tuple>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/tensor_rule.hpp"

namespace iga::quadrature::exact {
namespace {

using basis::PatchTile;
using basis::SubdivisionElement;
using basis::SubdivisionView;

void check_factor(Factor f) {
  if (f < -1 || f > 1) throw InputError("exact integrals: factor " + std::to_string(f) + " is not -1, 0 or 1");
}

int num_derivatives(std::initializer_list<Factor> fs) {
  int d = 0;
  for (Factor f : fs) d += f >= 0 ? 1 : 0;
  return d;
}

// The patch functions at a rule on the patch domain that is exact for products of three of them (degree
// 3·patch_degree per direction on the square, total degree on the triangle).
struct PatchSamples {
  Rule rule;
  basis::BasisValues values;
};

PatchSamples sample_patch(const SubdivisionView& v) {
  const int n = (3 * v.patch_degree) / 2 + 2;  // Gauss: 2n − 1 >= 3p per direction; collapsed: 2n − 2 >= 3p
  const Rule1D line = gauss_legendre(n);
  PatchSamples s;
  s.rule = v.patch_shape == basis::Shape::Quad ? tensor_rule(line, line) : collapsed_triangle_rule(line, line);
  v.patch_functions(s.rule.points, 1, s.values);
  return s;
}

// The factor of the tile's functions in element coordinates at the rule points (r × q): values, or
// d/dx_i = Σ_r J(r, i) d/dt_r.
Eigen::MatrixXd factor_values(const PatchSamples& s, const Eigen::Matrix2d& jacobian, Factor f) {
  if (f < 0) return s.values.value;
  return jacobian(0, f) * s.values.du + jacobian(1, f) * s.values.dv;
}

// ∫_tile F_a G_b over the tile (element coordinates): r × r.
Eigen::MatrixXd tile_products(const PatchSamples& s, const Eigen::Matrix2d& j, Factor f, Factor g) {
  const Eigen::VectorXd w = s.rule.weights / std::abs(j.determinant());
  return factor_values(s, j, f) * w.asDiagonal() * factor_values(s, j, g).transpose();
}

Tensor3 tile_products(const PatchSamples& s, const Eigen::Matrix2d& j, Factor f, Factor g, Factor h) {
  const Eigen::VectorXd w = s.rule.weights / std::abs(j.determinant());
  const Eigen::MatrixXd ff = factor_values(s, j, f), gg = factor_values(s, j, g), hh = factor_values(s, j, h);
  Tensor3 t(static_cast<std::size_t>(ff.rows()));
  for (Eigen::Index a = 0; a < ff.rows(); ++a) {
    t[static_cast<std::size_t>(a)] = gg * (w.array() * ff.row(a).transpose().array()).matrix().asDiagonal() * hh.transpose();
  }
  return t;
}

// The level series of a view in its m points, cached per (view, factors). Views live for the program.
template <class Value>
const Value& cached(const SubdivisionView* v, std::tuple<int, int, int> key, const std::function<Value()>& make) {
  static std::mutex mutex;
  static std::map<std::pair<const SubdivisionView*, std::tuple<int, int, int>>, Value> cache;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find({v, key});
    if (it != cache.end()) return it->second;
  }
  Value value = make();
  const std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(std::make_pair(v, key), std::move(value)).first->second;
}

const Eigen::MatrixXd& view_gram(const SubdivisionView& v, Factor f, Factor g) {
  return cached<Eigen::MatrixXd>(&v, {f, g, 9}, [&] {
    const PatchSamples s = sample_patch(v);
    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(v.subdivision.rows(), v.subdivision.cols());
    for (const PatchTile& t : v.tiles) c.noalias() += t.points.transpose() * tile_products(s, t.jacobian, f, g) * t.points;
    const Eigen::MatrixXd b = deflate_constant(v.subdivision, v.limit);
    return stein(f >= 0 ? b : v.subdivision, c, g >= 0 ? b : v.subdivision, std::ldexp(1.0, num_derivatives({f, g}) - 2));
  });
}

const Tensor3& view_triple(const SubdivisionView& v, Factor f, Factor g, Factor h) {
  return cached<Tensor3>(&v, {f, g, h}, [&] {
    const PatchSamples s = sample_patch(v);
    Tensor3 c(static_cast<std::size_t>(v.subdivision.rows()), Eigen::MatrixXd::Zero(v.subdivision.rows(), v.subdivision.cols()));
    for (const PatchTile& t : v.tiles) {
      const Tensor3 ck = contract(tile_products(s, t.jacobian, f, g, h), t.points, t.points, t.points);
      for (std::size_t i = 0; i < c.size(); ++i) c[i] += ck[i];
    }
    const Eigen::MatrixXd b = deflate_constant(v.subdivision, v.limit);
    auto pick = [&](Factor x) { return x >= 0 ? b : v.subdivision; };
    return triple_series(c, pick(f), pick(g), pick(h), std::ldexp(1.0, num_derivatives({f, g, h}) - 2));
  });
}

const Eigen::VectorXd& view_integral(const SubdivisionView& v) {
  return cached<Eigen::VectorXd>(&v, {-1, 9, 9}, [&] {
    const PatchSamples s = sample_patch(v);
    Eigen::VectorXd c = Eigen::VectorXd::Zero(v.subdivision.rows());
    for (const PatchTile& t : v.tiles) {
      c += t.points.transpose() * (s.values.value * s.rule.weights) / std::abs(t.jacobian.determinant());
    }
    return linear_series(v.subdivision, c, 0.25);
  });
}

const SubdivisionView& view_of(const SubdivisionElement& el) {
  if (!el.view) throw InputError("exact integrals: the element has no subdivision view");
  return *el.view;
}

}  // namespace

Eigen::VectorXd element_integral(const SubdivisionElement& el) {
  const SubdivisionView& v = view_of(el);
  Eigen::VectorXd r = std::ldexp(1.0, -2 * el.shift) * (el.to_points.transpose() * view_integral(v));
  if (!el.explicit_tiles.empty()) {
    const PatchSamples s = sample_patch(v);
    for (const PatchTile& t : el.explicit_tiles) {
      r += t.points.transpose() * (s.values.value * s.rule.weights) / std::abs(t.jacobian.determinant());
    }
  }
  return r;
}

Eigen::MatrixXd element_gram(const SubdivisionElement& el, Factor f, Factor g) {
  check_factor(f);
  check_factor(g);
  const SubdivisionView& v = view_of(el);
  const double scale = std::pow(std::ldexp(1.0, num_derivatives({f, g}) - 2), el.shift);
  Eigen::MatrixXd r = scale * (el.to_points.transpose() * view_gram(v, f, g) * el.to_points);
  if (!el.explicit_tiles.empty()) {
    const PatchSamples s = sample_patch(v);
    for (const PatchTile& t : el.explicit_tiles) r.noalias() += t.points.transpose() * tile_products(s, t.jacobian, f, g) * t.points;
  }
  return r;
}

Tensor3 element_triple(const SubdivisionElement& el, Factor f, Factor g, Factor h) {
  check_factor(f);
  check_factor(g);
  check_factor(h);
  const SubdivisionView& v = view_of(el);
  const double scale = std::pow(std::ldexp(1.0, num_derivatives({f, g, h}) - 2), el.shift);
  Tensor3 r = contract(view_triple(v, f, g, h), el.to_points, el.to_points, el.to_points);
  for (auto& m : r) m *= scale;
  if (!el.explicit_tiles.empty()) {
    const PatchSamples s = sample_patch(v);
    for (const PatchTile& t : el.explicit_tiles) {
      const Tensor3 tt = contract(tile_products(s, t.jacobian, f, g, h), t.points, t.points, t.points);
      for (std::size_t i = 0; i < r.size(); ++i) r[i] += tt[i];
    }
  }
  return r;
}

}  // namespace iga::quadrature::exact
