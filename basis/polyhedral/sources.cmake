# Sources of the polyhedral-spline backend (paths relative to basis/): classification and Bézier patches,
# the mask derivation (g1_cap: the constrained least-squares solver; star_cap, ngon_cap, polar_cap,
# tjunction_cap), the masks per configuration and the Space.
set(IGA_POLYHEDRAL_SOURCES
  polyhedral/configuration.cpp
  polyhedral/bezier.cpp
  polyhedral/g1_cap.cpp
  polyhedral/star_cap.cpp
  polyhedral/ngon_cap.cpp
  polyhedral/polar_cap.cpp
  polyhedral/tjunction_cap.cpp
  polyhedral/masks.cpp
  polyhedral/space.cpp
  polyhedral/backend.cpp
)
