// Exact area and enclosed volume of Catmull–Clark geometries (quadrature/exact/geometry_integrals.hpp):
// planar "wheel" nets whose limit boundary is a known regular n-gon (∫ det J depends only on the boundary, so
// interior control points may be moved freely), a square with boundary EVs, and closed surfaces against
// per-tile Gauss quadrature with growing numbers of levels.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <utility>

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include "basis/catmull_clark/space.hpp"
#include "basis/geometry.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/poly_mesh.hpp"
#include "quadrature/exact/geometry_integrals.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/tensor_rule.hpp"

using iga::Index;
using namespace iga::quadrature;
using namespace iga::quadrature::exact;

namespace {

// n sectors around a centre of valence n; sector k is the bilinear 2×2 block of the kite C, E_(k-1), P_k, E_k
// with P_k = (cos 2πk/n, sin 2πk/n) the polygon's corners (one face: interpolated corners) and E_k the
// midpoints of its sides. The boundary control polygon runs along the sides with collinear, evenly spaced
// points, so the limit boundary is the n-gon. Interior points (centre, ray midpoints, sector centres) are
// moved by up to `jitter`.
iga::mesh::PolyMesh wheel(int n, double jitter, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-jitter, jitter);
  std::vector<Eigen::Vector3d> pts;
  std::map<std::pair<long long, long long>, Index> index;
  auto vertex = [&](const Eigen::Vector2d& p) {
    const auto key = std::make_pair(std::llround(p.x() * 1e9), std::llround(p.y() * 1e9));
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    pts.emplace_back(p.x(), p.y(), 0.0);
    return index[key] = static_cast<Index>(pts.size()) - 1;
  };
  auto corner = [&](int k) {
    const double t = 2 * std::numbers::pi * k / n;
    return Eigen::Vector2d(std::cos(t), std::sin(t));
  };
  std::vector<std::vector<Index>> faces;
  const Eigen::Vector2d c(0, 0);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d e0 = 0.5 * (corner(k - 1) + corner(k)), e1 = 0.5 * (corner(k) + corner(k + 1)), p = corner(k);
    Index g[3][3];
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; b <= 2; ++b)
        g[a][b] = vertex(c + a / 2.0 * (e0 - c) + b / 2.0 * (e1 - c) + a * b / 4.0 * (p - e0 - e1 + c));
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) faces.push_back({g[a][b], g[a + 1][b], g[a + 1][b + 1], g[a][b + 1]});
  }
  // Move the interior vertices (not on the boundary polygon).
  auto mesh = iga::mesh::PolyMesh::build(pts, faces);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (!mesh.is_boundary_vertex(v)) pts[static_cast<std::size_t>(v)] += Eigen::Vector3d(d(gen), d(gen), 0.0);
  }
  return iga::mesh::PolyMesh::build(pts, faces);
}

double quadrature_integral(const iga::basis::Geometry& g, int levels, bool volume) {
  const Rule1D g5 = gauss_legendre(5);
  const Rule regular = tensor_rule(g5, g5), tiled = tiled_rule(5, levels);
  iga::basis::GeometryValues gv;
  double s = 0;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    const Rule& r = g.space().kind(e).family == iga::basis::Family::Regular ? regular : tiled;
    g.evaluate(e, r.points, gv);
    for (Eigen::Index q = 0; q < r.size(); ++q) {
      const double det = gv.xu(0, q) * gv.xv(1, q) - gv.xu(1, q) * gv.xv(0, q);
      s += r.weights(q) * det * (volume ? gv.x(2, q) : 1.0);
    }
  }
  return s;
}

// Reference: OpenSubdiv's limit surface as a Far::PatchTable (adaptive isolation to `level`, Gregory-basis
// end caps at the EVs), ∫ z (x_u y_v - y_u x_v) by 5×5 Gauss per patch in face coordinates. Its error is that
// of the end caps, which cover a region of size 2^-level around each EV.
struct Vtx {
  double p[3] = {0, 0, 0};
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Vtx& v, double w) {
    for (int i = 0; i < 3; ++i) p[i] += w * v.p[i];
  }
};

