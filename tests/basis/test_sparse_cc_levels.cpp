// Catmull–Clark levels held cell by cell (basis/catmull_clark/sparse_levels.hpp, issue 34) against the whole-net
// levels (levels.hpp: OpenSubdiv's refinement of the extended net, an independent construction) on the clamped
// square_evs.obj (interior EVs n = 3, 5, 6 and boundary EVs) and l_shape.obj: the same kinds, child maps,
// boundary parts, neighbours and continuity cell by cell; the same spaces (a field with random level-0
// coefficients, prolongated level by level through each hierarchy's own two-scale relation, has the same values
// and derivatives on every cell, and a vertex reached from different cells has one key and one coefficient); the
// supports are the inverse of the cells' function lists. Then depth: 32 levels toward the reflex corner's EV and
// toward a convex corner of the 48-face L-shape through the "cc" backend, with the cells made growing with the
// refined cells, not with 4^l, and the surface and partition of unity unchanged at the deepest elements.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <vector>

#include "basis/catmull_clark/levels.hpp"
#include "basis/catmull_clark/sparse_levels.hpp"
#include "basis/hierarchical/hierarchical_space.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using namespace iga;
using basis::catmull_clark::BoundaryRule;
using basis::catmull_clark::CatmullClarkLevels;
using basis::catmull_clark::CatmullClarkSpace;
using basis::catmull_clark::SparseCatmullClarkLevels;
using basis::hierarchical::Key;

mesh::PolyMesh net(const std::string& name) { return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name); }

std::shared_ptr<const CatmullClarkSpace> clamped(const std::string& name) {
  return std::make_shared<const CatmullClarkSpace>(net(name), name, basis::catmull_clark::IrregularMethod::kStam,
                                                   BoundaryRule::kClamped);
}

Eigen::Matrix2Xd grid_points() {
  Eigen::Matrix2Xd p(2, 25 + 3);
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) p.col(5 * j + i) << (i + 0.5) / 5, (j + 0.5) / 5;
  }
  p.col(25) << 1e-3, 2e-3;  // next to corner c0 (the EV of irregular cells)
  p.col(26) << 0.02, 0.01;
  p.col(27) << 1.0, 0.0;
  return p;
}

// Coefficients of a field on each level of one hierarchy, by key: level 0 random, the next levels prolongated
// cell by cell through refinement(); a key met twice must get the same value.
class Field {
 public:
  Field(const basis::hierarchical::LevelHierarchy& h, const Eigen::VectorXd& level0) : h_(h) {
    std::map<Key, double> c0;
    for (Eigen::Index i = 0; i < level0.size(); ++i) c0[i] = level0[i];
    coeff_.push_back(std::move(c0));
  }
  void add_level(int l) {  // l >= 1, every cell of level l - 1 refined
    std::map<Key, double>& fine = coeff_.emplace_back();
    std::vector<Key> pf(static_cast<std::size_t>(h_.max_local_functions())), cf(pf.size());
    Eigen::MatrixXd k;
    const Key cells = Key{h_.num_root_cells()} << (2 * (l - 1));
    for (Key c = 0; c < cells; ++c) {
      const int np = h_.local_functions(l - 1, c, pf.data());
      Eigen::VectorXd xp(np);
      for (int i = 0; i < np; ++i) xp[i] = coeff_[static_cast<std::size_t>(l) - 1].at(pf[static_cast<std::size_t>(i)]);
      for (int s = 0; s < 4; ++s) {
        h_.refinement(l - 1, c, s, k);
        const int nc = h_.local_functions(l, h_.child(l - 1, c, s), cf.data());
        ASSERT_EQ(k.cols(), nc);
        const Eigen::VectorXd xc = k.transpose() * xp;
        for (int j = 0; j < nc; ++j) {
          const auto [it, inserted] = fine.emplace(cf[static_cast<std::size_t>(j)], xc[j]);
          if (!inserted) {
            ASSERT_NEAR(it->second, xc[j], 1e-12) << "level " << l << " key met twice, two values";
          }
        }
      }
    }
  }
  // Value and first derivatives of the field on a cell.
  Eigen::MatrixXd on(int l, Key c, const Eigen::Matrix2Xd& pts) const {
    std::vector<Key> f(static_cast<std::size_t>(h_.max_local_functions()));
    const int n = h_.local_functions(l, c, f.data());
    basis::BasisValues v;
    h_.evaluate(l, c, pts, 1, v);
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x[i] = coeff_[static_cast<std::size_t>(l)].at(f[static_cast<std::size_t>(i)]);
    Eigen::MatrixXd out(3, pts.cols());
    const Eigen::MatrixXd* d[3] = {&v.value, &v.du, &v.dv};
    for (int i = 0; i < 3; ++i) out.row(i) = (d[i]->transpose() * x).transpose();
    return out;
  }

