#include "refine/refine_smooth_stream.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include <emmintrin.h>

#include "core/error.hpp"

namespace iga::refine::detail {
namespace {

constexpr Index mark_spacing = 4096;  // original knots between two generator marks
constexpr Index block = 1024;         // final positions per block
constexpr Index chunk = 32 * block;   // positions per OpenMP work item

// Walks the knot intervals [t_j, t_{j+1}] in order and tells which one has a new knot.
struct Cursor {
  const double* t = nullptr;
  Index k = 0;
  const NewKnots* nk = nullptr;
  Index j = 0;  // the interval
  Index i = 0;  // new knots in the intervals before j (for sorted knots: the next one)

  // The rule of NewKnots in full (for the pass that checks that each sorted knot gets its own interval).
  bool peek_checked(double& x) const {
    if (j + 1 >= k) return false;
    if (nk->per_interval) {
      x = nk->per_interval[j];
      return !std::isnan(x);
    }
    if (i >= nk->count || j < nk->first || j > nk->last) return false;
    x = nk->sorted[i];
    return t[j] < t[j + 1] && t[j] <= x && (x < t[j + 1] || j == nk->last);
  }
  // The same once that is known: the next sorted knot is never below t_j, nor in an interval below first.
  bool peek(double& x) const {
    if (nk->per_interval) {
      if (j + 1 >= k) return false;
      x = nk->per_interval[j];
      return !std::isnan(x);
    }
    if (i >= nk->count) return false;
    x = nk->sorted[i];
    return x < t[j + 1] || j == nk->last;
  }
  void next(bool had) {
    i += had;
    ++j;
  }
};

// Merges the knots with the new ones: Z entry by Z entry, each with its code 2·j + (new ? 1 : 0), j the
// original knot at or below it (so count_le = j + 1, and a new entry lies in interval j).
struct Generator {
  Cursor cur;     // phase 0: t_{cur.j} is next; phase 1: t_{cur.j} was emitted, its interval's knot is next
  int phase = 0;
  Index z = 0;    // Z index of the next entry

  void seek(Index z0, const std::vector<Index>& marks) {
    Index c = std::min(static_cast<Index>(marks.size()) - 1, z0 / mark_spacing);  // z(j) >= j
    while (c > 0 && c * mark_spacing + marks[static_cast<std::size_t>(c)] > z0) --c;
    cur.j = c * mark_spacing;
    cur.i = marks[static_cast<std::size_t>(c)];
    z = cur.j + cur.i;
    phase = 0;
    for (;;) {
      double x;
      const bool has = cur.peek(x);
      if (z + 1 + has > z0) break;
      z += 1 + has;
      cur.next(has);
    }
    if (z < z0) {  // z0 is the new knot of interval cur.j
      phase = 1;
      ++z;
    }
  }
  void emit(double& u, std::int32_t& code) {
    ++z;
    if (phase == 0) {
      u = cur.t[cur.j];
      code = static_cast<std::int32_t>(2 * cur.j);
      phase = 1;
      return;
    }
    double x;
    if (cur.peek(x)) {
      u = x;
      code = static_cast<std::int32_t>(2 * cur.j + 1);
      cur.next(true);
      phase = 0;
      return;
    }
    cur.next(false);
    u = cur.t[cur.j];
    code = static_cast<std::int32_t>(2 * cur.j);
  }
};

// What all blocks share.
struct Shape {
  int d = 0;
  const double* t = nullptr;
  Index k = 0;
  const double* cp = nullptr;  // column-major, rows × dim
  Index rows = 0, dim = 0;
  const NewKnots* nk = nullptr;
  std::vector<Index> marks;  // new knots in the intervals before j = c · mark_spacing
  Index nz = 0;              // |Z|
  Index pf = 0, n = 0;       // the first position (a Z index, or the Z interval (pf, pf+1) for even d); count
  int lambda0 = 0, levels = 0;
  Index expected = 0;        // surviving points = output rows
  Index zt0 = 0, zt1 = 0;    // Z range of the output knots
  double* out = nullptr;     // column-major, expected × dim
  double* knots = nullptr;   // output knots for Z indices zt0..zt1-1

  Cursor cursor() const { return Cursor{t, k, nk, 0, 0}; }
  Index count_before(Index r) const {  // new knots in the intervals before r
    Cursor c = cursor();
    c.j = r / mark_spacing * mark_spacing;
    c.i = marks[static_cast<std::size_t>(r / mark_spacing)];
    double x;
    while (c.j < r) c.next(c.peek(x));
    return c.i;
  }
  Index z_of(Index r) const { return r + count_before(r); }  // Z index of the original knot t_r
};

// The Z entries the current block reads, [base, gen.z), filled forward by the generator; before each block
// the entries no longer needed are dropped from the front. Writes the output knots it owns on the way.
struct Window {
  std::vector<double> u;
  std::vector<std::int32_t> code;
  Index base = 0;  // Z index of entry 0
  Generator gen;   // gen.z: the end of the window
  Index own0 = 0, own1 = 0;  // output knots written here: Z indices [own0, own1)

