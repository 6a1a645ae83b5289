#include "basis/thb/dyadic_levels.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>

#include "basis/bspline/extraction.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "core/error.hpp"

namespace iga::basis::thb {

using hierarchical::Key;

DyadicKnots::DyadicKnots(const bspline::KnotVector& coarse) : p_(coarse.degree()) {
  static std::atomic<std::uint64_t> instances{0};
  id_ = ++instances;
  const std::vector<double>& t = coarse.knots();
  for (Index i = p_; i <= coarse.num_basis(); ++i) {
    const double x = t[static_cast<std::size_t>(i)];
    if (b_.empty() || x > b_.back()) {
      b_.push_back(x);
      mult_.push_back(0);
    }
  }
  for (double x : t) {
    for (std::size_t c = 0; c < b_.size(); ++c) {
      if (x == b_[c]) ++mult_[c];
    }
  }
  k_ = static_cast<Index>(b_.size()) - 1;
  extra_.assign(static_cast<std::size_t>(k_), 0);
  for (Index c = 1; c < k_; ++c) extra_[static_cast<std::size_t>(c)] = extra_[static_cast<std::size_t>(c - 1)] + mult_[static_cast<std::size_t>(c)] - 1;
}

int DyadicKnots::max_level() const {
  int m = 0;
  while (m < 44 && (Key{k_ + p_ + extra_.back()} << (m + 1)) < (Key{1} << 60)) ++m;
  // A level's breakpoints must stay distinct doubles: its intervals at least 64 rounding units of their knots wide
  // (a narrower coarse interval would be "halved" into repeated knots).
  for (Index c = 0; c < k_; ++c) {
    const double a = b_[static_cast<std::size_t>(c)], b = b_[static_cast<std::size_t>(c + 1)];
    const double unit = std::nextafter(std::max(std::abs(a), std::abs(b)), HUGE_VAL) - std::max(std::abs(a), std::abs(b));
    while (m > 0 && std::ldexp(b - a, -m) < 64.0 * unit) --m;
  }
  return m;
}

Key DyadicKnots::span(int level, Key interval) const {
  return p_ + interval + extra_[static_cast<std::size_t>(interval >> level)];
}

double DyadicKnots::breakpoint(int level, Key j) const {
  const Index c = static_cast<Index>(j >> level);
  if (c >= k_) return b_.back();
  const Key r = j - (Key{c} << level);
  return b_[static_cast<std::size_t>(c)] +
         (b_[static_cast<std::size_t>(c + 1)] - b_[static_cast<std::size_t>(c)]) * std::ldexp(static_cast<double>(r), -level);
}

int DyadicKnots::multiplicity(int level, Key j) const {
  if (j == 0 || j == num_intervals(level)) return p_ + 1;
  const Key c = j >> level;
  return (c << level) == j ? mult_[static_cast<std::size_t>(c)] : 1;
}

void DyadicKnots::window(int level, Key interval, double* w) const {
  // Left: t_mu down to t_{mu-p}, walking breakpoints interval, interval-1, ... with their multiplicities.
  int filled = 0;
  for (Key j = interval; filled <= p_; --j) {
    const double x = breakpoint(level, j);
    for (int m = multiplicity(level, j); m > 0 && filled <= p_; --m) w[p_ - filled++] = x;
  }
  filled = 0;
  for (Key j = interval + 1; filled <= p_; ++j) {
    const double x = breakpoint(level, j);
    for (int m = multiplicity(level, j); m > 0 && filled <= p_; --m) w[p_ + 1 + filled++] = x;
  }
}

void DyadicKnots::support(int level, Key function, Key& first, Key& last) const {
  // span() is strictly increasing in the interval: first = min{i : span(i) >= f}, last = max{i : span(i) - p <= f}.
  const Key n = num_intervals(level);
  Key lo = 0, hi = n - 1;
  while (lo < hi) {
    const Key mid = (lo + hi) / 2;
    if (span(level, mid) >= function) hi = mid; else lo = mid + 1;
  }
  first = lo;
  lo = first;
  hi = n - 1;
  while (lo < hi) {
    const Key mid = (lo + hi + 1) / 2;
    if (span(level, mid) - p_ <= function) lo = mid; else hi = mid - 1;
  }
  last = lo;
}

void DyadicKnots::refinement(int level, Key interval, int half, Eigen::MatrixXd& k) const {
  // The hierarchical builds ask for both halves of an interval in turn, and for its neighbours: the last 64
  // relations per thread are kept (direct-mapped by the interval's low bits), ahead of the shared cache (perf of
  // the adaptive L-shape: a third of the refine step's relation time was that cache's key and lock).
  struct Recent {
    std::uint64_t owner = 0;
    int level = -1, half = 0;
    Key interval = -1;
    Eigen::MatrixXd k;
  };
  thread_local std::array<Recent, 64> recent;
  Recent& r = recent[(static_cast<std::size_t>(interval) * 2 + static_cast<std::size_t>(half)) & 63];
  if (r.owner == id_ && r.level == level && r.interval == interval && r.half == half) {
    k = r.k;
    return;
  }
  shared_refinement(level, interval, half, k);
  r.owner = id_;
  r.level = level;
  r.interval = interval;
  r.half = half;
  r.k = k;
}

void DyadicKnots::shared_refinement(int level, Key interval, int half, Eigen::MatrixXd& k) const {
  double wc[32], wf[32];
  window(level, interval, wc);
  window(level + 1, 2 * interval + half, wf);
  // The relation depends only on the knot windows up to an affine change of the parameter: cache it by the
  // windows normalised to the parent interval (interior intervals of dyadic levels all share one).
  const double a = wc[p_], h = wc[p_ + 1] - wc[p_];
  std::vector<long long> key(static_cast<std::size_t>(4 * p_ + 4));
  for (int i = 0; i < 2 * p_ + 2; ++i) {
    key[static_cast<std::size_t>(i)] = std::llround((wc[i] - a) / h * 1e12);
    key[static_cast<std::size_t>(2 * p_ + 2 + i)] = std::llround((wf[i] - a) / h * 1e12);
  }
  {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    const auto it = cache_.find(key);
    if (it != cache_.end()) {
      k = it->second;
      return;
    }
  }
  k.resize(p_ + 1, p_ + 1);
  for (int b = 0; b <= p_; ++b) k.col(b) = bspline::blossom_row(wc, p_, wf + b + 1);
  std::lock_guard<std::mutex> lock(cache_mutex_);
  cache_.emplace(std::move(key), k);
}

DyadicBsplineLevels::DyadicBsplineLevels(const bspline::KnotVector& u, const bspline::KnotVector& v) : u_(u), v_(v) {
  if (u.degree() > 15 || v.degree() > 15) throw UnsupportedError("THB splines: degrees above 15 are not supported");
}

int DyadicBsplineLevels::max_level() const { return std::min(u_.max_level(), v_.max_level()); }

Key DyadicBsplineLevels::child(int level, Key cell, int slot) const {
  const Key nx = u_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  return (2 * ix + (slot & 1)) + 2 * nx * (2 * iy + (slot >> 1));
}

Key DyadicBsplineLevels::parent(int level, Key cell, int& slot) const {
  const Key nx = u_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  slot = static_cast<int>((ix & 1) + 2 * (iy & 1));
  return (ix >> 1) + (nx >> 1) * (iy >> 1);
}

void DyadicBsplineLevels::child_map(int, Key, int slot, Eigen::Matrix2d& a, Eigen::Vector2d& b) const {
  a = 0.5 * Eigen::Matrix2d::Identity();
  b = Eigen::Vector2d(0.5 * (slot & 1), 0.5 * (slot >> 1));
}

int DyadicBsplineLevels::local_functions(int level, Key cell, Key* out) const {
  const Key nx = u_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  const int p = u_.degree(), q = v_.degree();
  const Key fx = u_.span(level, ix) - p, fy = v_.span(level, iy) - q;
  const Key nfx = u_.num_functions(level);
  int n = 0;
  for (int b = 0; b <= q; ++b) {
    for (int a = 0; a <= p; ++a) out[n++] = (fx + a) + nfx * (fy + b);
  }
  return n;
}

void DyadicBsplineLevels::support(int level, Key function, std::vector<Key>& cells) const {
  const Key nfx = u_.num_functions(level), nx = u_.num_intervals(level);
  Key x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  u_.support(level, function % nfx, x0, x1);
  v_.support(level, function / nfx, y0, y1);
  cells.clear();
  for (Key iy = y0; iy <= y1; ++iy) {
    for (Key ix = x0; ix <= x1; ++ix) cells.push_back(ix + nx * iy);
  }
}

void DyadicBsplineLevels::support_extension(int level, Key cell, std::vector<Key>& cells) const {
  // The box from the first local function's first interval to the last one's last, in each direction.
  const Key nx = u_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  Key x0 = 0, x1 = 0, y0 = 0, y1 = 0, unused = 0;
  u_.support(level, u_.span(level, ix) - u_.degree(), x0, unused);
  u_.support(level, u_.span(level, ix), unused, x1);
  v_.support(level, v_.span(level, iy) - v_.degree(), y0, unused);
  v_.support(level, v_.span(level, iy), unused, y1);
  cells.clear();
  for (Key y = y0; y <= y1; ++y) {
    for (Key x = x0; x <= x1; ++x) cells.push_back(x + nx * y);
  }
}

void DyadicBsplineLevels::refinement(int level, Key cell, int slot, Eigen::MatrixXd& k) const {
  const Key nx = u_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  thread_local Eigen::MatrixXd ku, kv;
  u_.refinement(level, ix, slot & 1, ku);
  v_.refinement(level, iy, slot >> 1, kv);
  const Index nu = ku.rows(), nv = kv.rows();
  k.resize(nu * nv, nu * nv);
  for (Index bi = 0; bi < nv; ++bi) {
    for (Index bj = 0; bj < nv; ++bj) k.block(bi * nu, bj * nu, nu, nu) = kv(bi, bj) * ku;
  }
}

void DyadicBsplineLevels::evaluate(int level, Key cell, const Eigen::Matrix2Xd& pts, int derivatives,
                                   BasisValues& out) const {
  const Key nx = u_.num_intervals(level);
  double w[32];
  u_.window(level, cell % nx, w);
  thread_local Eigen::MatrixXd cu, cv;
  cu = bspline::extraction_operator(w, u_.degree());
  v_.window(level, cell / nx, w);
  cv = bspline::extraction_operator(w, v_.degree());
  bspline::evaluate_bezier_tensor(cu, cv, pts, derivatives, out);
}

int DyadicBsplineLevels::boundary_part(int level, Key cell, int side) const {
  const Key nx = u_.num_intervals(level), ny = v_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  switch (side) {
    case 0: return iy == 0 ? 0 : -1;
    case 1: return ix == nx - 1 ? 1 : -1;
    case 2: return iy == ny - 1 ? 2 : -1;
    default: return ix == 0 ? 3 : -1;
  }
}

Key DyadicBsplineLevels::neighbour(int level, Key cell, int side, int& their_side) const {
  const Key nx = u_.num_intervals(level);
  their_side = (side + 2) % 4;
  switch (side) {
    case 0: return cell - nx;
    case 1: return cell + 1;
    case 2: return cell + nx;
    default: return cell - 1;
  }
}

int DyadicBsplineLevels::continuity(int level, Key cell, int side) const {
  const Key nx = u_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  switch (side) {
    case 0: return v_.degree() - v_.multiplicity(level, iy);
    case 1: return u_.degree() - u_.multiplicity(level, ix + 1);
    case 2: return v_.degree() - v_.multiplicity(level, iy + 1);
    default: return u_.degree() - u_.multiplicity(level, ix);
  }
}

Eigen::Vector4d DyadicBsplineLevels::cell_box(int level, Key cell) const {
  const Key nx = u_.num_intervals(level);
  const Key ix = cell % nx, iy = cell / nx;
  return {u_.breakpoint(level, ix), u_.breakpoint(level, ix + 1), v_.breakpoint(level, iy), v_.breakpoint(level, iy + 1)};
}

std::shared_ptr<const hierarchical::HierarchicalSpace> coarse_thb_space(const bspline::KnotVector& u,
                                                                       const bspline::KnotVector& v) {
  return std::make_shared<const hierarchical::HierarchicalSpace>(std::make_shared<const DyadicBsplineLevels>(u, v),
                                                                 hierarchical::RefinedCells{});
}

}  // namespace iga::basis::thb
