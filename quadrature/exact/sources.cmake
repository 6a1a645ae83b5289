# Sources of quadrature/exact (paths relative to quadrature/).
set(IGA_QUADRATURE_EXACT_SOURCES
)
