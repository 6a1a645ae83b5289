#pragma once
// Who assembles what in a distributed run: elements by a partition, dofs by the elements, and the distributed
// (PETSc) numbering. Three ways to part the elements (PartitionMethod), two of them computed in parallel.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "basis/space.hpp"

namespace iga::fem {

/// Curve: a Hilbert space-filling curve through the elements' centres (each rank maps its share of the elements,
/// the keys are exchanged, every rank cuts the same sorted curve into equal runs). Scotch: PT-Scotch through PETSc's
/// MatPartitioning on the elements' side-adjacency graph, each rank giving its block of rows. Metis: METIS on the
/// whole element-dof graph, the same computation on every rank (no communication; the cost does not shrink with the
/// ranks).
enum class PartitionMethod { Curve, Scotch, Metis };

/// "curve", "ptscotch" or "metis"; InputError naming the choices otherwise.
PartitionMethod parse_partition(const std::string& name);
std::string partition_name(PartitionMethod method);

struct Partition {
  int parts = 1;
  std::vector<int> element_owner;  ///< per element: the rank that assembles it
  std::vector<int> dof_owner;      ///< per dof: the lowest rank owning an element that touches it
  std::vector<Index> number;       ///< per dof: its index in the distributed numbering
  std::vector<Index> offsets;      ///< parts + 1 entries: rank r numbers [offsets[r], offsets[r + 1])
  std::string method = "none";     ///< partition_name of the method (one part: "none")
  double seconds = 0.0;            ///< the partition's wall time (the slowest rank's when computed in parallel)
  /// The edge cut as the communication sees it: dofs touched by elements of more than one part (each is a row that
  /// more than one rank adds to, and a value a matrix-vector product exchanges).
  Index interface_dofs = 0;
  Index owned_elements(int rank) const;
  Index owned_dofs(int rank) const { return offsets[static_cast<std::size_t>(rank) + 1] - offsets[static_cast<std::size_t>(rank)]; }
};

/// Elements into `parts` parts by METIS (METIS_PartMeshDual with the dofs as the mesh's nodes and one common node
/// for adjacency: two elements are neighbours when they share a dof, so each part's cut is the dofs it shares);
/// dofs owned by the lowest rank among their elements' owners; each rank's dofs numbered consecutively in
/// ascending dof order. One part: every element and dof on rank 0, numbering the identity. InputError when there
/// are fewer elements than parts; NumericalError when METIS fails.
Partition partition_elements(const basis::Space& space, int parts);

/// The elements of the geometry's space into fem::ranks() parts by `method` (collective: every rank of an open
/// ParallelSession calls it; without a session, one part), dofs owned and numbered as above. Curve and Metis give
/// every part elements; PT-Scotch may leave a part empty on a very small mesh (the system works with it). InputError
/// when there are fewer elements than ranks; NumericalError when the partitioner fails.
Partition partition_elements(const basis::Geometry& geometry, PartitionMethod method);

/// The index along the Hilbert curve of the cell with integer coordinates x[0..n) of `bits` bits each (n = 2 or 3,
/// n · bits <= 64): consecutive indices are cells that share a side.
std::uint64_t hilbert_key(std::array<std::uint32_t, 3> x, int n, int bits);

/// InputError when `elements` cannot give each of `parts` parts one (or parts < 1).
void check_parts(Index elements, int parts);

/// From p.parts and p.element_owner: p.dof_owner, p.number, p.offsets and p.interface_dofs as described above.
void number_dofs(const basis::Space& space, Partition& p);

/// The partition of a field with d interleaved components over the space (Assembler::field_dofs): element owners
/// as they are, field dof d·i + c owned with dof i and numbered d·number[i] + c, offsets scaled by d.
Partition with_components(const Partition& scalar, int d);

}  // namespace iga::fem
