#include "basis/catmull_clark/irregular_patch.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

#include "basis/catmull_clark/exact_view.hpp"
#include "basis/catmull_clark/regular_patch.hpp"

namespace iga::basis::catmull_clark {

namespace {

Eigen::MatrixXd select_rows(const Eigen::MatrixXd& w, const std::vector<int>& rows) {
  Eigen::MatrixXd s(static_cast<Eigen::Index>(rows.size()), w.cols());
  for (std::size_t i = 0; i < rows.size(); ++i) s.row(static_cast<Eigen::Index>(i)) = w.row(rows[i]);
  return s;
}

// Limit position of vertex 0 of a one-ring: interior (n^2 V + 4 sum e + sum f) / (n (n + 5)); smooth
// boundary (P_prev + 4 V + P_next) / 6.
Eigen::VectorXd limit_stencil(const QuadMesh& m) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(m.num_vertices);
  std::vector<int> hs;
  for (int h = 0; h < 4 * m.num_faces(); ++h) {
    if (m.origin(h) == 0) hs.push_back(h);
  }
  int prev_b = -1, next_b = -1;
  for (int h : hs) {
    if (m.twin[static_cast<std::size_t>(h)] < 0) next_b = m.target(h);
    if (m.twin[static_cast<std::size_t>(QuadMesh::prev(h))] < 0) prev_b = m.origin(QuadMesh::prev(h));
  }
  if (prev_b >= 0 || next_b >= 0) {
    if (prev_b < 0 || next_b < 0 || hs.size() < 2) throw std::logic_error("catmull_clark: EV is a corner");
    s(0) = 4.0 / 6.0;
    s(prev_b) += 1.0 / 6.0;
    s(next_b) += 1.0 / 6.0;
    return s;
  }
  const double n = static_cast<double>(hs.size()), d = n * (n + 5.0);
  s(0) += n * n / d;
  for (int h : hs) {
    s(m.target(h)) += 4.0 / d;
    s(m.origin(QuadMesh::next(QuadMesh::next(h)))) += 1.0 / d;
  }
  return s;
}

std::shared_ptr<const IrregularConfig> build_config(const QuadMesh& l1) {
  const Subdivided s = subdivide(l1);
  const OneRing r2 = unfold_one_ring(s.mesh, 0, 0);
  if (r2.mesh.quads != l1.quads || r2.mesh.num_vertices != l1.num_vertices) {
    throw std::logic_error("catmull_clark: the one-ring at an EV does not repeat under subdivision");
  }
  auto c = std::make_shared<IrregularConfig>();
  c->subdivision = select_rows(s.weights, r2.parent);
  std::array<Eigen::MatrixXd, 3> e;
  for (int k = 1; k <= 3; ++k) e[static_cast<std::size_t>(k - 1)] = grid_operator(s.mesh, k, (4 - k) % 4) * s.weights;
  c->limit = limit_stencil(l1);
  const Eigen::Index m = l1.num_vertices;
  if ((c->limit.transpose() * c->subdivision - c->limit.transpose()).cwiseAbs().maxCoeff() > 1e-13) {
    throw std::logic_error("catmull_clark: limit stencil is not a left eigenvector of the subdivision matrix");
  }
  const Eigen::MatrixXd b = c->subdivision - Eigen::VectorXd::Ones(m) * c->limit.transpose();
  c->tile_ops.resize(kLevels);
  c->tile_ops_deriv.resize(kLevels);
  Eigen::MatrixXd power = Eigen::MatrixXd::Identity(m, m), power_b = power;
  for (int j = 0; j < kLevels; ++j) {
    for (int k = 0; k < 3; ++k) {
      c->tile_ops[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)] = e[static_cast<std::size_t>(k)] * power;
      c->tile_ops_deriv[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)] = e[static_cast<std::size_t>(k)] * power_b;
    }
    power = (power * c->subdivision).eval();
    power_b = (power_b * b).eval();
    if (j == 0) c->view = quad_view(c->subdivision, c->limit, c->tile_ops[0]);
  }
  return c;
}

}  // namespace

std::shared_ptr<const IrregularConfig> irregular_config(const QuadMesh& level1) {
  static std::mutex mutex;
  static std::map<std::vector<int>, std::shared_ptr<const IrregularConfig>> cache;
  std::vector<int> key{level1.num_vertices};
  for (const auto& q : level1.quads) key.insert(key.end(), q.begin(), q.end());
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  auto config = build_config(level1);
  const std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(std::move(key), std::move(config)).first->second;
}

