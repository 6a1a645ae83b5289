# Sources of the half-box spline backend (paths relative to basis/).
set(IGA_HALF_BOX_SOURCES
)