 private:
  const basis::hierarchical::LevelHierarchy& h_;
  std::vector<std::map<Key, double>> coeff_;
};

void compare(const std::string& name) {
  SCOPED_TRACE(name);
  const auto level0 = clamped(name);
  const CatmullClarkLevels dense(level0);
  const SparseCatmullClarkLevels sparse(level0);
  EXPECT_GE(sparse.max_level(), 40);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd c0(level0->num_dofs());
  for (Eigen::Index i = 0; i < c0.size(); ++i) c0[i] = u(gen);
  Field fd(dense, c0), fs(sparse, c0);
  const Eigen::Matrix2Xd pts = grid_points();
  for (int l = 0; l <= 2; ++l) {
    if (l > 0) {
      fd.add_level(l);
      fs.add_level(l);
    }
    const Key cells = Key{level0->num_elements()} << (2 * l);
    std::map<Key, std::set<Key>> inverse;
    std::vector<Key> f(static_cast<std::size_t>(sparse.max_local_functions()));
    for (Key c = 0; c < cells; ++c) {
      SCOPED_TRACE("level " + std::to_string(l) + " cell " + basis::hierarchical::to_string(c));
      ASSERT_EQ(sparse.kind(l, c), dense.kind(l, c));
      EXPECT_EQ(sparse.polynomial_degree(l, c), dense.polynomial_degree(l, c));
      for (int side = 0; side < 4; ++side) {
        EXPECT_EQ(sparse.boundary_part(l, c, side), dense.boundary_part(l, c, side));
        int ts = 0, td = 0;
        EXPECT_EQ(sparse.neighbour(l, c, side, ts), dense.neighbour(l, c, side, td));
        EXPECT_EQ(ts, td);
        EXPECT_EQ(sparse.continuity(l, c, side), dense.continuity(l, c, side));
      }
      if (l < 2) {
        for (int s = 0; s < 4; ++s) {
          Eigen::Matrix2d as, ad;
          Eigen::Vector2d bs, bd;
          sparse.child_map(l, c, s, as, bs);
          dense.child_map(l, c, s, ad, bd);
          EXPECT_EQ(as, ad);
          EXPECT_EQ(bs, bd);
        }
      }
      const Eigen::MatrixXd vs = fs.on(l, c, pts), vd = fd.on(l, c, pts);
      EXPECT_LT((vs - vd).cwiseAbs().maxCoeff(), 1e-11 * (1 + vd.cwiseAbs().maxCoeff()));
      const int n = sparse.local_functions(l, c, f.data());
      for (int i = 0; i < n; ++i) inverse[f[static_cast<std::size_t>(i)]].insert(c);
    }
    std::vector<Key> support;
    for (const auto& [function, on] : inverse) {
      sparse.support(l, function, support);
      EXPECT_EQ(std::set<Key>(support.begin(), support.end()), on) << "level " << l;
    }
  }
}

TEST(SparseCatmullClarkLevels, SameLevelsAsWholeNets) {
  compare("square_evs.obj");
  compare("l_shape.obj");
}

// `steps` refinements through the registry, each of the elements of the deepest level with the smallest score
// pick(geometry, element); returns the cells made after each step.
struct Deep {
  basis::Geometry geometry;
  std::vector<std::size_t> cells_made;
};
template <class Pick>
Deep refine_toward(basis::Geometry g, int steps, Pick pick) {
  Deep d{g, {}};
  for (int s = 0; s < steps; ++s) {
    std::vector<Index> marked;
    std::vector<double> score(static_cast<std::size_t>(d.geometry.space().num_elements()), 1e300);
    const auto* h = dynamic_cast<const basis::hierarchical::HierarchicalSpace*>(&d.geometry.space());
    for (Index e = 0; e < d.geometry.space().num_elements(); ++e) {
      if (h == nullptr || h->level(e) == h->num_levels() - 1) score[static_cast<std::size_t>(e)] = pick(d.geometry, e);
    }
    const double best = *std::min_element(score.begin(), score.end());
    for (Index e = 0; e < d.geometry.space().num_elements(); ++e) {
      if (score[static_cast<std::size_t>(e)] == best) marked.push_back(e);
    }
    basis::BackendFacts facts;
    d.geometry = basis::refine_marked(d.geometry, marked, 2, facts).geometry;
    const auto& levels = dynamic_cast<const basis::hierarchical::HierarchicalSpace&>(d.geometry.space()).hierarchy();
    d.cells_made.push_back(dynamic_cast<const SparseCatmullClarkLevels&>(levels).cells_made());
  }
  return d;
}

// x at the reference corners of element e (columns).
Eigen::Matrix2Xd corners_of(const basis::Geometry& g, Index e) {
  Eigen::Matrix2Xd y(2, 4);
  y << 0, 1, 1, 0, 0, 0, 1, 1;
  basis::GeometryValues gv;
  g.evaluate(e, y, gv);
  return gv.x.topRows(2);
}