  double at(Index z) const { return u[static_cast<std::size_t>(z - base)]; }
  std::int32_t code_of(Index z) const { return code[static_cast<std::size_t>(z - base)]; }
  void drop_below(Index z) {
    const Index drop = z - base, keep = gen.z - z;
    if (drop <= 0) return;
    std::copy_n(u.begin() + drop, keep, u.begin());
    std::copy_n(code.begin() + drop, keep, code.begin());
    base = z;
  }
  void fill(const Shape& S, Index upto) {
    if (upto - base > static_cast<Index>(u.size())) {
      throw NumericalError("refine-smooth (internal error): the knot window is too small");
    }
    while (gen.z < upto) {
      const Index z = gen.z;
      const auto slot = static_cast<std::size_t>(z - base);
      gen.emit(u[slot], code[slot]);
      if (z >= own0 && z < own1) S.knots[z - S.zt0] = u[slot];
    }
  }
};

// Refine stage at position p: a copy of an input point, or (3) for a new knot of odd degree.
template <int DIM>
[[gnu::always_inline]] inline int refine_point(const Shape& S, const Window& W, Index p, double* out) {
  const Index dim = DIM > 0 ? DIM : S.dim, h = S.d / 2;
  const std::int32_t code = W.code_of(p);
  const Index r = code >> 1;
  if (S.d % 2 == 0 || !(code & 1)) {
    const double* src = S.cp + (S.d % 2 == 0 ? r - h + 1 : r - h);
    for (Index c = 0; c < dim; ++c) out[c] = src[c * S.rows];
    return 0;
  }
  const Index qa = r - h, qb = r + 1 - h;
  const double ta = S.t[qa], td = S.t[qb + S.d - 1];
  const double w = ratio(W.at(p) - ta, td - ta);
  for (Index c = 0; c < dim; ++c) out[c] = (1.0 - w) * S.cp[qa + c * S.rows] + w * S.cp[qb + c * S.rows];
  return 1;
}

// One smoothing level λ on a block buffer (positions from qlo on): what every position needs.
struct Level {
  const double* t = nullptr;   // the original knots
  const double* u = nullptr;   // window values, position q's Z index at q + zoff
  const std::int32_t* code = nullptr;
  Index zoff = 0, ob = 0, og = 0, s = 0;  // region [β, γ] = [p + ob, p + og]; s: Y knots beyond it in the labels
  Index zlo = 0, zhi = 0;      // window indices of Z indices 0 and nz
  Index k = 0, n = 0, qlo = 0;
  bool odd = false;
  double* buf = nullptr;
  char* valid = nullptr;
};

// Positions [from, to) of the level in place: the actions (a)-(d) of §3.2, markers where the end conditions
// (§7) leave a point undefined (ENDS). Elsewhere (margin in run_chunk) no check can fail: β >= d and
// γ < |Z| - d, so at least d/2 >= s knots of Y lie beyond the region on either side (Z starts and ends in Y
// and has no two new knots in a row), and every neighbour is defined. prev/vprev: P^{λ-2}_{from-1}, carried
// on. Returns the affine combinations made.
template <int DIM, bool ENDS>
[[gnu::always_inline]] inline long long smooth_range(const Level& V, Index dim_, Index from, Index to, double* prev,
                                                     double* old, bool& vprev) {
  const Index dim = DIM > 0 ? DIM : dim_;
  long long combinations = 0;
  for (Index q = from; q < to; ++q) {
    double* self = V.buf + (q - V.qlo) * dim;
    for (Index c = 0; c < dim; ++c) old[c] = self[c];
    const bool vself = !ENDS || V.valid[q - V.qlo];
    const bool has_next = !ENDS || q + 1 < V.n;
    const bool vnext = !ENDS || (has_next && V.valid[q + 1 - V.qlo]);
    const double* next = has_next ? self + dim : old;
    int made = -1;  // -1: marker
    const Index z = q + V.zoff, beta = z + V.ob, gamma = z + V.og;
    if (!ENDS || (vself && beta >= V.zlo && gamma < V.zhi)) {
      const std::int32_t cb = V.code[beta], cg = V.code[gamma];
      const bool nb = cb & 1, ng = cg & 1;
      if (!nb && !ng) {
        made = 0;  // (a): self is P^{λ-2}_q already
      } else {
        const Index ia = ((cb + 1) >> 1) - V.s, id = (cg >> 1) + V.s;  // the labels t_alpha, t_delta
        if (!ENDS || (ia >= 0 && id < V.k)) {
          const double ta = V.t[ia], td = V.t[id];
          if (nb && !ng) {  // (b): new knot below, from P_q and P_{q+1}
            if (vnext) {
              const double w1 = ratio(V.u[beta] - ta, td - ta), w0 = 1.0 - w1;
              for (Index c = 0; c < dim; ++c) self[c] = w0 * old[c] + w1 * next[c];
              made = 1;
            }
          } else if (!nb) {  // (c): new knot above, from P_{q-1} and P_q
            if (vprev) {
              const double w0 = ratio(td - V.u[gamma], td - ta), w1 = 1.0 - w0;
              for (Index c = 0; c < dim; ++c) self[c] = w0 * prev[c] + w1 * old[c];
              made = 1;
            }
          } else if (vprev && vnext) {  // (d): both, factorised about the pivot (6)-(8) when it lies inside
            const double ub = V.u[beta], ug = V.u[gamma];
            const double x = V.odd ? V.u[z] : 0.5 * (V.u[z] + V.u[z + 1]);
            if (ta < x && x < td) {
              const double dm = (td - ug) / (td - x), de = (ub - ta) / (x - ta), pm = (td - x) / (td - ta);
              for (Index c = 0; c < dim; ++c) {
                self[c] = pm * (dm * prev[c] + (1.0 - dm) * old[c]) + (1.0 - pm) * ((1.0 - de) * old[c] + de * next[c]);
              }
              made = 3;
            } else {  // (5) unfactorised
              const double w0 = ratio(td - ug, td - ta), w2 = ratio(ub - ta, td - ta), w1 = 1.0 - w0 - w2;
              for (Index c = 0; c < dim; ++c) self[c] = w0 * prev[c] + w1 * old[c] + w2 * next[c];
              made = 2;
            }
          }
        }
      }
    }
    if (ENDS) {
      V.valid[q - V.qlo] = made >= 0;
      if (made > 0) combinations += made;
    } else {
      combinations += made;
    }
    for (Index c = 0; c < dim; ++c) prev[c] = old[c];  // P^{λ-2}_{q-1} of the next position
    vprev = vself;
  }
  return combinations;
}

// One smoothing level λ in place on positions [lo, hi) of the block buffer; returns the affine combinations
// made at positions inside [b0, b1) (the others belong to the neighbouring blocks).
template <int DIM, bool ENDS>
long long smooth(const Shape& S, const Window& W, int lambda, Index lo, Index hi, Index qlo, Index b0, Index b1,
                 double* buf, char* valid, double* scratch) {
  const Index dim = DIM > 0 ? DIM : S.dim;
  Level V;
  V.t = S.t;
  V.u = W.u.data();
  V.code = W.code.data();
  V.zoff = S.pf - W.base;
  V.odd = S.d % 2;
  V.ob = V.odd ? -(lambda - 1) / 2 : 1 - lambda / 2;
  V.og = V.odd ? (lambda - 1) / 2 : lambda / 2;
  V.s = (S.d - lambda + 2) / 2;
  V.zlo = -W.base;
  V.zhi = S.nz - W.base;
  V.k = S.k;
  V.n = S.n;
  V.qlo = qlo;
  V.buf = buf;
  V.valid = valid;
  // P^{λ-2}_{q-1} and P^{λ-2}_q: local (registers) for a compile-time dimension.
  double fixed[2][DIM > 0 ? DIM : 1] = {};
  double* prev = DIM > 0 ? fixed[0] : scratch;
  double* old = DIM > 0 ? fixed[1] : scratch + dim;
  bool vprev = !ENDS;
  if (lo > 0) {
    for (Index c = 0; c < dim; ++c) prev[c] = buf[(lo - 1 - qlo) * dim + c];
    if (ENDS) vprev = valid[lo - 1 - qlo];
  }
  const Index m0 = std::clamp(b0, lo, hi), m1 = std::clamp(b1, m0, hi);
  smooth_range<DIM, ENDS>(V, dim, lo, m0, prev, old, vprev);
  const long long combinations = smooth_range<DIM, ENDS>(V, dim, m0, m1, prev, old, vprev);
  smooth_range<DIM, ENDS>(V, dim, m1, hi, prev, old, vprev);
  return combinations;
}

// dst[q] = src[q * stride], q < m, with non-temporal stores: the output is written once and not read here,
// so it need not be fetched into the cache first.
inline void stream_column(double* dst, const double* src, Index stride, Index m) {
  Index q = 0;
  if (reinterpret_cast<std::uintptr_t>(dst) % 16 != 0 && m > 0) {
    dst[0] = src[0];
    q = 1;
  }
  for (; q + 1 < m; q += 2) _mm_stream_pd(dst + q, _mm_set_pd(src[(q + 1) * stride], src[q * stride]));
  if (q < m) dst[q] = src[q * stride];
}

// Final positions [c0, c1): block by block. `first` is the first surviving position (found here if < 0),
// `got` counts the points written.
template <int DIM>
long long run_chunk(const Shape& S, Index c0, Index c1, Index& first, Index& got) {
  const Index dim = DIM > 0 ? DIM : S.dim;
  // Markers (§7) arise within d positions of the ends of Z and spread one position per level.
  const Index margin = 2 * S.d + 2 * S.levels + 4;
  const Index reach = S.d / 2 + 1;  // Z entries a position reads on either side
  const Index span = block + 2 * S.levels + 2 * reach + S.pf + 8;
  Window W;
  W.u.resize(static_cast<std::size_t>(span));
  W.code.resize(static_cast<std::size_t>(span));
  W.gen.cur = S.cursor();
  W.own0 = std::max(S.zt0, c0 == 0 ? Index{0} : S.pf + c0);
  W.own1 = std::min(S.zt1, c1 == S.n ? S.nz : S.pf + c1);
  const Index z_start = c0 == 0 ? 0 : std::max(Index{0}, S.pf + std::max(Index{0}, c0 - S.levels) - reach);
  W.gen.seek(std::min(z_start, W.own0), S.marks);
  W.base = W.gen.z;

  const Index width = block + 2 * S.levels;
  std::vector<double> buf(static_cast<std::size_t>(width * dim)), scratch(static_cast<std::size_t>(2 * dim));
  std::vector<char> valid(static_cast<std::size_t>(width));
  long long combinations = 0;
  Index written = 0;
  for (Index b0 = c0; b0 < c1; b0 += block) {
    const Index b1 = std::min(b0 + block, c1);
    const Index qlo = std::max(Index{0}, b0 - S.levels), qhi = std::min(S.n, b1 + S.levels);
    W.drop_below(std::min(W.gen.z, std::max(W.base, S.pf + qlo - reach)));
    W.fill(S, std::min(S.nz, S.pf + qhi + reach));
    for (Index q = qlo; q < qhi; ++q) {
      const int c = refine_point<DIM>(S, W, S.pf + q, buf.data() + (q - qlo) * dim);
      if (q >= b0 && q < b1) combinations += c;
      valid[static_cast<std::size_t>(q - qlo)] = 1;
    }
    const bool inner = first >= 0 && qlo >= margin && qhi <= S.n - margin;
    for (int l = 0; l < S.levels; ++l) {
      const Index lo = std::max(Index{0}, b0 - S.levels + l + 1), hi = std::min(S.n, b1 + S.levels - l - 1);
      combinations += inner ? smooth<DIM, false>(S, W, S.lambda0 + 2 * l, lo, hi, qlo, b0, b1, buf.data(),
                                                 valid.data(), scratch.data())
                            : smooth<DIM, true>(S, W, S.lambda0 + 2 * l, lo, hi, qlo, b0, b1, buf.data(),
                                                valid.data(), scratch.data());
    }
    if (inner) {  // every point survives
      if (b0 < first || b1 - first > S.expected) {
        throw NumericalError("refine-smooth (internal error): more control points survive the end conditions than " +
                             std::to_string(S.expected));
      }
      for (Index c = 0; c < dim; ++c) {
        stream_column(S.out + c * S.expected + (b0 - first), buf.data() + (b0 - qlo) * dim + c, dim, b1 - b0);
      }
      written += b1 - b0;
      continue;
    }
    for (Index q = b0; q < b1; ++q) {
      const bool v = valid[static_cast<std::size_t>(q - qlo)];
      if (v && first < 0) first = q;
      const Index row = first < 0 ? -1 : q - first;
      if (v != (row >= 0 && row < S.expected)) {
        throw NumericalError("refine-smooth (internal error): the control points surviving the end conditions are not " +
                             std::to_string(S.expected) + " consecutive ones");
      }
      if (!v) continue;
      const double* src = buf.data() + (q - qlo) * dim;
      for (Index c = 0; c < dim; ++c) S.out[row + c * S.expected] = src[c];
      ++written;
    }
  }
  got += written;
  _mm_sfence();
  W.drop_below(W.gen.z);
  W.fill(S, W.own1);
  return combinations;
}

template <int DIM>
long long run_all(const Shape& S) {
  Index first = -1, got = 0, c0 = 0;
  long long combinations = 0;
  // Serially until the first surviving point is known (the first chunk, unless the curve is tiny).
  while (c0 < S.n && first < 0) {
    const Index c1 = std::min(S.n, c0 + chunk);
    combinations += run_chunk<DIM>(S, c0, c1, first, got);
    c0 = c1;
  }
  if (c0 < S.n) {
    if (first < 0) throw NumericalError("refine-smooth (internal error): no control point survived the end conditions");
    const Index chunks = (S.n - c0 + chunk - 1) / chunk;
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : combinations, got)
    for (Index c = 0; c < chunks; ++c) {
      try {
        Index f = first;
        combinations += run_chunk<DIM>(S, c0 + c * chunk, std::min(S.n, c0 + (c + 1) * chunk), f, got);
      } catch (...) {
#pragma omp critical(iga_refine_smooth_error)
        if (!error) error = std::current_exception();
      }
    }
    if (error) std::rethrow_exception(error);
  }
  if (got != S.expected) {
    throw NumericalError("refine-smooth (internal error): " + std::to_string(got) + " control points survived the end conditions, " +
                         std::to_string(S.expected) + " expected");
  }
  return combinations;
}

}  // namespace

