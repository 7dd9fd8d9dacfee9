#!/usr/bin/env python3
"""Writes test meshes as STL files (no third-party modules): a cube, an icosphere, a box open at
the top, in ASCII or binary STL, faces wound outward (or inward with --inward, to test that the
reader turns a closed mesh outward).

  make_stl.py cube SIDE FILE [--binary] [--inward]          centred on the origin
  make_stl.py sphere RADIUS LEVELS FILE [--binary] [--inward]   icosahedron split LEVELS times
  make_stl.py open-box SIDE FILE [--binary]                  the cube without its top (+z) face
  make_stl.py garbage FILE                                   not an STL file at all
  make_stl.py random COUNT SIDE FILE [--binary]              COUNT random triangles in a cube of
                                                             SIDE (seeded: they intersect each other)
  make_stl.py nan-cube SIDE FILE                             the cube (binary) with one vertex NaN
"""
import math
import random
import struct
import sys


def cube_faces(side, top=True):
    h = side / 2
    v = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]  # index = 4x + 2y + z
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    # -x, +x, -y, +y, -z, +z; each wound counter-clockwise seen from outside
    faces = []
    for k, (a, b, c, d) in enumerate(quads):
        if not top and k == 5:
            continue
        faces += [(v[a], v[b], v[c]), (v[a], v[c], v[d])]
    return faces


def sphere_faces(radius, levels):
    t = (1 + math.sqrt(5)) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
             (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
            (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
            (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def unit(p):
        n = math.sqrt(sum(c * c for c in p))
        return tuple(c / n for c in p)

    faces = [tuple(unit(verts[i]) for i in tri) for tri in tris]
    for _ in range(levels):
        split = []
        for a, b, c in faces:
            ab, bc, ca = (unit(tuple((x + y) / 2 for x, y in zip(p, q))) for p, q in ((a, b), (b, c), (c, a)))
            split += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = split
    return [tuple(tuple(radius * c for c in p) for p in f) for f in faces]


def normal(f):
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = f
    ux, uy, uz, vx, vy, vz = bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az
    n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
    length = math.sqrt(sum(c * c for c in n)) or 1
    return tuple(c / length for c in n)


def write(path, faces, binary):
    if binary:
        with open(path, 'wb') as out:
            out.write(b'ryushi test mesh'.ljust(80, b' '))
            out.write(struct.pack('<I', len(faces)))
            for f in faces:
                out.write(struct.pack('<12fH', *normal(f), *f[0], *f[1], *f[2], 0))
    else:
        with open(path, 'w') as out:
            out.write('solid ryushi\n')
            for f in faces:
                out.write('facet normal %.9g %.9g %.9g\n outer loop\n' % normal(f))
                for p in f:
                    out.write('  vertex %.9g %.9g %.9g\n' % p)
                out.write(' endloop\nendfacet\n')
            out.write('endsolid ryushi\n')


def main(argv):
    flags = {a for a in argv if a.startswith('--')}
    args = [a for a in argv if not a.startswith('--')]
    kind = args[0]
    if kind == 'garbage':
        with open(args[1], 'w') as out:
            out.write('solid nothing\nthis is not a facet\n')
        return
    if kind == 'cube':
        faces, path = cube_faces(float(args[1])), args[2]
    elif kind == 'sphere':
        faces, path = sphere_faces(float(args[1]), int(args[2])), args[3]
    elif kind == 'random':
        rng = random.Random(1)
        side = float(args[2])
        faces = [tuple(tuple(rng.uniform(0, side) for _ in range(3)) for _ in range(3))
                 for _ in range(int(args[1]))]
        path = args[3]
    elif kind == 'nan-cube':
        faces, path = cube_faces(float(args[1])), args[2]
        faces[3] = (faces[3][0], (float('nan'), 0.0, 0.0), faces[3][2])
        flags.add('--binary')
    elif kind == 'open-box':
        faces, path = cube_faces(float(args[1]), top=False), args[2]
    else:
        sys.exit(__doc__)
    if '--inward' in flags:
        faces = [(a, c, b) for a, b, c in faces]
    write(path, faces, '--binary' in flags)


if __name__ == '__main__':
    main(sys.argv[1:])
