#!/usr/bin/env python3
"""Mitsuba 3 references and rtc twins for the path tracer (issue 39).

Each scene below is described once, as plain Python data; from that data this script writes
BOTH the rtc twin `scenes/gi/<name>.rtc` and the Mitsuba scene dict (`mi.load_dict`), so the
two cannot drift. It then renders a 64×64 reference `tests/data/gi/<name>_64.exr` (float RGB
linear radiance) and its per-pixel standard error `tests/data/gi/<name>_64_stderr.exr`.

Conventions (benches/gi/README.md says why):
  * radiance in W/(m²·sr) per linear RGB channel; albedo is rtc's kd·color = Mitsuba's diffuse
    reflectance; an emitter's radiance is rtc's emission·color = Mitsuba's `area` radiance.
  * emitters are one-sided: they emit on the side of u × v (rtc `emission_sides: 1`; Mitsuba's
    `rectangle` emits along its local +Z, which to_world maps to u × v).
  * diffuse surfaces are two-sided in both (Mitsuba `twosided`).
  * rtc `bounces: 64` (scattering events) = Mitsuba `max_depth: 65` (path segments).
  * Mitsuba `independent` sampler (its low-discrepancy sampler has a known bias) and `box`
    reconstruction filter (rtc averages samples over the pixel square).

Measured 2026-12-08 (Mitsuba 3.9.1 llvm_ad_rgb, 2-core AMD EPYC KVM guest shared with builds):
  cornell      64×64: 2²⁰ spp, 2083 s CPU; std error/value on lit pixels: median 0.07 %,
               p99 0.29 %, max 0.40 %
  spheres_env  64×64: 2¹⁸ spp, 119 s CPU; std error/value: median 0.05 %, p99 0.18 %, max 0.32 %

Usage:
  python3 benches/gi/mitsuba_refs.py                     # twins + 64×64 references
  python3 benches/gi/mitsuba_refs.py --twins-only        # only scenes/gi/*.rtc (no Mitsuba)
  python3 benches/gi/mitsuba_refs.py --full              # also 256×256 into target/gi-refs/
  python3 benches/gi/mitsuba_refs.py --check-normals target/release/rtc
  options: --scene NAME (repeatable), --spp N (override), --no-refs
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile
import textwrap
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

# ---------------------------------------------------------------------------------------------
# Scene data (the single description)
# ---------------------------------------------------------------------------------------------


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def add(*vs):
    return [sum(v[i] for v in vs) for i in range(3)]


def mul(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def quad(corner, u, v, mat, label, facing=None):
    """A parallelogram corner + s·u + t·v of material `mat` (a name in the scene's `materials`);
    `facing` (a vector) asserts that its front normal u × v points along it."""
    if facing is not None:
        assert dot(cross(u, v), facing) > 0, ("quad faces the wrong way", corner, u, v)
    # Mitsuba's rectangle takes its area from |du|·|dv|: exact only for a rectangle.
    assert abs(dot(u, v)) < 1e-9 * math.sqrt(dot(u, u) * dot(v, v)), "quads must be rectangles"
    return {"corner": list(corner), "u": list(u), "v": list(v), "mat": mat, "label": label}


def sphere(center, radius, mat, label):
    """A sphere of material `mat`."""
    return {"center": list(center), "radius": radius, "mat": mat, "label": label}


def material(albedo, emission=(0, 0, 0)):
    """Diffuse reflectance (rtc kd·color) and emitted radiance (rtc emission·color), linear."""
    return {"albedo": list(albedo), "emission": list(emission)}


def box_quads(cx, cz, sx, sz, h, angle_deg, mat, label):
    """The five visible faces (no bottom: it lies on the floor) of a box standing on y = 0,
    footprint sx × sz centred on (cx, cz), turned by angle_deg about +Y; normals outward."""
    t = math.radians(angle_deg)
    a = [sx * math.cos(t), 0.0, -sx * math.sin(t)]
    b = [sz * math.sin(t), 0.0, sz * math.cos(t)]
    up = [0.0, h, 0.0]
    p0 = [cx - a[0] / 2 - b[0] / 2, 0.0, cz - a[2] / 2 - b[2] / 2]
    mid = [cx, h / 2, cz]
    faces = [
        ("top", add(p0, up), b, a),  # +Y
        ("front", add(p0, b), a, up),  # +b
        ("back", p0, up, a),  # -b
        ("right", add(p0, a), up, b),  # +a
        ("left", p0, b, up),  # -a
    ]
    out = []
    for face, corner, u, v in faces:
        centre = add(corner, mul(u, 0.5), mul(v, 0.5))
        out.append(quad(corner, u, v, mat, f"{label}, {face}", facing=sub(centre, mid)))
    return out


def cornell():
    """The classic Cornell box (Shirley's 555-unit layout, in units of 100 mm), open towards +Z."""
    L = 5.55
    quads = [
        quad([0, 0, 0], [L, 0, 0], [0, 0, -L], "white", "floor", facing=[0, 1, 0]),
        quad([0, L, 0], [0, 0, -L], [L, 0, 0], "white", "ceiling", facing=[0, -1, 0]),
        quad([0, 0, -L], [L, 0, 0], [0, L, 0], "white", "back wall", facing=[0, 0, 1]),
        quad([0, 0, 0], [0, 0, -L], [0, L, 0], "red", "left wall", facing=[1, 0, 0]),
        quad([L, 0, 0], [0, L, 0], [0, 0, -L], "green", "right wall", facing=[-1, 0, 0]),
        quad([2.13, L - 0.01, -3.32], [1.30, 0, 0], [0, 0, 1.05], "light",
             "the light, 1.30 × 1.05, 0.01 under the ceiling, emitting downwards",
             facing=[0, -1, 0]),
    ]
    quads += box_quads(3.7, -1.5, 1.65, 1.65, 1.65, -18, "white", "short box")
    quads += box_quads(1.85, -3.7, 1.65, 1.65, 3.30, 17, "white", "tall box")
    return {
        "doc": "The classic Cornell box: white floor, ceiling and back wall, red left and green "
               "right wall, two white boxes, one downward light quad of radiance (17, 12, 4) "
               "under the ceiling; black environment. Units of 100 mm.",
        # the front opening (half-height 2.775) just fills the 40° view from z = 7.6; the eye is
        # 0.005 right of the box's axis (Shirley's 278 of 555) so that no pixel centre lies
        # exactly on the image of an edge (an eye on the axis puts the corners on the diagonals)
        "camera": {"eye": [2.78, L / 2, 7.6], "center": [2.78, L / 2, 0], "up": [0, 1, 0],
                   "fov": 40},
        "environment": [0, 0, 0],
        "materials": {
            "white": material((0.73, 0.73, 0.73)),
            "red": material((0.65, 0.05, 0.05)),
            "green": material((0.12, 0.45, 0.15)),
            "light": material((0, 0, 0), emission=(17, 12, 4)),
        },
        "quads": quads,
        "spheres": [],
        "spp": 1 << 20,
    }


def spheres_env():
    """Three diffuse spheres on a large grey floor, lit only by a uniform white environment."""
    return {
        "doc": "Three diffuse spheres of different albedo on a 40 × 40 grey floor, lit only by "
               "a constant environment of radiance (1, 1, 1).",
        "camera": {"eye": [0, 2.2, 7], "center": [0, 0.7, 0], "up": [0, 1, 0], "fov": 40},
        "environment": [1, 1, 1],
        "materials": {
            "grey": material((0.5, 0.5, 0.5)),
            "orange": material((0.8, 0.25, 0.2)),
            "blue": material((0.2, 0.5, 0.8)),
            "white": material((0.9, 0.9, 0.9)),
        },
        "quads": [quad([-20, 0, 20], [40, 0, 0], [0, 0, -40], "grey", "the floor",
                       facing=[0, 1, 0])],
        "spheres": [
            sphere([-1.4, 0.7, 0.4], 0.7, "orange", "left sphere"),
            sphere([0.4, 1.0, -1.0], 1.0, "blue", "back sphere"),
            sphere([1.6, 0.5, 1.0], 0.5, "white", "front right sphere"),
        ],
        "spp": 1 << 18,
    }


SCENES = {"cornell": cornell, "spheres_env": spheres_env}
BOUNCES = 64  # rtc's scattering events; Mitsuba's max_depth = BOUNCES + 1 path segments

# ---------------------------------------------------------------------------------------------
# rtc twins
# ---------------------------------------------------------------------------------------------


def num(x):
    """A number as rtc source: integers without a point, others in the shortest exact form."""
    x = float(x)
    if x == 0:
        return "0"
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(round(x, 12))


def vec(v):
    return "[" + ", ".join(num(x) for x in v) + "]"


def rgb(c):
    return "rgb(" + ", ".join(num(x) for x in c) + ")"


WIDTH = 100  # rtc fmt's line width: the twins are written in its canonical layout


def block(head, fields):
    """`head { a: x, b: y }` on one line if it fits, else one field a line (rtc fmt's layout)."""
    line = head + " { " + ", ".join(f"{k}: {v}" for k, v in fields) + " }"
    if len(line) <= WIDTH:
        return [line]
    return [head + " {"] + [f"    {k}: {v}" for k, v in fields] + ["}"]


def call(fn, args, tail=""):
    """`fn(a: x, b: y)tail` on one line if it fits, else one argument a line (rtc fmt's)."""
    line = fn + "(" + ", ".join(f"{k}: {v}" for k, v in args) + ")" + tail
    if len(line) <= WIDTH:
        return [line]
    return [fn + "("] + [f"    {k}: {v}," for k, v in args] + [")" + tail]


def rtc_material(albedo, emission):
    if any(emission):
        # emission·color is the radiance, kd·color the albedo: one colour serves both only when
        # the emitter is black, which every emitter here is.
        assert not any(albedo), "emitters here are black (albedo 0)"
        return [("color", "rgb(1, 1, 1)"), ("ka", "0"), ("kd", "0"), ("ks", "0"),
                ("emission", rgb(emission)), ("emission_sides", "1")]
    return [("color", rgb(albedo)), ("ka", "0"), ("kd", "1"), ("ks", "0")]


def rtc_source(name, scene, res, render_fields, with_materials=True):
    c = scene["camera"]
    head = (f"{name}.rtc: the rtc twin of a Mitsuba 3 reference, written by "
            "benches/gi/mitsuba_refs.py from the same data (edit the script, not this file). "
            + scene["doc"])
    lines = ["// " + line for line in textwrap.wrap(head, 96)] + ["rtc 1", ""]
    lines += block("camera", [("eye", vec(c["eye"])), ("center", vec(c["center"])),
                              ("up", vec(c["up"])), ("fov", num(c["fov"]) + "deg"),
                              ("resolution", f"[{res}, {res}]")])
    lines.append("")
    if with_materials:
        for mname, m in scene["materials"].items():
            lines += block(f"let {mname} = material", rtc_material(m["albedo"], m["emission"]))
        lines.append("")

    def tail(obj):
        return f".material({obj['mat']})" if with_materials else ""

    for q in scene["quads"]:
        lines.append(f"// {q['label']}")
        lines += call("quad", [("corner", vec(q["corner"])), ("u", vec(q["u"])),
                               ("v", vec(q["v"]))], tail(q))
    for s in scene["spheres"]:
        lines.append(f"// {s['label']}")
        lines += call("sphere", [("center", vec(s["center"])), ("radius", num(s["radius"]))],
                      tail(s))
    lines.append("")
    lines += block("render", render_fields)
    return "\n".join(lines) + "\n"


def rtc_twin(name, scene, res=64, spp=64):
    render = [("integrator", f"path(samples: {spp}, bounces: {BOUNCES})"),
              ("background", rgb(scene["environment"])), ("encoding", "linear"), ("cutoff", "0")]
    return rtc_source(name, scene, res, render)


def rtc_normals(name, scene, res=64):
    """The same camera and geometry as an AOV scene the current rtc renders: (N + 1)/2."""
    return rtc_source(name, scene, res, [("mode", "normal"), ("encoding", "linear")],
                      with_materials=False)


# ---------------------------------------------------------------------------------------------
# Mitsuba
# ---------------------------------------------------------------------------------------------


def rectangle_to_world(q):
    """Mitsuba's rectangle is [-1, 1]² in local xy, normal +Z: map it onto corner + [0,1]²·(u,v),
    with local Z along u × v so that the emitting side is rtc's front side."""
    u, v, c = q["u"], q["v"], q["corner"]
    n = cross(u, v)
    ln = math.sqrt(dot(n, n))
    n = [x / ln for x in n]
    t = add(c, mul(u, 0.5), mul(v, 0.5))
    return [[u[i] / 2, v[i] / 2, n[i], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


def mitsuba_dict(mi, scene, res, integrator, sampler):
    c = scene["camera"]
    d = {
        "type": "scene",
        "integrator": integrator,
        "sensor": {
            "type": "perspective",
            "fov": float(c["fov"]),
            "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=c["eye"], target=c["center"],
                                                       up=c["up"]),
            "sampler": sampler,
            "film": {"type": "hdrfilm", "width": res, "height": res, "rfilter": {"type": "box"},
                     "pixel_format": "rgb", "component_format": "float32"},
        },
    }
    if any(scene["environment"]):
        d["environment"] = {"type": "constant",
                            "radiance": {"type": "rgb", "value": scene["environment"]}}

    def decorate(shape, obj):
        obj = scene["materials"][obj["mat"]]
        shape["bsdf"] = {"type": "twosided",
                         "bsdf": {"type": "diffuse",
                                  "reflectance": {"type": "rgb", "value": obj["albedo"]}}}
        if any(obj["emission"]):
            shape["emitter"] = {"type": "area",
                                "radiance": {"type": "rgb", "value": obj["emission"]}}
        return shape

    for i, q in enumerate(scene["quads"]):
        d[f"quad{i}"] = decorate({"type": "rectangle",
                                  "to_world": mi.ScalarTransform4f(rectangle_to_world(q))}, q)
    for i, s in enumerate(scene["spheres"]):
        d[f"sphere{i}"] = decorate({"type": "sphere", "center": s["center"],
                                    "radius": float(s["radius"])}, s)
    return d


def path_integrator():
    # rr_depth stays at Mitsuba's default (5): Russian roulette is unbiased. Mitsuba splits a
    # large spp into passes itself (its `samples_per_pass` is deprecated).
    return {"type": "path", "max_depth": BOUNCES + 1}


def render_reference(mi, np, scene, res, spp):
    """Mean and standard error per pixel over independent batches (seeds 0, 1, ...): at least 16
    of them, each at most 2²³ samples in all so that one wavefront stays a few hundred MB."""
    import drjit as dr

    per = min(spp // 16, max(1, (1 << 23) // (res * res)))
    batches = spp // per
    assert per * batches == spp and batches >= 16, "spp must be 16 times a power of two"
    d = mitsuba_dict(mi, scene, res, path_integrator(),
                     {"type": "independent", "sample_count": per})
    w0, c0 = time.time(), time.process_time()
    sc = mi.load_dict(d)
    total = np.zeros((res, res, 3))
    squares = np.zeros((res, res, 3))
    for b in range(batches):
        img = np.array(mi.render(sc, spp=per, seed=b), dtype=np.float64)[:, :, :3]
        dr.sync_thread()
        total += img
        squares += img * img
    wall, cpu = time.time() - w0, time.process_time() - c0
    mean = total / batches
    var = np.maximum(squares / batches - mean * mean, 0) * batches / (batches - 1)
    stderr = np.sqrt(var / batches)
    return mean, stderr, batches, wall, cpu


def noise_summary(np, mean, stderr):
    """Relative standard error on lit pixels (luminance ≥ 5 % of the image's mean)."""
    lum = mean @ np.array([0.2126, 0.7152, 0.0722])
    lit = lum >= 0.05 * lum.mean()
    rel = stderr[lit] / np.maximum(mean[lit], 1e-12)
    rel_lum = (stderr[lit] @ np.array([0.2126, 0.7152, 0.0722])) / lum[lit]
    return {
        "lit": int(lit.sum()),
        "pixels": lum.size,
        "rel_lum_median": float(np.median(rel_lum)),
        "rel_lum_p99": float(np.percentile(rel_lum, 99)),
        "rel_lum_max": float(rel_lum.max()),
        "rel_chan_max": float(rel.max()),
        "rel_chan_p99": float(np.percentile(rel, 99)),
    }


def write_exr(mi, np, path, img):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    bmp = mi.Bitmap(np.ascontiguousarray(img, dtype=np.float32), mi.Bitmap.PixelFormat.RGB)
    bmp.write(path)


# ---------------------------------------------------------------------------------------------
# Normal check: Mitsuba's normal AOV against rtc's `mode: normal`
# ---------------------------------------------------------------------------------------------


def check_normals(mi, np, name, scene, rtc_binary, res=64):
    """Count pixels whose 8-bit normal code differs between Mitsuba and rtc, both sampled at the
    pixel centre (rtc without supersampling; Mitsuba's stratified sampler, 1 spp, no jitter)."""
    d = mitsuba_dict(mi, scene, res, {"type": "aov", "aovs": "n:geo_normal"},
                     {"type": "stratified", "sample_count": 1, "jitter": False})
    img = np.array(mi.render(mi.load_dict(d), spp=1), dtype=np.float64)[:, :, :3]
    hit = np.linalg.norm(img, axis=2) > 0.5  # a miss has a zero normal
    code = np.where(hit[:, :, None], np.floor(255 * np.clip((img + 1) / 2, 0, 1)), 0)
    with tempfile.TemporaryDirectory() as tmp:
        src = os.path.join(tmp, name + "_normals.rtc")
        png = os.path.join(tmp, name + "_normals.png")
        with open(src, "w") as f:
            f.write(rtc_normals(name, scene, res))
        run = subprocess.run([rtc_binary, "render", src, "-o", png], capture_output=True,
                             text=True)
        if run.returncode != 0:
            raise SystemExit(f"{rtc_binary} render {src} failed:\n{run.stderr}")
        ours = np.array(mi.Bitmap(png), dtype=np.float64)[:, :, :3]
    diff = np.abs(code - ours).max(axis=2)
    bad = diff > 1  # one level of slack for the last bit of the normal
    # the mirror image would match a flipped copy far better
    mirrored = int((np.abs(code[:, ::-1] - ours).max(axis=2) > 1).sum())
    flipped = int((np.abs(code[::-1] - ours).max(axis=2) > 1).sum())
    return {"pixels": res * res, "hits": int(hit.sum()), "differ": int(bad.sum()),
            "flipped_differ": flipped, "differ_any": int((diff > 0).sum()),
            "max_level_diff": int(diff.max()), "mirrored_differ": mirrored,
            "where": [tuple(map(int, p)) for p in np.argwhere(bad)][:12]}


# ---------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", action="append", choices=sorted(SCENES))
    ap.add_argument("--twins-only", action="store_true")
    ap.add_argument("--full", action="store_true", help="also 256×256 into target/gi-refs/")
    ap.add_argument("--no-refs", action="store_true", help="skip the 64×64 references")
    ap.add_argument("--spp", type=int, help="override each scene's spp (16 times a power of 2)")
    ap.add_argument("--check-normals", metavar="RTC_BINARY")
    args = ap.parse_args()
    names = args.scene or list(SCENES)
    scenes = {n: SCENES[n]() for n in names}

    for n, sc in scenes.items():
        path = os.path.join(ROOT, "scenes", "gi", n + ".rtc")
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(rtc_twin(n, sc))
        print(f"wrote {os.path.relpath(path, ROOT)}")
    if args.twins_only:
        return 0

    try:
        import mitsuba as mi
        import numpy as np
    except ImportError as e:
        print(f"skipped: mitsuba not installed ({e})")
        return 0
    mi.set_variant("llvm_ad_rgb" if "llvm_ad_rgb" in mi.variants() else "scalar_rgb")
    print(f"mitsuba {mi.__version__}, variant {mi.variant()}")

    status = 0
    if args.check_normals:
        for n, sc in scenes.items():
            r = check_normals(mi, np, n, sc, args.check_normals)
            print(f"normals {n}: {r['differ']} of {r['pixels']} pixels ({r['hits']} hit "
                  f"something in Mitsuba) differ by more than one level, {r['differ_any']} by "
                  f"any, at most {r['max_level_diff']} levels; a mirrored image would differ in "
                  f"{r['mirrored_differ']}, an upside-down one in {r['flipped_differ']}"
                  + (f"; first: {r['where']}" if r["where"] else ""))
            if r["differ"] > 0.05 * r["pixels"]:
                status = 1
        return status

    jobs = []
    if not args.no_refs:
        jobs += [(n, 64, os.path.join(ROOT, "tests", "data", "gi", f"{n}_64"))
                 for n in names]
    if args.full:
        jobs += [(n, 256, os.path.join(ROOT, "target", "gi-refs", f"{n}_256")) for n in names]
    for n, res, stem in jobs:
        sc = scenes[n]
        # 256×256 has 16 times the pixels: the same total number of samples, a quarter the spp
        # of 64×64 for the same time would be noisier; 1/16 keeps the time of the 64×64 one.
        spp = args.spp or (sc["spp"] if res == 64 else sc["spp"] // 16)
        mean, stderr, batches, wall, cpu = render_reference(mi, np, sc, res, spp)
        write_exr(mi, np, stem + ".exr", mean)
        write_exr(mi, np, stem + "_stderr.exr", stderr)
        s = noise_summary(np, mean, stderr)
        print(f"{n} {res}×{res}: {spp} spp ({batches} batches), Mitsuba {wall:.1f} s wall, "
              f"{cpu:.1f} s CPU; wrote {os.path.relpath(stem, ROOT)}.exr and _stderr.exr")
        print(f"  std error / value on {s['lit']} of {s['pixels']} lit pixels: luminance median "
              f"{100 * s['rel_lum_median']:.3f} %, p99 {100 * s['rel_lum_p99']:.3f} %, max "
              f"{100 * s['rel_lum_max']:.3f} %; worst channel p99 "
              f"{100 * s['rel_chan_p99']:.3f} %, max {100 * s['rel_chan_max']:.3f} %")
        print(f"  mean radiance {mean.mean(axis=(0, 1)).round(4).tolist()}")
    return status


if __name__ == "__main__":
    sys.exit(main())
