"""Splits the shapes benchmark's two scenes (benches/shapes.sh) into the whole scene, the floor
alone and each shape alone over the floor, for rtc and POV-Ray alike, into OUT as NAME.rtc and
NAME.pov, and writes the names to OUT/names.

A shape starts at a line beginning with its constructor (rtc) or keyword (POV-Ray) and runs to
the next such line or to the next blank or comment line; the k-th shape of one file is the
k-th of the other. POV-Ray's font path is made absolute.

    python3 benches/shapes_split.py SCENE.rtc SCENE.pov OUT
"""
import os
import re
import sys

SHAPES = ("text", "prism", "lathe", "superellipsoid", "sor", "sphere_sweep", "height_field", "isosurface")


def split(text, starts):
    head, shapes, cur = [], [], None
    for line in text.splitlines():
        if re.match(r"^(%s)\b" % "|".join(starts), line):
            cur = [line]
            shapes.append(cur)
        elif cur is not None and line.strip() and not line.lstrip().startswith("//") and (
            line.startswith((" ", "\t", ")", "}")) or line.startswith(".")
        ):
            cur.append(line)
        else:
            cur = None
            head.append(line)
    return "\n".join(head) + "\n", ["\n".join(s) + "\n" for s in shapes]


def main():
    rtc_path, pov_path, out = sys.argv[1:4]
    root = os.getcwd()
    rtc = open(rtc_path).read()
    pov = open(pov_path).read().replace('ttf "stdlib/', f'ttf "{root}/stdlib/')
    rtc_head, rtc_shapes = split(rtc, SHAPES)
    pov_head, pov_shapes = split(pov, SHAPES)
    if len(rtc_shapes) != len(pov_shapes):
        sys.exit(f"shapes_split: {len(rtc_shapes)} rtc shapes but {len(pov_shapes)} POV-Ray shapes")
    # Paths in the rtc scene are relative to its folder: keep them working from OUT.
    rtc_head = rtc_head.replace('path: "', f'path: "{os.path.dirname(os.path.abspath(rtc_path))}/')
    scenes = {"all": (rtc_head + "".join(rtc_shapes), pov_head + "".join(pov_shapes)),
              "floor": (rtc_head, pov_head)}
    for k, (r, p) in enumerate(zip(rtc_shapes, pov_shapes)):
        name = f"{k + 1}_{r.split('(')[0]}"
        scenes[name] = (rtc_head + r, pov_head + p)
    for name, (r, p) in scenes.items():
        open(os.path.join(out, f"{name}.rtc"), "w").write(r)
        open(os.path.join(out, f"{name}.pov"), "w").write(p)
    open(os.path.join(out, "names"), "w").write(" ".join(scenes))


main()
