#!/usr/bin/env python3
"""Plots benches/scaling.sh's measurements as log-log SVG (no plotting library needed) and prints
a Markdown table. Usage: scaling_plot.py MEASURE_DIR OUT_DIR"""
import math
import os
import sys

src, dst = sys.argv[1], sys.argv[2]


def rows(name):
    out = []
    for line in open(os.path.join(src, name)):
        x, first, render, rss, rays = line.split()
        out.append((float(x), float(first), float(render), int(rss) / 1024, int(rays)))
    return out


def svg(path, title, xlabel, series, ylabel):
    """series: [(label, colour, [(x, y)], dashed)] on log-log axes."""
    W, H, L, R, T, B = 640, 400, 70, 150, 40, 50
    xs = [p[0] for s in series for p in s[2] if p[1] > 0]
    ys = [p[1] for s in series for p in s[2] if p[1] > 0]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
    if x1 == x0:
        x1 += 1
    if y1 == y0:
        y1 += 1
    px = lambda x: L + (math.log10(x) - x0) / (x1 - x0) * (W - L - R)
    py = lambda y: H - B - (math.log10(y) - y0) / (y1 - y0) * (H - T - B)
    o = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
         f'<rect width="{W}" height="{H}" fill="white"/>',
         f'<text x="{W / 2 - R / 2}" y="20" text-anchor="middle" font-size="14">{title}</text>']
    for e in range(x0, x1 + 1):
        o.append(f'<line x1="{px(10**e)}" y1="{T}" x2="{px(10**e)}" y2="{H - B}" stroke="#ddd"/>')
        o.append(f'<text x="{px(10**e)}" y="{H - B + 16}" text-anchor="middle">1e{e}</text>')
    for e in range(y0, y1 + 1):
        o.append(f'<line x1="{L}" y1="{py(10**e)}" x2="{W - R}" y2="{py(10**e)}" stroke="#ddd"/>')
        o.append(f'<text x="{L - 6}" y="{py(10**e) + 4}" text-anchor="end">1e{e}</text>')
    o.append(f'<text x="{(L + W - R) / 2}" y="{H - 12}" text-anchor="middle">{xlabel}</text>')
    o.append(f'<text x="16" y="{(T + H - B) / 2}" transform="rotate(-90 16 {(T + H - B) / 2})" text-anchor="middle">{ylabel}</text>')
    for i, (label, colour, pts, dashed) in enumerate(series):
        pts = [p for p in pts if p[1] > 0]
        d = " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in pts)
        dash = ' stroke-dasharray="5,4"' if dashed else ""
        o.append(f'<polyline points="{d}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>')
        if not dashed:
            o += [f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{colour}"/>' for x, y in pts]
        o.append(f'<line x1="{W - R + 10}" y1="{T + 10 + 18 * i}" x2="{W - R + 30}" y2="{T + 10 + 18 * i}" stroke="{colour}" stroke-width="2"{dash}/>')
        o.append(f'<text x="{W - R + 35}" y="{T + 14 + 18 * i}">{label}</text>')
    o.append("</svg>")
    open(path, "w").write("\n".join(o) + "\n")
    print(f"wrote {path}")


obj = rows("objects")
ns = lambda r: r[2] / r[4] * 1e9  # tracing nanoseconds per ray (CPU of all cores is not split out)
n0, r0 = obj[0][0], ns(obj[0])
logref = [(n, r0 * math.log(n) / math.log(n0)) for n, *_ in obj]
svg(os.path.join(dst, "scaling-objects.svg"), "Spheres: time and memory against count",
    "spheres", [("tracing ns/ray", "#1f77b4", [(r[0], ns(r)) for r in obj], False),
                ("∝ log N", "#1f77b4", logref, True),
                ("first ray ms", "#ff7f0e", [(r[0], r[1] * 1000) for r in obj], False),
                ("peak MiB", "#2ca02c", [(r[0], r[3]) for r in obj], False)],
    "ns per ray, ms, MiB")
res = rows("resolution")
p0, t0 = res[0][0], res[0][2]
svg(os.path.join(dst, "scaling-resolution.svg"), "10⁵ spheres: tracing time against pixels",
    "pixels", [("tracing s", "#1f77b4", [(r[0], r[2]) for r in res], False),
               ("∝ pixels", "#1f77b4", [(r[0], t0 * r[0] / p0) for r in res], True)],
    "seconds")
print()


def count_table(rows, what, unit, first):
    """Prints time and memory against the count of `what` (objects or triangles), with the
    ns/ray a log N growth from the first row predicts and the bytes each one above it adds."""
    n0, ns0, rss0 = rows[0][0], ns(rows[0]), rows[0][3]
    print(f"| {what} | first ray s | tracing s | rays | ns/ray | ns/ray ÷ log N prediction | peak MiB | B/{unit} above {first} |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        n, first, render, rss, rays = r
        pred = ns0 * math.log(n) / math.log(n0)
        per = f"{(rss - rss0) * 1048576 / (n - n0):.0f}" if n > n0 else "—"
        print(f"| {int(n)} | {first:.3f} | {render:.3f} | {rays} | {ns(r):.0f} | {ns(r) / pred:.2f} | {rss:.0f} | {per} |")


count_table(obj, "spheres", "sphere", "10³")
print()
print("| pixels | tracing s | per Mpixel s |")
print("|---|---|---|")
for p, first, render, rss, rays in res:
    print(f"| {int(p)} | {render:.3f} | {render / p * 1e6:.3f} |")

meshes_file = os.path.join(src, "meshes")
if os.path.exists(meshes_file) and os.path.getsize(meshes_file) > 0:
    mesh = rows("meshes")
    m0, q0 = mesh[0][0], ns(mesh[0])
    svg(os.path.join(dst, "scaling-meshes.svg"), "Meshes: time and memory against triangles",
        "triangles", [("tracing ns/ray", "#1f77b4", [(r[0], ns(r)) for r in mesh], False),
                      ("∝ log N", "#1f77b4", [(r[0], q0 * math.log(r[0]) / math.log(m0)) for r in mesh], True),
                      ("first ray ms", "#ff7f0e", [(r[0], r[1] * 1000) for r in mesh], False),
                      ("peak MiB", "#2ca02c", [(r[0], r[3]) for r in mesh], False)],
        "ns per ray, ms, MiB")
    print()
    count_table(mesh, "triangles", "triangle", "10⁴")
