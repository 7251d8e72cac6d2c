#!/usr/bin/env python3
"""Writes a unit sphere of about N triangles (a latitude/longitude grid, as mesh_sphere.py) as
OBJ, binary little-endian PLY and binary STL with the same float32 positions and the same
triangles in the same order, for benches/mesh_formats.sh (standard library only).
usage: mesh_formats.py N OUT_STEM"""
import math
import struct
import sys
from array import array

n, stem = int(sys.argv[1]), sys.argv[2]
seg = max(8, int(round(math.sqrt(n))))
rings = max(4, int(round(n / (2 * seg))))
# Positions rounded to float32 once: every file holds exactly these (OBJ with 9 significant
# digits, which give the same float32 back).
pos = array("f")
for i in range(rings + 1):
    t = math.pi * i / rings
    for j in range(seg):
        p = 2 * math.pi * j / seg
        pos.extend((math.sin(t) * math.cos(p), math.cos(t), math.sin(t) * math.sin(p)))
faces = array("i")
for i in range(rings):
    for j in range(seg):
        a = i * seg + j
        b = i * seg + (j + 1) % seg
        faces.extend((a, a + seg, b))
for i in range(rings):
    for j in range(seg):
        a = i * seg + j
        b = i * seg + (j + 1) % seg
        faces.extend((b, a + seg, b + seg))
nv, nf = len(pos) // 3, len(faces) // 3
with open(stem + ".obj", "w") as o:
    o.write(f"# unit sphere: {rings} rings x {seg} segments, {nf} triangles\n")
    o.writelines("v %.9g %.9g %.9g\n" % (pos[k], pos[k + 1], pos[k + 2]) for k in range(0, len(pos), 3))
    o.writelines("f %d %d %d\n" % (faces[k] + 1, faces[k + 1] + 1, faces[k + 2] + 1) for k in range(0, len(faces), 3))
assert sys.byteorder == "little"
with open(stem + ".ply", "wb") as o:
    o.write(
        f"ply\nformat binary_little_endian 1.0\nelement vertex {nv}\nproperty float x\n"
        f"property float y\nproperty float z\nelement face {nf}\n"
        "property list uchar int vertex_indices\nend_header\n".encode()
    )
    o.write(pos.tobytes())
    rec = struct.Struct("<B3i")
    o.write(b"".join(rec.pack(3, faces[k], faces[k + 1], faces[k + 2]) for k in range(0, len(faces), 3)))
with open(stem + ".stl", "wb") as o:
    o.write(b"rtc benches/mesh_formats.py".ljust(80, b" "))
    o.write(struct.pack("<I", nf))
    rec = struct.Struct("<12fH")
    out = []
    for k in range(0, len(faces), 3):
        c = [pos[3 * faces[k + m] + x] for m in range(3) for x in range(3)]
        out.append(rec.pack(0, 0, 0, *c, 0))
    o.write(b"".join(out))
print(f"{stem}.{{obj,ply,stl}}: {nv} vertices, {nf} triangles")
