// refine_net: OpenSubdiv's uniform refinement with the prolongation matrix, against the limit surface of
// CatmullClarkSpace on the coarse and the refined net (the same surface, exactly: refinability).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <array>
#include <map>
#include <memory>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <random>
#include <vector>

#include "basis/catmull_clark/space.hpp"
#include "core/error.hpp"
#include "osd_reference.hpp"

namespace {

namespace Osd = OpenSubdiv::OPENSUBDIV_VERSION;
using iga::Index;
using iga::basis::BasisValues;
using iga::basis::catmull_clark::CatmullClarkSpace;
using iga::basis::catmull_clark::refine_net;
using iga::mesh::PolyMesh;

// Grid of nx × ny unit quads with random z; with `fan` an extra vertex of valence 5 or a boundary EV:
// interior EV: the quad grid's centre vertex gets one extra sector by splitting a face into... (kept simple:
// fans are built explicitly below).
PolyMesh fan_mesh(int sectors, int k, bool closed, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-0.2, 0.2);
  const int nspokes = closed ? sectors : sectors + 1;
  const double angle = (closed ? 2.0 : 1.0) * M_PI / sectors;
  std::vector<Eigen::Vector3d> p{Eigen::Vector3d(0, 0, d(rng))};
  std::vector<std::vector<Index>> spoke(static_cast<std::size_t>(nspokes), std::vector<Index>(static_cast<std::size_t>(k + 1), 0));
  auto dir = [&](int t) { return Eigen::Vector3d(std::cos(angle * t), std::sin(angle * t), 0.0); };
  for (int t = 0; t < nspokes; ++t) {
    for (int i = 1; i <= k; ++i) {
      spoke[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)] = static_cast<Index>(p.size());
      p.push_back(dir(t) * i / k + Eigen::Vector3d(0, 0, d(rng)));
    }
  }
  std::vector<std::vector<Index>> faces;
  for (int s = 0; s < sectors; ++s) {
    const auto t0 = static_cast<std::size_t>(s), t1 = static_cast<std::size_t>((s + 1) % nspokes);
    std::vector<std::vector<Index>> id(static_cast<std::size_t>(k + 1), std::vector<Index>(static_cast<std::size_t>(k + 1)));
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; j <= k; ++j) {
        Index v;
        if (j == 0) v = spoke[t0][static_cast<std::size_t>(i)];
        else if (i == 0) v = spoke[t1][static_cast<std::size_t>(j)];
        else {
          v = static_cast<Index>(p.size());
          p.push_back((dir(s) * i + dir(s + 1) * j) / k + Eigen::Vector3d(0, 0, d(rng)));
        }
        id[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = v;
      }
    }
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < k; ++j) {
        auto at = [&](int a, int b) { return id[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)]; };
        faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return PolyMesh::build(p, faces);
}

std::unique_ptr<Osd::Far::TopologyRefiner> make_refiner(const PolyMesh& m) { return iga::test::make_osd_refiner(m); }

Eigen::Vector2d corner(int j) {
  static const double c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return {c[((j % 4) + 4) % 4][0], c[((j % 4) + 4) % 4][1]};
}

std::vector<std::pair<std::string, PolyMesh>> nets() {
  return {{"interior EV n=5", fan_mesh(5, 2, true, 1)},
          {"interior EV n=3", fan_mesh(3, 2, true, 2)},
          {"boundary EV faces=4", fan_mesh(4, 2, false, 3)},
          {"boundary EV faces=3", fan_mesh(3, 3, false, 4)}};
}

// Where the vertices of the refined net sit in the native parameterisation of their parent quad (vertex j
// of the quad at corner(j)): OpenSubdiv's child of corner j at corner(j), of edge j at the edge's midpoint,
// of the face at the centre. Returns, for each child face of parent f, its four vertices' positions.
struct ChildMap {
  std::vector<int> parent;                               // fine face -> coarse face
  std::vector<std::array<Eigen::Vector2d, 4>> positions;  // fine face -> its corners in parent coordinates
};

