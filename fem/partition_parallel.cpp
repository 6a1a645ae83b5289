// The partitions computed in parallel (fem/partition.hpp): a Hilbert curve through the elements' centres, and
// PT-Scotch through PETSc's MatPartitioning on the side-adjacency graph of the elements.
#include <mpi.h>
#include <petscmat.h>
#include <stdio.h>  // scotch.h uses FILE
#include <scotch.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <numeric>

#include "core/error.hpp"
#include "fem/parallel.hpp"
#include "fem/partition.hpp"
#include "fem/petsc_util.hpp"

namespace iga::fem {

namespace {

using petsc::check;

// Rank r's block of n items among `parts`: [n r / parts, n (r + 1) / parts).
Index block_start(Index n, int r, int parts) { return n * r / parts; }

// Every rank's block of an array distributed by block_start, on every rank, in order.
template <class T>
std::vector<T> gather_blocks(const std::vector<T>& mine, Index n, MPI_Datatype type) {
  const int parts = ranks();
  std::vector<int> counts(static_cast<std::size_t>(parts)), starts(static_cast<std::size_t>(parts));
  for (int r = 0; r < parts; ++r) {
    starts[static_cast<std::size_t>(r)] = static_cast<int>(block_start(n, r, parts));
    counts[static_cast<std::size_t>(r)] = static_cast<int>(block_start(n, r + 1, parts) - block_start(n, r, parts));
  }
  std::vector<T> all(static_cast<std::size_t>(n));
  MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), type, all.data(), counts.data(), starts.data(), type,
                 PETSC_COMM_WORLD);
  return all;
}

// The physical centre of element e (the map at the reference element's centroid).
Eigen::Vector3d centre(const basis::Geometry& g, Index e, basis::BasisValues& values) {
  const basis::Space& space = g.space();
  const bool triangle = space.kind(e).shape == basis::Shape::Triangle;
  const Eigen::Matrix2Xd point = triangle ? Eigen::Vector2d(1.0 / 3.0, 1.0 / 3.0) : Eigen::Vector2d(0.5, 0.5);
  space.evaluate(e, point, 0, values);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  const std::span<const Index> dofs = space.dofs(e);
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    x.head(g.dim()) += values.value(static_cast<Eigen::Index>(i), 0) * g.control_points().row(dofs[i]).transpose();
  }
  return x;
}

