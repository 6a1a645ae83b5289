// CatmullClarkSpace against OpenSubdiv's Bfr (the independent reference for the limit surface), partition
// of unity, the unit-square net, and bad input.
#include <gtest/gtest.h>

#include <sstream>
#include "mesh/obj_reader.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <random>
#include <string>
#include <vector>

#include "basis/catmull_clark/space.hpp"
#include "core/error.hpp"
#include "osd_reference.hpp"

namespace {

namespace Osd = OpenSubdiv::OPENSUBDIV_VERSION;
using iga::Index;
using iga::basis::BasisValues;
using iga::basis::Family;
using iga::basis::catmull_clark::CatmullClarkSpace;
using iga::mesh::PolyMesh;

// ---------------------------------------------------------------------------------------------- meshes

// A fan of `sectors` k×k quad grids around vertex 0: closed (an interior vertex of valence `sectors`) or
// open (a boundary vertex with `sectors` faces). Sector s spans spokes s and s+1; its (i, j) grid point is
// spoke s at i, spoke s+1 at j. Planar positions: the sector corner i e_s + j e_{s+1} (scaled by 1/k).
struct Fan {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<Index>> faces;
  std::vector<Index> outer;  // open fans: boundary vertices from spoke 0's end around to spoke m's end
  Index spoke_vertex(int t, int i) const { return spoke[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)]; }
  std::vector<std::vector<Index>> spoke;  // spoke[t][i], i = 0 (centre) .. k
};

Fan make_fan(int sectors, int k, bool closed) {
  Fan fan;
  const int nspokes = closed ? sectors : sectors + 1;
  const double angle = (closed ? 2.0 : 1.0) * M_PI / sectors;
  fan.points.push_back(Eigen::Vector3d::Zero());
  fan.spoke.assign(static_cast<std::size_t>(nspokes), std::vector<Index>(static_cast<std::size_t>(k + 1), 0));
  auto dir = [&](int t) { return Eigen::Vector3d(std::cos(angle * t), std::sin(angle * t), 0.0); };
  for (int t = 0; t < nspokes; ++t) {
    for (int i = 1; i <= k; ++i) {
      fan.spoke[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)] = static_cast<Index>(fan.points.size());
      fan.points.push_back(dir(t) * i / k);
    }
  }
  for (int s = 0; s < sectors; ++s) {
    const int t0 = s, t1 = (s + 1) % nspokes;
    std::vector<std::vector<Index>> id(static_cast<std::size_t>(k + 1), std::vector<Index>(static_cast<std::size_t>(k + 1)));
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; j <= k; ++j) {
        Index v;
        if (j == 0) v = fan.spoke[static_cast<std::size_t>(t0)][static_cast<std::size_t>(i)];
        else if (i == 0) v = fan.spoke[static_cast<std::size_t>(t1)][static_cast<std::size_t>(j)];
        else {
          v = static_cast<Index>(fan.points.size());
          fan.points.push_back((dir(t0) * i + dir(t1) * j) / k);
        }
        id[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = v;
      }
    }
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < k; ++j) {
        auto at = [&](int a, int b) { return id[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)]; };
        fan.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
    if (!closed) {
      for (int j = 0; j < k; ++j) fan.outer.push_back(id[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)]);
      for (int i = k; i >= 1; --i) fan.outer.push_back(id[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)]);
    }
  }
  if (!closed) fan.outer.push_back(fan.spoke[static_cast<std::size_t>(sectors)][static_cast<std::size_t>(k)]);
  return fan;
}

