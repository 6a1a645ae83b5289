#include "quadrature/exact/irregular_integrals.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "basis/catmull_clark/exact_view.hpp"
#include "basis/catmull_clark/stam.hpp"
#include "basis/catmull_clark/subdivision_matrix.hpp"
#include "core/error.hpp"
#include "quadrature/exact/subdivision_integrals.hpp"

namespace iga::quadrature::exact {

namespace {

using basis::catmull_clark::StamEvaluator;


// Stam's element of valence n on its own 2n+8 points (the scheme-neutral view, exact_view.hpp).
basis::SubdivisionElement stam_element(int n) {
  const int m = 2 * n + 8;
  return {&basis::catmull_clark::stam_view(n), Eigen::MatrixXd::Identity(m, m), 0, {}};
}

// E_k = X^k Ā (16 × (2n+8)): tile k of level 1 in terms of the level-0 points.
std::array<Eigen::MatrixXd, 3> stam_tiles(const StamEvaluator& st) {
  std::array<Eigen::MatrixXd, 3> t;
  for (int k = 1; k <= 3; ++k) t[static_cast<std::size_t>(k - 1)] = st.picking_matrix(k) * st.extended_subdivision_matrix();
  return t;
}

IrregularIntegrals compute(int n) {
  const basis::SubdivisionElement el = stam_element(n);
  IrregularIntegrals r;
  r.phi = element_integral(el);
  r.phi_phi = element_gram(el, -1, -1);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) r.d[i][j] = element_gram(el, i, j);
  return r;
}

}  // namespace

const IrregularIntegrals& irregular_integrals(int n) {
  basis::catmull_clark::check_valence(n);
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const IrregularIntegrals>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<const IrregularIntegrals>(compute(n));
  return *slot;
}

std::array<std::array<Eigen::MatrixXd, 3>, 3> second_derivative_products(int n) {
  basis::catmull_clark::check_valence(n);
  const StamEvaluator& st = basis::catmull_clark::stam_evaluator(n);
  const auto tiles = stam_tiles(st);
  const Eigen::MatrixXd& a = st.subdivision_matrix();
  std::array<std::array<Eigen::MatrixXd, 3>, 3> c;
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(a.rows(), a.cols());
  for (int d = 0; d < 3; ++d) {
    for (int e = 0; e < 3; ++e) {
      const Eigen::MatrixXd gram = tile_gram2(d, e);
      auto& cde = c[static_cast<std::size_t>(d)][static_cast<std::size_t>(e)];
      cde = Eigen::MatrixXd::Zero(a.rows(), a.cols());
      for (const auto& t : tiles) cde.noalias() += t.transpose() * gram * t;
    }
    total += c[static_cast<std::size_t>(d)][static_cast<std::size_t>(d)];
  }
  // Modes whose second derivatives vanish identically (C v = 0 for the positive semidefinite sum of the
  // diagonal blocks) are deflated; every other mode must satisfy 4 λ² < 1.
  const Eigen::MatrixXd& v = st.eigenvectors();
  const Eigen::MatrixXd& vinv = st.inverse_eigenvectors();
  const Eigen::VectorXd& lambda = st.eigenvalues();
  std::vector<Eigen::Index> dropped;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    const bool annihilated = (total * v.col(i)).norm() <= 1e-10 * total.norm() * v.col(i).norm();
    if (annihilated) {
      dropped.push_back(i);
    } else if (4.0 * lambda(i) * lambda(i) >= 1.0) {
      throw UnsupportedError("exact integration: second-derivative products at an extraordinary vertex of valence " +
                             std::to_string(n) + " are infinite: the eigenfunction of eigenvalue " +
                             std::to_string(lambda(i)) + " has non-zero second derivatives that grow like (4λ)^l " +
                             "on level l (area 4^-l), so ∫|∂²φ|² = Σ (4λ²)^l diverges (4λ² = " +
                             std::to_string(4.0 * lambda(i) * lambda(i)) + " >= 1; n >= 5)");
    }
  }
  Eigen::MatrixXd right(a.rows(), static_cast<Eigen::Index>(dropped.size()));
  Eigen::MatrixXd left(static_cast<Eigen::Index>(dropped.size()), a.cols());
  Eigen::VectorXd lam(static_cast<Eigen::Index>(dropped.size()));
  for (std::size_t k = 0; k < dropped.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    right.col(i) = v.col(dropped[k]);
    left.row(i) = vinv.row(dropped[k]);
    lam(i) = lambda(dropped[k]);
  }
  const Eigen::MatrixXd b = deflate_modes(a, right, left, lam);
  // Level l: area 4^-l, each second derivative 4^l: sum_l 4^l (B^(l-1))^T C B^(l-1) = 4 sum_j 4^j (...).
  for (auto& row : c)
    for (auto& m : row) m = 4.0 * stein(b, m, 4.0);
  return c;
}

Tensor3 triple(int n, Factor da, Factor db, Factor dc) {
  basis::catmull_clark::check_valence(n);
  return element_triple(stam_element(n), da, db, dc);
}

}  // namespace iga::quadrature::exact
