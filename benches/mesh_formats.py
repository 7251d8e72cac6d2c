#!/usr/bin/env python3
"""Writes a unit sphere of about N triangles (a latitude/longitude grid, as mesh_sphere.py) as
OBJ, binary little-endian PLY and binary STL with the same float32 positions and the same
triangles in the same order, for benches/mesh_formats.sh. usage: mesh_formats.py N OUT_STEM"""
import math
import sys

import numpy as np

n, stem = int(sys.argv[1]), sys.argv[2]
seg = max(8, int(round(math.sqrt(n))))
rings = max(4, int(round(n / (2 * seg))))
theta = np.linspace(0.0, math.pi, rings + 1)
phi = np.linspace(0.0, 2 * math.pi, seg + 1)[:-1]
t, p = np.meshgrid(theta, phi, indexing="ij")
v = np.stack([np.sin(t) * np.cos(p), np.cos(t), np.sin(t) * np.sin(p)], -1).reshape(-1, 3)
# The positions every file holds: float32, written in OBJ with 9 significant digits (enough to
# give back the same float32).
v = v.astype(np.float32)
i = np.arange(rings)[:, None]
j = np.arange(seg)[None, :]
a = i * seg + j
b = i * seg + (j + 1) % seg
c = a + seg
d = b + seg
f = np.concatenate([np.stack([a, c, b], -1).reshape(-1, 3), np.stack([b, c, d], -1).reshape(-1, 3)])
f = f.astype(np.int32)
with open(stem + ".obj", "w") as o:
    o.write(f"# unit sphere: {rings} rings x {seg} segments, {len(f)} triangles\n")
    np.savetxt(o, v.astype(np.float64), fmt="v %.9g %.9g %.9g")
    np.savetxt(o, f + 1, fmt="f %d %d %d")
with open(stem + ".ply", "wb") as o:
    o.write(
        f"ply\nformat binary_little_endian 1.0\nelement vertex {len(v)}\nproperty float x\n"
        f"property float y\nproperty float z\nelement face {len(f)}\n"
        "property list uchar int vertex_indices\nend_header\n".encode()
    )
    o.write(v.astype("<f4").tobytes())
    faces = np.zeros(len(f), dtype=[("n", "u1"), ("i", "<i4", 3)])
    faces["n"] = 3
    faces["i"] = f
    o.write(faces.tobytes())
with open(stem + ".stl", "wb") as o:
    o.write(b"rtc benches/mesh_formats.py".ljust(80, b" "))
    o.write(np.uint32(len(f)).astype("<u4").tobytes())
    rec = np.zeros(len(f), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["v"] = v[f]
    o.write(rec.tobytes())
print(f"{stem}.{{obj,ply,stl}}: {len(v)} vertices, {len(f)} triangles")