// Harmonic interior positions for fixed boundary positions (Jacobi iterations).
void smooth_interior(std::vector<Eigen::Vector3d>& pts, const std::vector<std::vector<Index>>& faces,
                     const std::vector<bool>& fixed) {
  std::vector<std::vector<Index>> nbrs(pts.size());
  for (const auto& f : faces) {
    for (std::size_t i = 0; i < f.size(); ++i) {
      const Index a = f[i], b = f[(i + 1) % f.size()];
      nbrs[static_cast<std::size_t>(a)].push_back(b);
      nbrs[static_cast<std::size_t>(b)].push_back(a);
    }
  }
  for (int it = 0; it < 2000; ++it) {
    std::vector<Eigen::Vector3d> next = pts;
    for (std::size_t v = 0; v < pts.size(); ++v) {
      if (fixed[v]) continue;
      Eigen::Vector3d s = Eigen::Vector3d::Zero();
      for (Index w : nbrs[v]) s += pts[static_cast<std::size_t>(w)];
      next[v] = s / static_cast<double>(nbrs[v].size());
    }
    pts = next;
  }
}

// An open fan of m sectors whose boundary polygon is the unit square: the EV at (0.5, 0).
PolyMesh square_boundary_fan(int m, int k) {
  Fan fan = make_fan(m, k, false);
  std::vector<bool> fixed(fan.points.size(), false);
  auto place = [&](Index v, double x, double y) {
    fan.points[static_cast<std::size_t>(v)] = {x, y, 0.0};
    fixed[static_cast<std::size_t>(v)] = true;
  };
  place(0, 0.5, 0.0);
  for (int i = 1; i <= k; ++i) place(fan.spoke_vertex(0, i), 0.5 + 0.5 * i / k, 0.0);
  for (int i = 1; i <= k; ++i) place(fan.spoke_vertex(m, i), 0.5 - 0.5 * i / k, 0.0);
  const int n = static_cast<int>(fan.outer.size()) - 1;  // 2 k m edges: (1,0) -> (1,1) at k -> (0,1) at n-k -> (0,0)
  for (int idx = 0; idx <= n; ++idx) {
    const Index v = fan.outer[static_cast<std::size_t>(idx)];
    if (idx <= k) place(v, 1.0, static_cast<double>(idx) / k);
    else if (idx <= n - k) place(v, 1.0 - static_cast<double>(idx - k) / (n - 2 * k), 1.0);
    else place(v, 0.0, 1.0 - static_cast<double>(idx - (n - k)) / k);
  }
  smooth_interior(fan.points, fan.faces, fixed);
  return PolyMesh::build(fan.points, fan.faces);
}

// The unit square split into quads, triangles and a pentagon; corners have one face, (0.5, 0) and (1, 0.5)
// three (boundary EVs after the global step), the triangles and the pentagon give interior EVs 3 and 5.
PolyMesh square_mixed() {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0, 0}, {1, 0.5, 0},
                                    {0.5, 1, 0}, {0, 0.5, 0}, {0.3, 0.3, 0}, {0.7, 0.3, 0}, {0.5, 0.7, 0}};
  enum { c0, c1, c2, c3, b, r, t, l, pp, q, s };
  std::vector<std::vector<Index>> f = {{c0, b, pp, l}, {b, c1, r, q}, {b, q, pp},     {r, c2, t, s},
                                       {s, t, c3, l, pp}, {q, r, s},   {pp, q, s}};
  return PolyMesh::build(p, f);
}

// L-shape: a 4×4 grid of unit quads without the top-right 2×2 block; the reflex corner (2,2) has 3 faces.
PolyMesh l_shape() {
  std::vector<Eigen::Vector3d> p;
  std::map<std::pair<int, int>, Index> id;
  auto vid = [&](int i, int j) {
    auto [it, inserted] = id.emplace(std::pair{i, j}, static_cast<Index>(p.size()));
    if (inserted) p.emplace_back(i / 4.0, j / 4.0, 0.0);
    return it->second;
  };
  std::vector<std::vector<Index>> f;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      if (i >= 2 && j >= 2) continue;
      f.push_back({vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)});
    }
  }
  return PolyMesh::build(p, f);
}

PolyMesh with_random_z(const PolyMesh& m, unsigned seed, double amp = 0.3, double xy = 0.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<Eigen::Vector3d> p = m.points();
  for (auto& x : p) x += Eigen::Vector3d(xy * d(rng), xy * d(rng), amp * d(rng));
  std::vector<std::vector<Index>> f;
  for (Index i = 0; i < m.num_faces(); ++i) f.emplace_back(m.face(i).begin(), m.face(i).end());
  return PolyMesh::build(p, f);
}

