# Tests of quadrature/exact, spline_gauss and moment_fit (each helper appends its own lines).
