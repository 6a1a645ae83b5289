# Sources of quadrature/moment_fit (paths relative to quadrature/).
set(IGA_QUADRATURE_MOMENT_FIT_SOURCES
  moment_fit/fit.cpp
  moment_fit/table.cpp
  moment_fit/table_directory.cpp
)
