#pragma once
// A geometry of any backend for the distributed tests: a backend's default geometry, or a net of data/meshes/
// (half-box: the dual of the file's triangles), refined `refine` times; B-splines of degree 3.
#include <string>

#include "basis/registry.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "support/paths.hpp"

namespace iga::test {

struct BackendCase {
  std::string backend, mesh;  // mesh empty: the backend's default geometry
  int refine;
};

inline mesh::PolyMesh net_of(const std::string& backend, const std::string& file) {
  mesh::PolyMesh m = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file);
  return backend == "halfbox" ? mesh::dual_net(m) : m;
}

inline basis::Geometry geometry_of(const BackendCase& c) {
  basis::BackendFacts facts;
  basis::BackendOptions options;
  if (c.backend == "bspline") options.degree = 3;
  if (c.mesh.empty()) return basis::make_refined_geometry(basis::backend(c.backend), nullptr, options, c.refine, facts).geometry;
  const mesh::PolyMesh net = net_of(c.backend, c.mesh);
  return basis::make_refined_geometry(basis::backend(c.backend), &net, options, c.refine, facts).geometry;
}

}  // namespace iga::test
