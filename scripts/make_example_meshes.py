#!/usr/bin/env python3
"""Writes the meshes shipped in examples/data (run from the repository root).

wavy_sheet_with_hole.off: a 40 x 30 grid over [0, 2] x [0, 1.5] on the surface
z = 0.15 sin(2x) cos(3y), triangulated with alternating diagonals, with a
rectangular hole. It is curved (not developable) and has two border loops.
"""
import math

def wavy_sheet_with_hole(path, nx=40, ny=30):
    pts = []
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y = 2.0 * i / nx, 1.5 * j / ny
            pts.append((x, y, 0.15 * math.sin(2 * x) * math.cos(3 * y)))
    vid = lambda i, j: j * (nx + 1) + i
    tris = []
    for j in range(ny):
        for i in range(nx):
            if 24 <= i < 31 and 10 <= j < 19:
                continue
            if (i + j) % 2 == 0:
                tris += [(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)), (vid(i, j), vid(i + 1, j + 1), vid(i, j + 1))]
            else:
                tris += [(vid(i, j), vid(i + 1, j), vid(i, j + 1)), (vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1))]
    used = sorted({v for t in tris for v in t})
    remap = {v: k for k, v in enumerate(used)}
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(used), len(tris)))
        for v in used:
            f.write("%.9g %.9g %.9g\n" % pts[v])
        for t in tris:
            f.write("3 %d %d %d\n" % tuple(remap[v] for v in t))

if __name__ == "__main__":
    wavy_sheet_with_hole("examples/data/wavy_sheet_with_hole.off")