// ------------------------------------------------------------------------------------------- reference

std::unique_ptr<Osd::Far::TopologyRefiner> make_refiner(const PolyMesh& m) { return iga::test::make_osd_refiner(m); }

constexpr int kApprox = 10;

struct Deviation {
  double value = 0, deriv = 0, surface = 0;
  int points = 0;
};

// Bfr quad parameterisation: face vertex j at (0,0), (1,0), (1,1), (0,1).
Eigen::Vector2d quad_corner(int j) {
  static const double c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return {c[j % 4][0], c[j % 4][1]};
}

// Compares every element of `space` with Bfr on the control net: basis stencils (value, d/du, d/dv) per
// control point and the surface Σ φ_i P_i, deviations per element class ("regular", "irregular").
std::map<std::string, Deviation> compare_with_bfr(const CatmullClarkSpace& space, int points_per_face,
                                                  unsigned seed) {
  const PolyMesh& net = space.control_mesh();
  auto refiner = make_refiner(net);
  Osd::Bfr::RefinerSurfaceFactory<>::Options opts;
  opts.SetApproxLevelSharp(kApprox);
  opts.SetApproxLevelSmooth(kApprox);
  Osd::Bfr::RefinerSurfaceFactory<> factory(*refiner, opts);
  Osd::Bfr::Surface<double> surface;
  Eigen::MatrixXd x(net.num_vertices(), 3);
  for (Index v = 0; v < net.num_vertices(); ++v) x.row(v) = net.point(v).transpose();
  const double bbox = (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::map<std::string, Deviation> dev;
  BasisValues bv;
  for (Index e = 0; e < space.num_elements(); ++e) {
    const bool irregular = space.kind(e).family == Family::Irregular;
    EXPECT_TRUE(factory.InitVertexSurface(static_cast<int>(e), &surface));
    const int ncv = surface.GetNumControlPoints();
    std::vector<int> cv(static_cast<std::size_t>(ncv));
    surface.GetControlPointIndices(cv.data());
    Eigen::Matrix2Xd pts(2, points_per_face);
    for (int p = 0; p < points_per_face; ++p) {
      if (irregular) {  // max(u,v) log-uniform in [2^-kApprox, 1]; Bfr is exact there
        const double m = std::ldexp(1.0, -kApprox) * std::pow(2.0, kApprox * uni(rng)) * (1.0 + 1e-9);
        const double o = m * uni(rng);
        pts.col(p) = uni(rng) < 0.5 ? Eigen::Vector2d(std::min(m, 1.0), o) : Eigen::Vector2d(o, std::min(m, 1.0));
      } else {
        pts.col(p) = Eigen::Vector2d(uni(rng), uni(rng));
      }
    }
    space.evaluate(e, pts, 1, bv);
    const auto dofs = space.dofs(e);
    const int r = space.rotation(e);
    const Eigen::Vector2d q0 = quad_corner(r), eu = quad_corner(r + 1) - q0, ev = quad_corner(r + 3) - q0;
    Deviation& d = dev[irregular ? "irregular" : "regular"];
    for (int p = 0; p < points_per_face; ++p) {
      const Eigen::Vector2d uv = q0 + pts(0, p) * eu + pts(1, p) * ev;
      std::vector<double> sp(static_cast<std::size_t>(ncv)), su(sp.size()), sv(sp.size());
      const double uvb[2] = {uv.x(), uv.y()};
      surface.EvaluateStencil(uvb, sp.data(), su.data(), sv.data());
      Eigen::VectorXd ref_v = Eigen::VectorXd::Zero(net.num_vertices()), ref_u = ref_v, ref_w = ref_v;
      for (int c = 0; c < ncv; ++c) {
        const auto i = static_cast<std::size_t>(c);
        ref_v(cv[i]) += sp[i];
        // chain rule: d/du = eu · grad_UV, d/dv = ev · grad_UV
        ref_u(cv[i]) += eu.x() * su[i] + eu.y() * sv[i];
        ref_w(cv[i]) += ev.x() * su[i] + ev.y() * sv[i];
      }
      Eigen::VectorXd our_v = Eigen::VectorXd::Zero(net.num_vertices()), our_u = our_v, our_w = our_v;
      for (std::size_t k = 0; k < dofs.size(); ++k) {
        our_v(dofs[k]) += bv.value(static_cast<Eigen::Index>(k), p);
        our_u(dofs[k]) += bv.du(static_cast<Eigen::Index>(k), p);
        our_w(dofs[k]) += bv.dv(static_cast<Eigen::Index>(k), p);
      }
      const double scale = std::max({1.0, ref_u.cwiseAbs().maxCoeff(), ref_w.cwiseAbs().maxCoeff()});
      d.value = std::max(d.value, (our_v - ref_v).cwiseAbs().maxCoeff());
      d.deriv = std::max(d.deriv, std::max((our_u - ref_u).cwiseAbs().maxCoeff(), (our_w - ref_w).cwiseAbs().maxCoeff()) / scale);
      d.surface = std::max(d.surface, ((our_v - ref_v).transpose() * x).norm() / bbox);
      ++d.points;
    }
  }
  return dev;
}

void expect_matches_bfr(const CatmullClarkSpace& space, int points_per_face, unsigned seed, const std::string& what) {
  const auto dev = compare_with_bfr(space, points_per_face, seed);
  for (const auto& [cls, d] : dev) {
    std::printf("[bfr] %-28s %-9s points %6d  max|dphi| %.2e  max|d grad phi|/scale %.2e  surface/bbox %.2e\n",
                what.c_str(), cls.c_str(), d.points, d.value, d.deriv, d.surface);
    EXPECT_LE(d.value, 1e-12) << what << " " << cls;
    EXPECT_LE(d.deriv, 1e-12) << what << " " << cls;
    EXPECT_LE(d.surface, 1e-12) << what << " " << cls;
  }
}

// --------------------------------------------------------------------------------------------- tests

TEST(CatmullClarkSpace, RegularGridMatchesBfr) {
  // An open fan of 2 sectors of 3×3 quads is a 6×3 grid (its centre a regular boundary vertex): interior,
  // boundary and corner faces.
  const PolyMesh m = with_random_z(square_boundary_fan(2, 3), 1, 0.3, 0.02);
  const CatmullClarkSpace space(m);
  EXPECT_EQ(space.refinement_steps(), 0);
  for (Index e = 0; e < space.num_elements(); ++e) EXPECT_EQ(space.kind(e).family, Family::Regular);
  expect_matches_bfr(space, 200, 2, "regular grid");
}

// Twins: on an 8 × 8 grid numbered row by row, the 36 faces away from the boundary gather their 16 control points
// in the same pattern, so they form one class at least; every twin's functions are bit for bit those of its class's
// lowest element (the same operator applied to the same bicubic values).
TEST(CatmullClarkSpace, RegularTwinsHaveTheSameFunctions) {
  std::vector<Eigen::Vector3d> p;
  std::vector<std::vector<Index>> f;
  for (int j = 0; j <= 8; ++j) {
    for (int i = 0; i <= 8; ++i) p.emplace_back(i, j + 0.1 * std::sin(i), 0.0);
  }
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) f.push_back({i + 9 * j, i + 1 + 9 * j, i + 1 + 9 * (j + 1), i + 9 * (j + 1)});
  }
  const CatmullClarkSpace space(PolyMesh::build(p, f));
  Eigen::Matrix2Xd pts(2, 5);
  pts << 0.1, 0.9, 0.5, 0.3, 0.7, 0.2, 0.4, 0.5, 0.95, 0.05;
  Index twins = 0;
  BasisValues a, b;
  for (Index e = 0; e < space.num_elements(); ++e) {
    const Index twin = space.reference_element(e);
    ASSERT_LE(twin, e);
    twins += twin != e;
    space.evaluate(e, pts, 2, a);
    space.evaluate(twin, pts, 2, b);
    EXPECT_TRUE(a.value == b.value && a.du == b.du && a.dv == b.dv && a.duu == b.duu && a.duv == b.duv &&
                a.dvv == b.dvv) << "element " << e << ", twin " << twin;
  }
  EXPECT_GE(twins, 35);
}

