#!/usr/bin/python3
"""Writes the project's own control nets to data/meshes/ (run from the repository root:
/usr/bin/python3 tools/make_meshes.py). Standard library only; the output is deterministic.

Extraordinary vertices are made by an edge flip: two quads sharing an edge form a hexagon, which is split
into two quads along another pair of opposite vertices; the ends of the old edge lose a valence, the ends of
the new one gain one. Positions are not moved.

The triangle meshes (tri_*.obj, input of the three-valent net constructions) split grid cells along one
diagonal; flipping the diagonals of a rectangle of cells keeps every interior vertex at valence 6 except the
rectangle's corners: 5 at its lower-left and upper-right corner, 7 at the other two (separated when the
rectangle is at least 2 x 2 cells)."""
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

def fan(n, radius=0.5, centre=(0.5, 0.5)):
    """The regular n-gon of circumradius `radius` about `centre`: n quads around one interior vertex of valence n
    (centre, edge midpoint k, corner k + 1, edge midpoint k + 1); the corners have one face, the midpoints two."""
    corners = [(centre[0] + radius * math.cos(2 * math.pi * k / n), centre[1] + radius * math.sin(2 * math.pi * k / n), 0.0)
               for k in range(n)]
    mids = [((corners[k][0] + corners[(k + 1) % n][0]) / 2, (corners[k][1] + corners[(k + 1) % n][1]) / 2, 0.0)
            for k in range(n)]
    verts = [(centre[0], centre[1], 0.0)] + corners + mids
    faces = [[0, 1 + n + k, 1 + (k + 1) % n, 1 + n + (k + 1) % n] for k in range(n)]
    return verts, faces

def triangulated_grid(nx, ny, x0, x1, y0, y1, skip=lambda i, j: False, flipped=lambda i, j: False):
    """Each quad of grid() split into two counter-clockwise triangles along the diagonal (i,j)-(i+1,j+1), or
    along (i+1,j)-(i,j+1) where flipped(i, j)."""
    verts, quads, index = grid(nx, ny, x0, x1, y0, y1, skip)
    grid_point = {v: ij for ij, v in index.items()}
    faces = []
    for a, b, c, d in quads:
        i, j = grid_point[a]
        if flipped(i, j):
            faces += [[a, b, d], [b, c, d]]
        else:
            faces += [[a, b, c], [a, c, d]]
    return verts, faces

def in_rectangles(rects):
    return lambda i, j: any(i0 <= i < i1 and j0 <= j < j1 for i0, i1, j0, j1 in rects)

def tri_square():
    """Unit square, 8 x 8 cells, 128 triangles; flipped cells [2,5)^2 make interior valences 5 at grid points
    (2,2), (5,5) and 7 at (5,2), (2,5)."""
    return triangulated_grid(8, 8, 0.0, 1.0, 0.0, 1.0, flipped=in_rectangles([(2, 5, 2, 5)]))

def tri_l_shape():
    """[0,2]^2 minus [1,2]^2, cells of side 1/4, 96 triangles; flipped cells [1,3)x[1,3) and [5,7)x[1,3) make
    interior valences 5 at grid points (1,1), (3,3), (5,1), (7,3) and 7 at (3,1), (1,3), (7,1), (5,3)."""
    return triangulated_grid(8, 8, 0.0, 2.0, 0.0, 2.0, skip=lambda i, j: i >= 4 and j >= 4,
                             flipped=in_rectangles([(1, 3, 1, 3), (5, 7, 1, 3)]))

def tri_sphere(levels=2):
    """Icosahedron, each triangle split into 4 `levels` times, projected to the unit sphere: 320 triangles,
    162 vertices, the 12 of the icosahedron of valence 5 (two edges apart after one split), the rest 6."""
    g = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
             (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    faces = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
             [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5],
             [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    unit = lambda p: tuple(c / math.sqrt(sum(x * x for x in p)) for c in p)
    verts = [unit(p) for p in verts]
    for _ in range(levels):
        mid = {}
        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                mid[key] = len(verts)
                verts.append(unit(tuple((verts[a][c] + verts[b][c]) / 2 for c in range(3))))
            return mid[key]
        faces = [t for a, b, c in faces for t in ([a, m(a, b), m(c, a)], [b, m(b, c), m(a, b)],
                                                   [c, m(c, a), m(b, c)], [m(a, b), m(b, c), m(c, a)])]
    for a, b, c in faces:  # outward counter-clockwise: (b - a) x (c - a) points away from the centre
        u = [verts[b][k] - verts[a][k] for k in range(3)]
        w = [verts[c][k] - verts[a][k] for k in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        if sum(n[k] * verts[a][k] for k in range(3)) <= 0:
            raise ValueError("icosphere triangle not outward")
    return verts, faces

def tri_torus(m=12, n=6, big=2.0, small=0.7):
    """The torus of torus_with_evs() without flips, each quad split along one diagonal: 144 triangles, every
    vertex of valence 6."""
    verts, quads = [], []
    for j in range(n):
        for i in range(m):
            t, p = 2 * math.pi * i / m, 2 * math.pi * j / n
            verts.append(((big + small * math.cos(p)) * math.cos(t), (big + small * math.cos(p)) * math.sin(t), small * math.sin(p)))
    vid = lambda i, j: (i % m) + m * (j % n)
    faces = []
    for j in range(n):
        for i in range(m):
            a, b, c, d = vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)
            faces += [[a, b, c], [a, c, d]]
    return verts, faces

def main():
    out = os.path.join("data", "meshes")
    os.makedirs(out, exist_ok=True)
    nets = {
        "square_6x6.obj": (grid(6, 6, 0.0, 1.0, 0.0, 1.0)[:2], "unit square [0,1]^2, 6 x 6 quads, no extraordinary vertex"),
        "square_evs.obj": (square_with_evs(), "unit square [0,1]^2 with interior EVs (valences 3, 5, 6) and boundary EVs"),
        "square_three_holes.obj": (square_with_three_holes(), "unit square with three square holes (area 1 - 12/144); reflex hole corners are boundary EVs"),
        "l_shape.obj": (l_shape(), "L-shaped domain [0,2]^2 minus [1,2]^2 (area 3); the reflex corner is a boundary EV"),
        "cube.obj": (cube(), "closed surface: the cube [-1,1]^3, 2 x 2 quads per side; corners have valence 3"),
        "torus_evs.obj": (torus_with_evs(), "closed torus-like surface (R = 2, r = 0.7) with EVs of valence 3 and 5"),
        **{"fan_%d.obj" % n: (fan(n), "regular %d-gon (circumradius 0.5 about (0.5, 0.5)): %d quads around one interior "
                                         "EV of valence %d" % (n, n, n)) for n in (3, 5, 6, 8)},
        "tri_square.obj": (tri_square(), "triangulated unit square, separated interior vertices of valence 5 (2) and 7 (2)"),
        "tri_l_shape.obj": (tri_l_shape(), "triangulated L-shape [0,2]^2 minus [1,2]^2, separated interior vertices of valence 5 (4) and 7 (4)"),
        "tri_sphere.obj": (tri_sphere(), "unit sphere: icosahedron split twice, 12 separated vertices of valence 5, the rest 6"),
        "tri_torus.obj": (tri_torus(), "triangulated torus (R = 2, r = 0.7), every vertex of valence 6"),
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
