# 1D: cubic B-spline, clamped (open) knot vectors, midpoint refinement by Boehm insertion, exact fractions.
from fractions import Fraction as F
import numpy as np

def boehm(knots, t):
    """Insert knot t (degree 3). Returns (new knots, matrix R with new = R @ old) as Fraction lists."""
    p = 3; n = len(knots) - p - 1
    k = max(i for i in range(len(knots) - 1) if knots[i] <= t and t < knots[i + 1])
    R = [[F(0)] * n for _ in range(n + 1)]
    for i in range(n + 1):
        if i <= k - p: R[i][i] = F(1)
        elif i > k: R[i][i - 1] = F(1)
        else:
            a = (t - knots[i]) / (knots[i + p] - knots[i])
            R[i][i] = a; R[i][i - 1] = 1 - a
    return sorted(knots + [t]), R

def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(len(B))) for j in range(len(B[0]))] for i in range(len(A))]

def refine(knots, new):
    n = len(knots) - 4
    S = [[F(int(i == j)) for j in range(n)] for i in range(n)]
    for t in new:
        knots, R = boehm(knots, t); S = matmul(R, S)
    return knots, S

def fmt(row):
    return "  ".join(f"P{j}:{str(w)}" for j, w in enumerate(row) if w != 0)

L = 12
for name, k0 in [("A: clamped 0,0,0,0,1,2,3,...", [F(0)] * 4 + [F(j) for j in range(1, L)] + [F(L)] * 4),
                 ("B: clamped, first interior knot removed: 0,0,0,0,2,3,...", [F(0)] * 4 + [F(j) for j in range(2, L)] + [F(L)] * 4)]:
    new = [F(2 * j + 1, 2) for j in range(L)] if name[0] == "A" else [F(1)] + [F(2 * j + 1, 2) for j in range(1, L)]
    k1, S = refine(k0, new)
    scaled = [2 * t for t in k1]
    # stationarity: level-1 knots scaled by 2, restricted to [0, L], equal the level-0 pattern (near the left end)
    print("==", name)
    print("level-0 knots (head):", [str(t) for t in k0[:9]])
    print("level-1 knots x2 (head):", [str(t) for t in scaled[:9]])
    print("#ctrl level0 =", len(k0) - 4, " level1 =", len(k1) - 4, " #intervals", L, "->", 2 * L)
    for i in range(9):
        print(f"  Q{i} = {fmt(S[i])}")
    # twice refined: check the same masks at level 1 -> 2 (stationarity)
    new2 = [t for t in ([F(2 * j + 1, 4) for j in range(2 * L)] if name[0] == "A" else [F(1, 2)] + [F(2 * j + 1, 4) for j in range(1, 2 * L)])]
    k2, S2 = refine(k1, new2)
    same = all(S2[i][:9] == S[i][:9] for i in range(9))
    print("  level1->2 masks identical to level0->1 (first 9 rows):", same)
    # end subdivision matrix: the rows/cols of the first m points closed under refinement
    for m in (3, 4, 5, 6):
        closed = all(S[i][j] == 0 for i in range(m) for j in range(m, len(S[0])))
        if closed:
            A = np.array([[float(S[i][j]) for j in range(m)] for i in range(m)])
            print(f"  end block {m}x{m} (first {m} new pts depend only on first {m} old): eigenvalues", np.round(np.sort(np.linalg.eigvals(A).real)[::-1], 15))
            break
    # which rows differ from uniform rules (vertex 1/8(1,6,1), edge 1/2(1,1))
    uni = []
    for i in range(12):
        nz = [(j, S[i][j]) for j in range(len(S[0])) if S[i][j] != 0]
        ws = sorted([w for _, w in nz])
        uniform = ws in ([F(1, 8), F(1, 8), F(3, 4)], [F(1, 2), F(1, 2)])
        if not uniform: uni.append(i)
    print("  non-uniform rows:", uni)