TEST(CatmullClarkSpace, InteriorEvMatchesBfr) {
  for (int n = 3; n <= 8; ++n) {
    if (n == 4) continue;
    const Fan fan = make_fan(n, 3, true);
    const PolyMesh m = with_random_z(PolyMesh::build(fan.points, fan.faces), 10 + n, 0.3, 0.05);
    const CatmullClarkSpace stam(m), subdivision(m, "mesh", iga::basis::catmull_clark::IrregularMethod::kSubdivision);
    EXPECT_EQ(stam.refinement_steps(), 0);
    expect_matches_bfr(stam, 1000 / n + 10, 20 + n, "Stam: interior EV n=" + std::to_string(n));
    expect_matches_bfr(subdivision, 1000 / n + 10, 20 + n, "powers: interior EV n=" + std::to_string(n));
  }
}

TEST(CatmullClarkSpace, BoundaryEvMatchesBfr) {
  for (int m = 3; m <= 6; ++m) {
    const PolyMesh mesh = with_random_z(square_boundary_fan(m, 3), 30 + m, 0.3, 0.0);
    const CatmullClarkSpace space(mesh);
    EXPECT_EQ(space.refinement_steps(), 0);
    expect_matches_bfr(space, 1000 / m + 10, 40 + m, "boundary EV faces=" + std::to_string(m));
  }
}

