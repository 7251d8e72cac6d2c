# Compares the exact refined masks of the full and deterministic showcase and draws showcase-refined.png.
import numpy as np
from PIL import Image
M = lambda n: np.asarray(Image.open(n).convert("L")) > 0
full, det, nodof, noarea = M("mask.png"), M("mask-det.png"), M("mask-nodof.png"), M("mask-noarea.png")
print("full", full.sum(), "det", det.sum(), "full&det", (full&det).sum(), "full only", (full&~det).sum(), "det only", (det&~full).sum())
h = full.shape[0]
for y0 in range(0, h, 20):
    print(f"rows {y0:3d}-{y0+19:3d}: full {full[y0:y0+20].mean():.2f} det {det[y0:y0+20].mean():.2f} nodof {nodof[y0:y0+20].mean():.2f} noarea {noarea[y0:y0+20].mean():.2f}")
img = np.zeros(full.shape + (3,), np.uint8)
img[full & det] = (255, 90, 90)
img[full & ~det] = (90, 170, 255)
img[det & ~full] = (90, 255, 90)
Image.fromarray(img).resize((640, 360), Image.NEAREST).save("showcase-refined.png")
