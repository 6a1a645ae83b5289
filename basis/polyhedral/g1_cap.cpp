#include "basis/polyhedral/g1_cap.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/SVD>

namespace iga::basis::polyhedral {
namespace {

constexpr int kCapDegree = 3;
constexpr int kCapCoefficients = (kCapDegree + 1) * (kCapDegree + 1);
/// Samples per shared boundary: C0 and (4) are polynomial identities of degree 3 in t here (cap cross
/// derivative: degree 3; a·∂p: 1 + 2; b·∂_t p: 2 + 1 on the outer edges, 1 + 2 on the spokes), so 4
/// distinct points force them; 8 leave margin for reparameterisations of higher degree.
constexpr int kEdgeSamples = 8;
/// Relative singular-value threshold of the rank decisions.
constexpr double kRankTolerance = 1e-10;

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

/// 5-point Gauss–Legendre rule on [0, 1] (exact to degree 9).
constexpr std::array<double, 5> kGaussNodes = {0.0469100770306680, 0.2307653449471585, 0.5,
                                               0.7692346550528415, 0.9530899229693320};
constexpr std::array<double, 5> kGaussWeights = {0.1184634425280945, 0.2393143352496832, 0.2844444444444444,
                                                 0.2393143352496832, 0.1184634425280945};

}  // namespace

Eigen::MatrixXd fairness_gram(Fairness fairness, int degree_u, int degree_v) {
  std::vector<std::pair<std::array<int, 2>, double>> terms;
  if (fairness == Fairness::ThinPlate)
    terms = {{{2, 0}, 1.0}, {{1, 1}, 2.0}, {{0, 2}, 1.0}};
  else
    terms = {{{3, 0}, 1.0}, {{2, 1}, 3.0}, {{1, 2}, 3.0}, {{0, 3}, 1.0}};
  const int n = (degree_u + 1) * (degree_v + 1);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd d(n);
  for (std::size_t a = 0; a < kGaussNodes.size(); ++a)
    for (std::size_t b = 0; b < kGaussNodes.size(); ++b)
      for (const auto& [k, w] : terms) {
        for (int j = 0; j <= degree_v; ++j)
          for (int i = 0; i <= degree_u; ++i)
            d(j * (degree_u + 1) + i) = bernstein_derivative(degree_u, i, kGaussNodes[a], k[0]) *
                                        bernstein_derivative(degree_v, j, kGaussNodes[b], k[1]);
        h += (w * kGaussWeights[a] * kGaussWeights[b]) * d * d.transpose();
      }
  return h;
}

double bernstein(int degree, int i, double t) {
  if (i < 0 || i > degree) return 0.0;
  return binomial(degree, i) * std::pow(t, i) * std::pow(1.0 - t, degree - i);
}

double bernstein_derivative(int degree, int i, double t, int order) {
  if (order == 0) return bernstein(degree, i, t);
  if (degree == 0) return 0.0;
  // d/dt B^d_i = d (B^{d−1}_{i−1} − B^{d−1}_i)
  return degree * (bernstein_derivative(degree - 1, i - 1, t, order - 1) -
                   bernstein_derivative(degree - 1, i, t, order - 1));
}

G1CapSystem::G1CapSystem(int cap_patches, int gathered) : cap_patches_(cap_patches), gathered_(gathered) {
  for (int k = 0; k < cap_patches; ++k)
    patches_.push_back(Patch{kCapDegree, kCapDegree, k * kCapCoefficients, Eigen::MatrixXd()});
}

int G1CapSystem::add_known_patch(int degree_u, int degree_v, Eigen::MatrixXd coefficients) {
  if (coefficients.rows() != (degree_u + 1) * (degree_v + 1) || coefficients.cols() != gathered_)
    throw std::invalid_argument("G1CapSystem::add_known_patch: coefficient matrix has the wrong shape");
  patches_.push_back(Patch{degree_u, degree_v, -1, std::move(coefficients)});
  return static_cast<int>(patches_.size()) - 1;
}

Eigen::RowVectorXd G1CapSystem::evaluate(int patch, double u, double v, int du, int dv) const {
  const Patch& p = patches_.at(static_cast<std::size_t>(patch));
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(cap_patches_ * kCapCoefficients + gathered_);
  for (int j = 0; j <= p.degree_v; ++j)
    for (int i = 0; i <= p.degree_u; ++i) {
      const double w =
          bernstein_derivative(p.degree_u, i, u, du) * bernstein_derivative(p.degree_v, j, v, dv);
      const int index = j * (p.degree_u + 1) + i;
      if (p.offset >= 0)
        row(p.offset + index) += w;
      else
        row.tail(gathered_) += w * p.known.row(index);
    }
  return row;
}

// Directional derivative of order (order_cross along e.cross, order_along along e.along) at e(t); orders ≤ 1.
Eigen::RowVectorXd G1CapSystem::directional(const CapEdge& e, double t, int order_cross,
                                            int order_along) const {
  const Eigen::Vector2d x = e.origin + t * e.along;
  if (order_cross == 0 && order_along == 0) return evaluate(e.patch, x(0), x(1), 0, 0);
  const Eigen::Vector2d d = order_cross == 1 ? e.cross : e.along;
  return d(0) * evaluate(e.patch, x(0), x(1), 1, 0) + d(1) * evaluate(e.patch, x(0), x(1), 0, 1);
}

void G1CapSystem::add_row(const Eigen::RowVectorXd& row) {
  const double norm = row.norm();
  if (norm > 0.0) rows_.push_back(row / norm);
}

void G1CapSystem::join_c0(const CapEdge& q, const CapEdge& p) {
  for (int m = 0; m < kEdgeSamples; ++m) {
    const double t = (m + 0.5) / kEdgeSamples;
    add_row(directional(q, t, 0, 0) - directional(p, t, 0, 0));
  }
}

void G1CapSystem::join_g1(const CapEdge& q, const CapEdge& p, const EdgeFunction& a, const EdgeFunction& b) {
  join_c0(q, p);
  for (int m = 0; m < kEdgeSamples; ++m) {
    const double t = (m + 0.5) / kEdgeSamples;
    // (4): ∂_cross q + a ∂_cross p − b ∂_t p = 0
    add_row(directional(q, t, 1, 0) + a(t) * directional(p, t, 1, 0) - b(t) * directional(p, t, 0, 1));
  }
}

CapDerivation solve_cap_constraints(const std::vector<Eigen::RowVectorXd>& rows, int patches, int degree_u,
                                    int degree_v, int gathered, Fairness fairness, const std::string& what) {
  const int coefficients = (degree_u + 1) * (degree_v + 1);
  const int unknowns = patches * coefficients;
  const int m = static_cast<int>(rows.size());
  Eigen::MatrixXd a(m, unknowns), b(m, gathered);
  for (int r = 0; r < m; ++r) {
    a.row(r) = rows[static_cast<std::size_t>(r)].head(unknowns);
    b.row(r) = -rows[static_cast<std::size_t>(r)].tail(gathered);
  }

  // rank A and rank [A | B] (both from singular values, relative threshold)
  Eigen::BDCSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const double threshold = kRankTolerance * (sigma.size() > 0 ? sigma(0) : 1.0);
  int rank = 0;
  while (rank < sigma.size() && sigma(rank) > threshold) ++rank;
  Eigen::MatrixXd ab(m, unknowns + gathered);
  ab << a, b;
  const Eigen::VectorXd sigma_ab = Eigen::BDCSVD<Eigen::MatrixXd>(ab).singularValues();
  const double threshold_ab = kRankTolerance * (sigma_ab.size() > 0 ? sigma_ab(0) : 1.0);
  int rank_ab = 0;
  while (rank_ab < sigma_ab.size() && sigma_ab(rank_ab) > threshold_ab) ++rank_ab;
  if (rank_ab != rank)
    throw std::runtime_error(what + ": inconsistent constraints (rank A = " + std::to_string(rank) +
                             ", rank [A|B] = " + std::to_string(rank_ab) + ")");

  // particular (least-norm) solution and null space of A
  const Eigen::MatrixXd& v = svd.matrixV();
  // x_p = V_r y with y the least-squares solution of (A V_r) y = B (full column rank; a Householder QR
  // is more accurate here than BDCSVD's U, whose errors reached 1e-11 in A x_p − B for n = 7)
  const Eigen::MatrixXd v_r = v.leftCols(rank);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a * v_r);
  Eigen::MatrixXd x = v_r * qr.solve(b);
  x += v_r * qr.solve(b - a * x);  // one step of iterative refinement
  const Eigen::MatrixXd null = v.rightCols(unknowns - rank);

