# iga-geometry: export the geometry of a control net (tools/iga_geometry.cpp).
iga_add_program(iga-geometry iga_geometry.cpp)
