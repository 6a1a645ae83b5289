#!/usr/bin/python3
"""Writes the project's own control nets to data/meshes/ (run from the repository root:
/usr/bin/python3 tools/make_meshes.py). Standard library only; the output is deterministic.

Extraordinary vertices are made by an edge flip: two quads sharing an edge form a hexagon, which is split
into two quads along another pair of opposite vertices; the ends of the old edge lose a valence, the ends of
the new one gain one. Positions are not moved."""
import math
import os

def grid(nx, ny, x0, x1, y0, y1, skip=lambda i, j: False):
    """Quads of an nx × ny grid on [x0,x1]×[y0,y1] (counter-clockwise), minus the cells skip(i, j)."""
    verts, index, faces = [], {}, []
    def vid(i, j):
        if (i, j) not in index:
            index[(i, j)] = len(verts)
            verts.append((x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny, 0.0))
        return index[(i, j)]
    for j in range(ny):
        for i in range(nx):
            if not skip(i, j):
                faces.append([vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)])
    return verts, faces, index

def rotate_to(face, v):
    k = face.index(v)
    return face[k:] + face[:k]

def flip(faces, f1, f2, choice=0):
    """Re-splits the hexagon of faces f1, f2 (sharing one edge) along the other diagonal `choice` (0 or 1)."""
    a, b = faces[f1], faces[f2]
    for k in range(4):
        s, t = a[k], a[(k + 1) % 4]
        if s in b and b[(b.index(s) - 1) % 4] == t:
            break
    else:
        raise ValueError("faces do not share an edge")
    _, _, p1, p2 = rotate_to(a, s)      # a = [s, t, p1, p2]
    _, _, q1, q2 = rotate_to(b, t)      # b = [t, s, q1, q2]
    hexagon = [t, p1, p2, s, q1, q2]
    if choice == 0:                     # diagonal p1 - q1
        faces[f1], faces[f2] = [p1, p2, s, q1], [q1, q2, t, p1]
    else:                               # diagonal p2 - q2
        faces[f1], faces[f2] = [p2, s, q1, q2], [q2, t, p1, p2]
    return hexagon

def cell(nx, i, j):
    """Index of grid cell (i, j) in a full nx-wide grid() (faces are made row by row)."""
    return i + nx * j

def write_obj(path, verts, faces, comment):
    with open(path, "w") as out:
        out.write("# " + comment + "\n# made by tools/make_meshes.py\n")
        for x, y, z in verts:
            out.write("v %.17g %.17g %.17g\n" % (x, y, z))
        for f in faces:
            out.write("f " + " ".join(str(v + 1) for v in f) + "\n")

def valences(verts, faces):
    edges = set()
    for f in faces:
        for k in range(len(f)):
            a, b = f[k], f[(k + 1) % len(f)]
            edges.add((min(a, b), max(a, b)))
    val = [0] * len(verts)
    for a, b in edges:
        val[a] += 1
        val[b] += 1
    return val

def square_with_evs():
    """Unit square, 6 × 6 quads; flips make interior EVs of valence 3, 5 and 6 and boundary EVs."""
    verts, faces, index = grid(6, 6, 0.0, 1.0, 0.0, 1.0)
    # Interior: cells (1,2)-(2,2) make valences 3, 3, 5, 5; cells (3,1)-(4,1) then raise one of the
    # valence-5 vertices to 6 (found by trying the flips of neighbouring cells).
    flip(faces, cell(6, 1, 2), cell(6, 2, 2), 0)
    flip(faces, cell(6, 3, 1), cell(6, 4, 1), 0)
    # Boundary: cells (1,0)-(2,0) along the bottom edge: a boundary vertex with 3 faces (a boundary EV) and
    # one with a single face (an interpolated corner on the straight edge).
    flip(faces, cell(6, 1, 0), cell(6, 2, 0), 0)
    return verts, faces