Partition by_curve(const basis::Geometry& g, int parts) {
  const basis::Space& space = g.space();
  const Index ne = space.num_elements();
  const int me = rank(), n = g.dim(), bits = n == 2 ? 31 : 21;
  const Index lo = block_start(ne, me, parts), hi = block_start(ne, me + 1, parts);
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(static_cast<std::size_t>(hi - lo));
  basis::BasisValues values;
  std::array<double, 6> box{1e300, 1e300, 1e300, 1e300, 1e300, 1e300};  // min x, y, z and -max x, y, z
  for (Index e = lo; e < hi; ++e) {
    centres.push_back(centre(g, e, values));
    for (int k = 0; k < 3; ++k) {
      box[static_cast<std::size_t>(k)] = std::min(box[static_cast<std::size_t>(k)], centres.back()(k));
      box[static_cast<std::size_t>(k) + 3] = std::min(box[static_cast<std::size_t>(k) + 3], -centres.back()(k));
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, box.data(), 6, MPI_DOUBLE, MPI_MIN, PETSC_COMM_WORLD);
  const double extent = std::max({-box[3] - box[0], -box[4] - box[1], -box[5] - box[2], 1e-300});
  const double cells = static_cast<double>((std::uint64_t{1} << bits) - 1);
  std::vector<std::uint64_t> keys;
  keys.reserve(centres.size());
  for (const Eigen::Vector3d& x : centres) {
    std::array<std::uint32_t, 3> q{0, 0, 0};
    for (int k = 0; k < n; ++k) {
      const double t = std::clamp((x(k) - box[static_cast<std::size_t>(k)]) / extent, 0.0, 1.0);
      q[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(t * cells);
    }
    keys.push_back(hilbert_key(q, n, bits));
  }
  const std::vector<std::uint64_t> all = gather_blocks(keys, ne, MPI_UINT64_T);
  std::vector<Index> order(static_cast<std::size_t>(ne));
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    const std::uint64_t ka = all[static_cast<std::size_t>(a)], kb = all[static_cast<std::size_t>(b)];
    return ka != kb ? ka < kb : a < b;
  });
  Partition p;
  p.parts = parts;
  p.element_owner.resize(static_cast<std::size_t>(ne));
  for (Index k = 0; k < ne; ++k) {
    p.element_owner[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = static_cast<int>(k * parts / ne);
  }
  return p;
}

Partition by_scotch(const basis::Space& space, int parts) {
  const Index ne = space.num_elements();
  const int me = rank();
  const Index lo = block_start(ne, me, parts), hi = block_start(ne, me + 1, parts);
  // This rank's rows of the graph whose edges are the sides two elements share.
  std::vector<std::vector<PetscInt>> rows(static_cast<std::size_t>(hi - lo));
  for (const basis::InteriorEdge& edge : space.interior_edges()) {
    const Index a = edge.element[0], b = edge.element[1];
    if (a == b) continue;
    if (a >= lo && a < hi) rows[static_cast<std::size_t>(a - lo)].push_back(static_cast<PetscInt>(b));
    if (b >= lo && b < hi) rows[static_cast<std::size_t>(b - lo)].push_back(static_cast<PetscInt>(a));
  }
  std::size_t nnz = 0;
  for (std::vector<PetscInt>& r : rows) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    nnz += r.size();
  }
  PetscInt *ia = nullptr, *ja = nullptr;  // MatCreateMPIAdj takes them over
  check(PetscMalloc1(rows.size() + 1, &ia), "PetscMalloc1");
  check(PetscMalloc1(std::max<std::size_t>(nnz, 1), &ja), "PetscMalloc1");
  ia[0] = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::copy(rows[i].begin(), rows[i].end(), ja + ia[i]);
    ia[i + 1] = ia[i] + static_cast<PetscInt>(rows[i].size());
  }
  rows = {};
  petsc::MatH adjacency;
  check(MatCreateMPIAdj(PETSC_COMM_WORLD, static_cast<PetscInt>(hi - lo), static_cast<PetscInt>(ne), ia, ja, nullptr,
                        adjacency.out()),
        "MatCreateMPIAdj");
  MatPartitioning partitioning = nullptr;
  check(MatPartitioningCreate(PETSC_COMM_WORLD, &partitioning), "MatPartitioningCreate");
  petsc::IsH owners;
  PetscErrorCode code = MatPartitioningSetAdjacency(partitioning, adjacency);
  if (!code) code = MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH);
  if (!code) code = MatPartitioningSetNParts(partitioning, parts);
  SCOTCH_randomReset();  // the same partition for the same graph, whatever was partitioned before
  if (!code) code = MatPartitioningApply(partitioning, owners.out());
  MatPartitioningDestroy(&partitioning);
  check(code, "MatPartitioningApply (PT-Scotch)");
  const PetscInt* local = nullptr;
  check(ISGetIndices(owners, &local), "ISGetIndices");
  std::vector<int> mine(local, local + (hi - lo));
  ISRestoreIndices(owners, &local);
  Partition p;
  p.parts = parts;
  p.element_owner = gather_blocks(mine, ne, MPI_INT);
  return p;
}

}  // namespace

std::uint64_t hilbert_key(std::array<std::uint32_t, 3> x, int n, int bits) {
  // J. Skilling, "Programming the Hilbert curve", AIP Conf. Proc. 707 (2004) 381: the axes are turned in place
  // into the transposed index (undo the excess work of the inverse map, then Gray-encode); its bits, read from the
  // most significant down and across the axes, are the index along the curve.
  const std::uint32_t top = std::uint32_t{1} << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < n; ++i) {
      if (x[static_cast<std::size_t>(i)] & q) {
        x[0] ^= p;  // invert the low bits of the first axis
      } else {      // exchange the low bits of the first axis and axis i
        const std::uint32_t t = (x[0] ^ x[static_cast<std::size_t>(i)]) & p;
        x[0] ^= t;
        x[static_cast<std::size_t>(i)] ^= t;
      }
    }
  }
  for (int i = 1; i < n; ++i) x[static_cast<std::size_t>(i)] ^= x[static_cast<std::size_t>(i) - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    if (x[static_cast<std::size_t>(n) - 1] & q) t ^= q - 1;
  }
  for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] ^= t;
  std::uint64_t key = 0;
  for (int bit = bits - 1; bit >= 0; --bit) {
    for (int i = 0; i < n; ++i) key = (key << 1) | ((x[static_cast<std::size_t>(i)] >> bit) & 1u);
  }
  return key;
}

Partition partition_elements(const basis::Geometry& geometry, PartitionMethod method) {
  const auto t0 = std::chrono::steady_clock::now();
  const basis::Space& space = geometry.space();
  const int parts = ranks();
  check_parts(space.num_elements(), parts);
  if (parts == 1 || method == PartitionMethod::Metis) {
    Partition p = partition_elements(space, parts);
    p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return p;
  }
  Partition p = method == PartitionMethod::Curve ? by_curve(geometry, parts) : by_scotch(space, parts);
  p.method = partition_name(method);
  number_dofs(space, p);
  p.seconds = max_over_ranks(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return p;
}

}  // namespace iga::fem
