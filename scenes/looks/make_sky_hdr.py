#!/usr/bin/env python3
"""Writes docs/images/sky.hdr: a small procedural latitude-longitude sky (128 x 64, Radiance RGBE)
for docs/looks.md's environment-map pictures and the language reference's examples.

Made by this script for rtc (no photograph, no third-party data; same licence as the repository).
The picture is laid out as rtc's equirectangular camera and `render { sky: image(..) }` read it:
column u looks along longitude (u - 1/2)*360 deg from -Z towards +X, row v at latitude
(1/2 - v)*180 deg. Above the horizon a haze-to-blue gradient and a sun of radiance 40 (brighter
than 1: what an HDR picture is for, so `sky_strength` and reflections show it); below it a
dark ground with a faint horizon glow.

    python3 scenes/looks/make_sky_hdr.py     # rewrites docs/images/sky.hdr
"""
import math
import os

W, H = 128, 64
SUN = (math.radians(40.0), math.radians(25.0))  # longitude from -Z towards +X, latitude
SUN_RADIUS = math.radians(4.0)


def direction(lon, lat):
    return (math.cos(lat) * math.sin(lon), math.sin(lat), -math.cos(lat) * math.cos(lon))


def radiance(lon, lat):
    d = direction(lon, lat)
    s = direction(*SUN)
    cos_sun = max(-1.0, min(1.0, sum(a * b for a, b in zip(d, s))))
    if lat >= 0.0:
        t = math.sin(lat) ** 0.5
        haze, blue = (0.95, 0.9, 0.8), (0.15, 0.3, 0.75)
        c = [h + (b - h) * t for h, b in zip(haze, blue)]
        glow = 0.6 * math.exp((cos_sun - 1.0) * 12.0)
        c = [x + glow * y for x, y in zip(c, (1.0, 0.85, 0.6))]
        if math.acos(cos_sun) < SUN_RADIUS:
            c = [40.0, 36.0, 30.0]
        return c
    t = min(1.0, -lat / math.radians(20.0))
    ground, horizon = (0.12, 0.1, 0.08), (0.5, 0.45, 0.4)
    return [g + (h - g) * (1.0 - t) for g, h in zip(ground, horizon)]


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return bytes(4)
    e = math.frexp(m)[1]
    scale = 256.0 / 2.0 ** e
    return bytes([int(x * scale) for x in c] + [e + 128])


def main():
    out = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "images", "sky.hdr")
    with open(out, "wb") as f:
        f.write(b"#?RADIANCE\n# made by scenes/looks/make_sky_hdr.py (rtc)\nFORMAT=32-bit_rle_rgbe\n\n")
        f.write(f"-Y {H} +X {W}\n".encode())
        for j in range(H):
            lat = (0.5 - (j + 0.5) / H) * math.pi
            for i in range(W):
                lon = ((i + 0.5) / W - 0.5) * 2.0 * math.pi
                f.write(rgbe(radiance(lon, lat)))
    print(os.path.normpath(out))


if __name__ == "__main__":
    main()