def square_with_three_holes():
    holes = {(2, 2), (3, 2), (2, 3), (3, 3), (7, 3), (8, 3), (7, 4), (8, 4), (4, 7), (5, 7), (4, 8), (5, 8)}
    verts, faces, _ = grid(12, 12, 0.0, 1.0, 0.0, 1.0, skip=lambda i, j: (i, j) in holes)
    return verts, faces

def l_shape():
    verts, faces, _ = grid(8, 8, 0.0, 2.0, 0.0, 2.0, skip=lambda i, j: i >= 4 and j >= 4)
    return verts, faces

def cube(k=2):
    """The surface of [-1,1]^3, k × k quads per side, outward counter-clockwise faces."""
    verts, index, faces = [], {}, []
    def vid(p):
        key = tuple(round(c * 1e9) for c in p)
        if key not in index:
            index[key] = len(verts)
            verts.append(p)
        return index[key]
    # Each side: origin o, axes a (u) and b (v) with a × b = outward normal.
    sides = [((-1, -1, -1), (0, 2, 0), (2, 0, 0)),   # z = -1, normal -z
             ((-1, -1, 1), (2, 0, 0), (0, 2, 0)),    # z = +1, normal +z
             ((-1, -1, -1), (2, 0, 0), (0, 0, 2)),   # y = -1, normal -y
             ((-1, 1, -1), (0, 0, 2), (2, 0, 0)),    # y = +1, normal +y
             ((-1, -1, -1), (0, 0, 2), (0, 2, 0)),   # x = -1, normal -x
             ((1, -1, -1), (0, 2, 0), (0, 0, 2))]    # x = +1, normal +x
    for o, a, b in sides:
        def point(i, j):
            return tuple(float(o[c] + a[c] * i / k + b[c] * j / k) for c in range(3))
        for j in range(k):
            for i in range(k):
                faces.append([vid(point(i, j)), vid(point(i + 1, j)), vid(point(i + 1, j + 1)), vid(point(i, j + 1))])
    return verts, faces

def torus_with_evs(m=12, n=6, big=2.0, small=0.7):
    verts, faces = [], []
    for j in range(n):
        for i in range(m):
            t, p = 2 * math.pi * i / m, 2 * math.pi * j / n
            verts.append(((big + small * math.cos(p)) * math.cos(t), (big + small * math.cos(p)) * math.sin(t), small * math.sin(p)))
    vid = lambda i, j: (i % m) + m * (j % n)
    for j in range(n):
        for i in range(m):
            faces.append([vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)])
    flip(faces, 2 + m * 1, 3 + m * 1, 0)
    flip(faces, 8 + m * 3, 8 + m * 4, 1)
    return verts, faces

def main():
    out = os.path.join("data", "meshes")
    os.makedirs(out, exist_ok=True)
    nets = {
        "square_evs.obj": (square_with_evs(), "unit square [0,1]^2 with interior EVs (valences 3, 5, 6) and boundary EVs"),
        "square_three_holes.obj": (square_with_three_holes(), "unit square with three square holes (area 1 - 12/144); reflex hole corners are boundary EVs"),
        "l_shape.obj": (l_shape(), "L-shaped domain [0,2]^2 minus [1,2]^2 (area 3); the reflex corner is a boundary EV"),
        "cube.obj": (cube(), "closed surface: the cube [-1,1]^3, 2 x 2 quads per side; corners have valence 3"),
        "torus_evs.obj": (torus_with_evs(), "closed torus-like surface (R = 2, r = 0.7) with EVs of valence 3 and 5"),
    }
    for name, ((verts, faces), comment) in nets.items():
        val = valences(verts, faces)
        hist = {}
        for v in val:
            hist[v] = hist.get(v, 0) + 1
        write_obj(os.path.join(out, name), verts, faces, comment)
        print(name, len(verts), "vertices,", len(faces), "faces, valence histogram", dict(sorted(hist.items())))

if __name__ == "__main__":
    main()
