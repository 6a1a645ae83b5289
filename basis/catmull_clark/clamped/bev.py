# Spectrum of the CURRENT (natural / OpenSubdiv edge-and-corner) CC rules at a boundary vertex with k faces.
import numpy as np, itertools
def fan(k, s):
    """Quad fan: k sectors of s x s faces around vertex 0 on the boundary. Returns points dict name->idx, quads."""
    idx = {}; quads = []
    def P(j, a, b):  # point (a,b) of sector j; (a,0) in sector j == (0,a) in sector j-1
        if a == 0 and b == 0: key = ('ev',)
        elif b == 0: key = ('ray', j, a)
        elif a == 0: key = ('ray', j + 1, b)
        else: key = ('in', j, a, b)
        return idx.setdefault(key, len(idx))
    for j in range(k):
        for a in range(s):
            for b in range(s):
                quads.append((P(j, a, b), P(j, a + 1, b), P(j, a + 1, b + 1), P(j, a, b + 1)))
    return idx, quads, P
def cc_matrix(nv, quads):
    """One CC step with boundary rules (crease: boundary edges midpoints, boundary vertices (1,6,1)/8;
    corner = vertex with one face fixed). Returns (rows dict new-key -> weight vector)."""
    edges = {}
    for f, q in enumerate(quads):
        for i in range(4):
            e = tuple(sorted((q[i], q[(i + 1) % 4]))); edges.setdefault(e, []).append(f)
    fp = {f: np.bincount(q, minlength=nv) / 4.0 for f, q in enumerate(quads)}
    ep = {}
    for e, fs in edges.items():
        v = np.zeros(nv); v[list(e)] += 0.5
        ep[e] = v if len(fs) == 1 else 0.5 * v + 0.25 * (fp[fs[0]] + fp[fs[1]])
    vp = {}
    for v in range(nv):
        inc = [e for e in edges if v in e]; bnd = [e for e in inc if len(edges[e]) == 1]
        fs = [f for f, q in enumerate(quads) if v in q]; w = np.zeros(nv)
        if bnd:
            if len(fs) == 1: w[v] = 1
            else:
                w[v] = 0.75
                for e in bnd: w[e[0] if e[1] == v else e[1]] += 0.125
        else:
            n = len(inc); Q = sum(fp[f] for f in fs) / n; R = sum(0.5 * (np.eye(nv)[e[0]] + np.eye(nv)[e[1]]) for e in inc) / n
            w = Q / n + 2 * R / n + (n - 3) / n * np.eye(nv)[v]
        vp[v] = w
    return fp, ep, vp, edges
for k in (1, 2, 3, 4, 5, 6):
    s = 3; idx, quads, P = fan(k, s); nv = len(idx)
    fp, ep, vp, edges = cc_matrix(nv, quads)
    # invariant set: points with max(a,b) <= 2 (in every sector); new point (a,b) at half spacing:
    inv = sorted({P(j, a, b) for j in range(k) for a in range(3) for b in range(3)})
    rows = []
    for j in range(k):
        pass
    # new point of name (j,a,b) at level 1: a,b even -> vertex pt of old (a/2,b/2); one odd -> edge pt; both odd -> face pt
    def newpt(j, a, b):
        if a % 2 == 0 and b % 2 == 0: return vp[P(j, a // 2, b // 2)]
        if a % 2 == 1 and b % 2 == 1:
            q = (P(j, a // 2, b // 2), P(j, a // 2 + 1, b // 2), P(j, a // 2 + 1, b // 2 + 1), P(j, a // 2, b // 2 + 1))
            return fp[quads.index(q)]
        if a % 2 == 1: e = tuple(sorted((P(j, a // 2, b // 2), P(j, a // 2 + 1, b // 2))))
        else: e = tuple(sorted((P(j, a // 2, b // 2), P(j, a // 2, b // 2 + 1))))
        return ep[e]
    order = {}
    for j in range(k):
        for a in range(3):
            for b in range(3): order.setdefault(P(j, a, b), (j, a, b))
    A = np.array([[newpt(*order[p])[c] for c in inv] for p in inv])
    assert np.allclose(A.sum(1), 1)
    # check closure: rows use only inv columns
    full = np.array([newpt(*order[p]) for p in inv]); assert np.abs(np.delete(full, inv, axis=1)).max() < 1e-15
    ev = np.sort(np.linalg.eigvals(A).real)[::-1]
    print(f"k={k} faces: |local set|={len(inv)}  leading eigenvalues", np.round(ev[:7], 6))
