// iga-geometry end to end: JSON counts, the .bv read back with io/bv and checked against closed forms (corner
// and centre BB coefficients of bi-2 patches, corner interpolation of open B-splines, Catmull–Clark limit
// points), the .vtu read back with VTK, and one clear error line with a non-zero exit on bad input.
#include "support/paths.hpp"
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "basis/registry.hpp"
#include "io/bv.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/obj_writer.hpp"
#include "mesh/three_valent.hpp"

namespace fs = std::filesystem;

namespace {

struct Outcome {
  int code;
  std::string err;
};

/// Vertex (i, j) of an n × n grid at (i, j, z) with a fixed non-polynomial z.
Eigen::Vector3d grid_point(int i, int j) { return Eigen::Vector3d(i, j, 0.3 * std::sin(1.3 * i + 0.7 * j * j)); }

std::string grid_obj(int n) {
  std::ostringstream s;
  s.precision(17);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) s << "v " << grid_point(i, j).transpose() << "\n";
  }
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      const int a = 1 + i + n * j;
      s << "f " << a << " " << a + 1 << " " << a + 1 + n << " " << a + n << "\n";
    }
  }
  return s.str();
}

/// A 5 × 5 vertex grid whose quad at (1,1) is split into two triangles (faces 6 and 7): unsupported.
std::string split_quad_obj() {
  std::ostringstream s;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) s << "v " << i << " " << j << " 0\n";
  }
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const int a = 1 + i + 5 * j;
      if (i == 1 && j == 1) {
        s << "f " << a << " " << a + 1 << " " << a + 6 << "\nf " << a << " " << a + 6 << " " << a + 5 << "\n";
      } else {
        s << "f " << a << " " << a + 1 << " " << a + 6 << " " << a + 5 << "\n";
      }
    }
  }
  return s.str();
}

class IgaGeometry : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("iga_geometry_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  Outcome run(const std::string& args) {
    const fs::path err = dir_ / "stderr.txt";
    const std::string cmd = "cd '" + dir_.string() + "' && '" + IGA_GEOMETRY_EXE + "' " + args + " 2> '" + err.string() + "' > /dev/null";
    const int status = std::system(cmd.c_str());
    std::ifstream in(err);
    std::stringstream ss;
    ss << in.rdbuf();
    return {WEXITSTATUS(status), ss.str()};
  }
  nlohmann::json report(const std::string& name) {
    std::ifstream in(dir_ / name);
    return nlohmann::json::parse(in);
  }
  fs::path dir_;
};

bool contains_point(const std::vector<Eigen::RowVector3d>& pts, const Eigen::RowVector3d& p, double tol) {
  for (const auto& q : pts) {
    if ((q - p).norm() < tol) return true;
  }
  return false;
}

TEST_F(IgaGeometry, PolyhedralRegularGrid) {
  write("grid.obj", grid_obj(5));
  const Outcome r = run("--basis polyhedral --mesh grid.obj --bv out.bv --vtu out.vtu --vtu-format linear --vtu-samples 5 --json out.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = report("out.json");
  // 9 interior vertices, each a regular configuration with one bi-2 patch (paper Section 3 (1)).
  EXPECT_EQ(j["configurations"]["regular"]["configurations"], 9);
  EXPECT_EQ(j["configurations"]["regular"]["patches"], 9);
  EXPECT_EQ(j["configurations"].size(), 1u);
  EXPECT_EQ(j["bv_patches"], 9);
  const auto patches = iga::io::read_bv((dir_ / "out.bv").string());
  ASSERT_EQ(patches.size(), 9u);
  // Closed form of the uniform bi-2 piece: the middle BB coefficient is the centre vertex, the corner ones
  // are the centroids of the four quads around it.
  std::vector<Eigen::RowVector3d> vertices, centroids;
  for (int jj = 1; jj <= 3; ++jj) {
    for (int i = 1; i <= 3; ++i) vertices.push_back(grid_point(i, jj).transpose());
  }
  for (int jj = 0; jj < 4; ++jj) {
    for (int i = 0; i < 4; ++i) {
      centroids.push_back(0.25 * (grid_point(i, jj) + grid_point(i + 1, jj) + grid_point(i, jj + 1) + grid_point(i + 1, jj + 1)).transpose());
    }
  }
  for (const auto& p : patches) {
    EXPECT_EQ(p.group, "Group 0 Regular");
    ASSERT_EQ(p.degree_u, 2);
    ASSERT_EQ(p.degree_v, 2);
    EXPECT_TRUE(contains_point(vertices, p.points.row(4), 1e-13));
    for (int c : {0, 2, 6, 8}) EXPECT_TRUE(contains_point(centroids, p.points.row(c), 1e-13));
  }
  // The .vtu: 9 elements × (5 − 1)² quad cells.
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((dir_ / "out.vtu").string().c_str());
  reader->Update();
  ASSERT_NE(reader->GetOutput(), nullptr);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 9 * 16);
  EXPECT_EQ(reader->GetOutput()->GetPointData()->GetArray("u"), nullptr);  // the geometry alone: no field

  // --degree-raise: the same patches as bi-3; corners (interpolated) unchanged.
  ASSERT_EQ(run("--mesh grid.obj --bv raised.bv --degree-raise --quiet").code, 0);
  const auto raised = iga::io::read_bv((dir_ / "raised.bv").string());
  ASSERT_EQ(raised.size(), 9u);
  for (std::size_t k = 0; k < 9; ++k) {
    EXPECT_EQ(raised[k].degree_u, 3);
    EXPECT_LT((raised[k].points.row(0) - patches[k].points.row(0)).norm(), 1e-14);
    EXPECT_LT((raised[k].points.row(15) - patches[k].points.row(8)).norm(), 1e-14);
  }
}