void expect_deep(const Deep& d, const Eigen::Vector2d& target, const std::string& what) {
  SCOPED_TRACE(what);
  const auto& h = dynamic_cast<const basis::hierarchical::HierarchicalSpace&>(d.geometry.space());
  EXPECT_GE(h.num_levels(), 33);
  // Memory follows the refined cells: a step adds about the same number of cells at any depth.
  const std::size_t half = d.cells_made[d.cells_made.size() / 2 - 1], all = d.cells_made.back();
  std::printf("[sparse cc] %s: %d levels, %lld dofs, %zu cells made (%zu after half the steps)\n", what.c_str(),
              h.num_levels(), static_cast<long long>(h.num_dofs()), all, half);
  EXPECT_LT(static_cast<double>(all), 2.3 * static_cast<double>(half));
  // The deepest elements: partition of unity, and one of them has the target at a corner (the map unchanged
  // through every level: the target is a point of the level-0 surface).
  double pou = 0, nearest = 1e300;
  basis::BasisValues bv;
  Eigen::Matrix2Xd y(2, 3);
  y << 0.1, 0.5, 0.9, 0.2, 0.5, 0.7;
  for (Index e = 0; e < h.num_elements(); ++e) {
    if (h.level(e) != h.num_levels() - 1) continue;
    h.evaluate(e, y, 0, bv);
    pou = std::max(pou, (bv.value.colwise().sum().array() - 1.0).abs().maxCoeff());
    nearest = std::min(nearest, (corners_of(d.geometry, e).colwise() - target).colwise().norm().minCoeff());
  }
  EXPECT_LT(pou, 1e-13);
  EXPECT_LT(nearest, 1e-12);
}

// 32 levels on the 48-face L-shape (clamped): toward the reflex corner (a boundary EV: 3 faces, valence 5 in the
// extended net) and toward a convex corner (a net vertex with one face, interpolated by the clamped rule).
TEST(SparseCatmullClarkLevels, ThirtyTwoLevelsTowardAVertexAndACorner) {
  const mesh::PolyMesh lshape = net("l_shape.obj");
  ASSERT_EQ(lshape.num_faces(), 48);
  const basis::Geometry g0 = basis::catmull_clark::make_catmull_clark_geometry(lshape, "l_shape.obj", BoundaryRule::kClamped);
  // The EV's limit point: corner 0 of an irregular level-0 element.
  Index ev = -1;
  for (Index e = 0; e < g0.space().num_elements() && ev < 0; ++e) {
    if (g0.space().kind(e).family == basis::Family::Irregular) ev = e;
  }
  ASSERT_GE(ev, 0);
  const Eigen::Vector2d limit = corners_of(g0, ev).col(0);
  const Deep to_ev = refine_toward(g0, 32, [](const basis::Geometry& g, Index e) {
    return g.space().kind(e).family == basis::Family::Irregular ? 0.0 : 1.0;
  });
  expect_deep(to_ev, limit, "toward the reflex corner");

  Eigen::Vector2d corner = Eigen::Vector2d::Zero();
  for (Index v = 0; v < lshape.num_vertices(); ++v) {
    if (lshape.num_vertex_faces(v) == 1) corner = lshape.point(v).head<2>();
  }
  const Deep to_corner = refine_toward(g0, 32, [&](const basis::Geometry& g, Index e) {
    return (corners_of(g, e).colwise() - corner).colwise().norm().minCoeff();
  });
  expect_deep(to_corner, corner, "toward a convex corner");

  // On toward the EV until the deepest level: refused by name (the adaptive loop stops there with this reason).
  const auto& h = dynamic_cast<const basis::hierarchical::HierarchicalSpace&>(to_ev.geometry.space());
  const int deepest = h.hierarchy().max_level();
  EXPECT_GE(deepest, 40);  // edges of 0.25 / 2^l (or 0.125 / 2^l) against 64 ulp(2.25) = 2^-45
  try {
    refine_toward(to_ev.geometry, deepest, [](const basis::Geometry& g, Index e) {
      return g.space().kind(e).family == basis::Family::Irregular ? 0.0 : 1.0;
    });
    ADD_FAILURE() << "no error past the deepest level";
  } catch (const UnsupportedError& e) {
    const std::string expect = "is deeper than the " + std::to_string(deepest) + " levels the 'cc' hierarchy can index";
    EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
  }
}

TEST(SparseCatmullClarkLevels, RefusesTheNaturalRuleOnAnOpenNet) {
  const auto natural = std::make_shared<const CatmullClarkSpace>(net("l_shape.obj"), "l_shape.obj");
  EXPECT_FALSE(SparseCatmullClarkLevels::supports(*natural));
  EXPECT_THROW(SparseCatmullClarkLevels{natural}, InputError);
}

}  // namespace
