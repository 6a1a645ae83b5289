exec(open('small.py').read().split("# exact basis values")[0].split("L = 20")[0])
def N(knots, i, x, p=3):
    if p == 0: return F(1) if knots[i] <= x < knots[i+1] else F(0)
    a = F(0) if knots[i+p] == knots[i] else (x-knots[i])/(knots[i+p]-knots[i])*N(knots, i, x, p-1)
    b = F(0) if knots[i+p+1] == knots[i+1] else (knots[i+p+1]-x)/(knots[i+p+1]-knots[i+1])*N(knots, i+1, x, p-1)
    return a + b
kn = knotsB(7); print("B m=7 knots", [str(k) for k in kn])
for x in (F(1,2), F(5,2), F(7,2)):
    print(" x=%s:" % x, [str(N(kn, i, x)) for i in range(len(kn)-4)])
n = len(kn)-4
print(" x coeffs", [str(sum(kn[i+1:i+4])/3) for i in range(n)])
print(" x^2 coeffs", [str((kn[i+1]*kn[i+2]+kn[i+1]*kn[i+3]+kn[i+2]*kn[i+3])/3) for i in range(n)])