IrregularElement make_irregular_element(const OneRing& ring, const Eigen::MatrixXd& to_dofs) {
  const Subdivided s = subdivide(ring.mesh);
  IrregularElement el;
  for (int k = 1; k <= 3; ++k) {
    el.level0[static_cast<std::size_t>(k - 1)] = grid_operator(s.mesh, k, (4 - k) % 4) * s.weights * to_dofs;
  }
  const OneRing r1 = unfold_one_ring(s.mesh, 0, 0);
  el.level1 = select_rows(s.weights, r1.parent) * to_dofs;
  el.config = irregular_config(r1.mesh);
  el.limit = el.level1.transpose() * el.config->limit;
  el.level1_deriv = el.level1 - Eigen::VectorXd::Ones(el.level1.rows()) * el.limit.transpose();
  return el;
}

void evaluate_irregular(const IrregularElement& el, const Eigen::Matrix2Xd& pts, int derivatives,
                        BasisValues& out) {
  const Eigen::Index q = pts.cols(), nd = el.level1.cols();
  out.resize(nd, q, derivatives);
  // Group the points by (level, tile); key -1 = limit point.
  thread_local std::vector<std::pair<int, Eigen::Index>> keyed;
  thread_local Eigen::Matrix2Xd tile;
  thread_local BasisValues bic;
  thread_local Eigen::MatrixXd w, res;
  keyed.clear();
  for (Eigen::Index p = 0; p < q; ++p) {
    const double m = std::max(pts(0, p), pts(1, p));
    int key = -1;
    if (m > 0.0) {
      int e = 0;
      std::frexp(m, &e);
      const int l = std::max(0, -e);
      if (l <= kLevels) {
        const double h = std::ldexp(1.0, -l - 1);
        const int k = pts(0, p) >= h ? (pts(1, p) >= h ? 2 : 1) : 3;
        key = 3 * l + (k - 1);
      }
    }
    keyed.emplace_back(key, p);
  }
  std::sort(keyed.begin(), keyed.end());
  std::size_t a = 0;
  while (a < keyed.size()) {
    std::size_t b = a;
    while (b < keyed.size() && keyed[b].first == keyed[a].first) ++b;
    const int key = keyed[a].first;
    const Eigen::Index g = static_cast<Eigen::Index>(b - a);
    if (key < 0) {
      for (std::size_t i = a; i < b; ++i) {
        const Eigen::Index p = keyed[i].second;
        out.zero_column(p, derivatives);
        out.value.col(p) = el.limit;
      }
      a = b;
      continue;
    }
    const int l = key / 3, k = key % 3 + 1;
    const double h = std::ldexp(1.0, -l - 1), scale = std::ldexp(1.0, l + 1);
    tile.resize(2, g);
    for (std::size_t i = a; i < b; ++i) {
      const Eigen::Index p = keyed[i].second, c = static_cast<Eigen::Index>(i - a);
      const double u = pts(0, p), v = pts(1, p);
      tile(0, c) = (k == 3 ? u : u - h) * scale;
      tile(1, c) = (k == 1 ? v : v - h) * scale;
    }
    bicubic_values(tile, derivatives, scale, bic);
    const auto j = static_cast<std::size_t>(l - 1), kk = static_cast<std::size_t>(k - 1);
    auto scatter = [&](const Eigen::MatrixXd& src, Eigen::MatrixXd& dst) {
      res.noalias() = w.transpose() * src;
      for (std::size_t i = a; i < b; ++i) dst.col(keyed[i].second) = res.col(static_cast<Eigen::Index>(i - a));
    };
    if (l == 0) w = el.level0[kk];
    else w.noalias() = el.config->tile_ops[j][kk] * el.level1;
    scatter(bic.value, out.value);
    // Derivatives annihilate the constant mode; at levels >= 1 it is removed exactly beforehand.
    if (l > 0 && derivatives >= 1) w.noalias() = el.config->tile_ops_deriv[j][kk] * el.level1_deriv;
    if (derivatives >= 1) {
      scatter(bic.du, out.du);
      scatter(bic.dv, out.dv);
    }
    if (derivatives >= 2) {
      scatter(bic.duu, out.duu);
      scatter(bic.duv, out.duv);
      scatter(bic.dvv, out.dvv);
    }
    a = b;
  }
}

}  // namespace iga::basis::catmull_clark
