# Sources of the Catmull–Clark backend (paths relative to basis/).
set(IGA_CATMULL_CLARK_SOURCES
  catmull_clark/stam.cpp
)
