// Registration of the polyhedral bi-3 spline backend (basis/registry.hpp). Refined nets give spaces that do
// not contain the coarse one: refinement is a Catmull–Clark step of the net and a new space (not nested).
#include <memory>
#include <string>

#include "basis/polyhedral/bezier.hpp"
#include "basis/polyhedral/configuration.hpp"
#include "basis/polyhedral/masks.hpp"
#include "basis/polyhedral/space.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"

namespace iga::basis {
namespace {

using polyhedral::PolyhedralSpace;

const PolyhedralSpace& polyhedral_of(const Geometry& g) {
  const auto* p = dynamic_cast<const PolyhedralSpace*>(&g.space());
  if (!p) throw InputError("a '" + g.space().name() + "' space is not a polyhedral space");
  return *p;
}

/// "star5", "ngon3", "polar6", "regular", "T0".
std::string site_name(const polyhedral::ConfigurationSite& s) {
  std::string name = to_string(s.type);
  if (s.type == polyhedral::Configuration::Star || s.type == polyhedral::Configuration::NGon ||
      s.type == polyhedral::Configuration::Polar) {
    name += std::to_string(s.valence);
  }
  return name;
}

void count_patches(const PolyhedralSpace& space, BackendFacts& facts) {
  std::erase_if(facts.counts, [](const auto& kv) { return kv.first.starts_with("patches_per_configuration/"); });
  for (Index e = 0; e < space.num_elements(); ++e) {
    ++facts.counts["patches_per_configuration/" + to_string(space.configuration(e))];
  }
}

Geometry build(const mesh::PolyMesh& net, const std::string& name, BackendFacts& facts) {
  try {
    Geometry g = polyhedral::make_polyhedral_geometry(net);
    count_patches(polyhedral_of(g), facts);
    return g;
  } catch (const polyhedral::UnsupportedConfigurationError& e) {
    throw InputError(name, 0, e.what());
  }
}

Geometry from_net(const mesh::PolyMesh& net, const BackendOptions& o, BackendFacts& facts) {
  const int steps = o.presubdivide == BackendOptions::kUnset ? 0 : o.presubdivide;
  facts.counts["net_catmull_clark_steps"] += steps;
  if (steps > 0) {
    const mesh::PolyMesh fine = polyhedral::presubdivide(net, steps);
    facts.notes.push_back("applied " + std::to_string(steps) + " Catmull-Clark step(s) to the net: " +
                          std::to_string(fine.num_vertices()) + " vertices, " + std::to_string(fine.num_faces()) + " faces");
    return build(fine, o.net_name, facts);
  }
  return build(net, o.net_name, facts);
}

// The net with the geometry's control points at the vertices that are dofs.
mesh::PolyMesh current_net(const Geometry& geometry) {
  const auto& space = polyhedral_of(geometry);
  return net_with_control_points(space.control_net(), geometry, [&](Index d) { return space.vertex(d); });
}

mesh::PolyMesh refine_net_first(const mesh::PolyMesh& net, int steps, const BackendOptions&, BackendFacts& facts) {
  facts.counts["net_catmull_clark_steps"] += steps;
  return polyhedral::presubdivide(net, steps);
}

Refinement refine_net(const Geometry& geometry, int steps, BackendFacts& facts) {
  facts.counts["net_catmull_clark_steps"] += steps;
  Geometry fine = build(polyhedral::presubdivide(current_net(geometry), steps), "refined net", facts);
  return {std::move(fine), Eigen::SparseMatrix<double>(), false};
}

// Every patch of every configuration in the degrees the paper outputs (regular bi-2, polar (3,2)), or all
// bi-3 with degree_raise; counts per configuration under "configurations/<name>/{configurations,patches}".
std::vector<BezierPatch> configuration_patches(const Geometry& geometry, const BackendOptions& o, BackendFacts& facts) {
  const PolyhedralSpace& space = polyhedral_of(geometry);
  const mesh::PolyMesh net = current_net(geometry);
  std::vector<BezierPatch> patches;
  for (const auto& s : space.sites()) {
    const polyhedral::ConfigurationMask& mask = polyhedral::native_mask(s.type, s.valence);
    Eigen::MatrixXd gathered(static_cast<Index>(s.gathered.size()), 3);
    for (std::size_t k = 0; k < s.gathered.size(); ++k) gathered.row(static_cast<Index>(k)) = net.point(s.gathered[k]).transpose();
    for (const polyhedral::PatchMask& pm : mask.patches) {
      polyhedral::BezierPatch patch{pm.degree_u, pm.degree_v, pm.coefficients * gathered};
      if (o.degree_raise) patch = polyhedral::elevate(patch, 3, 3);
      patches.push_back({polyhedral::bv_group_name(s.type), false, patch.degree_u, patch.degree_v, patch.coefficients});
    }
    const std::string key = "configurations/" + site_name(s);
    ++facts.counts[key + "/configurations"];
    facts.counts[key + "/patches"] += static_cast<long long>(mask.patches.size());
  }
  return patches;
}

}  // namespace

Backend polyhedral_backend() {
  Backend b;
  b.name = "polyhedral";
  b.description = "bi-3 polyhedral splines (Peters, Lo, Karčiauskas) on a polyhedral control net";
  b.options = {"presubdivide", "degree-raise"};
  b.default_degree = 3;
  b.default_refine = 0;
  b.nested = false;
  b.from_net = from_net;
  b.refine = refine_net;
  b.refine_net = refine_net_first;
  b.default_quadrature = [](int) { return std::string("gauss:4"); };
  b.bezier_patches = configuration_patches;
  return b;
}

}  // namespace iga::basis