ChildMap child_map(const PolyMesh& m, const PolyMesh& fine_mesh) {
  auto refiner = make_refiner(m);
  refiner->RefineUniform(Osd::Far::TopologyRefiner::UniformOptions(1));
  const auto& coarse = refiner->GetLevel(0);
  ChildMap map;
  map.parent.assign(static_cast<std::size_t>(fine_mesh.num_faces()), -1);
  map.positions.resize(static_cast<std::size_t>(fine_mesh.num_faces()));
  for (int f = 0; f < coarse.GetNumFaces(); ++f) {
    const auto fv = coarse.GetFaceVertices(f);
    const auto fe = coarse.GetFaceEdges(f);
    std::map<Index, Eigen::Vector2d> where;
    for (int j = 0; j < 4; ++j) {
      where[coarse.GetVertexChildVertex(fv[j])] = corner(j);
      where[coarse.GetEdgeChildVertex(fe[j])] = 0.5 * (corner(j) + corner(j + 1));
    }
    where[coarse.GetFaceChildVertex(f)] = Eigen::Vector2d(0.5, 0.5);
    const auto children = coarse.GetFaceChildFaces(f);
    for (int k = 0; k < children.size(); ++k) {
      const auto c = static_cast<std::size_t>(children[k]);
      map.parent[c] = f;
      const auto cv = fine_mesh.face(children[k]);
      for (int j = 0; j < 4; ++j) map.positions[c][static_cast<std::size_t>(j)] = where.at(cv[j]);
    }
  }
  return map;
}

// The ordering refine_net documents: the children of quad f are faces 4f + k, child k in the quarter of f
// at its corner k, with its vertex j at (corner(k) + corner(j)) / 2 in f's coordinates (vertex j of f at
// corner(j)): the child's parameterisation is the quarter of the parent's, (s, t) = (corner(k) + (a, b)) / 2.
TEST(RefineNet, ChildOrdering) {
  for (const auto& [what, m] : nets()) {
    const auto r = refine_net(m, 1);
    const ChildMap map = child_map(m, r.mesh);
    for (Index f = 0; f < m.num_faces(); ++f) {
      for (int k = 0; k < 4; ++k) {
        const auto c = static_cast<std::size_t>(4 * f + k);
        EXPECT_EQ(map.parent[c], f) << what;
        for (int j = 0; j < 4; ++j) {
          EXPECT_EQ(map.positions[c][static_cast<std::size_t>(j)], 0.5 * (corner(k) + corner(j))) << what << " face " << f << " child " << k;
        }
      }
    }
  }
}