TEST(CatmullClarkSpace, LShapeMatchesBfr) {
  const CatmullClarkSpace space(with_random_z(l_shape(), 5, 0.2, 0.01));
  EXPECT_EQ(space.refinement_steps(), 0);
  expect_matches_bfr(space, 400, 6, "L-shape");
}

// The cube: quads only, every face touches four EVs -> one step. The mixed square: triangles and a pentagon
// with EV corners -> two steps.
PolyMesh cube() {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  return PolyMesh::build(p, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

TEST(CatmullClarkSpace, GlobalStepMatchesBfr) {
  const CatmullClarkSpace one(with_random_z(cube(), 9, 0.1, 0.1));
  EXPECT_EQ(one.refinement_steps(), 1);
  EXPECT_EQ(one.num_elements(), 24);
  EXPECT_TRUE(one.boundary_edges().empty());
  expect_matches_bfr(one, 300, 10, "cube after one step");
  const CatmullClarkSpace two(with_random_z(square_mixed(), 7, 0.3, 0.0));
  EXPECT_EQ(two.refinement_steps(), 2);
  expect_matches_bfr(two, 300, 8, "mixed net after two steps");
}

// Random points of an element: uniform, and (for irregular elements) clustered at the EV down to 1e-12.
Eigen::Matrix2Xd random_points(bool irregular, int count, std::mt19937& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  Eigen::Matrix2Xd pts(2, count);
  for (int p = 0; p < count; ++p) {
    if (irregular && p % 2 == 1) {
      const double m = std::pow(10.0, -12.0 * uni(rng));
      pts.col(p) = uni(rng) < 0.5 ? Eigen::Vector2d(m, m * uni(rng)) : Eigen::Vector2d(m * uni(rng), m);
    } else {
      pts.col(p) = Eigen::Vector2d(uni(rng), uni(rng));
    }
  }
  pts.col(0) = Eigen::Vector2d(1e-12, 1e-12);
  return pts;
}

std::vector<std::pair<std::string, PolyMesh>> all_test_nets() {
  std::vector<std::pair<std::string, PolyMesh>> nets;
  for (int n : {3, 5, 8, 16}) {
    const Fan fan = make_fan(n, 2, true);
    nets.emplace_back("interior EV n=" + std::to_string(n), PolyMesh::build(fan.points, fan.faces));
  }
  for (int m : {3, 6, 15}) nets.emplace_back("boundary EV faces=" + std::to_string(m), square_boundary_fan(m, 2));
  nets.emplace_back("L-shape", l_shape());
  nets.emplace_back("mixed square", square_mixed());
  return nets;
}

TEST(CatmullClarkSpace, PartitionOfUnityAndPlaneReproduction) {
  std::mt19937 rng(99);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.3, -0.5, 1.0).normalized();
  for (const auto& [what, planar] : all_test_nets()) {
    // Control points on the tilted plane normal · x = 0.25 (z from x, y).
    std::vector<Eigen::Vector3d> p = planar.points();
    for (auto& x : p) x.z() = (0.25 - normal.x() * x.x() - normal.y() * x.y()) / normal.z();
    std::vector<std::vector<Index>> f;
    for (Index i = 0; i < planar.num_faces(); ++i) f.emplace_back(planar.face(i).begin(), planar.face(i).end());
    const CatmullClarkSpace space(PolyMesh::build(p, f));
    const PolyMesh& net = space.control_mesh();
    double pou = 0, grad = 0, hess = 0, plane = 0;
    BasisValues bv;
    for (Index e = 0; e < space.num_elements(); ++e) {
      const Eigen::Matrix2Xd pts = random_points(space.kind(e).family == Family::Irregular, 40, rng);
      space.evaluate(e, pts, 2, bv);
      const auto dofs = space.dofs(e);
      ASSERT_EQ(bv.value.rows(), static_cast<Eigen::Index>(dofs.size()));
      EXPECT_TRUE(bv.value.allFinite() && bv.du.allFinite() && bv.dvv.allFinite()) << what;
      pou = std::max(pou, (bv.value.colwise().sum().array() - 1.0).abs().maxCoeff());
      const double gscale = std::max({1.0, bv.du.cwiseAbs().maxCoeff(), bv.dv.cwiseAbs().maxCoeff()});
      grad = std::max({grad, bv.du.colwise().sum().cwiseAbs().maxCoeff() / gscale,
                       bv.dv.colwise().sum().cwiseAbs().maxCoeff() / gscale});
      const double hscale = std::max({1.0, bv.duu.cwiseAbs().maxCoeff(), bv.duv.cwiseAbs().maxCoeff(),
                                      bv.dvv.cwiseAbs().maxCoeff()});
      hess = std::max({hess, bv.duu.colwise().sum().cwiseAbs().maxCoeff() / hscale,
                       bv.duv.colwise().sum().cwiseAbs().maxCoeff() / hscale,
                       bv.dvv.colwise().sum().cwiseAbs().maxCoeff() / hscale});
      for (Eigen::Index q = 0; q < pts.cols(); ++q) {
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < dofs.size(); ++k) x += bv.value(static_cast<Eigen::Index>(k), q) * net.point(dofs[k]);
        plane = std::max(plane, std::abs(normal.dot(x) - 0.25));
      }
    }
    std::printf("[pou] %-22s |sum phi - 1| %.1e  |sum grad|/scale %.1e  |sum hess|/scale %.1e  plane %.1e\n", what.c_str(), pou,
                grad, hess, plane);
    EXPECT_LE(pou, 1e-13) << what;
    EXPECT_LE(grad, 1e-11) << what;
    EXPECT_LE(hess, 1e-11) << what;
    EXPECT_LE(plane, 1e-13) << what;
  }
}

