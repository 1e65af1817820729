#!/usr/bin/env python3
"""Writes an icosphere with inward-facing triangles as OBJ to stdout (standard library only):
    python3 tests/03-path-tracing/data/icosphere.py 3 > tests/03-path-tracing/data/icosphere-inward.obj
Level L subdivides the icosahedron L times (20 * 4^L faces) and pushes the new vertices out to the
unit sphere. Every face is counter-clockwise seen from INSIDE, so its normal points to the centre:
a closed emitting enclosure for the sphere furnace (furnace-sphere.scene)."""
import math
import sys


def icosphere(level):
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
             (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]   # counter-clockwise seen from outside
    for _ in range(level):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = [(verts[a][i] + verts[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(x * x for x in m))
                verts.append(tuple(x / n for x in m))
                middle[key] = len(verts) - 1
            return middle[key]

        faces = [f for a, b, c in faces for f in
                 ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)), (c, mid(c, a), mid(b, c)),
                  (mid(a, b), mid(b, c), mid(c, a)))]
    return verts, faces


def main():
    level = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    verts, faces = icosphere(level)
    print("# Icosphere (level %d: %d vertices, %d faces), circumradius 1, every face counter-clockwise seen"
          % (level, len(verts), len(faces)))
    print("# from INSIDE (normals inward). Written by tests/03-path-tracing/data/icosphere.py %d." % level)
    for v in verts:
        print("v %.9f %.9f %.9f" % v)
    for a, b, c in faces:   # reversed: counter-clockwise seen from inside
        print("f %d %d %d" % (a + 1, c + 1, b + 1))


if __name__ == "__main__":
    main()
