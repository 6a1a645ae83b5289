iga_add_program(iga-knots iga_knots.cpp)
