// Hierarchical (truncated) Catmull–Clark subdivision splines (basis/catmull_clark/levels.hpp, thesis §4.2.5):
// CatmullClarkLevels under HierarchicalSpace, refined through the "cc" backend's refine_marked at and next to
// the extraordinary vertices of data/meshes/square_evs.obj (interior EVs n = 3, 5, 6, boundary EVs) and
// data/meshes/l_shape.obj (boundary EV at the reflex corner). Checked against closed forms: partition of
// unity (Σ = 1), the unchanged geometry map (refinability: the prolongated control points give the same
// surface), nestedness (coarse functions = P^T fine functions), rank of the collocation matrix, conformity of
// the interior edges, and a Poisson patch test (1 + 2x - 3y is in the isoparametric space).
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <span>
#include <vector>

#include "basis/catmull_clark/levels.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/hierarchical/refine.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/poisson.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/rule_provider.hpp"

namespace {

using namespace iga;
using basis::catmull_clark::CatmullClarkLevels;
using basis::hierarchical::HierarchicalSpace;

mesh::PolyMesh net(const std::string& name) { return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name); }

const HierarchicalSpace& hier(const basis::Geometry& g) { return dynamic_cast<const HierarchicalSpace&>(g.space()); }

// Reference points of an element: a 6 × 6 grid, and (elements at an EV) points on the tiles of levels 2..6
// next to the EV corner (0, 0), where the functions are piecewise on ever smaller tiles.
Eigen::Matrix2Xd sample(bool irregular) {
  std::vector<Eigen::Vector2d> p;
  for (int j = 0; j < 6; ++j) {
    for (int i = 0; i < 6; ++i) p.emplace_back((i + 0.5) / 6.0, (j + 0.5) / 6.0);
  }
  if (irregular) {
    for (int k = 2; k <= 6; ++k) {
      const double h = std::ldexp(1.0, -k);
      for (const auto& q : {Eigen::Vector2d(0.3, 0.8), Eigen::Vector2d(0.8, 0.3), Eigen::Vector2d(0.7, 0.7),
                            Eigen::Vector2d(0.9, 0.1), Eigen::Vector2d(0.1, 0.9)}) {
        p.push_back(h * (Eigen::Vector2d::Ones() + q));  // max(u, v) in [h, 2h): a tile of level k - 1
      }
    }
  }
  Eigen::Matrix2Xd m(2, static_cast<Eigen::Index>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = p[i];
  return m;
}

// Maps reference points of cell (level, cell) up to the first ancestor (or itself) for which stop() holds.
template <class Stop>
void climb(const basis::hierarchical::LevelHierarchy& h, int& level, Index& cell, Eigen::Matrix2Xd& pts, Stop stop) {
  Eigen::Matrix2d a;
  Eigen::Vector2d b;
  while (!stop(level, cell)) {
    int slot = 0;
    cell = h.parent(level, cell, slot);
    --level;
    h.child_map(level, cell, slot, a, b);
    pts = (a * pts).colwise() + b;
  }
}

// Elements at an EV and their edge neighbours (leaves of the same level).
std::vector<Index> at_and_next_to_evs(const HierarchicalSpace& s) {
  const auto& h = s.hierarchy();
  std::vector<Index> marked;
  for (Index e = 0; e < s.num_elements(); ++e) {
    if (s.kind(e).family != basis::Family::Irregular) continue;
    marked.push_back(e);
    for (int side = 0; side < 4; ++side) {
      if (h.boundary_part(s.level(e), s.cell(e), side) >= 0) continue;
      int their = 0;
      const Index n = s.element_of(s.level(e), h.neighbour(s.level(e), s.cell(e), side, their));
      if (n >= 0) marked.push_back(n);
    }
  }
  return marked;
}

struct Chain {
  std::vector<basis::Geometry> geometries;               // [0]: the CatmullClarkSpace geometry
  std::vector<Eigen::SparseMatrix<double>> prolongations;  // [k]: geometries[k] → geometries[k + 1]
};

// `steps` refinements at and next to the EVs through the registry (the first makes the net level 0).
Chain refine_at_evs(const std::string& name, int steps, int admissibility,
                    basis::catmull_clark::BoundaryRule rule = basis::catmull_clark::BoundaryRule::kNatural) {
  Chain c;
  c.geometries.push_back(basis::catmull_clark::make_catmull_clark_geometry(net(name), name, rule));
  for (int s = 0; s < steps; ++s) {
    std::vector<Index> marked;
    const basis::Geometry& g = c.geometries.back();
    if (s == 0) {
      for (Index e = 0; e < g.space().num_elements(); ++e) {
        if (g.space().kind(e).family == basis::Family::Irregular) marked.push_back(e);
      }
    } else {
      marked = at_and_next_to_evs(hier(g));
    }
    basis::BackendFacts facts;
    basis::Refinement r = basis::refine_marked(g, marked, admissibility, facts);
    c.prolongations.push_back(r.prolongation);
    c.geometries.push_back(r.geometry);
  }
  return c;
}

// The natural rule's levels are whole refined nets (CatmullClarkLevels); the clamped rule's are made cell by cell
// (SparseCatmullClarkLevels, chosen by coarse_hierarchical_space).
struct NetCase {
  const char* name;
  basis::catmull_clark::BoundaryRule rule;
};
const NetCase kNets[] = {{"square_evs.obj", basis::catmull_clark::BoundaryRule::kNatural},
                         {"l_shape.obj", basis::catmull_clark::BoundaryRule::kNatural},
                         {"square_evs.obj", basis::catmull_clark::BoundaryRule::kClamped},
                         {"l_shape.obj", basis::catmull_clark::BoundaryRule::kClamped}};

TEST(HierarchicalCatmullClark, LevelsAndChildMaps) {
  auto level0 = std::make_shared<const basis::catmull_clark::CatmullClarkSpace>(net("square_evs.obj"));
  const CatmullClarkLevels h(level0);
  // The net has a face with two EVs: one global step, 144 faces; 4^6 · 144 = 589824 <= 2^20 < 4^7 · 144.
  ASSERT_EQ(level0->num_elements(), 144);
  EXPECT_EQ(h.max_level(), 6);
  EXPECT_EQ(h.built_levels(), 1);
  EXPECT_THROW(h.space(7), UnsupportedError);
  // Every child's reference square maps onto a quarter of its parent's, and the level-(l+1) limit surface
  // of the refined net there is the level-l one (S · positions).
  Eigen::MatrixXd x0(level0->num_dofs(), 2);
  for (Index v = 0; v < level0->num_dofs(); ++v) x0.row(v) = level0->control_mesh().point(v).head<2>().transpose();
  std::vector<Eigen::MatrixXd> x{x0};
  for (int l = 1; l <= 2; ++l) x.push_back(Eigen::MatrixXd(h.subdivision(l) * x.back()));
  EXPECT_EQ(h.built_levels(), 3);
  const Eigen::Matrix2Xd pts = sample(true);
  double worst = 0;
  int rotated = 0;
  basis::BasisValues fine, coarse;
  for (int l = 0; l < 2; ++l) {
    for (Index c = 0; c < h.space(l).num_elements(); ++c) {
      for (int slot = 0; slot < 4; ++slot) {
        Eigen::Matrix2d a;
        Eigen::Vector2d b;
        h.child_map(l, c, slot, a, b);
        EXPECT_NEAR(std::abs(a.determinant()), 0.25, 1e-15);
        if (a(0, 1) != 0.0) ++rotated;
        const auto child = h.child(l, c, slot);
        int back = -1;
        EXPECT_EQ(h.parent(l + 1, child, back), c);
        EXPECT_EQ(back, slot);
        h.evaluate(l + 1, child, pts, 0, fine);
        h.evaluate(l, c, (a * pts).colwise() + b, 0, coarse);
        std::vector<basis::hierarchical::Key> df(static_cast<std::size_t>(h.max_local_functions())), dc = df;
        const int nf = h.local_functions(l + 1, child, df.data()), nc = h.local_functions(l, c, dc.data());
        Eigen::MatrixXd pf = Eigen::MatrixXd::Zero(nf, 2), pc = Eigen::MatrixXd::Zero(nc, 2);
        for (int j = 0; j < nf; ++j) pf.row(j) = x[static_cast<std::size_t>(l) + 1].row(df[static_cast<std::size_t>(j)]);
        for (int j = 0; j < nc; ++j) pc.row(j) = x[static_cast<std::size_t>(l)].row(dc[static_cast<std::size_t>(j)]);
        worst = std::max(worst, (fine.value.transpose() * pf - coarse.value.transpose() * pc).cwiseAbs().maxCoeff());
        // The two-scale relation on the child: coarse local functions = k × fine local functions.
        Eigen::MatrixXd k;
        h.refinement(l, c, slot, k);
        worst = std::max(worst, (coarse.value - k * fine.value).cwiseAbs().maxCoeff());
      }
    }
  }
  std::printf("[hcc] child maps: %d rotated (EV faces), max deviation %.1e\n", rotated, worst);
  EXPECT_GT(rotated, 0);  // the map does depend on the cell
  EXPECT_LE(worst, 1e-12);
}

TEST(HierarchicalCatmullClark, PartitionOfUnityGeometryAndNestedness) {
  for (const auto& [name, rule] : kNets) {
    const Chain c = refine_at_evs(name, 4, 2, rule);
    const basis::Geometry& g0 = c.geometries.front();
    EXPECT_EQ(c.geometries.back().space().name(), "cc");
    EXPECT_EQ(hier(c.geometries.back()).num_levels(), 5) << name;
    double pou = 0, geo = 0, nest = 0;
    for (std::size_t k = 1; k < c.geometries.size(); ++k) {
      const basis::Geometry& g = c.geometries[k];
      const HierarchicalSpace& s = hier(g);
      const HierarchicalSpace* coarse = k >= 2 ? &hier(c.geometries[k - 1]) : nullptr;
      const auto& h = s.hierarchy();
      const Eigen::SparseMatrix<double> pt = c.prolongations[k - 1].transpose();
      basis::BasisValues bv, bc;
      basis::GeometryValues gv, gv0;
      for (Index e = 0; e < s.num_elements(); ++e) {
        const Eigen::Matrix2Xd y = sample(s.kind(e).family == basis::Family::Irregular);
        s.evaluate(e, y, 1, bv);
        pou = std::max(pou, (bv.value.colwise().sum().array() - 1.0).abs().maxCoeff());
        pou = std::max(pou, bv.du.colwise().sum().cwiseAbs().maxCoeff());
        // The same point on the root cell (level 0 = the CatmullClarkSpace's element of that index).
        int level = s.level(e);
        Index cell = s.cell(e);
        Eigen::Matrix2Xd x = y;
        climb(h, level, cell, x, [](int l, Index) { return l == 0; });
        g.evaluate(e, y, gv);
        g0.evaluate(cell, x, gv0);
        geo = std::max(geo, (gv.x - gv0.x).cwiseAbs().maxCoeff());
        // Nestedness: the coarse functions at the point = P^T × the fine ones.
        Eigen::VectorXd phi = Eigen::VectorXd::Zero(s.num_dofs());
        const auto d = s.dofs(e);
        Eigen::VectorXd expect = Eigen::VectorXd::Zero(pt.rows());
        for (Eigen::Index q = 0; q < y.cols(); ++q) {
          phi.setZero();
          for (std::size_t i = 0; i < d.size(); ++i) phi(d[i]) = bv.value(static_cast<Eigen::Index>(i), q);
          expect.setZero();
          Eigen::Matrix2Xd yq = y.col(q);
          int lq = s.level(e);
          Index cq = s.cell(e);
          Index ce = -1;
          std::span<const Index> dc;
          if (coarse) {
            climb(h, lq, cq, yq, [&](int l, Index cc) { return coarse->element_of(l, cc) >= 0; });
            ce = coarse->element_of(lq, cq);
            coarse->evaluate(ce, yq, 0, bc);
            dc = coarse->dofs(ce);
          } else {
            climb(h, lq, cq, yq, [](int l, Index) { return l == 0; });
            ce = cq;
            g0.space().evaluate(ce, yq, 0, bc);
            dc = g0.space().dofs(ce);
          }
          for (std::size_t i = 0; i < dc.size(); ++i) expect(dc[i]) = bc.value(static_cast<Eigen::Index>(i), 0);
          nest = std::max(nest, (expect - pt * phi).cwiseAbs().maxCoeff());
        }
      }
    }
    std::printf("[hcc] %-15s %d levels, %lld dofs: |Σφ - 1|, |Σ∂φ| %.1e; geometry %.1e; nestedness %.1e\n", name,
                hier(c.geometries.back()).num_levels(), static_cast<long long>(c.geometries.back().space().num_dofs()),
                pou, geo, nest);
    EXPECT_LE(pou, 1e-12) << name;
    EXPECT_LE(geo, 1e-12) << name;
    EXPECT_LE(nest, 1e-12) << name;
  }
}

// Conformity: on every interior edge (hanging ones included) the geometry map agrees from both sides.
TEST(HierarchicalCatmullClark, InteriorEdgesMatch) {
  for (const auto& [name, rule] : kNets) {
    const Chain c = refine_at_evs(name, 3, 2, rule);
    const basis::Geometry& g = c.geometries.back();
    double worst = 0;
    Index hanging = 0;
    basis::GeometryValues a, b;
    for (const basis::InteriorEdge& edge : g.space().interior_edges()) {
      if (edge.t0[1] != 1.0 || edge.t1[1] != 0.0) ++hanging;
      for (double s : {0.1, 0.5, 0.9}) {  // the ends may be an EV, where the map is degenerate
        Eigen::Matrix2Xd pa(2, 1), pb(2, 1);
        pa.col(0) = basis::side_point(basis::Shape::Quad, edge.side[0], edge.t0[0] + s * (edge.t1[0] - edge.t0[0]));
        pb.col(0) = basis::side_point(basis::Shape::Quad, edge.side[1], edge.t0[1] + s * (edge.t1[1] - edge.t0[1]));
        g.evaluate(edge.element[0], pa, a);
        g.evaluate(edge.element[1], pb, b);
        worst = std::max(worst, (a.x - b.x).cwiseAbs().maxCoeff());
      }
    }
    std::printf("[hcc] %-15s interior edges: %lld hanging, max mismatch %.1e\n", name, static_cast<long long>(hanging), worst);
    EXPECT_GT(hanging, 0) << name;
    EXPECT_LE(worst, 1e-12) << name;
  }
}

// Linear independence: the collocation matrix A (sample points of every element × dofs) has full column rank.
// Each element's sample is unisolvent for its level's local functions (checked), so rank A = dim of the span.
// Reported: σ_min / σ_max from the Gram matrix A^T A (σ² = its eigenvalues).
double collocation_ratio(const HierarchicalSpace& s) {
  const auto& h = s.hierarchy();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(s.num_dofs(), s.num_dofs());
  basis::BasisValues bv, local;
  for (Index e = 0; e < s.num_elements(); ++e) {
    const Eigen::Matrix2Xd y = sample(s.kind(e).family == basis::Family::Irregular);
    h.evaluate(s.level(e), s.cell(e), y, 0, local);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(local.value.transpose());
    EXPECT_GT(svd.singularValues().minCoeff(), 1e-8 * svd.singularValues().maxCoeff()) << "sample not unisolvent on element " << e;
    s.evaluate(e, y, 0, bv);
    const auto d = s.dofs(e);
    const Eigen::MatrixXd g = bv.value * bv.value.transpose();
    for (std::size_t i = 0; i < d.size(); ++i) {
      for (std::size_t j = 0; j < d.size(); ++j) gram(d[i], d[j]) += g(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(0.0, eig.eigenvalues()(0)) / eig.eigenvalues()(eig.eigenvalues().size() - 1));
}

TEST(HierarchicalCatmullClark, CollocationRank) {
  for (const auto& [name, rule] : kNets) {
    for (int admissibility : {0, 2}) {
      const Chain c = refine_at_evs(name, 4, admissibility, rule);
      for (std::size_t k = 1; k < c.geometries.size(); ++k) {
        const double ratio = collocation_ratio(hier(c.geometries[k]));
        std::printf("[hcc] %-15s admissibility %d, %zu refinements: %lld dofs, sigma_min/sigma_max %.2e\n", name,
                    admissibility, k, static_cast<long long>(c.geometries[k].space().num_dofs()), ratio);
        EXPECT_GT(ratio, 1e-6) << name << " admissibility " << admissibility << " step " << k;
      }
    }
  }
}

// The same for random markings (fixed seed): each leaf marked with probability 0.3, `steps` times, no admissibility
// in trials 0 and 1, admissibility 2 in trial 2 (the most irregular hierarchies; admissibility adds cells and
// changes nothing in principle). The full form (label slow, 20 s) takes four steps, the quick form (the default
// run) three: the same seed, so its hierarchies are the full form's first three.
namespace {
void collocation_rank_random_marking(int steps) {
  std::mt19937 rng(7);
  std::bernoulli_distribution pick(0.3);
  for (const auto& [name, rule] : kNets) {
    for (int trial = 0; trial < 3; ++trial) {
      basis::Geometry g = basis::catmull_clark::make_catmull_clark_geometry(net(name), name, rule);
      double worst = 1.0;
      for (int step = 0; step < 4; ++step) {
        std::vector<Index> marked;
        for (Index e = 0; e < g.space().num_elements(); ++e) {
          if (pick(rng)) marked.push_back(e);
        }
        if (step >= steps) continue;  // the draws of the full form, so that the next trial starts from the same state
        basis::BackendFacts facts;
        g = basis::refine_marked(g, marked, trial == 2 ? 2 : 0, facts).geometry;
        worst = std::min(worst, collocation_ratio(hier(g)));
      }
      std::printf("[hcc] %-15s random marking %d: %d levels, %lld dofs, min sigma_min/sigma_max %.2e\n", name, trial,
                  hier(g).num_levels(), static_cast<long long>(g.space().num_dofs()), worst);
      EXPECT_GT(worst, 1e-6) << name << " trial " << trial;
    }
  }
}
}  // namespace

TEST(HierarchicalCatmullClarkSlow, CollocationRankRandomMarking) { collocation_rank_random_marking(4); }

TEST(HierarchicalCatmullClark, CollocationRankRandomMarkingQuick) { collocation_rank_random_marking(3); }

// Patch test (thesis §4.2.2 (i), here with local refinement): u = 1 + 2x - 3y, Dirichlet everywhere, f = 0; u is
// in the isoparametric space, so only the quadrature error remains, which the tiles rule removes at the EVs.
TEST(HierarchicalCatmullClark, PoissonPatchTest) {
  for (const auto& [name, rule] : kNets) {
    const Chain c = refine_at_evs(name, 3, 2, rule);
    const basis::Geometry& g = c.geometries.back();
    const auto rules = quadrature::make_rule_provider("tiles:4:24", 4);
    fem::PoissonProblem p;
    p.exact = std::make_shared<fem::Expression>("1 + 2*x - 3*y", "--exact");
    p.dirichlet = p.exact;
    // The clamped rule's boundary traces are dependent at boundary EVs: weak conditions (as iga-poisson asks).
    if (rule == basis::catmull_clark::BoundaryRule::kClamped) p.dirichlet_method = fem::DirichletMethod::kNitsche;
    const fem::PoissonResult r = fem::solve_poisson(g, *rules, p);
    std::printf("[hcc] %-15s patch test: %lld dofs, L2 %.1e, H1 %.1e\n", name, static_cast<long long>(r.dofs),
                r.errors->l2, r.errors->h1);
    EXPECT_LE(r.errors->l2, 1e-10) << name;
    EXPECT_LE(r.errors->h1, 1e-10) << name;
  }
}

// The registry: uniform refinement of a hierarchical cc geometry splits every element; the default quadrature
// names a rule; a level past max_level() is refused.
TEST(HierarchicalCatmullClark, Registry) {
  const Chain c = refine_at_evs("square_evs.obj", 1, 2);
  const basis::Geometry& g = c.geometries.back();
  EXPECT_EQ(basis::backend_of(g.space()).name, "cc");
  basis::BackendFacts facts;
  const basis::Refinement r = basis::refine_uniform(g, 1, facts);
  EXPECT_EQ(r.geometry.space().num_elements(), 4 * g.space().num_elements());
  EXPECT_EQ(r.prolongation.rows(), r.geometry.space().num_dofs());
  EXPECT_EQ(r.prolongation.cols(), g.space().num_dofs());
}

}  // namespace

// Item 5 of the whole-net levels: a level predicted not to fit is refused before it is built, with what it would
// need and what is available (UnsupportedError, which the adaptive loop reports as the reason it stopped). The
// limit is the process's address space (ulimit -v), 200 MB above what it uses: levels 4 and 5 of l_shape.obj
// (12,288 and 49,152 faces, 31 and 123 MB predicted) are built, level 6 (196,608 faces, 0.49 GB predicted, 0.56 GB
// measured) is refused.
// Not under ASan, whose shadow memory needs an unlimited address space.
TEST(HierarchicalCatmullClark, LevelPredictedNotToFitIsRefused) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "an address-space limit breaks ASan";
#else
  auto level0 = std::make_shared<const basis::catmull_clark::CatmullClarkSpace>(
      mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/l_shape.obj"));
  const CatmullClarkLevels h(level0);
  ASSERT_GE(h.max_level(), 6);
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &old), 0);
  long vm_kb = 0;
  {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    ASSERT_NE(f, nullptr);
    char line[256];
    while (std::fgets(line, sizeof line, f)) {
      if (std::sscanf(line, "VmSize: %ld kB", &vm_kb) == 1) break;
    }
    std::fclose(f);
  }
  ASSERT_GT(vm_kb, 0);
  rlimit low = old;
  low.rlim_cur = static_cast<rlim_t>(vm_kb) * 1024 + 200l * 1024 * 1024;
  ASSERT_EQ(setrlimit(RLIMIT_AS, &low), 0);
  std::string message;
  bool level4 = false;
  try {
    level4 = h.space(4).num_elements() == 48 * 256;
    h.space(6);
  } catch (const UnsupportedError& e) {
    message = e.what();
  }
  ASSERT_EQ(setrlimit(RLIMIT_AS, &old), 0);
  EXPECT_TRUE(level4);
  // Level 5 (49,152 faces, 0.12 GB predicted) still fits; level 6 does not.
  EXPECT_EQ(message.find("Catmull–Clark levels: level 6 (the whole net refined 6 times, 196608 faces) would need about 0.46 GiB"), 0u)
      << message;
  EXPECT_EQ(h.built_levels(), 6);
#endif
}
