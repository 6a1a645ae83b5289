#include "fem/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace iga::fem {

Index Partition::owned_elements(int rank) const {
  return static_cast<Index>(std::count(element_owner.begin(), element_owner.end(), rank));
}

PartitionMethod parse_partition(const std::string& name) {
  if (name == "curve") return PartitionMethod::Curve;
  if (name == "ptscotch") return PartitionMethod::Scotch;
  if (name == "metis") return PartitionMethod::Metis;
  throw InputError("partition '" + name + "': not one of curve, ptscotch, metis");
}

std::string partition_name(PartitionMethod method) {
  switch (method) {
    case PartitionMethod::Curve: return "curve";
    case PartitionMethod::Scotch: return "ptscotch";
    case PartitionMethod::Metis: return "metis";
  }
  return "?";
}

void number_dofs(const basis::Space& space, Partition& p) {
  const Index ne = space.num_elements(), nd = space.num_dofs();
  const int parts = p.parts;
  // Per dof the lowest and highest owner among its elements: it is an interface dof when they differ.
  p.dof_owner.assign(static_cast<std::size_t>(nd), parts);
  std::vector<int> highest(static_cast<std::size_t>(nd), -1);
  for (Index e = 0; e < ne; ++e) {
    const int owner = p.element_owner[static_cast<std::size_t>(e)];
    for (Index d : space.dofs(e)) {
      int& o = p.dof_owner[static_cast<std::size_t>(d)];
      o = std::min(o, owner);
      int& h = highest[static_cast<std::size_t>(d)];
      h = std::max(h, owner);
    }
  }
  std::vector<Index> count(static_cast<std::size_t>(parts), 0);
  p.interface_dofs = 0;
  for (Index d = 0; d < nd; ++d) {
    int& o = p.dof_owner[static_cast<std::size_t>(d)];
    if (o == parts) o = 0;  // a dof no element touches (none in a valid space): rank 0 keeps it
    else if (highest[static_cast<std::size_t>(d)] != o) ++p.interface_dofs;
    ++count[static_cast<std::size_t>(o)];
  }
  p.offsets.assign(static_cast<std::size_t>(parts) + 1, 0);
  for (int r = 0; r < parts; ++r) p.offsets[static_cast<std::size_t>(r) + 1] = p.offsets[static_cast<std::size_t>(r)] + count[static_cast<std::size_t>(r)];
  std::vector<Index> next(p.offsets.begin(), p.offsets.end() - 1);
  p.number.resize(static_cast<std::size_t>(nd));
  for (Index d = 0; d < nd; ++d) p.number[static_cast<std::size_t>(d)] = next[static_cast<std::size_t>(p.dof_owner[static_cast<std::size_t>(d)])]++;
}

void check_parts(Index elements, int parts) {
  if (parts < 1) throw InputError("partition: the number of parts must be at least 1, got " + std::to_string(parts));
  if (elements < parts) {
    throw InputError(std::to_string(elements) + " elements cannot be spread over " + std::to_string(parts) +
                     " ranks: run on fewer ranks or refine");
  }
}

Partition partition_elements(const basis::Space& space, int parts) {
  const Index ne = space.num_elements(), nd = space.num_dofs();
  check_parts(ne, parts);
  Partition p;
  p.parts = parts;
  p.element_owner.assign(static_cast<std::size_t>(ne), 0);
  if (parts > 1) {
    p.method = partition_name(PartitionMethod::Metis);
    std::vector<idx_t> eptr{0}, eind;
    for (Index e = 0; e < ne; ++e) {
      for (Index d : space.dofs(e)) eind.push_back(static_cast<idx_t>(d));
      eptr.push_back(static_cast<idx_t>(eind.size()));
    }
    if (eind.size() > static_cast<std::size_t>(std::numeric_limits<idx_t>::max())) {
      throw InputError("partition: more element-dof pairs than METIS's 32-bit indices hold");
    }
    idx_t n_el = static_cast<idx_t>(ne), n_nodes = static_cast<idx_t>(nd), ncommon = 1, nparts = parts, cut = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 1;  // the same partition on every rank and every run
    std::vector<idx_t> epart(static_cast<std::size_t>(ne)), npart(static_cast<std::size_t>(nd));
    const int status = METIS_PartMeshDual(&n_el, &n_nodes, eptr.data(), eind.data(), nullptr, nullptr, &ncommon,
                                          &nparts, nullptr, options, &cut, epart.data(), npart.data());
    if (status != METIS_OK) {
      throw NumericalError("METIS could not partition the " + std::to_string(ne) + " elements into " +
                           std::to_string(parts) + " parts (status " + std::to_string(status) + ")");
    }
    for (Index e = 0; e < ne; ++e) p.element_owner[static_cast<std::size_t>(e)] = static_cast<int>(epart[static_cast<std::size_t>(e)]);
  }
  number_dofs(space, p);
  return p;
}

Partition with_components(const Partition& scalar, int d) {
  if (d == 1) return scalar;
  Partition p = scalar;
  const std::size_t n = scalar.number.size(), du = static_cast<std::size_t>(d);
  p.dof_owner.resize(n * du);
  p.number.resize(n * du);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < du; ++c) {
      p.dof_owner[du * i + c] = scalar.dof_owner[i];
      p.number[du * i + c] = d * scalar.number[i] + static_cast<Index>(c);
    }
  }
  for (Index& o : p.offsets) o *= d;
  p.interface_dofs = d * scalar.interface_dofs;
  return p;
}

}  // namespace iga::fem