TEST(CatmullClarkSpace, UnitSquareNet) {
  std::mt19937 rng(7);
  std::vector<std::pair<std::string, PolyMesh>> nets = {{"mixed square", square_mixed()}};
  for (int m : {3, 4, 5, 6}) nets.emplace_back("boundary fan " + std::to_string(m), square_boundary_fan(m, 3));
  for (const auto& [what, mesh] : nets) {
    const iga::basis::Geometry geo = iga::basis::catmull_clark::make_catmull_clark_geometry(mesh);
    const auto& space = dynamic_cast<const CatmullClarkSpace&>(geo.space());
    EXPECT_EQ(geo.dim(), 2);
    double outside = 0, off_edge = 0;
    BasisValues bv;
    for (Index e = 0; e < space.num_elements(); ++e) {
      const Eigen::Matrix2Xd pts = random_points(space.kind(e).family == Family::Irregular, 50, rng);
      space.evaluate(e, pts, 0, bv);
      Eigen::MatrixXd x = Eigen::MatrixXd::Zero(2, pts.cols());
      const auto dofs = space.dofs(e);
      for (std::size_t k = 0; k < dofs.size(); ++k) {
        x += geo.control_points().row(dofs[k]).transpose() * bv.value.row(static_cast<Eigen::Index>(k));
      }
      outside = std::max({outside, (-x.array()).maxCoeff(), (x.array() - 1.0).maxCoeff()});
    }
    // Boundary sides lie on the square's edges; each part on one edge.
    const auto names = space.boundary_part_names();
    std::vector<int> part_edge(names.size(), -1);
    for (const auto& be : space.boundary_edges()) {
      Eigen::Matrix2Xd pts(2, 11);
      for (int i = 0; i <= 10; ++i) pts.col(i) = iga::basis::side_point(iga::basis::Shape::Quad, be.side, i / 10.0);
      space.evaluate(be.element, pts, 0, bv);
      const auto dofs = space.dofs(be.element);
      for (int i = 0; i <= 10; ++i) {
        Eigen::Vector2d x = Eigen::Vector2d::Zero();
        for (std::size_t k = 0; k < dofs.size(); ++k) x += bv.value(static_cast<Eigen::Index>(k), i) * geo.control_points().row(dofs[k]).transpose();
        // distance to the nearest square edge
        const double d[4] = {std::abs(x.y()), std::abs(x.x() - 1.0), std::abs(x.y() - 1.0), std::abs(x.x())};
        const int edge = static_cast<int>(std::min_element(d, d + 4) - d);
        off_edge = std::max(off_edge, d[edge]);
        if (i == 5) {
          if (part_edge[static_cast<std::size_t>(be.part)] < 0) part_edge[static_cast<std::size_t>(be.part)] = edge;
          EXPECT_EQ(part_edge[static_cast<std::size_t>(be.part)], edge) << what << " part " << names[static_cast<std::size_t>(be.part)];
        }
      }
    }
    std::printf("[square] %-18s outside [0,1]^2 by %.1e, boundary off the square's edges by %.1e, %zu parts\n",
                what.c_str(), outside, off_edge, names.size());
    EXPECT_LE(outside, 1e-14) << what;
    EXPECT_LE(off_edge, 1e-14) << what;
    EXPECT_EQ(names.front(), "b0.0");
  }
}

