#!/usr/bin/env python3
"""Writes the parse benchmark of issue 11: the same 100 000 spheres three ways.

  spheres_literal.rtc  one `sphere(center: [x, y, z], radius: r).material(m)` per line (~7 MB)
  spheres_loop.rtc     a `for` over the same grid that computes the same numbers
  spheres_translate.rtc  the loop with each sphere written `sphere(radius: r).translate(p)`
  spheres_scale.rtc    the loop with each sphere written `sphere().scale(r).translate(p)`
  spheres_literal.pov  the POV-Ray 3.7 twin of the literal file
  spheres_loop.pov     the POV-Ray 3.7 twin of the loop file (`#while`, issue 12's 100k row)
  points_literal.rtc   a 100 000-point list literal bound with `let` (the memory case)

Every coordinate is computed here exactly as the loop computes it (IEEE doubles, same operations
in the same order) and printed with repr(), which round-trips, so the literal and the loop files
describe bit-identical spheres. Usage: benches/literal_spheres.py OUT_DIR [N_X N_Z N_Y]
"""
import os
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "target/bench-parse"
nx, nz, ny = (int(a) for a in sys.argv[2:5]) if len(sys.argv) >= 5 else (100, 100, 10)
os.makedirs(out, exist_ok=True)

# Shared header: a 640×480 view of the grid from the front and above, one light, shadows.
CAMERA = "camera { eye: [0, 14, 34], center: [0, 0, 0], fov: 50deg, resolution: [640, 480] }"
LIGHT = "point_light { position: [20, 40, 30] }"
MATERIAL = "let m = material { color: rgb(0.8, 0.3, 0.2), ka: 0.2, kd: 0.7, ks: 0.3, n: 16 }"
RENDER = "render { shadows: true, max_depth: 0, encoding: linear }"


def spheres():
    for i in range(nx):
        for j in range(nz):
            for k in range(ny):
                x = i * 0.4 - 20.0
                y = k * 0.4
                z = j * 0.4 - 20.0
                r = 0.1 + 0.05 * ((i + j + k) % 3)
                yield x, y, z, r


def header(f):
    f.write("rtc 1\n")
    f.write(f"{CAMERA}\n{LIGHT}\n{MATERIAL}\n{RENDER}\n")


with open(os.path.join(out, "spheres_literal.rtc"), "w") as f:
    header(f)
    for x, y, z, r in spheres():
        f.write(f"sphere(center: [{x!r}, {y!r}, {z!r}], radius: {r!r}).material(m)\n")

with open(os.path.join(out, "spheres_loop.rtc"), "w") as f:
    header(f)
    f.write(
        f"for i in 0..{nx}, j in 0..{nz}, k in 0..{ny} {{\n"
        "  sphere(center: [i * 0.4 - 20.0, k * 0.4, j * 0.4 - 20.0], radius: 0.1 + 0.05 * ((i + j + k) % 3))\n"
        "    .material(m)\n"
        "}\n"
    )

# The same loop with the spheres placed by transforms (issue 42 item 4: a sphere's memory must
# not depend on how it is written). The same spheres, not the same bits: a transformed sphere
# is intersected in its own space.
for name, shape in [
    ("spheres_translate.rtc", "sphere(radius: 0.1 + 0.05 * ((i + j + k) % 3))"),
    ("spheres_scale.rtc", "sphere().scale(0.1 + 0.05 * ((i + j + k) % 3))"),
]:
    with open(os.path.join(out, name), "w") as f:
        header(f)
        f.write(
            f"for i in 0..{nx}, j in 0..{nz}, k in 0..{ny} {{\n"
            f"  {shape}\n"
            "    .material(m)\n"
            "    .translate([i * 0.4 - 20.0, k * 0.4, j * 0.4 - 20.0])\n"
            "}\n"
        )


def pov_header(f):
    # POV-Ray is left-handed: z is negated so the image is not mirrored.
    f.write("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n")
    f.write(
        "camera { perspective location <0, 14, -34> look_at <0, 0, 0> up y right x*640/480\n"
        "  angle 63.75 }\n"
    )
    f.write("light_source { <20, 40, -30> color rgb 1 }\n")
    f.write(
        "#declare M = texture { pigment { color rgb <0.8, 0.3, 0.2> }\n"
        "  finish { ambient 0.2 diffuse 0.7 specular 0.3 roughness 1/16 } }\n"
    )


with open(os.path.join(out, "spheres_literal.pov"), "w") as f:
    pov_header(f)
    for x, y, z, r in spheres():
        f.write(f"sphere {{ <{x!r}, {y!r}, {-z!r}>, {r!r} texture {{ M }} }}\n")

with open(os.path.join(out, "spheres_loop.pov"), "w") as f:
    pov_header(f)
    f.write(
        f"#declare I = 0;\n#while (I < {nx})\n"
        f"  #declare J = 0;\n  #while (J < {nz})\n"
        f"    #declare K = 0;\n    #while (K < {ny})\n"
        "      sphere { <I * 0.4 - 20.0, K * 0.4, -(J * 0.4 - 20.0)>, 0.1 + 0.05 * mod(I + J + K, 3)\n"
        "        texture { M } }\n"
        "      #declare K = K + 1;\n    #end\n"
        "    #declare J = J + 1;\n  #end\n"
        "  #declare I = I + 1;\n#end\n"
    )

with open(os.path.join(out, "points_literal.rtc"), "w") as f:
    header(f)
    f.write("let points = [\n")
    for x, y, z, _ in spheres():
        f.write(f"  [{x!r}, {y!r}, {z!r}],\n")
    f.write("]\nassert(len(points) == {})\n".format(nx * ny * nz))
    f.write("sphere(center: points[0], radius: 0.5).material(m)\n")

print(
    f"wrote {out}/spheres_literal.rtc, spheres_loop.rtc, spheres_translate.rtc,"
    " spheres_scale.rtc, spheres_literal.pov, spheres_loop.pov, points_literal.rtc"
)
