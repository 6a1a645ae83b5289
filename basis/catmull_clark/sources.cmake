# Sources of the Catmull–Clark backend (paths relative to basis/).
set(IGA_CATMULL_CLARK_SOURCES
  catmull_clark/stam.cpp
  catmull_clark/quad_mesh.cpp
  catmull_clark/regular_patch.cpp
  catmull_clark/irregular_patch.cpp
  catmull_clark/topology.cpp
  catmull_clark/ghost_net.cpp
  catmull_clark/space.cpp
  catmull_clark/levels.cpp
  catmull_clark/local_mesh.cpp
  catmull_clark/sparse_levels.cpp
  catmull_clark/subdivision_matrix.cpp
  catmull_clark/eigen_structure.cpp
  catmull_clark/backend.cpp
  catmull_clark/ev_enrichment.cpp
  catmull_clark/exact_view.cpp
)
