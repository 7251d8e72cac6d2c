# Splits each setting's squared error (vs sh_u16) by the exact refined mask (mask.png, mask-det.png from refine_probe).
import numpy as np
from PIL import Image
def lin(n):
    v = np.asarray(Image.open(n + ".png").convert("RGB")).astype(np.float64) / 255
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)
M = lambda n: np.asarray(Image.open(n).convert("L")) > 0
ref = lin("sh_u16")
mask = M("mask.png"); det = M("mask-det.png")
N = mask.size
def sq(n): return ((lin(n) - ref) ** 2).mean(axis=2)
for n in ["sh_u1", "sh_u2", "sh_u4", "sh_a1-4-0.02", "sh_a2-4-0.02", "sh_a1-8-0.02", "sh_u8"]:
    e = sq(n)
    tot = e.sum()
    print(f"{n:14s} RMSE {np.sqrt(e.mean()):.5f}  share of MSE in refined-mask pixels {e[mask].sum()/tot:.2f}, "
          f"unrefined {e[~mask].sum()/tot:.2f}; noise-only-refined {e[mask & ~det].sum()/tot:.2f}")
# how useful is each refinement? u1 error in refined pixels vs the u4 error level
e1, e4 = sq("sh_u1"), sq("sh_u4")
print("refined pixels whose 1x1 error is already below the mean 4x4 error:", ((e1 <= e4.mean()) & mask).sum(), "of", mask.sum())
print("unrefined pixels whose 1x1 error exceeds the mean 4x4 error:", ((e1 > e4.mean()) & ~mask).sum(), "of", (~mask).sum())
# horizon band
for y0, y1 in [(0, 20), (20, 60), (60, 100), (100, 180)]:
    sl = slice(y0, y1)
    print(f"rows {y0}-{y1}: u4 MSE share {e4[sl].sum()/e4.sum():.2f}, a1-4 MSE share {sq('sh_a1-4-0.02')[sl].sum()/sq('sh_a1-4-0.02').sum():.2f}")
print("--- mean squared error inside the refined mask / outside")
for n in ["sh_u1", "sh_u4", "sh_u4_s1", "sh_a1-4-0.02", "sh_a1-4-0.02_s1", "sh_a2-4-0.02"]:
    e = sq(n)
    print(f"{n:16s} in mask {e[mask].mean():.3e}  outside {e[~mask].mean():.3e}")
