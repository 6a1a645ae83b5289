exec(open('oned.py').read().split("L = 12")[0])
def knotsB(m): return [F(0)]*4 + [F(j) for j in range(2, m-1)] + [F(m)]*4
def knotsA(m): return [F(0)]*4 + [F(j) for j in range(1, m)] + [F(m)]*4
def insB(m): return sorted(set([F(2*j+1, 2) for j in range(m)]) - {F(1,2), F(2*m-1,2)} | ({F(1), F(m-1)} if m >= 3 else set()))
def insA(m): return [F(2*j+1, 2) for j in range(m)]
L = 20
_, SBL = refine(knotsB(L), insB(L)); _, SAL = refine(knotsA(L), insA(L))
def expected(SL, nL, i, n_new, n_old):
    # row i from the left-end stationary rule, or mirrored right-end rule
    if i < n_new // 2 + 1 and i < 10:
        return SL[i][:n_old] + [F(0)] * max(0, n_old - len(SL[i][:n_old]))
    r = SL[n_new - 1 - i][:n_old]; r = r + [F(0)] * (n_old - len(r)); return r[::-1]
for nm, kf, insf, SL in (("B", knotsB, insB, SBL), ("A", knotsA, insA, SAL)):
    for m in range(3, 10):
        kn = kf(m); k1, S = refine(kn, insf(m)); n_old = len(kn) - 4; n_new = len(k1) - 4
        ok = all(S[i] == expected(SL, L, i, n_new, n_old) for i in range(n_new))
        print(nm, "m=%d" % m, "ctrl %d -> %d" % (n_old, n_new), "masks = stationary end rules:", ok)
    print()
# exact basis values, reading B, m = 6, knots 0,0,0,0,2,3,4,6,6,6,6
def N(knots, i, x, p=3):
    if p == 0: return F(1) if knots[i] <= x < knots[i+1] else F(0)
    a = F(0) if knots[i+p] == knots[i] else (x-knots[i])/(knots[i+p]-knots[i])*N(knots, i, x, p-1)
    b = F(0) if knots[i+p+1] == knots[i+1] else (knots[i+p+1]-x)/(knots[i+p+1]-knots[i+1])*N(knots, i+1, x, p-1)
    return a + b
kn = knotsB(6); print("B m=6 knots", [str(k) for k in kn])
for x in (F(1,2), F(5,2)):
    print(" x=%s:" % x, [str(N(kn, i, x)) for i in range(len(kn)-4)])
kn = knotsA(4); print("A m=4 knots", [str(k) for k in kn])
for x in (F(1,2), F(5,2)):
    print(" x=%s:" % x, [str(N(kn, i, x)) for i in range(len(kn)-4)])
