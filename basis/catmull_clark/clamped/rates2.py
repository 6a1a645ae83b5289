exec(open('rates.py').read().split('for kind in')[0])
prev=None
for m in (128, 256, 512):
    n,e0,e1 = run("B", m)
    if prev: print(m, np.log2(prev[0]/e0), np.log2(prev[1]/e1))
    prev=(e0,e1)
