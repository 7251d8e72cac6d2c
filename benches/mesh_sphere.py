#!/usr/bin/env python3
"""Writes a unit sphere tessellated into about N triangles as OBJ (benches/scaling.sh's mesh
curve): a latitude/longitude grid of rings x segments quads, each split into two triangles (the
caps' quads have a zero-length edge, so their degenerate halves are dropped when loaded). The
surface is the same at every N, so the picture and the rays are alike and only the triangle
count changes. usage: mesh_sphere.py N OUT.obj"""
import math
import sys

import numpy as np

n, out = int(sys.argv[1]), sys.argv[2]
seg = max(8, int(round(math.sqrt(n))))
rings = max(4, int(round(n / (2 * seg))))
theta = np.linspace(0.0, math.pi, rings + 1)
phi = np.linspace(0.0, 2 * math.pi, seg + 1)[:-1]
t, p = np.meshgrid(theta, phi, indexing="ij")
v = np.stack([np.sin(t) * np.cos(p), np.cos(t), np.sin(t) * np.sin(p)], -1).reshape(-1, 3)
i = np.arange(rings)[:, None]
j = np.arange(seg)[None, :]
a = i * seg + j
b = i * seg + (j + 1) % seg
c = a + seg
d = b + seg
f = np.concatenate([np.stack([a, c, b], -1).reshape(-1, 3), np.stack([b, c, d], -1).reshape(-1, 3)])
with open(out, "w") as o:
    o.write(f"# unit sphere: {rings} rings x {seg} segments, {len(f)} triangles\n")
    np.savetxt(o, v, fmt="v %.7g %.7g %.7g")
    np.savetxt(o, f + 1, fmt="f %d %d %d")
print(f"{out}: {len(v)} vertices, {len(f)} triangles")
