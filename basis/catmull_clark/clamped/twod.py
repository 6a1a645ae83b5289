import sys; sys.path.insert(0, '.')
from fractions import Fraction as F
import numpy as np, itertools
exec(open('oned.py').read().split("L = 12")[0])
L = 12
kA = [F(0)]*4 + [F(j) for j in range(1, L)] + [F(L)]*4
kB = [F(0)]*4 + [F(j) for j in range(2, L)] + [F(L)]*4
_, SA = refine(kA, [F(2*j+1, 2) for j in range(L)])
_, SB = refine(kB, [F(1)] + [F(2*j+1, 2) for j in range(1, L)])
for nm, S in (("A", SA), ("B", SB)):
    M = np.array([[float(x) for x in r[:4]] for r in S[:4]])
    closed = all(S[i][j] == 0 for i in range(4) for j in range(4, len(S[0])))
    ev = np.linalg.eigvals(M)
    print(nm, "4x4 block closed:", closed, "eigenvalues", np.round(sorted(ev.real, reverse=True), 14))
    # left eigenvectors (limit / derivative stencils at the end)
    w, V = np.linalg.eig(M.T)
    for lam in (1, .5, .25):
        i = np.argmin(abs(w - lam)); v = V[:, i].real
        v = v / (v[np.argmax(abs(v))]); print("   left eigvec for", lam, [str(F(x).limit_denominator(1000)) for x in v])

# Bezier extraction: Bernstein coefficients of each B-spline on each element [e, e+1]
def bspl(knots, i, x):  # Cox-de Boor, degree 3, right-continuous, exact
    def N(i, p):
        if p == 0: return F(1) if knots[i] <= x < knots[i+1] else F(0)
        a = F(0) if knots[i+p] == knots[i] else (x - knots[i]) / (knots[i+p] - knots[i]) * N(i, p-1)
        b = F(0) if knots[i+p+1] == knots[i+1] else (knots[i+p+1] - x) / (knots[i+p+1] - knots[i+1]) * N(i+1, p-1)
        return a + b
    return N(i, 3)
def bern(t):  # cubic Bernstein at t
    return [(1-t)**3, 3*t*(1-t)**2, 3*t**2*(1-t), t**3]
ts = [F(0), F(1, 3), F(2, 3), F(9, 10)]
Binv = np.linalg.inv(np.array([[float(b) for b in bern(t)] for t in ts]))
for nm, kn in (("A", kA), ("B", kB)):
    print("== Bezier extraction", nm, " (row = Bernstein coefficient b0..b3 of the element, column = control point)")
    for e in range(6):
        vals = np.array([[float(bspl(kn, i, e + t)) for i in range(len(kn) - 4)] for t in ts])
        C = Binv @ vals
        cols = [i for i in range(C.shape[1]) if abs(C[:, i]).max() > 1e-14]
        print(f" element [{e},{e+1}] control points {cols}:")
        for r in range(4):
            print("   b%d =" % r, "  ".join(f"{str(F(C[r, i]).limit_denominator(200))}·P{i}" for i in cols if abs(C[r, i]) > 1e-14))
# Marsden: coefficients of 1, x, x^2 (Greville / symmetric sums); check by evaluation
for nm, kn in (("A", kA), ("B", kB)):
    n = len(kn) - 4
    c1 = [sum(kn[i+1:i+4]) / 3 for i in range(n)]
    c2 = [(kn[i+1]*kn[i+2] + kn[i+1]*kn[i+3] + kn[i+2]*kn[i+3]) / 3 for i in range(n)]
    err = max(abs(sum(c2[i]*bspl(kn, i, x) for i in range(n)) - x*x) for x in [F(1,7), F(3,2), F(5,2), F(9,2)])
    print(nm, "x coeffs", [str(c) for c in c1[:6]], " x^2 coeffs", [str(c) for c in c2[:6]], " exact x^2 err", err)
