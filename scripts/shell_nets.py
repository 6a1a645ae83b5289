#!/usr/bin/python3
"""Quad nets of the shell obstacle course's shapes, each with one rotated edge (two extraordinary vertices of valence 3,
two of valence 5), written as Wavefront OBJ for `iga-shell --basis cc --fit-to ...` (README, Kirchhoff-Love shells).
The vertices lie on the shape; --fit-to then fits the limit surface to it.

  scripts/shell_nets.py tube R L NA NY OUT.obj     the whole tube x = (R sin a, y, R cos a), 0 <= y <= L: NA quads
                                                   around, NY along; the rotated edge near a = pi/2, mid-length
  scripts/shell_nets.py band R LAT NA NB OUT.obj   the sphere of radius R from the equator to latitude LAT (degrees):
                                                   NA quads around, NB from the equator up
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


def main(argv):
    if len(argv) != 7 or argv[1] not in ("tube", "band"):
        sys.stderr.write(__doc__)
        return 2
    try:
        r, extent, na, nb = float(argv[2]), float(argv[3]), int(argv[4]), int(argv[5])
    except ValueError:
        sys.stderr.write("shell_nets.py: error: R and L (or LAT) are numbers, NA and NY (or NB) whole numbers\n")
        return 2
    if not (r > 0 and extent > 0 and na >= 8 and nb >= 2 and (argv[1] == "tube" or extent <= 90)):
        sys.stderr.write("shell_nets.py: error: need R > 0, L > 0 (or 0 < LAT <= 90), NA >= 8, NY (NB) >= 2\n")
        return 2
    points, quads = (tube if argv[1] == "tube" else band)(r, extent, na, nb)
    with open(argv[6], "w") as out:
        out.write(f"# scripts/shell_nets.py {' '.join(argv[1:6])}\n")
        for p in points:
            out.write("v " + " ".join(repr(c) for c in p) + "\n")
        for f in quads:
            out.write("f " + " ".join(str(k + 1) for k in f) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
