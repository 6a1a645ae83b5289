#include "basis/polyhedral/space.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <tuple>
#include <unordered_map>

#include "basis/polyhedral/masks.hpp"
#include "core/error.hpp"

namespace iga::basis::polyhedral {
namespace {

// Cubic Bernstein polynomials and their first and second derivatives at t.
struct Cubic {
  std::array<double, 4> b, d1, d2;
  explicit Cubic(double t) {
    const double s = 1.0 - t;
    b = {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
    d1 = {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t};
    d2 = {6.0 * s, -12.0 * s + 6.0 * t, 6.0 * s - 12.0 * t, 6.0 * t};
  }
};

// The BB rows of side `side` (sides as in space.hpp: 0 (t,0), 1 (1,t), 2 (1-t,1), 3 (0,1-t)), in the
// direction of t. Row of b_ij is 4j + i.
std::array<int, 4> side_rows(int side) {
  switch (side) {
    case 0: return {0, 1, 2, 3};
    case 1: return {3, 7, 11, 15};
    case 2: return {15, 14, 13, 12};
    default: return {12, 8, 4, 0};
  }
}

}  // namespace

PolyhedralSpace::PolyhedralSpace(const mesh::PolyMesh& net) : net_(net), sites_(classify(net)) {
  // Every configuration must have a mask: name each missing one once, with its count and first site.
  std::map<std::pair<int, int>, std::pair<int, std::string>> missing;
  for (const ConfigurationSite& s : sites_) {
    std::string reason;
    if (has_mask(s.type, s.valence)) {
      try {
        native_mask(s.type, s.valence);
        continue;
      } catch (const UnsupportedError& e) {
        reason = std::string("; ") + e.what();
      }
    }
    auto& m = missing[{static_cast<int>(s.type), s.valence}];
    if (m.first++ == 0) m.second = (s.at_face ? "face " : "vertex ") + std::to_string(s.centre + 1) + reason;
  }
  if (!missing.empty()) {
    std::string what;
    for (const auto& [key, m] : missing) {
      const auto c = static_cast<Configuration>(key.first);
      what += (what.empty() ? "" : ", ") + to_string(c) +
              (c == Configuration::Regular || c == Configuration::T0 || c == Configuration::T1 || c == Configuration::T2
                   ? ""
                   : " n=" + std::to_string(key.second)) +
              " ×" + std::to_string(m.first) + " (first at " + m.second + ")";
    }
    throw UnsupportedError("polyhedral splines: no mask is available yet in this build for the configurations " +
                           what + " of this net; the surface would have holes");
  }
  std::vector<Index> dof_of_vertex(static_cast<std::size_t>(net.num_vertices()), -1);
  for (Index si = 0; si < static_cast<Index>(sites_.size()); ++si) {
    const ConfigurationSite& s = sites_[static_cast<std::size_t>(si)];
    const ConfigurationMask& mask = bicubic_mask(s.type, s.valence);
    if (mask.gathered != static_cast<int>(s.gathered.size())) {
      throw NumericalError("polyhedral splines: the " + to_string(s.type) + " mask gathers " +
                           std::to_string(mask.gathered) + " vertices, the classifier " +
                           std::to_string(s.gathered.size()));
    }
    // Local dofs: the distinct gathered vertices in order of first appearance; repeated columns summed.
    std::vector<Index> local;
    std::vector<int> column_to_local(s.gathered.size());
    for (std::size_t k = 0; k < s.gathered.size(); ++k) {
      const Index v = s.gathered[k];
      Index& d = dof_of_vertex[static_cast<std::size_t>(v)];
      if (d < 0) {
        d = static_cast<Index>(vertex_of_dof_.size());
        vertex_of_dof_.push_back(v);
      }
      const auto it = std::find(local.begin(), local.end(), d);
      column_to_local[k] = static_cast<int>(it - local.begin());
      if (it == local.end()) local.push_back(d);
    }
    for (int p = 0; p < static_cast<int>(mask.patches.size()); ++p) {
      Element e;
      e.site = si;
      e.patch = p;
      e.dofs = local;
      e.c = Eigen::MatrixXd::Zero(16, static_cast<Eigen::Index>(local.size()));
      const Eigen::MatrixXd& m = mask.patches[static_cast<std::size_t>(p)].coefficients;
      for (std::size_t k = 0; k < s.gathered.size(); ++k) e.c.col(column_to_local[k]) += m.col(static_cast<Eigen::Index>(k));
      max_local_ = std::max<Index>(max_local_, static_cast<Index>(local.size()));
      elements_.push_back(std::move(e));
    }
  }
  if (elements_.empty()) throw InputError("polyhedral splines: the net produces no patch (the outer layer recedes)");
  build_sides();
}

ElementKind PolyhedralSpace::kind(Index e) const {
  const ConfigurationSite& s = sites_[static_cast<std::size_t>(site(e))];
  switch (s.type) {
    case Configuration::Polar: return {Shape::Quad, Family::Polar, s.valence, false};
    case Configuration::T0:
    case Configuration::T1:
    case Configuration::T2: return {Shape::Quad, Family::TJunction, 4, false};
    default: return {Shape::Quad, Family::Regular, 4, false};
  }
}

std::span<const Index> PolyhedralSpace::dofs(Index e) const { return elements_[static_cast<std::size_t>(e)].dofs; }

void PolyhedralSpace::evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  const Eigen::Index n = el.c.cols(), q = pts.cols();
  out.resize(n, q, derivatives);
  using Vec16 = Eigen::Matrix<double, 16, 1>;
  Vec16 b, bu, bv, buu, buv, bvv;
  for (Eigen::Index k = 0; k < q; ++k) {
    const Cubic cu(pts(0, k)), cv(pts(1, k));
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        const int r = 4 * j + i;
        b(r) = cu.b[i] * cv.b[j];
        if (derivatives >= 1) {
          bu(r) = cu.d1[i] * cv.b[j];
          bv(r) = cu.b[i] * cv.d1[j];
        }
        if (derivatives >= 2) {
          buu(r) = cu.d2[i] * cv.b[j];
          buv(r) = cu.d1[i] * cv.d1[j];
          bvv(r) = cu.b[i] * cv.d2[j];
        }
      }
    }
    out.value.col(k).noalias() = el.c.transpose() * b;
    if (derivatives >= 1) {
      out.du.col(k).noalias() = el.c.transpose() * bu;
      out.dv.col(k).noalias() = el.c.transpose() * bv;
    }
    if (derivatives >= 2) {
      out.duu.col(k).noalias() = el.c.transpose() * buu;
      out.duv.col(k).noalias() = el.c.transpose() * buv;
      out.dvv.col(k).noalias() = el.c.transpose() * bvv;
    }
  }
}

