#include "basis/half_box/subdivision_structure.hpp"

#include <Eigen/LU>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "basis/half_box/local_net.hpp"
#include "basis/half_box/patch_net.hpp"
#include "basis/half_box/subdivision.hpp"
#include "core/error.hpp"

namespace iga::basis::half_box {

int tile_of(double u, double v) {
  if (u >= 0.5) return 0;
  if (v >= 0.5) return 1;
  return 2;
}

Eigen::MatrixXd SubdivisionStructure::picking_matrix(int tile) const {
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(kRegularPatchSize, extended_matrix.rows());
  for (int i = 0; i < kRegularPatchSize; ++i) x(i, picking[static_cast<std::size_t>(tile)][static_cast<std::size_t>(i)]) = 1.0;
  return x;
}

namespace {

// Rows `rows` and columns `cols` of the prolongation; every row must have all its weight inside `cols`.
Eigen::MatrixXd restrict_rows(const Eigen::SparseMatrix<double>& p, const std::vector<Index>& rows,
                              const std::vector<Index>& cols) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> pr = p;
  std::map<Index, int> col_of;
  for (std::size_t j = 0; j < cols.size(); ++j) col_of[cols[j]] = static_cast<int>(j);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(pr, rows[i]); it; ++it) {
      const auto c = col_of.find(it.col());
      if (c == col_of.end()) throw NumericalError("half-box local subdivision: a stencil leaves the local net");
      m(static_cast<Index>(i), c->second) = it.value();
    }
  return m;
}

void expect(bool ok, const char* what) {
  if (!ok) throw NumericalError(std::string("half-box local subdivision: ") + what);
}

// Generates ring_matrix, patch_matrix, extended_matrix, picking and tiles from ring_net(n).
void generate_matrices(int n, SubdivisionStructure& s) {
  const mesh::PolyMesh net = ring_net(n);
  const NetSubdivision sub = subdivide_local(net);
  const mesh::PolyMesh& fine = sub.net;
  // Thesis ordering: new v_k0 = S1 corner in the n-gon, v_k1 = S2(v_k0), v_k2 / v_k3 = S1 corners at v_k0 in
  // H_k / H_(k+1).
  std::vector<Index> ring_rows, ring_cols;
  for (int k = 0; k < n; ++k) {
    const Index v = 4 * k;
    ring_rows.push_back(half_edge_of(net, 0, v));
    ring_rows.push_back(sub.vertex_point[static_cast<std::size_t>(v)]);
    ring_rows.push_back(half_edge_of(net, 1 + k, v));
    ring_rows.push_back(half_edge_of(net, 1 + (k + 1) % n, v));
    for (int j = 0; j < 4; ++j) ring_cols.push_back(v + j);
  }
  s.ring_matrix = restrict_rows(sub.prolongation, ring_rows, ring_cols);

  // The coarse EF patch of v_00 (F0 = the n-gon) and its one-step refinement.
  const Index h0 = net.face_half_edge(0);
  const PatchNet coarse = gather_patch(net, h0);
  const Index h1 = net.half_edge(net.half_edge(h0).prev).twin, h2 = net.half_edge(net.half_edge(h1).prev).twin;
  const Index hex01 = sub.edge_face[static_cast<std::size_t>(net.half_edge(h0).prev)];  // edge (v, u0): F0|F1
  const Index hex12 = sub.edge_face[static_cast<std::size_t>(net.half_edge(h1).prev)];  // edge (v, spoke)
  const Index hex20 = sub.edge_face[static_cast<std::size_t>(h0)];                      // edge (v, p1): F2|F0
  const Index v = coarse.vertex;
  // Child patches: (fine vertex, its F'_0, expected F'_1, F'_2) — the corners of each child counter-clockwise.
  struct Child { Index vertex, f0, f1, f2; };
  const Child ef{h0, coarse.faces[0], hex01, hex20};
  const std::array<Child, 3> tiles{Child{h1, hex01, coarse.faces[1], hex12}, Child{h2, hex20, hex12, coarse.faces[2]},
                                   Child{sub.vertex_point[static_cast<std::size_t>(v)], hex01, hex12, hex20}};
  auto gather = [&](const Child& c) {
    const PatchNet p = gather_patch(fine, half_edge_of(fine, c.f0, c.vertex));
    expect(p.faces[1] == c.f1 && p.faces[2] == c.f2, "child faces are not in the expected order");
    return p.points;
  };
  std::vector<Index> rows = gather(ef);
  const std::size_t np = rows.size();
  std::map<Index, int> position;
  for (std::size_t i = 0; i < np; ++i) position[rows[i]] = static_cast<int>(i);
  for (int k = 0; k < 3; ++k) {
    const std::vector<Index> t = gather(tiles[static_cast<std::size_t>(k)]);
    for (int i = 0; i < kRegularPatchSize; ++i) {
      const Index p = t[static_cast<std::size_t>(i)];
      if (!position.count(p)) {
        position[p] = static_cast<int>(rows.size());
        rows.push_back(p);
      }
      s.picking[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)] = position[p];
    }
  }
  expect(rows.size() == np + 9, "a layer does not have patch_size + 9 points");
  s.extended_matrix = restrict_rows(sub.prolongation, rows, coarse.points);
  s.patch_matrix = s.extended_matrix.topRows(static_cast<Index>(np));
  s.tiles[0] = {2.0 * Eigen::Matrix2d::Identity(), Eigen::Vector2d(-1.0, 0.0)};
  s.tiles[1] = {2.0 * Eigen::Matrix2d::Identity(), Eigen::Vector2d(0.0, -1.0)};
  s.tiles[2].jacobian << 2.0, 2.0, -2.0, 0.0;
  s.tiles[2].offset = Eigen::Vector2d(-1.0, 1.0);
}

