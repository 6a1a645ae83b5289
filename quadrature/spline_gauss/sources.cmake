# Sources of quadrature/spline_gauss (paths relative to quadrature/).
set(IGA_QUADRATURE_SPLINE_GAUSS_SOURCES
  spline_gauss/generator.cpp
  spline_gauss/macro_rule.cpp
)
