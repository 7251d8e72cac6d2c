# The oracle bound: refine the pixels with the largest error gain first until the MSE of uniform 4x4 is reached.
import numpy as np
from PIL import Image
def lin(n):
    v = np.asarray(Image.open(n + ".png").convert("RGB")).astype(np.float64) / 255
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)
ref = lin("sh_u16")
sq = lambda n: ((lin(n) - ref) ** 2).mean(axis=2).ravel()
N = ref.shape[0] * ref.shape[1]
target = sq("sh_u4").mean()
print(f"u4 MSE {target:.3e} RMSE {np.sqrt(target):.5f}")
def oracle(lo, lo_spp, hi, hi_spp, name):
    el, eh = sq(lo), sq(hi)
    gain = el - eh
    order = np.argsort(-gain)
    mse = el.sum() - np.cumsum(gain[order])  # refine the k+1 best pixels
    k = np.argmax(mse / N <= target)
    if mse[k] / N > target:
        print(f"{name}: never reaches u4"); return
    cost = (N * lo_spp + (k + 1) * hi_spp) / (16 * N)
    print(f"{name}: refine {k+1} pixels ({(k+1)/N:.1%}) -> cost {cost:.1%} of u4 camera samples")
oracle("sh_u1", 1, "sh_u4", 16, "oracle 1 -> 4x4")
oracle("sh_u1", 1, "sh_u8", 64, "oracle 1 -> 8x8")
oracle("sh_u2", 4, "sh_u4", 16, "oracle 2x2 -> 4x4")
oracle("sh_u2", 4, "sh_u8", 64, "oracle 2x2 -> 8x8")
oracle("sh_u1", 1, "sh_u16_s1", 256, "oracle 1 -> 16x16")
