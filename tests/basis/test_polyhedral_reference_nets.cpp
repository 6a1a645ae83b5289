// Our polyhedral surfaces against the reference implementation's masks on its own input nets
// (../shared/reference/polyhedral, read only, skipped when absent): for every patch of a configuration with
// a reference table, the maximum distance between our patch and the reference patch (both bi-3, sampled on a
// 9 × 9 grid; polar (3,2) patches degree-raised) relative to the net's bounding-box diagonal, reported per net and required <= 2e-2 (the
// fairness functionals differ, so equality is not expected; a large gap means a wrong construction).
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

#include "basis/polyhedral/bezier.hpp"
#include "basis/polyhedral/masks.hpp"
#include "basis/polyhedral/space.hpp"
#include "basis/polyhedral_cap_support.hpp"
#include "basis/polyhedral_nets.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"

using namespace iga;
using namespace iga::basis::polyhedral;
using namespace polyhedral_cap_support;

namespace {

// The reference masks in our layout (bi-3 rows × our gathered columns), per configuration; empty when the
// configuration has no reference table here.
std::vector<MatrixXd> reference_patches(Configuration c, int n) {
  auto bicubic = [](const ConfigurationMask& m) {
    std::vector<MatrixXd> out;
    for (const PatchMask& p : m.patches) out.push_back(elevate(p, 3, 3).coefficients);
    return out;
  };
  switch (c) {
    case Configuration::Star: return star_reference_in_our_layout(n);
    case Configuration::NGon: return ngon_reference_in_our_layout(n);
    case Configuration::Polar: {
      ConfigurationMask m;
      for (const MatrixXd& k : polar_reference_in_our_layout(n)) m.patches.push_back({3, 2, k});
      return bicubic(m);
    }
    case Configuration::T0: return bicubic(tjunction_reference_mask("T0"));
    case Configuration::T1: return bicubic(tjunction_reference_mask("T1"));
    case Configuration::T2: return bicubic(tjunction_reference_mask("T2"));
    default: return {};
  }
}

// Max distance of two bi-3 patches sampled at the same 9 × 9 parameters; the T1 masks run along (v, u) of
// the reference's picture, so the transposed parameterisation is tried as well.
double patch_distance(const MatrixXd& a, const MatrixXd& b) {
  double same = 0.0, transposed = 0.0;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const double u = i / 8.0, v = j / 8.0;
      same = std::max(same, (bezier3(a, u, v).x - bezier3(b, u, v).x).norm());
      transposed = std::max(transposed, (bezier3(a, u, v).x - bezier3(b, v, u).x).norm());
    }
  }
  return std::min(same, transposed);
}

}  // namespace

TEST(PolyhedralReferenceNets, CloseToTheReferenceSurfaces) {
  const auto dir = polyhedral_nets::reference_dir() / "testfile";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "reference nets not found at " << dir;
  int compared_nets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".obj") continue;
    const std::string name = entry.path().stem().string();
    const mesh::PolyMesh net = mesh::read_obj(entry.path().string());
    std::unique_ptr<PolyhedralSpace> space;
    try {
      space = std::make_unique<PolyhedralSpace>(net);
    } catch (const UnsupportedError& e) {
      std::cout << "[reference net " << name << "] skipped: " << e.what() << "\n";
      continue;
    }
    Eigen::Vector3d lo = net.point(0), hi = net.point(0);
    for (Index v = 0; v < net.num_vertices(); ++v) {
      lo = lo.cwiseMin(net.point(v));
      hi = hi.cwiseMax(net.point(v));
    }
    const double diagonal = (hi - lo).norm();
    double worst = 0.0;
    int patches = 0;
    std::map<std::pair<int, int>, std::vector<MatrixXd>> cache;
    for (Index e = 0; e < space->num_elements(); ++e) {
      const ConfigurationSite& site = space->sites()[static_cast<std::size_t>(space->site(e))];
      auto key = std::make_pair(static_cast<int>(site.type), site.valence);
      if (!cache.count(key)) cache[key] = reference_patches(site.type, site.valence);
      const std::vector<MatrixXd>& ref = cache[key];
      if (ref.empty()) continue;
      MatrixXd points(static_cast<Eigen::Index>(site.gathered.size()), 3);
      for (std::size_t k = 0; k < site.gathered.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = net.point(site.gathered[k]).transpose();
      const MatrixXd ours = bicubic_mask(site.type, site.valence).patches[static_cast<std::size_t>(space->patch(e))].coefficients * points;
      const MatrixXd theirs = ref[static_cast<std::size_t>(space->patch(e))] * points;
      worst = std::max(worst, patch_distance(ours, theirs) / diagonal);
      ++patches;
    }
    if (patches == 0) continue;
    ++compared_nets;
    std::cout << "[reference net " << name << "] " << patches << " cap patches, max distance / bbox diagonal "
              << worst << "\n";
    EXPECT_LE(worst, 2e-2) << name;
  }
  EXPECT_GT(compared_nets, 0);
}