// Left eigenvector of 1 (normalised to sum 1) and the spectral projector of the eigenvalue 1/2.
void generate_spectral_parts(SubdivisionStructure& s) {
  const Eigen::MatrixXd& a = s.patch_matrix;
  const Index np = a.rows();
  const Eigen::MatrixXd id = Eigen::MatrixXd::Identity(np, np);
  Eigen::FullPivLU<Eigen::MatrixXd> lu0(a.transpose() - id);
  lu0.setThreshold(1e-10);
  const Eigen::MatrixXd w = lu0.kernel();
  expect(w.cols() == 1, "the eigenvalue 1 is not simple");
  s.limit_stencil = (w.col(0) / w.col(0).sum()).transpose();
  Eigen::FullPivLU<Eigen::MatrixXd> lr(a - 0.5 * id), ll(a.transpose() - 0.5 * id);
  lr.setThreshold(1e-10);
  ll.setThreshold(1e-10);
  const Eigen::MatrixXd r = lr.kernel(), l = ll.kernel().transpose();
  expect(r.cols() == l.rows() && r.cols() >= 2, "eigenvalue 1/2: left and right eigenspaces differ");
  const Eigen::MatrixXd lrm = l * r;
  Eigen::FullPivLU<Eigen::MatrixXd> g(lrm);
  expect(g.isInvertible() && g.rcond() > 1e-8, "the eigenvalue 1/2 is defective");
  s.half_projector = r * g.solve(l);
}

// Tile operators of every layer and order, the cached powers and the tangent stencils.
void generate_operators(SubdivisionStructure& s) {
  const Eigen::MatrixXd& a = s.patch_matrix;
  const Index np = a.rows();
  const Eigen::MatrixXd id = Eigen::MatrixXd::Identity(np, np);
  const Eigen::MatrixXd one_w0 = Eigen::VectorXd::Ones(np) * s.limit_stencil;
  const Eigen::MatrixXd b = a - one_w0;
  Eigen::MatrixXd pa = id, pb = id - one_w0;  // m = 0; B^m = A^m − 1 w0 for m >= 1
  s.operators_.assign(static_cast<std::size_t>(6 * kCachedLayers), Eigen::MatrixXd());
  s.powers_.clear();
  std::array<Eigen::MatrixXd, 3> xa;
  for (int k = 0; k < 3; ++k) xa[static_cast<std::size_t>(k)] = s.picking_matrix(k) * s.extended_matrix;
  for (int m = 0; m < kCachedLayers; ++m) {
    s.powers_.push_back(pa);
    for (int k = 0; k < 3; ++k) {
      const Eigen::MatrixXd& x = xa[static_cast<std::size_t>(k)];
      s.operators_[static_cast<std::size_t>((0 * 3 + k) * kCachedLayers + m)] = x * pa;
      s.operators_[static_cast<std::size_t>((1 * 3 + k) * kCachedLayers + m)] = x * pb;
    }
    pa = a * pa;
    pb = b * pb;
  }
  s.bezier_operators_.clear();
  for (const Eigen::MatrixXd& op : s.operators_) s.bezier_operators_.emplace_back(op.transpose() * bezier_matrix().transpose());
  // Tangent stencils: lim 2^(l−1) ∇ X Ā B^(l−1) = ∇ X Ā P at the centroid of tile 2 of layer 1.
  const TileMap& t = s.tiles[2];
  const Eigen::Vector2d c = t.jacobian * Eigen::Vector2d(1.0 / 3.0, 1.0 / 3.0) + t.offset;
  BernsteinValues bv;
  bernstein_cubic(c(0), c(1), 1, bv);
  const Eigen::Matrix<double, kRegularPatchSize, 1> hs = bezier_matrix().transpose() * bv.du,
                                                    ht = bezier_matrix().transpose() * bv.dv;
  const Eigen::RowVectorXd ds = hs.transpose() * xa[2] * s.half_projector,
                           dt = ht.transpose() * xa[2] * s.half_projector;
  s.tangent_stencils.resize(2, np);
  s.tangent_stencils.row(0) = t.jacobian(0, 0) * ds + t.jacobian(1, 0) * dt;
  s.tangent_stencils.row(1) = t.jacobian(0, 1) * ds + t.jacobian(1, 1) * dt;
}

}  // namespace

const SubdivisionStructure& subdivision_structure(int valence) {
  if (valence < kMinValence || valence > kMaxValence)
    throw UnsupportedError("half-box: extraordinary faces of " + std::to_string(valence) + " vertices are not supported (" +
                           std::to_string(kMinValence) + ".." + std::to_string(kMaxValence) + ")");
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const SubdivisionStructure>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[valence];
  if (!slot) {
    auto s = std::make_unique<SubdivisionStructure>();
    s->valence = valence;
    generate_matrices(valence, *s);
    generate_spectral_parts(*s);
    generate_operators(*s);
    slot = std::move(s);
  }
  return *slot;
}

}  // namespace iga::basis::half_box