TEST(CatmullClarkSpace, MixedSquareParts) {
  const CatmullClarkSpace space(square_mixed());
  EXPECT_EQ(space.refinement_steps(), 2);
  const std::vector<std::string> expect = {"b0.0", "b0.1", "b0.2", "b0.3"};
  EXPECT_EQ(space.boundary_part_names(), expect);
  EXPECT_EQ(space.boundary_edges().size(), 32u);  // 8 coarse boundary edges, two steps
}

TEST(CatmullClarkSpace, EvLimitPointMatchesBfr) {
  for (int n : {3, 5, 7}) {
    const Fan fan = make_fan(n, 2, true);
    const CatmullClarkSpace space(with_random_z(PolyMesh::build(fan.points, fan.faces), 3, 0.3, 0.05));
    auto refiner = make_refiner(space.control_mesh());
    Osd::Bfr::RefinerSurfaceFactory<> factory(*refiner);
    Osd::Bfr::Surface<double> surface;
    BasisValues bv;
    for (Index e = 0; e < space.num_elements(); ++e) {
      if (space.kind(e).family != Family::Irregular) continue;
      ASSERT_TRUE(factory.InitVertexSurface(static_cast<int>(e), &surface));
      std::vector<int> cv(static_cast<std::size_t>(surface.GetNumControlPoints()));
      surface.GetControlPointIndices(cv.data());
      std::vector<double> sp(cv.size());
      const Eigen::Vector2d uv = quad_corner(space.rotation(e));
      const double uvb[2] = {uv.x(), uv.y()};
      surface.EvaluateStencil(uvb, sp.data());
      Eigen::VectorXd ref = Eigen::VectorXd::Zero(space.num_dofs()), ours = ref;
      for (std::size_t c = 0; c < cv.size(); ++c) ref(cv[c]) += sp[c];
      space.evaluate(e, Eigen::Matrix2Xd::Zero(2, 1), 1, bv);
      const auto dofs = space.dofs(e);
      for (std::size_t k = 0; k < dofs.size(); ++k) ours(dofs[k]) += bv.value(static_cast<Eigen::Index>(k), 0);
      EXPECT_LE((ours - ref).cwiseAbs().maxCoeff(), 1e-14) << "n=" << n;
    }
  }
}

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const iga::InputError& e) {
    return e.what();
  }
  return "no InputError";
}