TEST_F(IgaGeometry, BsplineByBezierExtraction) {
  write("grid.obj", grid_obj(6));
  ASSERT_EQ(run("--basis bspline --degree 3 --mesh grid.obj --bv out.bv --json out.json --vtu out.vtu").code, 0);
  const auto j = report("out.json");
  EXPECT_EQ(j["elements"], 9);  // 6 − 3 = 3 intervals per direction
  const auto patches = iga::io::read_bv((dir_ / "out.bv").string());
  ASSERT_EQ(patches.size(), 9u);
  // Open knot vectors interpolate the corner control points: the four domain corners are BB corners.
  std::vector<Eigen::RowVector3d> corners;
  for (const auto& p : patches) {
    EXPECT_EQ(p.degree_u, 3);
    for (int c : {0, 3, 12, 15}) corners.push_back(p.points.row(c));
  }
  for (int i : {0, 5}) {
    for (int jj : {0, 5}) EXPECT_TRUE(contains_point(corners, grid_point(i, jj).transpose(), 1e-13)) << i << " " << jj;
  }
  // Neighbouring patches share their boundary curves (C0 at least): every corner appears 1, 2 or 4 times.
  for (const auto& c : corners) {
    int k = 0;
    for (const auto& d : corners) k += (c - d).norm() < 1e-12;
    EXPECT_TRUE(k == 1 || k == 2 || k == 4) << k;
  }
}

