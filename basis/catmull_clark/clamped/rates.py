# L2 projection of u = exp(x) (u'' != 0 at both ends) on [0,1] onto three cubic spline spaces with m elements.
import numpy as np
def basis(knots, x, der=0):
    """All degree-3 B-splines (and first derivative) at points x; knots float array."""
    t = np.asarray(knots, float); n = len(t) - 4
    # degree 0, right-continuous except at the right end
    B = np.zeros((len(x), len(t) - 1))
    for i in range(len(t) - 1):
        if t[i] < t[i+1]:
            B[:, i] = (x >= t[i]) & ((x < t[i+1]) | ((x == t[-1]) & (t[i+1] == t[-1])))
    for p in range(1, 4):
        Bn = np.zeros((len(x), len(t) - 1 - p))
        for i in range(len(t) - 1 - p):
            a = (x - t[i]) / (t[i+p] - t[i]) * B[:, i] if t[i+p] > t[i] else 0
            b = (t[i+p+1] - x) / (t[i+p+1] - t[i+1]) * B[:, i+1] if t[i+p+1] > t[i+1] else 0
            if p == 3 and der:
                a = 3 / (t[i+p] - t[i]) * B[:, i] if t[i+p] > t[i] else 0
                b = -3 / (t[i+p+1] - t[i+1]) * B[:, i+1] if t[i+p+1] > t[i+1] else 0
            Bn[:, i] = a + b
        B = Bn
    return B
g, gw = np.polynomial.legendre.leggauss(6)
def run(kind, m):
    h = 1.0 / m
    xs = np.concatenate([(e + (g + 1) / 2) * h for e in range(m)]); ws = np.tile(gw * h / 2, m)
    if kind == "natural (current CC)":
        kn = np.arange(-3, m + 4) * h; T = np.zeros((m + 3, m + 1))
        T[1:m+2, :] = np.eye(m + 1); T[0, 0] += 2; T[0, 1] -= 1; T[m+2, m] += 2; T[m+2, m-1] -= 1
    elif kind == "A clamped 0^4,1,2..":
        kn = np.r_[[0] * 4, np.arange(1, m) * h, [1] * 4]; T = np.eye(m + 3)
    else:
        kn = np.r_[[0] * 4, np.arange(2, m - 1) * h, [1] * 4]; T = np.eye(m + 1)
    N = basis(kn, xs) @ T; D = basis(kn, xs, 1) @ T
    M = N.T @ (ws[:, None] * N); c = np.linalg.solve(M, N.T @ (ws * np.exp(xs)))
    e0 = np.sqrt(ws @ (N @ c - np.exp(xs)) ** 2); e1 = np.sqrt(ws @ (D @ c - np.exp(xs)) ** 2)
    return T.shape[1], e0, e1
for kind in ("natural (current CC)", "A clamped 0^4,1,2..", "B clamped 0^4,2,3.."):
    prev = None
    for m in (8, 16, 32, 64, 128):
        n, e0, e1 = run(kind, m)
        r = "" if prev is None else f"  rates L2 {np.log2(prev[0]/e0):.2f}  H1 {np.log2(prev[1]/e1):.2f}"
        print(f"{kind:22s} m={m:4d} dofs={n:4d} L2={e0:.3e} H1semi={e1:.3e}{r}"); prev = (e0, e1)
