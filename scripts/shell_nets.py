#!/usr/bin/python3
"""Quad nets of the shell obstacle course's shapes, each with one rotated edge (two extraordinary vertices of valence 3,
two of valence 5), written as Wavefront OBJ for `iga-shell --basis cc --fit-to ...` (README, Kirchhoff-Love shells).
The vertices lie on the shape; --fit-to then fits the limit surface to it.

  scripts/shell_nets.py tube R L NA NY OUT.obj     the whole tube x = (R sin a, y, R cos a), 0 <= y <= L: NA quads
                                                   around, NY along; the rotated edge near a = pi/2, mid-length
  scripts/shell_nets.py band R LAT NA NB OUT.obj   the sphere of radius R from the equator to latitude LAT (degrees):
                                                   NA quads around, NB from the equator up
  scripts/shell_nets.py roof R L A NA NY OUT.obj   the cylindrical roof x = (R sin a, y, R cos a), -A <= a <= A (degrees),
                                                   0 <= y <= L: NA quads across, NY along; the rotated edge mid-roof

With --triangles (before the kind) each quad is split along its diagonal from its first vertex: a triangle mesh whose
dual (`iga-geometry --three-valent dual`) is a three-valent net for half-box splines.
"""
import math
import sys


def faces(ni, nj, v, ri, rj):
    """ni x nj quads, vertex (i, j) = v(i, j), the edge between quads (ri, rj) and (ri + 1, rj) rotated: the hexagon
    f a b c d e of the two split by its other diagonal c f."""
    out = []
    for j in range(nj):
        for i in range(ni):
            if (i, j) == (ri, rj):
                out.append([v(ri, rj), v(ri + 1, rj), v(ri + 2, rj), v(ri + 2, rj + 1)])
                out.append([v(ri + 2, rj + 1), v(ri + 1, rj + 1), v(ri, rj + 1), v(ri, rj)])
            elif (i, j) != (ri + 1, rj):
                out.append([v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)])
    return out


def tube(r, length, na, ny):
    points = [[r * math.sin(-math.pi + 2 * math.pi * i / na), length * j / ny, r * math.cos(-math.pi + 2 * math.pi * i / na)]
              for j in range(ny + 1) for i in range(na)]
    v = lambda i, j: j * na + i % na
    ri, rj = 3 * na // 4 - 1, ny // 2 - 1
    points[v(ri + 1, rj)][1] -= 0.25 * length / ny  # both quads of the hexagon convex
    points[v(ri + 1, rj + 1)][1] += 0.25 * length / ny
    return points, faces(na, ny, v, ri, rj)


def band(r, top, na, nb):
    points = []
    for j in range(nb + 1):
        for i in range(na):
            lon, lat = 2 * math.pi * i / na, math.radians(top) * j / nb
            points.append([r * math.cos(lat) * math.cos(lon), r * math.cos(lat) * math.sin(lon), r * math.sin(lat)])
    v = lambda i, j: j * na + i % na
    return points, faces(na, nb, v, na // 8, nb // 2 - 1)


def roof(r, length, angle, na, ny):
    a = math.radians(angle)
    points = [[r * math.sin(-a + 2 * a * i / na), length * j / ny, r * math.cos(-a + 2 * a * i / na)]
              for j in range(ny + 1) for i in range(na + 1)]
    v = lambda i, j: j * (na + 1) + i
    ri, rj = na // 2 - 1, ny // 2
    points[v(ri + 1, rj)][1] -= 0.25 * length / ny
    points[v(ri + 1, rj + 1)][1] += 0.25 * length / ny
    return points, faces(na, ny, v, ri, rj)


def main(argv):
    triangles = len(argv) > 1 and argv[1] == "--triangles"
    if triangles:
        argv = argv[:1] + argv[2:]
    counts = {"tube": 7, "band": 7, "roof": 8}
    if len(argv) < 2 or counts.get(argv[1]) != len(argv):
        sys.stderr.write(__doc__)
        return 2
    try:
        numbers = [float(w) for w in argv[2:-3]]
        na, nb = int(argv[-3]), int(argv[-2])
    except ValueError:
        sys.stderr.write("shell_nets.py: error: R, L, LAT and A are numbers, NA and NY (or NB) whole numbers\n")
        return 2
    r, extent = numbers[0], numbers[1]
    if not (r > 0 and extent > 0 and na >= (4 if argv[1] == "roof" else 8) and nb >= 2 and
            (argv[1] != "band" or extent <= 90) and (argv[1] != "roof" or 0 < numbers[2] < 180)):
        sys.stderr.write("shell_nets.py: error: need R > 0, L > 0 (or 0 < LAT <= 90), 0 < A < 180, NA >= 8 (roof: 4), "
                         "NY (NB) >= 2\n")
        return 2
    points, quads = {"tube": tube, "band": band, "roof": roof}[argv[1]](*numbers, na, nb)
    if triangles:
        quads = [t for q in quads for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])]
    with open(argv[-1], "w") as out:
        out.write(f"# scripts/shell_nets.py {'--triangles ' if triangles else ''}{' '.join(argv[1:-1])}\n")
        for p in points:
            out.write("v " + " ".join(repr(c) for c in p) + "\n")
        for f in quads:
            out.write("f " + " ".join(str(k + 1) for k in f) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
