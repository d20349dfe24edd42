#!/usr/bin/env python3
"""Writes the one-sided meshes of this folder (README.md): python3 make_files.py. The files are committed; the
tests read them, not this script."""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, comment, positions, faces):
    with open(os.path.join(HERE, name), "w") as out:
        for line in comment:
            out.write("# " + line + "\n")
        for p in positions:
            out.write("v %s\n" % " ".join("%.6f" % (c + 0.0) for c in p))
        for f in faces:
            out.write("f %s\n" % " ".join(str(v + 1) for v in f))


def moebius_strip():
    # Six quads around a circle; vertex 2i is on one side at angle 60i degrees, 2i + 1 on the other. The strip's
    # cross-section turns half a turn on the way round, so the last quad joins vertices 10, 11 to 0, 1 swapped.
    positions = []
    for i in range(6):
        t = 2 * math.pi * i / 6
        for side in (-0.3, 0.3):
            r = 1 + side * math.cos(t / 2)
            positions.append((r * math.cos(t), r * math.sin(t), side * math.sin(t / 2)))
    faces = [(2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2) for i in range(5)] + [(10, 11, 0, 1)]
    write("moebius_strip.obj", ["A Moebius strip: six quads around a circle with a half twist (faces 0..4 agree,",
                                "face 5 joins vertices 10 and 11 to 0 and 1 the other way round). One-sided: no",
                                "orientation of its faces agrees along every edge."], positions, faces)


def klein_bottle():
    # The figure-8 Klein bottle: 8 x 4 quads, u around the loop, v around the tube. Going once round in u turns the
    # tube over (v -> -v), so column 8 is column 0 with its rows in the other order: a closed one-sided surface.
    columns, rows, radius = 8, 4, 2.0
    positions = []
    for j in range(rows):
        for i in range(columns):
            u, v = 2 * math.pi * i / columns, 2 * math.pi * (j + 0.5) / rows
            r = radius + math.cos(u / 2) * math.sin(v) - math.sin(u / 2) * math.sin(2 * v)
            positions.append((r * math.cos(u), r * math.sin(u),
                              math.sin(u / 2) * math.sin(v) + math.cos(u / 2) * math.sin(2 * v)))

    def vertex(i, j):
        if i == columns:
            i, j = 0, rows - 1 - j  # v -> -v: row j + 0.5 becomes row -(j + 0.5), that is row rows - 1 - j
        return i + columns * (j % rows)

    faces = [(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1))
             for j in range(rows) for i in range(columns)]
    write("klein_bottle.obj", ["A Klein bottle (the figure-8 immersion): 8 x 4 quads, vertex i + 8j at u = 45i",
                               "degrees round the loop and v = 90(j + 1/2) degrees round the tube. Column 7's",
                               "quads join column 0 with the tube turned over. Closed and one-sided."],
          positions, faces)


def scan_with_twisted_flap():
    # A scanned sheet: 4 x 3 quads over (x, y) in [0, 4] x [0, 3], each cut into two triangles, heights like a scan's.
    # A flap two quads wide arches over it from the sheet's left edge (x = 0, y = 0..2) to its right edge (x = 4),
    # turning half a turn on the way, so that it meets the right edge with its rows the other way round (as a scan
    # of a thin twisted part welded to the sheet at both ends). Faces 6 and 7 are flipped (scanned from behind).
    positions = []
    for j in range(4):
        for i in range(5):
            positions.append((i, j, 0.15 * math.sin(1.3 * i) * math.cos(0.9 * j)))
    sheet = lambda i, j: i + 5 * j
    faces = []
    for j in range(3):
        for i in range(4):
            a, b, c, d = sheet(i, j), sheet(i + 1, j), sheet(i + 1, j + 1), sheet(i, j + 1)
            faces += [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
    faces[6] = tuple(reversed(faces[6]))
    faces[7] = tuple(reversed(faces[7]))
    length = 6  # quads along the flap
    flap = {}
    for s_step in range(1, length):
        s = s_step / length
        centre = (2 - 2 * math.cos(math.pi * s), 1, 2 * math.sin(math.pi * s))
        tangent = (2 * math.pi * math.sin(math.pi * s), 0, 2 * math.pi * math.cos(math.pi * s))
        norm = math.hypot(tangent[0], tangent[2])
        normal = (-tangent[2] / norm, 0, tangent[0] / norm)  # the arch's normal, across y
        a = math.pi * s
        width = (math.sin(a) * normal[0], math.cos(a), math.sin(a) * normal[2])
        for k in range(3):
            flap[(s_step, k)] = len(positions)
            positions.append(tuple(centre[c] + (k - 1) * width[c] for c in range(3)))

    def flap_vertex(s_step, k):
        if s_step == 0:
            return sheet(0, k)
        if s_step == length:
            return sheet(4, 2 - k)  # the half twist
        return flap[(s_step, k)]

    for s_step in range(length):
        for k in range(2):
            a, b = flap_vertex(s_step, k), flap_vertex(s_step + 1, k)
            c, d = flap_vertex(s_step + 1, k + 1), flap_vertex(s_step, k + 1)
            faces += [(a, d, c), (a, c, b)]
    write("scan_with_twisted_flap.obj",
          ["A scan-like sheet (4 x 3 quads as 24 triangles, vertex i + 5j at (i, j)) with faces 6 and 7",
           "flipped, and a flap two quads wide (faces 24..47, vertices 20..34) arching from the sheet's left",
           "edge to its right edge with a half twist: the sheet and the flap together are one-sided."],
          positions, faces)


moebius_strip()
klein_bottle()
scan_with_twisted_flap()
