# Sources of the half-box spline backend (paths relative to basis/).
set(IGA_HALF_BOX_SOURCES
  half_box/regular_patch.cpp
  half_box/subdivision.cpp
  half_box/local_net.cpp
  half_box/patch_net.cpp
  half_box/subdivision_structure.cpp
  half_box/irregular_patch.cpp
)
