#!/usr/bin/python3
"""A turbine-like closed surface: a hub with 8 twisted blades, as an OFF file.

The cross-section at height z is star-shaped, r(theta) = hub + blade * bump(theta - twist z), so
the surface (side + two fan caps) is a closed, manifold, non-self-intersecting triangle mesh.
Usage: turbine_mesh.py OUT.off [angular steps] [height steps]
"""
import math
import sys

out = sys.argv[1]
nt = int(sys.argv[2]) if len(sys.argv) > 2 else 256
nz = int(sys.argv[3]) if len(sys.argv) > 3 else 32
hub, blade, blades, height, twist = 0.35, 0.65, 8, 0.5, 1.2


def radius(theta, z):
    phase = blades * (theta - twist * z)
    return hub + blade * ((0.5 + 0.5 * math.cos(phase)) ** 6)


verts = []
for k in range(nz + 1):
    z = height * k / nz
    for i in range(nt):
        th = 2 * math.pi * i / nt
        r = radius(th, z)
        verts.append((r * math.cos(th), r * math.sin(th), z))
bottom, top = len(verts), len(verts) + 1
verts += [(0.0, 0.0, 0.0), (0.0, 0.0, height)]
faces = []
for k in range(nz):
    for i in range(nt):
        a, b = k * nt + i, k * nt + (i + 1) % nt
        c, d = a + nt, b + nt
        faces += [(a, b, d), (a, d, c)]
for i in range(nt):
    faces.append((bottom, (i + 1) % nt, i))
    faces.append((top, nz * nt + i, nz * nt + (i + 1) % nt))
with open(out, "w") as f:
    f.write("OFF\n# turbine-like: hub %.2f, %d twisted blades (experiments/mesh-speed/turbine_mesh.py)\n" % (hub, blades))
    f.write("%d %d 0\n" % (len(verts), len(faces)))
    for v in verts:
        f.write("%.17g %.17g %.17g\n" % v)
    for t in faces:
        f.write("3 %d %d %d\n" % t)
