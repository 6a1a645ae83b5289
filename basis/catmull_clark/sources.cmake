# Sources of the Catmull–Clark backend (paths relative to basis/).
set(IGA_CATMULL_CLARK_SOURCES
  catmull_clark/stam.cpp
  catmull_clark/subdivision_matrix.cpp
  catmull_clark/eigen_structure.cpp
)