void zero_span() { throw NumericalError("refine-and-smooth: a zero knot span in an affine combination"); }

void check_new_knot(const double* t, Index k, Index j, double x, int d) {
  if (t[j] < x && x < t[j + 1]) return;  // strictly inside: a simple knot
  Index m = 1;                           // only the runs at the interval ends can equal x
  for (Index i = j; i >= 0 && t[i] == x; --i) ++m;
  for (Index i = j + 1; i < k && t[i] == x; ++i) ++m;
  if (m > d) {
    char text[48];
    std::snprintf(text, sizeof text, "%.17g", x);
    throw InputError("the knot " + std::string(text) + " would appear " + std::to_string(m) +
                     " times: refine-smooth keeps the curve C^0 at least, so a knot appears at most degree (" +
                     std::to_string(d) + ") times (boehm and oslo allow degree + 1)");
  }
}

bool refine_smooth_stream(int d, const double* t, Index k, const Eigen::MatrixXd& cp, const NewKnots& knots,
                          long long& count, Eigen::MatrixXd& out, std::vector<double>& out_knots,
                          std::size_t offset) {
  if (k > (Index{1} << 29)) throw UnsupportedError("refine-smooth: more than 2^29 knots are not supported");
  Shape S;
  S.d = d;
  S.t = t;
  S.k = k;
  S.cp = cp.data();
  S.rows = cp.rows();
  S.dim = cp.cols();
  S.nk = &knots;
  // One pass over the intervals: the marks, the multiplicity check, and whether every sorted knot found
  // an interval of its own.
  Cursor c = S.cursor();
  for (; c.j < k;) {
    if (c.j % mark_spacing == 0) S.marks.push_back(c.i);
    double x;
    const bool has = c.peek_checked(x);
    if (has && !(t[c.j] < x && x < t[c.j + 1])) check_new_knot(t, k, c.j, x, d);
    c.next(has);
  }
  if (!knots.per_interval && c.i != knots.count) return false;
  S.nz = k + c.i;
  const Index h = d / 2;
  const Index last = d % 2 ? S.z_of(k - 1 - h) : S.z_of(k - h) - 1;
  S.pf = d % 2 ? S.z_of(h) : S.z_of(h - 1);
  S.n = last - S.pf + 1;
  S.lambda0 = 2 + d % 2;
  S.levels = d >= S.lambda0 ? (d - S.lambda0) / 2 + 1 : 0;
  // §7: the points left are the control points whose arguments reach into [u_a, u_b].
  const Index a = S.z_of(d - 1), b = S.z_of(k - d);
  S.expected = b - a + d;
  S.zt0 = a - d + 1;
  S.zt1 = b + d;
  out.resize(S.expected, S.dim);
  out_knots.resize(offset + static_cast<std::size_t>(S.zt1 - S.zt0) + offset);
  S.out = out.data();
  S.knots = out_knots.data() + offset;
  switch (S.dim) {
    case 1: count += run_all<1>(S); break;
    case 2: count += run_all<2>(S); break;
    case 3: count += run_all<3>(S); break;
    case 4: count += run_all<4>(S); break;
    default: count += run_all<0>(S); break;
  }
  return true;
}

}  // namespace iga::refine::detail
