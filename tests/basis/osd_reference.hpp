#pragma once
// The OpenSubdiv topology refiner of a PolyMesh, as the Catmull–Clark tests' independent reference
// (Catmark scheme, VTX_BOUNDARY_EDGE_AND_CORNER).
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>
#include <vector>

#include "mesh/poly_mesh.hpp"

namespace iga::test {

inline std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> make_osd_refiner(const mesh::PolyMesh& m) {
  namespace Osd = OpenSubdiv::OPENSUBDIV_VERSION;
  std::vector<int> sizes, idx;
  for (Index f = 0; f < m.num_faces(); ++f) {
    sizes.push_back(static_cast<int>(m.face_size(f)));
    for (Index v : m.face(f)) idx.push_back(static_cast<int>(v));
  }
  Osd::Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(m.num_vertices());
  desc.numFaces = static_cast<int>(m.num_faces());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = idx.data();
  Osd::Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Osd::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Osd::Far::TopologyRefinerFactory<Osd::Far::TopologyDescriptor>;
  return std::unique_ptr<Osd::Far::TopologyRefiner>(
      Factory::Create(desc, Factory::Options(Osd::Sdc::SCHEME_CATMARK, sdc)));
}

}  // namespace iga::test