void opensubdiv_volume(const iga::mesh::PolyMesh& m, int level, double& vol) {
  using namespace OpenSubdiv;
  std::vector<int> sizes, verts;
  for (Index f = 0; f < m.num_faces(); ++f) {
    sizes.push_back(static_cast<int>(m.face_size(f)));
    for (Index v : m.face(f)) verts.push_back(static_cast<int>(v));
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(m.num_vertices());
  desc.numFaces = static_cast<int>(m.num_faces());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = verts.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  std::unique_ptr<Far::TopologyRefiner> refiner(Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
      desc, Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(Sdc::SCHEME_CATMARK, sdc)));
  Far::PatchTableFactory::Options po(level);
  po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  po.SetPatchPrecision<double>();  // the local-point stencils are read as double below (OpenSubdiv asserts the match)
  po.useInfSharpPatch = true;
  refiner->RefineAdaptive(po.GetRefineAdaptiveOptions());
  std::unique_ptr<Far::PatchTable> table(Far::PatchTableFactory::Create(*refiner, po));
  const int nref = refiner->GetNumVerticesTotal(), nloc = table->GetNumLocalPoints();
  std::vector<Vtx> v(static_cast<std::size_t>(nref + nloc));
  for (Index i = 0; i < m.num_vertices(); ++i)
    for (int k = 0; k < 3; ++k) v[static_cast<std::size_t>(i)].p[k] = m.point(i)(k);
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  Vtx* src = v.data();
  for (int l = 1; l <= refiner->GetMaxLevel(); ++l) {
    Vtx* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
    primvar.Interpolate(l, src, dst);
    src = dst;
  }
  if (nloc > 0) table->GetLocalPointStencilTable<double>()->UpdateValues(v.data(), v.data() + nref);
  const Rule1D g5 = gauss_legendre(5);
  const Rule rule = tensor_rule(g5, g5);
  vol = 0;
  double w[20], wu[20], wv[20];
  const Far::PatchMap map(*table);
  for (int a = 0; a < table->GetNumPatchArrays(); ++a) {
    for (int i = 0; i < table->GetNumPatches(a); ++i) {
      const Far::PatchParam param = table->GetPatchParam(a, i);
      const auto cvs = table->GetPatchVertices(a, i);
      const double frac = param.GetParamFraction();
      for (Eigen::Index q = 0; q < rule.size(); ++q) {
        double u = rule.points(0, q), t = rule.points(1, q);
        param.Unnormalize(u, t);
        const Far::PatchTable::PatchHandle* handle = map.FindPatch(param.GetFaceId(), u, t);
        ASSERT_NE(handle, nullptr);
        table->EvaluateBasis(*handle, u, t, w, wu, wv);
        double x[3] = {0, 0, 0}, xu[3] = {0, 0, 0}, xv[3] = {0, 0, 0};
        for (int c = 0; c < cvs.size(); ++c) {
          const Vtx& p = v[static_cast<std::size_t>(cvs[c])];
          for (int k = 0; k < 3; ++k) {
            x[k] += w[c] * p.p[k];
            xu[k] += wu[c] * p.p[k];
            xv[k] += wv[c] * p.p[k];
          }
        }
        vol += rule.weights(q) * frac * frac * x[2] * (xu[0] * xv[1] - xu[1] * xv[0]);
      }
    }
  }
}

std::string data(const char* name) { return std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name; }

}  // namespace

TEST(ExactGeometry, WheelAreaIsTheRegularPolygon) {
  for (int n = 3; n <= 8; ++n) {
    const double polygon = 0.5 * n * std::sin(2 * std::numbers::pi / n);
    for (double jitter : {0.0, 0.05}) {
      const auto g = iga::basis::catmull_clark::make_catmull_clark_geometry(wheel(n, jitter, 7u + static_cast<unsigned>(n)));
      const auto& cc = dynamic_cast<const iga::basis::catmull_clark::CatmullClarkSpace&>(g.space());
      EXPECT_EQ(cc.refinement_steps(), 0);
      const double a = exact_area(g);
      std::printf("n = %d jitter %.2f: exact area %.16f  polygon %.16f  rel %.2e\n", n, jitter, a, polygon,
                  std::abs(a - polygon) / polygon);
      EXPECT_LT(std::abs(a - polygon), 1e-13 * polygon) << "n = " << n;
    }
  }
}

TEST(ExactGeometry, SquareWithBoundaryEVs) {
  const auto g = iga::basis::catmull_clark::make_catmull_clark_geometry(iga::mesh::read_obj(data("square_evs.obj")));
  const double a = exact_area(g);
  std::printf("square_evs: exact area %.16f; tiled L=20: %.16f\n", a, quadrature_integral(g, 20, false));
  EXPECT_NEAR(a, 1.0, 1e-13);
}

TEST(ExactGeometry, ClosedSurfaceVolumes) {
  for (const char* name : {"cube.obj", "torus_evs.obj"}) {
    const auto mesh = iga::mesh::read_obj(data(name));
    const auto g = iga::basis::catmull_clark::make_catmull_clark_geometry(mesh);
    const double v = exact_volume(g);
    double prev = 1e300;
    for (int levels : {4, 8, 12, 16, 20, 24}) {
      const double q = quadrature_integral(g, levels, true);
      const double e = std::abs(q - v) / std::abs(v);
      std::printf("%s: exact volume %.16f  tiled L=%2d %.16f  rel diff %.2e\n", name, v, levels, q, e);
      // Geometric decrease (≈ λ^(2L)) down to the rounding floor of the tiled sum (~1e-13: 10^5 terms).
      EXPECT_TRUE(e < prev || e < 2e-13) << name << " L = " << levels;
      prev = e;
    }
    EXPECT_LT(prev, 2e-13) << name;
    // The end caps' error decays geometrically with the isolation level (measured: cube ×~35, torus ×~11 per
    // two levels; 2.0e-8 and 2.0e-6 at level 10): the reference converges to the exact value.
    double prev_os = 1e300;
    for (int level : {4, 6, 8, 10}) {
      double r = 0;
      opensubdiv_volume(mesh, level, r);
      if (level == 10) {
        EXPECT_LT(std::abs(r - v), 5e-6 * std::abs(v)) << name;
      }
      std::printf("%s: OpenSubdiv patch table (isolation %2d, Gregory end caps) %.16f  rel diff %.2e\n", name,
                  level, r, std::abs(r - v) / std::abs(v));
      const double e = std::abs(r - v) / std::abs(v);
      EXPECT_LT(e, prev_os / 8) << name << " isolation " << level;
      prev_os = e;
    }
    // ∫ (z + c) n_z dA = V for a closed surface: translation invariance.
    Eigen::MatrixXd shifted = g.control_points();
    shifted.col(2).array() += 3.0;
    shifted.col(0).array() -= 1.5;
    const iga::basis::Geometry gs(g.space_ptr(), shifted);
    EXPECT_NEAR(exact_volume(gs), v, 1e-13 * std::abs(v)) << name;
  }
}

TEST(ExactGeometry, WrongDimension) {
  const auto g = iga::basis::catmull_clark::make_catmull_clark_geometry(wheel(5, 0.0, 1u));
  EXPECT_THROW(exact_volume(g), iga::InputError);
}