TEST_F(IgaGeometry, CatmullClarkRegularElementsAndSkippedOnes) {
  write("grid.obj", grid_obj(7));
  ASSERT_EQ(run("--basis cc --mesh grid.obj --bv out.bv --json out.json --vtu out.vtu --net net.vtu").code, 0);
  const auto j = report("out.json");
  EXPECT_EQ(j["elements"], 36);
  // --net: the 7 × 7 control points (the net's vertices, no global step needed) and the 36 faces as polygons.
  EXPECT_EQ(j["net_vtu"], "net.vtu");
  auto net_reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  net_reader->SetFileName((dir_ / "net.vtu").string().c_str());
  net_reader->Update();
  EXPECT_EQ(net_reader->GetOutput()->GetNumberOfPoints(), 49);
  EXPECT_EQ(net_reader->GetOutput()->GetNumberOfCells(), 49 + 36);
  // The default --vtu-format bezier: one bi-3 cell per element, the outline beside it, no u.
  EXPECT_EQ(j["vtu_output"]["format"], "bezier");
  EXPECT_TRUE(fs::exists(dir_ / "out_outline.vtu"));
  EXPECT_EQ(j["bv_patches"].get<int>() + j["bv_skipped"].get<int>(), 36);
  const auto patches = iga::io::read_bv((dir_ / "out.bv").string());
  ASSERT_EQ(static_cast<int>(patches.size()), j["bv_patches"].get<int>());
  // The limit point of the centre vertex (3,3) of a regular ring: (16 v + 4 Σ e + Σ f) / 36; it is a corner
  // of the four bi-3 patches around it.
  const Eigen::Vector3d v = grid_point(3, 3);
  const Eigen::Vector3d e = grid_point(2, 3) + grid_point(4, 3) + grid_point(3, 2) + grid_point(3, 4);
  const Eigen::Vector3d f = grid_point(2, 2) + grid_point(4, 2) + grid_point(2, 4) + grid_point(4, 4);
  const Eigen::RowVector3d limit = ((16 * v + 4 * e + f) / 36).transpose();
  int hits = 0;
  for (const auto& p : patches) {
    for (int c : {0, 3, 12, 15}) hits += (p.points.row(c) - limit).norm() < 1e-12;
  }
  EXPECT_EQ(hits, 4);

  // A net with a 5-valent vertex: the elements at it are not polynomial and are skipped, and said so.
  write("star.obj", "v 0 0 0\nv 1 0 0\nv 0.3 1 0\nv -0.8 0.6 0\nv -0.8 -0.6 0\nv 0.3 -1 0\n"
                    "v 1 1 0\nv -0.3 1.3 0\nv -1.3 0 0.1\nv -0.3 -1.3 0\nv 1 -1 0\n"
                    "f 1 2 7 3\nf 1 3 8 4\nf 1 4 9 5\nf 1 5 10 6\nf 1 6 11 2\n");
  const Outcome r = run("--basis cc --mesh star.obj --bv star.bv --json star.json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_GT(report("star.json")["bv_skipped"].get<int>(), 0);
  EXPECT_NE(r.err.find("not in the .bv"), std::string::npos) << r.err;
}

// --cc-corners (README): the clamped L-shape's reflex corner is a point of the drawn limit domain, (1, 1), only
// when it is kept as a corner (the linear cells sample every element's corners exactly).
TEST_F(IgaGeometry, CatmullClarkCornerVertexIsOnTheDrawnDomain) {
  const std::string net = std::string(IGA_SOURCE_DIR) + "/data/meshes/l_shape.obj";
  const auto distance_to_corner = [&](const std::string& extra) {
    const Outcome r = run("--basis cc --mesh '" + net + "' --cc-boundary clamped --vtu corner.vtu --vtu-format linear "
                          "--vtu-samples 4 --quiet " + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName((dir_ / "corner.vtu").string().c_str());
    reader->Update();
    double best = 1e300;
    for (vtkIdType i = 0; i < reader->GetOutput()->GetNumberOfPoints(); ++i) {
      double x[3];
      reader->GetOutput()->GetPoint(i, x);
      best = std::min(best, std::hypot(x[0] - 1, x[1] - 1));
    }
    return best;
  };
  EXPECT_LT(distance_to_corner("--cc-corners 41"), 1e-12);
  EXPECT_GT(distance_to_corner(""), 1e-3);
}

TEST_F(IgaGeometry, ErrorsAreOneLineAndNonZero) {
  // (Every configuration of the paper has a mask now: the former "polar fan has no mask" case is gone.)
  // An unsupported configuration: each offending face named, with the suggestion.
  write("split.obj", split_quad_obj());
  Outcome r = run("--mesh split.obj --bv out.bv");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("face 6: 3-gon"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("face 7: 3-gon"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--presubdivide"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  // After one Catmull–Clark step the net is admissible: only stars (the triangles' face points, valence 3,
  // and the diagonal's ends, valence 5) and regular vertices (paper, Section 3).
  r = run("--mesh split.obj --presubdivide 1 --bv out.bv --json out.json --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = report("out.json");
  EXPECT_EQ(j["configurations"]["star3"]["configurations"], 2);
  EXPECT_EQ(j["configurations"]["star5"]["configurations"], 2);
  EXPECT_EQ(j["configurations"]["star3"]["patches"], 6);
  EXPECT_EQ(j["configurations"]["star5"]["patches"], 10);
  EXPECT_EQ(j["configurations"].size(), 3u);
  EXPECT_EQ(iga::io::read_bv((dir_ / "out.bv").string()).size(), j["bv_patches"].get<std::size_t>());

  // A malformed OBJ: file and line.
  write("bad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 x\nf 1 2 3\n");
  r = run("--mesh bad.obj --bv out.bv");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("bad.obj:3"), std::string::npos) << r.err;
  // A bspline net that is not a grid.
  r = run("--basis bspline --mesh split.obj --bv out.bv");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("iga-geometry: error: "), std::string::npos) << r.err;
  // Unknown option values are refused by the parser.
  EXPECT_NE(run("--basis halfbox --mesh split.obj").code, 0);
  EXPECT_NE(run("--mesh missing.obj").code, 0);
}

/// The boundary curves of a bi-3 patch (BB rows of its four sides, each in increasing parameter).
std::vector<Eigen::MatrixXd> sides(const iga::io::BvPatch& p) {
  std::vector<Eigen::MatrixXd> out(4, Eigen::MatrixXd(4, 3));
  for (int t = 0; t < 4; ++t) {
    out[0].row(t) = p.points.row(t);           // v = 0
    out[1].row(t) = p.points.row(t * 4 + 3);   // u = 1
    out[2].row(t) = p.points.row(12 + t);      // v = 1
    out[3].row(t) = p.points.row(t * 4);       // u = 0
  }
  return out;
}

TEST_F(IgaGeometry, ClosedNetGivesAWatertightSurface) {
  // The cube: 8 vertices of valence 3, 6 quads, closed. 8 star caps of 3 bi-3 patches; every patch side is
  // shared with exactly one other patch side (same BB boundary curve, possibly reversed): no holes.
  write("cube.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const Outcome r = run("--mesh cube.obj --bv out.bv --json out.json --vtu out.vtu");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = report("out.json");
  EXPECT_EQ(j["configurations"]["star3"]["configurations"], 8);
  const auto patches = iga::io::read_bv((dir_ / "out.bv").string());
  ASSERT_EQ(patches.size(), 24u);
  std::vector<Eigen::MatrixXd> all;
  for (const auto& p : patches) {
    EXPECT_EQ(p.group, "Group 1 ExtraordinaryPoint");
    ASSERT_EQ(p.degree_u, 3);
    ASSERT_EQ(p.degree_v, 3);
    for (const auto& s : sides(p)) all.push_back(s);
  }
  for (std::size_t a = 0; a < all.size(); ++a) {
    int partners = 0;
    for (std::size_t b = 0; b < all.size(); ++b) {
      if (a / 4 == b / 4) continue;
      const bool same = (all[a] - all[b]).cwiseAbs().maxCoeff() < 1e-10;
      const bool reversed = (all[a] - all[b].colwise().reverse()).cwiseAbs().maxCoeff() < 1e-10;
      partners += same || reversed;
    }
    EXPECT_EQ(partners, 1) << "side " << a % 4 << " of patch " << a / 4;
  }
}

}  // namespace

// Triangle mesh → three-valent net (Appendix B): the dual of the 8 × 8 square triangulation has a face per
// vertex (81), a vertex per triangle plus two per boundary edge (128 + 2·32), and the interior 5- and 7-gons
// of its valence-5 and -7 vertices; the trisection has V + F faces and 2E + B vertices. The net is read back.
TEST_F(IgaGeometry, ThreeValentNetsFromATriangulation) {
  const std::string tri = std::string(IGA_SOURCE_DIR) + "/data/meshes/tri_square.obj";
  ASSERT_EQ(run("--three-valent dual --mesh '" + tri + "' --obj net.obj --json net.json --quiet").code, 0);
  nlohmann::json j = report("net.json");
  EXPECT_EQ(j["net_faces"], 81);
  EXPECT_EQ(j["net_vertices"], 128 + 2 * 32);
  // Face sizes from the triangulation: an interior vertex of valence k gives a k-gon, a boundary vertex with
  // k edges a (k + 2)-gon (its two boundary-edge midpoints and itself close the fan).
  const iga::mesh::PolyMesh tris = iga::mesh::read_obj(tri);
  std::map<std::string, long long> sizes;
  for (iga::Index v = 0; v < tris.num_vertices(); ++v) {
    ++sizes[std::to_string(tris.valence(static_cast<iga::Index>(v)) + (tris.is_boundary_vertex(v) ? 2 : 0))];
  }
  using SizeCounts = std::map<std::string, long long>;
  EXPECT_EQ(j["faces_per_size"].get<SizeCounts>(), sizes);
  EXPECT_GE(sizes["7"], 2);
  const iga::mesh::PolyMesh net = iga::mesh::read_obj((dir_ / "net.obj").string());
  EXPECT_EQ(net.num_faces(), 81);
  EXPECT_NO_THROW(iga::mesh::check_three_valent(net, "net.obj"));
  ASSERT_EQ(run("--three-valent trisect --mesh '" + tri + "' --obj tri.obj --json tri.json --quiet").code, 0);
  j = report("tri.json");
  EXPECT_EQ(j["net_faces"], 81 + 128);
  EXPECT_EQ(j["net_vertices"], 2 * 208 + 32);
  // A quad mesh is not a triangulation: one line naming the file and the face.
  write("quads.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const Outcome r = run("--three-valent dual --mesh quads.obj --obj out.obj");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("quads.obj:0: face 1 has 4 vertices"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(run("--three-valent dual --mesh quads.obj").code, 0);  // no --obj
}

namespace {
// A triangular Bézier patch of io/bv.hpp's order at (u, v): Σ d!/(i! j! k!) λ0^i λ1^j λ2^k b_ijk.
Eigen::RowVector3d bezier_triangle(const iga::io::BvPatch& p, double u, double v) {
  const int d = p.degree_u;
  auto fact = [](int n) { return std::tgamma(n + 1.0); };
  Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
  for (int k = 0; k <= d; ++k) {
    for (int j = 0; j + k <= d; ++j) {
      const int i = d - j - k;
      const double b = fact(d) / (fact(i) * fact(j) * fact(k)) * std::pow(1 - u - v, i) * std::pow(u, j) * std::pow(v, k);
      x += b * p.points.row(iga::io::triangle_index(d, j, k));
    }
  }
  return x;
}
}  // namespace

// Half-box splines: the regular elements are written as cubic triangles (kind 3), the elements at the 5- and
// 7-gons of the dual of tri_square are skipped. The net is lifted (z = 0.2 sin(3x + 2y²)) so the surface is
// not affine. Each patch, in the order of the regular elements, equals the limit surface (the half-box geometry
// of the same net) at the element's centroid and at the non-symmetric point (0.6, 0.25), which a wrong
// corner order would move; 1e-12 is rounding of the 13-point BB sums (coordinates O(1)).
TEST_F(IgaGeometry, HalfBoxRegularElementsAsTriangles) {
  const iga::mesh::PolyMesh flat =
      iga::mesh::dual_net(iga::mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/tri_square.obj"));
  std::vector<Eigen::Vector3d> points = flat.points();
  for (Eigen::Vector3d& x : points) x(2) = 0.2 * std::sin(3 * x(0) + 2 * x(1) * x(1));
  std::vector<std::vector<iga::Index>> faces;
  for (iga::Index f = 0; f < flat.num_faces(); ++f) faces.emplace_back(flat.face(f).begin(), flat.face(f).end());
  iga::mesh::write_obj(iga::mesh::PolyMesh::build(points, faces), (dir_ / "dual.obj").string());
  const Outcome r = run("--basis halfbox --mesh dual.obj --bv out.bv --json out.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = report("out.json");
  EXPECT_EQ(j["bv_patches"].get<int>() + j["bv_skipped"].get<int>(), j["elements"].get<int>());
  EXPECT_GT(j["bv_skipped"].get<int>(), 0);
  const auto patches = iga::io::read_bv((dir_ / "out.bv").string());
  ASSERT_EQ(static_cast<int>(patches.size()), j["bv_patches"].get<int>());

  const iga::mesh::PolyMesh back = iga::mesh::read_obj((dir_ / "dual.obj").string());
  iga::basis::BackendFacts facts;
  const iga::basis::Geometry g = iga::basis::make_geometry(iga::basis::backend("halfbox"), &back, {}, facts);
  ASSERT_EQ(g.space().num_elements(), j["elements"].get<int>());
  Eigen::Matrix2Xd pts(2, 2);
  pts << 1.0 / 3, 0.6, 1.0 / 3, 0.25;
  iga::basis::GeometryValues gv;
  std::size_t next = 0;
  double worst = 0;
  for (iga::Index e = 0; e < g.space().num_elements(); ++e) {
    if (g.space().kind(e).family != iga::basis::Family::Regular) continue;
    ASSERT_LT(next, patches.size());
    const iga::io::BvPatch& p = patches[next++];
    ASSERT_TRUE(p.triangle);
    ASSERT_EQ(p.degree_u, 3);
    g.evaluate(e, pts, gv);
    for (int c = 0; c < 2; ++c) {
      const Eigen::RowVector3d limit = gv.x.col(c).transpose();
      worst = std::max(worst, (bezier_triangle(p, pts(0, c), pts(1, c)) - limit).norm());
    }
  }
  EXPECT_EQ(next, patches.size());
  EXPECT_LT(worst, 1e-12);
}
