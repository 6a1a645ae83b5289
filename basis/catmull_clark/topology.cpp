#include "basis/catmull_clark/topology.hpp"

#include <memory>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace iga::basis::catmull_clark {

namespace Osd = OpenSubdiv::OPENSUBDIV_VERSION;

void check_no_isolated_vertices(const mesh::PolyMesh& mesh, const std::string& name) {
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.num_vertex_faces(v) == 0) {
      throw InputError(name, mesh.vertex_line(v), "vertex " + std::to_string(v + 1) +
                       " is not used by any face (an isolated control point has no basis function)");
    }
  }
}

NetRefinement refine_net(const mesh::PolyMesh& mesh, int steps) {
  if (steps < 0 || steps > 10) throw InputError("refine_net: steps " + std::to_string(steps) + " is not in 0..10");
  check_no_isolated_vertices(mesh, "refine_net");
  const Index nv = mesh.num_vertices();
  if (steps == 0) {
    NetRefinement r{mesh, Eigen::SparseMatrix<double>(nv, nv)};
    r.prolongation.setIdentity();
    return r;
  }
  std::vector<int> sizes;
  std::vector<int> indices;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    sizes.push_back(static_cast<int>(mesh.face_size(f)));
    for (Index v : mesh.face(f)) indices.push_back(static_cast<int>(v));
  }
  Osd::Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(nv);
  desc.numFaces = static_cast<int>(mesh.num_faces());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = indices.data();
  Osd::Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Osd::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Osd::Far::TopologyRefinerFactory<Osd::Far::TopologyDescriptor>;
  std::unique_ptr<Osd::Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(Osd::Sdc::SCHEME_CATMARK, sdc)));
  if (!refiner) throw InputError("refine_net: OpenSubdiv rejected the mesh topology");
  Osd::Far::TopologyRefiner::UniformOptions uniform(steps);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);

  Osd::Far::StencilTableFactoryReal<double>::Options options;
  options.generateIntermediateLevels = false;
  options.generateOffsets = true;
  options.maxLevel = static_cast<unsigned>(steps);
  std::unique_ptr<const Osd::Far::StencilTableReal<double>> table(
      Osd::Far::StencilTableFactoryReal<double>::Create(*refiner, options));
  const Osd::Far::TopologyLevel& fine = refiner->GetLevel(steps);
  const int nfine = fine.GetNumVertices();
  if (table->GetNumStencils() != nfine) throw std::logic_error("refine_net: stencil count mismatch");
  std::vector<Eigen::Triplet<double>> entries;
  const auto& st_sizes = table->GetSizes();
  const auto& st_offsets = table->GetOffsets();
  const auto& st_indices = table->GetControlIndices();
  const auto& st_weights = table->GetWeights();
  for (int s = 0; s < nfine; ++s) {
    for (int k = 0; k < st_sizes[static_cast<std::size_t>(s)]; ++k) {
      const std::size_t o = static_cast<std::size_t>(st_offsets[static_cast<std::size_t>(s)] + k);
      entries.emplace_back(s, st_indices[o], st_weights[o]);
    }
  }
  NetRefinement r;
  r.prolongation.resize(nfine, nv);
  r.prolongation.setFromTriplets(entries.begin(), entries.end());  // sums duplicates
  Eigen::MatrixXd coarse(nv, 3);
  for (Index v = 0; v < nv; ++v) coarse.row(v) = mesh.point(v).transpose();
  const Eigen::MatrixXd fine_points = r.prolongation * coarse;
  std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(nfine));
  for (int v = 0; v < nfine; ++v) points[static_cast<std::size_t>(v)] = fine_points.row(v).transpose();
  if (mesh.is_planar()) {
    for (auto& p : points) p.z() = 0.0;
  }
  std::vector<std::vector<Index>> faces(static_cast<std::size_t>(fine.GetNumFaces()));
  for (int f = 0; f < fine.GetNumFaces(); ++f) {
    const auto fv = fine.GetFaceVertices(f);
    for (int i = 0; i < fv.size(); ++i) faces[static_cast<std::size_t>(f)].push_back(fv[i]);
  }
  r.mesh = mesh::PolyMesh::build(std::move(points), std::move(faces));
  return r;
}

}  // namespace iga::basis::catmull_clark