  // fairness: minimise (x_p + N z)ᵀ H (x_p + N z) over z
  if (null.cols() > 0) {
    const Eigen::MatrixXd h_patch = fairness_gram(fairness, degree_u, degree_v);
    Eigen::MatrixXd hn(unknowns, null.cols()), hx(unknowns, gathered);
    for (int k = 0; k < patches; ++k) {
      const int o = k * coefficients;
      hn.middleRows(o, coefficients) = h_patch * null.middleRows(o, coefficients);
      hx.middleRows(o, coefficients) = h_patch * x.middleRows(o, coefficients);
    }
    const Eigen::MatrixXd reduced = null.transpose() * hn;
    x += null * reduced.ldlt().solve(-(null.transpose() * hx));
  }

  CapDerivation d;
  d.unknowns = unknowns;
  d.equations = m;
  d.rank = rank;
  d.rank_augmented = rank_ab;
  d.null_dimension = unknowns - rank;
  d.constraint_residual = m > 0 ? (a * x - b).cwiseAbs().maxCoeff() : 0.0;
  d.mask.gathered = gathered;
  for (int k = 0; k < patches; ++k)
    d.mask.patches.push_back(PatchMask{degree_u, degree_v, x.middleRows(k * coefficients, coefficients)});
  return d;
}

