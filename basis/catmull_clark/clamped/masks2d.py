from fractions import Fraction as F
from math import lcm
B = {0: [F(1)], 1: [F(1,2), F(1,2)], 2: [F(1,8), F(5,8), F(1,4)], 3: [F(0), F(1,3), F(13,24), F(1,8)],
     4: [F(0), F(1,12), F(29,48), F(5,16)], 5: [F(0), F(0), F(3,8), F(5,8)], 6: [F(0), F(0), F(3,32), F(25,32), F(1,8)]}
tv = [F(1,8), F(6,8), F(1,8)]; te = [F(1,2), F(1,2)]
def show(name, nrow, tang):
    rows = [[a*b for b in tang] for a in nrow]
    while rows and all(x == 0 for x in rows[0]): rows.pop(0); off = True
    d = lcm(*[x.denominator for r in rows for x in r])
    first = next(i for i, a in enumerate(nrow) if a != 0)
    print(f"{name}: 1/{d} x  (normal rows P{first}..P{first+len(rows)-1}, top = nearer the boundary)")
    for r in rows: print("     ", [int(x*d) for x in r])
for r in range(4):
    show(f"vertex point of a row-{r} vertex  [Q{2*r} (x) (1,6,1)/8]", B[2*r], tv)
    show(f"edge pt of a tangential edge in row {r}  [Q{2*r} (x) (1,1)/2]", B[2*r], te)
    if 2*r+1 <= 6:
        show(f"edge pt of a normal edge rows {r}-{r+1}  [Q{2*r+1} (x) (1,6,1)/8]", B[2*r+1], tv)
        show(f"face pt of a face rows {r}-{r+1}  [Q{2*r+1} (x) (1,1)/2]", B[2*r+1], te)
print("corner, clamped x clamped (B):")
for (i, j) in [(0,0), (0,1), (1,1), (0,2), (1,2), (2,2), (1,3), (3,3)]:
    a, b = B[i], B[j]; rows = [[x*y for y in b] for x in a]
    d = lcm(*[x.denominator for r in rows for x in r]); print(f"  Q{i}(x)Q{j}: 1/{d}", [[int(x*d) for x in r] for r in rows])
