# Sources of the polyhedral-spline backend (paths relative to basis/): classification and Bézier patches,
# then the mask derivation (star_*, ngon_*, g1_*, cap_*).
set(IGA_POLYHEDRAL_SOURCES
  polyhedral/configuration.cpp
  polyhedral/bezier.cpp
  polyhedral/g1_cap.cpp
  polyhedral/star_cap.cpp
)