CapDerivation G1CapSystem::solve(Configuration configuration, int valence, Fairness fairness) const {
  const auto start = std::chrono::steady_clock::now();
  CapDerivation d = solve_cap_constraints(rows_, cap_patches_, kCapDegree, kCapDegree, gathered_, fairness,
                                          "G1CapSystem, configuration " +
                                              std::to_string(static_cast<int>(configuration)) +
                                              ", n = " + std::to_string(valence));
  d.mask.configuration = configuration;
  d.mask.valence = valence;
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

SectorCapSystem::SectorCapSystem(int sectors, bool split, int gathered)
    : sectors_(sectors), split_(split), system_(split ? 4 * sectors : sectors, gathered) {
  if (!split_) return;
  // C1 between the four sub-patches of every sector (a = 1, b = 0 in (4))
  const EdgeFunction one = [](double) { return 1.0; };
  const EdgeFunction zero = [](double) { return 0.0; };
  for (int k = 0; k < sectors_; ++k) {
    for (int beta = 0; beta < 2; ++beta)  // across u = 1/2
      system_.join_g1(CapEdge{4 * k + 2 * beta + 1, {0, 0}, {0, 1}, {1, 0}},
                      CapEdge{4 * k + 2 * beta, {1, 0}, {0, 1}, {-1, 0}}, one, zero);
    for (int alpha = 0; alpha < 2; ++alpha)  // across v = 1/2
      system_.join_g1(CapEdge{4 * k + 2 + alpha, {0, 0}, {1, 0}, {0, 1}},
                      CapEdge{4 * k + alpha, {0, 1}, {1, 0}, {0, -1}}, one, zero);
  }
}

// Sub-patch edge of the sector-level edge e (of sector e.patch) on the segment t ∈ [t0, t0 + 1/2].
CapEdge SectorCapSystem::segment(const CapEdge& e, double t0) const {
  const Eigen::Vector2d mid = e.origin + (t0 + 0.25) * e.along;
  const int alpha = mid(0) < 0.5 ? 0 : 1;
  const int beta = mid(1) < 0.5 ? 0 : 1;
  CapEdge s;
  s.patch = 4 * e.patch + 2 * beta + alpha;
  s.origin = 2.0 * (e.origin + t0 * e.along) - Eigen::Vector2d(alpha, beta);
  s.along = e.along;        // τ ∈ [0, 1] covers half the sector edge at twice the sub-patch's scale
  s.cross = 2.0 * e.cross;  // the sector-level cross derivative
  return s;
}

void SectorCapSystem::join(const CapEdge& q, const CapEdge& p, bool p_is_sector, const EdgeFunction& a,
                           const EdgeFunction& b) {
  if (!split_) {
    system_.join_g1(q, p, a, b);
    return;
  }
  for (double t0 : {0.0, 0.5}) {
    CapEdge ps = p;
    if (p_is_sector) {
      ps = segment(p, t0);
    } else {
      ps.origin = p.origin + t0 * p.along;
      ps.along = 0.5 * p.along;
    }
    // d/dτ = ½ d/dt on both sides, so b multiplies twice the local tangent
    system_.join_g1(
        segment(q, t0), ps, [a, t0](double tau) { return a(t0 + 0.5 * tau); },
        [b, t0](double tau) { return 2.0 * b(t0 + 0.5 * tau); });
  }
}

}  // namespace iga::basis::polyhedral