TEST(RefineNet, ProlongationAndSameLimitSurface) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const auto& [what, m] : nets()) {
    const auto r = refine_net(m, 1);
    ASSERT_EQ(r.prolongation.rows(), r.mesh.num_vertices());
    ASSERT_EQ(r.prolongation.cols(), m.num_vertices());
    const Eigen::VectorXd rows = r.prolongation * Eigen::VectorXd::Ones(m.num_vertices());
    EXPECT_LE((rows.array() - 1.0).abs().maxCoeff(), 1e-15) << what;
    const CatmullClarkSpace coarse(m), fine(r.mesh);
    ASSERT_EQ(coarse.refinement_steps(), 0);
    ASSERT_EQ(fine.refinement_steps(), 0);
    const ChildMap map = child_map(m, r.mesh);
    const Eigen::MatrixXd pt = Eigen::MatrixXd(r.prolongation).transpose();
    double dev = 0, dev_d = 0;
    BasisValues bc, bf;
    for (Index e = 0; e < coarse.num_elements(); ++e) {
      const int rc = coarse.rotation(e);
      const Eigen::Vector2d q0 = corner(rc), eu = corner(rc + 1) - q0, ev = corner(rc + 3) - q0;
      for (int p = 0; p < 50; ++p) {
        Eigen::Matrix2Xd x(2, 1);
        x << uni(rng), uni(rng);
        if (p % 2 == 1) x *= std::pow(10.0, -8.0 * uni(rng));  // near the EV corner
        const Eigen::Vector2d s = q0 + x(0, 0) * eu + x(1, 0) * ev;  // parent-native coordinates
        // The child containing s, and s in the child's native coordinates (its corners 0, 1, 3 span it).
        Index fe = -1;
        Eigen::Vector2d child = Eigen::Vector2d::Zero();
        for (int k = 0; k < 4 && fe < 0; ++k) {
          const auto& pos = map.positions[static_cast<std::size_t>(4 * e + k)];
          const Eigen::Vector2d a = 4.0 * Eigen::Vector2d((s - pos[0]).dot(pos[1] - pos[0]), (s - pos[0]).dot(pos[3] - pos[0]));
          if (a.minCoeff() >= 0.0 && a.maxCoeff() <= 1.0) {
            fe = 4 * e + k;
            child = a;
          }
        }
        ASSERT_GE(fe, 0);
        const auto& pos = map.positions[static_cast<std::size_t>(fe)];
        const int rf = fine.rotation(fe);
        const Eigen::Vector2d fu = corner(rf + 1) - corner(rf), fv = corner(rf + 3) - corner(rf);
        Eigen::Matrix2Xd y(2, 1);
        y << (child - corner(rf)).dot(fu), (child - corner(rf)).dot(fv);
        coarse.evaluate(e, x, 1, bc);
        fine.evaluate(fe, y, 1, bf);
        Eigen::VectorXd phi_c = Eigen::VectorXd::Zero(m.num_vertices()), phi_f = Eigen::VectorXd::Zero(r.mesh.num_vertices());
        Eigen::VectorXd du_c = phi_c, du_f = phi_f;
        const auto dc = coarse.dofs(e);
        const auto df = fine.dofs(fe);
        for (std::size_t i = 0; i < dc.size(); ++i) phi_c(dc[i]) = bc.value(static_cast<Eigen::Index>(i), 0);
        for (std::size_t i = 0; i < df.size(); ++i) phi_f(df[i]) = bf.value(static_cast<Eigen::Index>(i), 0);
        for (std::size_t i = 0; i < dc.size(); ++i) du_c(dc[i]) = bc.du(static_cast<Eigen::Index>(i), 0);
        // chain rule: coarse u -> parent-native eu -> child-native 4 (eu . (pos1 - pos0), eu . (pos3 - pos0))
        // -> fine element (fu, fv)
        const Eigen::Vector2d dchild = 4.0 * Eigen::Vector2d(eu.dot(pos[1] - pos[0]), eu.dot(pos[3] - pos[0]));
        const double a = dchild.dot(fu), b = dchild.dot(fv);
        for (std::size_t i = 0; i < df.size(); ++i) {
          du_f(df[i]) = a * bf.du(static_cast<Eigen::Index>(i), 0) + b * bf.dv(static_cast<Eigen::Index>(i), 0);
        }
        dev = std::max(dev, (phi_c - pt * phi_f).cwiseAbs().maxCoeff());
        dev_d = std::max(dev_d, (du_c - pt * du_f).cwiseAbs().maxCoeff() / std::max(1.0, du_c.cwiseAbs().maxCoeff()));
      }
    }
    std::printf("[refine] %-20s max|phi_coarse - P^T phi_fine| %.1e, d/du (relative) %.1e\n", what.c_str(), dev, dev_d);
    EXPECT_LE(dev, 1e-13) << what;
    EXPECT_LE(dev_d, 1e-12) << what;
  }
}

TEST(RefineNet, TwoStepsCompose) {
  const PolyMesh m = fan_mesh(5, 2, false, 7);
  const auto one = refine_net(m, 1), two = refine_net(m, 2), again = refine_net(one.mesh, 1);
  // The same refined vertices (OpenSubdiv numbers the second level differently from a fresh refiner on the
  // first level's net: match the rows by position).
  const Eigen::MatrixXd composed = Eigen::MatrixXd(again.prolongation) * Eigen::MatrixXd(one.prolongation);
  const Eigen::MatrixXd p2(two.prolongation);
  ASSERT_EQ(p2.rows(), composed.rows());
  double dev = 0;
  for (Index i = 0; i < two.mesh.num_vertices(); ++i) {
    Index best = 0;
    for (Index j = 1; j < again.mesh.num_vertices(); ++j) {
      if ((again.mesh.point(j) - two.mesh.point(i)).norm() < (again.mesh.point(best) - two.mesh.point(i)).norm()) best = j;
    }
    dev = std::max(dev, (p2.row(i) - composed.row(best)).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(dev, 1e-15);
  const Eigen::VectorXd rows = two.prolongation * Eigen::VectorXd::Ones(m.num_vertices());
  EXPECT_LE((rows.array() - 1.0).abs().maxCoeff(), 1e-15);
  EXPECT_THROW(refine_net(m, -1), iga::InputError);
  EXPECT_THROW(refine_net(m, 11), iga::InputError);
}

}  // namespace
