# Sources of quadrature/exact (paths relative to quadrature/).
set(IGA_QUADRATURE_EXACT_SOURCES
  exact/series.cpp
  exact/tile_integrals.cpp
  exact/irregular_integrals.cpp
  exact/geometry_integrals.cpp
  exact/subdivision_integrals.cpp
)
