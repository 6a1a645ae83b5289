#pragma once
// Who assembles what in a distributed run: elements by a METIS partition of the element graph, dofs by the
// elements, and the distributed (PETSc) numbering. Every rank computes the same partition from the replicated
// space: no communication, O(elements + dofs) memory on every rank.
#include <vector>

#include "basis/space.hpp"

namespace iga::fem {

struct Partition {
  int parts = 1;
  std::vector<int> element_owner;  ///< per element: the rank that assembles it
  std::vector<int> dof_owner;      ///< per dof: the lowest rank owning an element that touches it
  std::vector<Index> number;       ///< per dof: its index in the distributed numbering
  std::vector<Index> offsets;      ///< parts + 1 entries: rank r numbers [offsets[r], offsets[r + 1])
  Index owned_elements(int rank) const;
  Index owned_dofs(int rank) const { return offsets[static_cast<std::size_t>(rank) + 1] - offsets[static_cast<std::size_t>(rank)]; }
};

/// Elements into `parts` parts by METIS (METIS_PartMeshDual with the dofs as the mesh's nodes and one common node
/// for adjacency: two elements are neighbours when they share a dof, so each part's cut is the dofs it shares);
/// dofs owned by the lowest rank among their elements' owners; each rank's dofs numbered consecutively in
/// ascending dof order. One part: every element and dof on rank 0, numbering the identity. InputError when there
/// are fewer elements than parts; NumericalError when METIS fails.
Partition partition_elements(const basis::Space& space, int parts);

/// The partition of a field with d interleaved components over the space (Assembler::field_dofs): element owners
/// as they are, field dof d·i + c owned with dof i and numbered d·number[i] + c, offsets scaled by d.
Partition with_components(const Partition& scalar, int d);

}  // namespace iga::fem
