#!/usr/bin/env python3
"""Renders each hard case of docs/numerics.md with rtc and with POV-Ray 3.7 and writes one
side-by-side PNG per case (rtc left, POV-Ray right) into this directory.

Usage (from the repository root): python3 docs/images/numerics/make.py RTC_BINARY
Each case is one scene written twice: in rtc and in POV-Ray's language. POV-Ray is left-handed,
so its scenes negate every z coordinate; both cameras look the same way and see the same image.
The scene sources are written next to the PNGs (cases/*.rtc, cases/*.pov)."""

import os
import subprocess
import sys
import tempfile

from PIL import Image, ImageDraw

W, H = 200, 150
HERE = os.path.dirname(os.path.abspath(__file__))

POV_HEAD = """#version 3.7;
global_settings {{ assumed_gamma 1.0 ambient_light rgb 1 max_trace_level {depth} adc_bailout 0 }}
background {{ color rgb 0 }}
camera {{ perspective location {eye} look_at {center} right x*{aspect} up y angle {hfov} }}
"""


def pov_vec(v):
    return "<%r, %r, %r>" % (v[0], v[1], -v[2])


def pov_camera(eye, center, vfov_deg, depth=6):
    import math
    aspect = W / H
    hfov = 2 * math.degrees(math.atan(aspect * math.tan(math.radians(vfov_deg) / 2)))
    return POV_HEAD.format(depth=depth, eye=pov_vec(eye), center=pov_vec(center), aspect=aspect, hfov=hfov)


def rtc_camera(eye, center, vfov_deg, extra=""):
    return ("rtc 1\ncamera { eye: [%r, %r, %r], center: [%r, %r, %r], fov: %rdeg, resolution: [%d, %d] }\n%s\n"
            % (*eye, *center, vfov_deg, W, H, extra))


MATTE = "finish { ambient 0.2 diffuse 0.8 }"

CASES = []

# 1. Coincident CSG faces: a cube drilled by a flush cutter, seen from [0.3, 0.2, 6].
eye, center = (0.3, 0.2, 6.0), (0.0, 0.0, 0.0)
CASES.append(("csg_flush_hole",
    rtc_camera(eye, center, 30, "point_light { position: [3, 4, 8] }\n") +
    "box(min: [-1, -1, -1], max: [1, 1, 1]) - box(min: [-0.4, -0.4, -1], max: [0.4, 0.4, 1])\n",
    pov_camera(eye, center, 30) +
    "light_source { %s color rgb 1 }\n" % pov_vec((3, 4, 8)) +
    "difference { box { <-1,-1,-1>, <1,1,1> } box { <-0.4,-0.4,-1>, <0.4,0.4,1> } texture { pigment { color rgb 1 } %s } }\n" % MATTE))

# 2. A unit sphere seen from 1e8 with a view 3 units high.
import math
d = 1e8
fov = math.degrees(2 * math.atan(1.5 / d))
CASES.append(("far_sphere",
    rtc_camera((0, 0, d), (0, 0, 0), fov, "point_light { position: [0, 0, 2e8] }\n") + "sphere(radius: 1)\n",
    pov_camera((0, 0, d), (0, 0, 0), fov) + "light_source { %s color rgb 1 }\n" % pov_vec((0, 0, 2e8)) +
    "sphere { <0,0,0>, 1 texture { pigment { color rgb 1 } %s } }\n" % MATTE))

# 3. A point light lying on the floor beside a ball above it.
eye, center = (0.0, 2.0, 6.0), (0.0, 0.5, 0.0)
CASES.append(("light_on_plane",
    rtc_camera(eye, center, 40, "point_light { position: [2, 0, 1] }\n") +
    "plane()\nsphere(center: [0, 1, 0], radius: 0.5)\n",
    pov_camera(eye, center, 40) + "light_source { %s color rgb 1 }\n" % pov_vec((2, 0, 1)) +
    "plane { y, 0 texture { pigment { color rgb 1 } %s } }\n" % MATTE +
    "sphere { <0,1,0>, 0.5 texture { pigment { color rgb 1 } %s } }\n" % MATTE))

# 4. Balls 0.05 across on an Earth-radius ground sphere.
eye, center = (0.0, 0.12, 0.35), (0.0, 0.03, 0.0)
CASES.append(("earth_ground",
    rtc_camera(eye, center, 40, "point_light { position: [0.3, 0.5, 0.4] }\n") +
    "sphere(center: [0, -6.371e6, 0], radius: 6.371e6)\n"
    "sphere(center: [-0.06, 0.025, 0], radius: 0.025).material(material { color: rgb(0.9, 0.2, 0.1) })\n"
    "box(min: [0.01, 0, -0.04], max: [0.05, 0.04, 0]).material(material { color: rgb(0.2, 0.5, 0.9) })\n",
    pov_camera(eye, center, 40) + "light_source { %s color rgb 1 }\n" % pov_vec((0.3, 0.5, 0.4)) +
    "sphere { <0,-6.371e6,0>, 6.371e6 texture { pigment { color rgb 1 } %s } }\n" % MATTE +
    "sphere { %s, 0.025 texture { pigment { color rgb <0.9,0.2,0.1> } %s } }\n" % (pov_vec((-0.06, 0.025, 0)), MATTE) +
    "box { %s, %s texture { pigment { color rgb <0.2,0.5,0.9> } %s } }\n" % (pov_vec((0.01, 0, -0.04)), pov_vec((0.05, 0.04, 0)), MATTE)))