// Messages name vertices and faces in the file's own 1-based numbers (issue 14, class 8: they used to count from
// 0 and so named the wrong vertex), with the file's line when the net was read from one.
TEST(CatmullClarkSpace, BadInput) {
  {  // isolated vertex: the fifth
    std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {5, 5, 0}};
    const PolyMesh m = PolyMesh::build(p, {{0, 1, 2, 3}});
    const std::string msg = error_of([&] { CatmullClarkSpace s(m, "net.obj"); });
    EXPECT_NE(msg.find("net.obj"), std::string::npos) << msg;
    EXPECT_NE(msg.find("vertex 5 is not used"), std::string::npos) << msg;
  }
  {  // valence 17
    const Fan fan = make_fan(17, 2, true);
    const std::string msg = error_of([&] { CatmullClarkSpace s(PolyMesh::build(fan.points, fan.faces)); });
    EXPECT_NE(msg.find("vertex 1 has valence 17"), std::string::npos) << msg;
  }
  {  // boundary vertex with 16 faces
    const PolyMesh m = square_boundary_fan(16, 2);
    const std::string msg = error_of([&] { CatmullClarkSpace s(m); });
    EXPECT_NE(msg.find("boundary vertex 1 has 16 faces"), std::string::npos) << msg;
  }
  {  // a 17-gon (needs the global step; its face point would have valence 17)
    std::vector<Eigen::Vector3d> p;
    std::vector<Index> f;
    for (int i = 0; i < 17; ++i) {
      p.emplace_back(std::cos(2 * M_PI * i / 17), std::sin(2 * M_PI * i / 17), 0.0);
      f.push_back(i);
    }
    const std::string msg = error_of([&] { CatmullClarkSpace s(PolyMesh::build(p, {f})); });
    EXPECT_NE(msg.find("face 1 has 17 sides"), std::string::npos) << msg;
  }
  {  // interior vertices of valence 2: a pillow of two quads
    std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const PolyMesh m = PolyMesh::build(p, {{0, 1, 2, 3}, {0, 3, 2, 1}});
    const std::string msg = error_of([&] { CatmullClarkSpace s(m); });
    EXPECT_NE(msg.find("interior vertex 1 has valence 2"), std::string::npos) << msg;
  }
  {  // read from a file: the message has the line on which the unused vertex stands
    std::istringstream obj("# a square and a stray point\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\nv 5 5 0\nf 1 2 3 4\n");
    const PolyMesh m = iga::mesh::parse_obj(obj, "net.obj");
    EXPECT_EQ(error_of([&] { CatmullClarkSpace s(m, "net.obj"); }),
              "net.obj:7: vertex 5 is not used by any face (an isolated control point has no basis function)");
  }
}

}  // namespace