void PolyhedralSpace::build_sides() {
  // A generic embedding of the dofs: sides that run along the same curve in it do so for every net.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  Eigen::MatrixXd probe(num_dofs(), 3);
  for (Index d = 0; d < num_dofs(); ++d) probe.row(d) << coord(rng), coord(rng), coord(rng);
  // Each side sampled at t = k/16, k = 0..16: sides that share a curve do so as wholes, halves or quarters (a coarse
  // patch's side next to four patches of a refined configuration: issue 32 found such sides, each reported as two
  // boundary slits inside square_evs.obj), and every such piece's samples land on samples of the longer side.
  constexpr int kSamples = 17;
  const Index nsides = 4 * num_elements();
  std::vector<std::array<Eigen::Vector3d, kSamples>> samples(static_cast<std::size_t>(nsides));
  double scale = 0.0;
  for (Index e = 0; e < num_elements(); ++e) {
    const Element& el = elements_[static_cast<std::size_t>(e)];
    Eigen::MatrixXd local(static_cast<Eigen::Index>(el.dofs.size()), 3);
    for (std::size_t a = 0; a < el.dofs.size(); ++a) local.row(static_cast<Eigen::Index>(a)) = probe.row(el.dofs[a]);
    const Eigen::MatrixXd bb = el.c * local;  // 16 × 3
    for (int side = 0; side < 4; ++side) {
      const auto rows = side_rows(side);
      for (int k = 0; k < kSamples; ++k) {
        const Cubic c(k / 16.0);
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for (int i = 0; i < 4; ++i) x += c.b[static_cast<std::size_t>(i)] * bb.row(rows[static_cast<std::size_t>(i)]).transpose();
        samples[static_cast<std::size_t>(4 * e + side)][static_cast<std::size_t>(k)] = x;
        scale = std::max(scale, x.cwiseAbs().maxCoeff());
      }
    }
  }
  const double tol = 1e-9 * std::max(1.0, scale);
  // Every sample point of every side in two grids of cell 16·tol, the second shifted by half a cell:
  // two points within tol share a cell of at least one grid unless they straddle a cell face of each grid in
  // different coordinates (probability ~(tol/cell)², negligible).
  using Key = std::array<long long, 3>;
  const double cell = 16 * tol;
  auto key = [&](const Eigen::Vector3d& x, double shift) {
    return Key{static_cast<long long>(std::floor(x(0) / cell + shift)), static_cast<long long>(std::floor(x(1) / cell + shift)),
               static_cast<long long>(std::floor(x(2) / cell + shift))};
  };
  std::vector<std::pair<Key, Index>> grid[2];  // sorted by key
  for (int gi = 0; gi < 2; ++gi) {
    grid[gi].reserve(static_cast<std::size_t>(kSamples * nsides));
    for (Index s = 0; s < nsides; ++s) {
      for (int k = 0; k < kSamples; ++k) grid[gi].emplace_back(key(samples[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)], 0.5 * gi), s);
    }
    std::sort(grid[gi].begin(), grid[gi].end());
  }
  auto same = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).cwiseAbs().maxCoeff() <= tol; };
  // Whether side a runs along side b over b's range (r0, r1) (r0, r1 multiples of 1/4, either order): a(t) =
  // b(r0 + t (r1 − r0)), checked at the samples of a that land on samples of b (all 17 for a whole, 9 for a half,
  // 5 for a quarter).
  auto along = [&](Index sa, Index sb, double r0, double r1) {
    const auto& a = samples[static_cast<std::size_t>(sa)];
    const auto& b = samples[static_cast<std::size_t>(sb)];
    for (int k = 0; k < kSamples; ++k) {
      const double r = 16.0 * (r0 + (k / 16.0) * (r1 - r0));  // b's sample index, when integral
      const double ri = std::round(r);
      if (std::abs(r - ri) > 1e-12) continue;
      if (!same(a[static_cast<std::size_t>(k)], b[static_cast<std::size_t>(ri)])) return false;
    }
    return true;
  };
  // The ranges of a piece: whole, halves, quarters, each either way.
  std::vector<std::array<double, 2>> ranges;
  for (const int n : {1, 2, 4}) {
    for (int j = 0; j < n; ++j) {
      ranges.push_back({static_cast<double>(j) / n, static_cast<double>(j + 1) / n});
      ranges.push_back({static_cast<double>(j + 1) / n, static_cast<double>(j) / n});
    }
  }
  // How side s meets side o: s runs along o over o's range (r0, r1) (s the shorter or equal), or o is a piece of s
  // (`piece_of_s`: the piece is listed from o), or not along a curve.
  struct Match {
    bool found = false, piece_of_s = false;
    double r0 = 0.0, r1 = 1.0;
  };
  auto match = [&](Index s, Index o) {
    for (const auto& r : ranges) {
      if (along(s, o, r[0], r[1])) return Match{true, false, r[0], r[1]};
    }
    for (const auto& r : ranges) {
      if (std::abs(r[1] - r[0]) < 1.0 && along(o, s, r[0], r[1])) return Match{true, true, 0.0, 0.0};
    }
    return Match{};
  };
  // A side whose samples coincide (the collapsed side of a polar patch at its pole) is a point, no edge.
  auto degenerate = [&](Index s) {
    const auto& a = samples[static_cast<std::size_t>(s)];
    return same(a[0], a[8]) && same(a[8], a[16]);
  };
  std::vector<Index> candidates;
  for (Index s = 0; s < nsides; ++s) {
    // Every side that s is a piece of passes through s's midpoint at one of its samples; of the pieces of s, those
    // next to s's midpoint end there.
    candidates.clear();
    const Eigen::Vector3d& mid = samples[static_cast<std::size_t>(s)][8];
    for (int gi = 0; gi < 2; ++gi) {
      const Key k = key(mid, 0.5 * gi);
      const auto first = std::lower_bound(grid[gi].begin(), grid[gi].end(), std::make_pair(k, Index{-1}));
      for (auto it = first; it != grid[gi].end() && it->first == k; ++it) {
        if (it->second / 4 != s / 4) candidates.push_back(it->second);
      }
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    bool covered = false;
    const bool point = degenerate(s);
    for (const Index o : candidates) {
      const Match m = match(s, o);
      if (!m.found) continue;
      covered = true;
      if (point || m.piece_of_s) continue;
      const bool whole = std::abs(std::abs(m.r1 - m.r0) - 1.0) < 1e-12;
      if (whole && o < s) continue;  // the same piece, listed from o
      interior_.push_back({{s / 4, o / 4}, {static_cast<int>(s % 4), static_cast<int>(o % 4)}, {0.0, m.r0}, {1.0, m.r1}, 1});
    }
    if (!covered) boundary_.push_back({s / 4, static_cast<int>(s % 4), 0});
  }
}

Geometry make_polyhedral_geometry(const mesh::PolyMesh& net) {
  auto space = std::make_shared<const PolyhedralSpace>(net);
  const int dim = net.is_planar() ? 2 : 3;
  Eigen::MatrixXd cp(space->num_dofs(), dim);
  for (Index d = 0; d < space->num_dofs(); ++d) cp.row(d) = net.point(space->vertex(d)).head(dim).transpose();
  return Geometry(space, std::move(cp));
}

}  // namespace iga::basis::polyhedral