# 5. A ball and a box far from the origin (1e8 along every axis).
S = 1e8
def sh(p):
    return (p[0] + S, p[1] + S, p[2] + S)
eye, center = sh((0, 2, 6)), sh((0, 0.5, 0))
CASES.append(("far_from_origin",
    rtc_camera(eye, center, 40, "point_light { position: [%r, %r, %r] }\n" % sh((3, 5, 2))) +
    "plane(point: [%r, %r, %r], normal: Y)\n" % sh((0, 0, 0)) +
    "sphere(center: [%r, %r, %r], radius: 0.5)\n" % sh((-0.6, 0.5, 0)) +
    "box(min: [%r, %r, %r], max: [%r, %r, %r])\n" % (sh((0.4, 0, -1)) + sh((1.2, 0.8, -0.2))),
    pov_camera(eye, center, 40) + "light_source { %s color rgb 1 }\n" % pov_vec(sh((3, 5, 2))) +
    "plane { y, %r texture { pigment { color rgb 1 } %s } }\n" % (S, MATTE) +
    "sphere { %s, 0.5 texture { pigment { color rgb 1 } %s } }\n" % (pov_vec(sh((-0.6, 0.5, 0))), MATTE) +
    "box { %s, %s texture { pigment { color rgb 1 } %s } }\n" % (pov_vec(sh((0.4, 0, -1))), pov_vec(sh((1.2, 0.8, -0.2))), MATTE)))

# 6. Two glass boxes merged along a shared face, over a checker wall.
eye, center = (1.5, 1.2, 5.0), (0.0, 0.0, 0.0)
CASES.append(("glass_merge",
    rtc_camera(eye, center, 40, "render { max_depth: 8 }\npoint_light { position: [3, 4, 5] }\n") +
    "plane(point: [0, 0, -3], normal: Z).material(material { texture: checker(size: 0.4) })\n"
    "union([box(min: [-1, -1, -1], max: [0, 1, 1]), box(min: [0, -1, -1], max: [1, 1, 1])], merge: true)"
    ".material(material { color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, refract: 1, eta: 1.5 })\n",
    pov_camera(eye, center, 40, 9) + "light_source { %s color rgb 1 }\n" % pov_vec((3, 4, 5)) +
    "plane { z, 3 texture { pigment { checker color rgb 1 color rgb 0 scale 0.4 } %s } }\n" % MATTE +
    "merge { box { <-1,-1,-1>, <0,1,1> } box { <0,-1,-1>, <1,1,1> } "
    "texture { pigment { color rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } } interior { ior 1.5 } }\n"))

# 7. A glass shell 1e-6 thick (difference of two spheres) over the checker wall.
eye, center = (0.0, 0.0, 5.0), (0.0, 0.0, 0.0)
CASES.append(("thin_shell",
    rtc_camera(eye, center, 40, "render { max_depth: 8 }\npoint_light { position: [2, 3, 6] }\n") +
    "plane(point: [0, 0, -3], normal: Z).material(material { texture: checker(size: 0.5) })\n"
    "(sphere(radius: 1) - sphere(radius: 1 - 1e-6)).material(material { color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, refract: 1, eta: 1.5 })\n",
    pov_camera(eye, center, 40, 9) + "light_source { %s color rgb 1 }\n" % pov_vec((2, 3, 6)) +
    "plane { z, 3 texture { pigment { checker color rgb 1 color rgb 0 scale 0.5 } %s } }\n" % MATTE +
    "difference { sphere { <0,0,0>, 1 } sphere { <0,0,0>, 0.999999 } "
    "texture { pigment { color rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } } interior { ior 1.5 } }\n"))


def main():
    rtc = os.path.abspath(sys.argv[1])
    src = os.path.join(HERE, "cases")
    os.makedirs(src, exist_ok=True)
    only = sys.argv[2:]
    with tempfile.TemporaryDirectory() as tmp:
        for name, rtc_src, pov_src in CASES:
            if only and name not in only:
                continue
            r, p = os.path.join(src, name + ".rtc"), os.path.join(src, name + ".pov")
            open(r, "w").write(rtc_src)
            open(p, "w").write(pov_src)
            a, b = os.path.join(tmp, name + "_rtc.png"), os.path.join(tmp, name + "_pov.png")
            subprocess.run([rtc, "render", r, "-o", a], check=True, capture_output=True)
            subprocess.run(["povray", "+I" + p, "+O" + b, "+W%d" % W, "+H%d" % H, "-D", "-A", "-GA"],
                           check=True, capture_output=True)
            pair = Image.new("RGB", (2 * W + 4, H + 14), (255, 255, 255))
            pair.paste(Image.open(a).convert("RGB"), (0, 14))
            pair.paste(Image.open(b).convert("RGB"), (W + 4, 14))
            draw = ImageDraw.Draw(pair)
            draw.text((2, 1), "rtc", fill=(0, 0, 0))
            draw.text((W + 6, 1), "POV-Ray 3.7", fill=(0, 0, 0))
            pair.save(os.path.join(HERE, name + ".png"), optimize=True)
            print(name)


if __name__ == "__main__":
    main()
