# Tests of the half-box spline backend (registered with iga_add_test).
