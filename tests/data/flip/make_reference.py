#!/usr/bin/env python3
"""Makes the ꟻLIP test pairs of tests/data/flip and their reference numbers (reference.tsv).

The numbers come from NVIDIA's own implementation, the `flip-evaluator` package on PyPI:

    python3 -m venv /tmp/flipvenv
    /tmp/flipvenv/bin/pip install flip-evaluator==1.7 numpy pillow
    /tmp/flipvenv/bin/python tests/data/flip/make_reference.py      # from the repository root

Images (all 8-bit sRGB PNG):
- zoom-4x4.png: a 256×192 crop at (400, 100) of the course reference
  scene01-zoom-ss-reflect-lights-shadows.png (4×4 supersampled);
  zoom-1x1.png: the same crop of rtc's render of that scene with `SuperSampling: factor: 1`
  (`rtc render zoom-1x1.yaml`, the course YAML with factor 4 changed to 1), kept as committed.
- scene02-crop.png: a 192×192 crop at (104, 104) of the course reference scene02.png;
  scene02-noise-A.png: that crop with noise of amplitude A added by this rule, per channel c of
  pixel (x, y) of a W-pixel-wide image:
      h = lowbias32(((y·W + x)·3 + c) XOR 0x9e3779b9)       (Wellons' 32-bit hash)
      v' = clamp(v + round(A · (2·h / 2^32 − 1)), 0, 255)
- Pairs of course references are used in place (two students' renders of one scene).
- zoom-1x1-vs-4x4-magma.png: flip-evaluator's magma picture of the zoom pair (×255, rounded).

Columns of reference.tsv: pair name, test image, reference image (paths from the repository
root), mean ꟻLIP (LDR, 67 pixels per degree), the mean of the worst 1% of the ꟻLIP map
(the ceil(1% of N) largest values), and the RMSE in linear light (both decoded with the sRGB
curve), computed here with numpy.
"""
import importlib.metadata
import math
import os
import sys

import numpy as np
from PIL import Image
import flip_evaluator as flip

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
HERE = "tests/data/flip"
COURSE = "tests/data/course/reference"


def lowbias32(x):
    x &= 0xFFFFFFFF
    x ^= x >> 16
    x = (x * 0x7FEB352D) & 0xFFFFFFFF
    x ^= x >> 15
    x = (x * 0x846CA68B) & 0xFFFFFFFF
    x ^= x >> 16
    return x


def load(rel):
    return np.asarray(Image.open(os.path.join(ROOT, rel)).convert("RGB"))


def save(rel, pixels):
    Image.fromarray(pixels.astype(np.uint8), "RGB").save(os.path.join(ROOT, rel), optimize=True)


def crop(pixels, x, y, w, h):
    return pixels[y:y + h, x:x + w, :]


def noisy(pixels, amplitude):
    h, w, _ = pixels.shape
    out = pixels.astype(np.int64).copy()
    for y in range(h):
        for x in range(w):
            for c in range(3):
                u = 2.0 * lowbias32(((y * w + x) * 3 + c) ^ 0x9E3779B9) / 2.0**32 - 1.0
                # Python's round() is half-to-even; floor(x + 0.5) is the rule stated above.
                out[y, x, c] += math.floor(amplitude * u + 0.5)
    return np.clip(out, 0, 255)


def srgb_to_linear(v):
    v = v.astype(np.float64) / 255.0
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def make_images():
    zoom_ref = load(f"{COURSE}/scene01-zoom-ss-reflect-lights-shadows.png")
    save(f"{HERE}/zoom-4x4.png", crop(zoom_ref, 400, 100, 256, 192))
    full_1x1 = os.path.join(ROOT, HERE, "zoom-1x1-full.png")
    if os.path.exists(full_1x1):  # rtc's 800×400 render, cropped once, then removed
        save(f"{HERE}/zoom-1x1.png", crop(load(f"{HERE}/zoom-1x1-full.png"), 400, 100, 256, 192))
        os.remove(full_1x1)
    scene02 = crop(load(f"{COURSE}/scene02.png"), 104, 104, 192, 192)
    save(f"{HERE}/scene02-crop.png", scene02)
    for amplitude in (4, 16, 48):
        save(f"{HERE}/scene02-noise-{amplitude}.png", noisy(scene02, amplitude))


PAIRS = [
    ("identical", f"{HERE}/scene02-crop.png", f"{HERE}/scene02-crop.png"),
    ("noise-4", f"{HERE}/scene02-noise-4.png", f"{HERE}/scene02-crop.png"),
    ("noise-16", f"{HERE}/scene02-noise-16.png", f"{HERE}/scene02-crop.png"),
    ("noise-48", f"{HERE}/scene02-noise-48.png", f"{HERE}/scene02-crop.png"),
    ("zoom-1x1-vs-4x4", f"{HERE}/zoom-1x1.png", f"{HERE}/zoom-4x4.png"),
    ("lights-shadows-ole", f"{COURSE}/scene01-lights-shadows__ole.png", f"{COURSE}/scene01-lights-shadows.png"),
    ("reflect-ole", f"{COURSE}/scene01-reflect-lights-shadows__ole.png", f"{COURSE}/scene01-reflect-lights-shadows.png"),
    ("zbuffer-ang-vs-blu", f"{COURSE}/scene01-zbuffer__ang.png", f"{COURSE}/scene01-zbuffer__blu.png"),
]


def main():
    make_images()
    lines = [
        f"# made by tests/data/flip/make_reference.py with flip-evaluator "
        f"{importlib.metadata.version('flip-evaluator')}, numpy {np.__version__}",
        "# pair\ttest\treference\tmean_flip\tworst_1pct_flip\trmse_linear",
    ]
    for name, test, ref in PAIRS:
        error_map, mean, _ = flip.evaluate(os.path.join(ROOT, ref), os.path.join(ROOT, test), "LDR",
                                           applyMagma=False)
        values = np.sort(np.asarray(error_map, dtype=np.float64).ravel())[::-1]
        count = max(1, math.ceil(0.01 * values.size))
        worst = values[:count].mean()
        rmse = math.sqrt(np.mean((srgb_to_linear(load(test)) - srgb_to_linear(load(ref))) ** 2))
        lines.append(f"{name}\t{test}\t{ref}\t{mean:.7f}\t{worst:.7f}\t{rmse:.7f}")
        if name == "zoom-1x1-vs-4x4":
            magma, _, _ = flip.evaluate(os.path.join(ROOT, ref), os.path.join(ROOT, test), "LDR")
            save(f"{HERE}/zoom-1x1-vs-4x4-magma.png", np.round(np.asarray(magma) * 255.0))
    with open(os.path.join(ROOT, HERE, "reference.tsv"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
