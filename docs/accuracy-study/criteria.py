# Emulates refinement criteria on the 2x2 pass (sh_u2) with the 4x4 render (sh_u4) as refinement; masks from x2_u1_s0.png (640x360, 1 spp) for the within-pixel ones.
import numpy as np
from PIL import Image
B = lambda n: np.asarray(Image.open(n + ".png").convert("RGB")).astype(np.float64)
def lin_bytes(b):
    v = b / 255
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)
ref = lin_bytes(B("sh_u16"))
H, W = ref.shape[:2]; N = H * W
x2 = B("x2_u1_s0") / 255                                   # film values of 4 samples per pixel
samples = x2.reshape(H, 2, W, 2, 3).transpose(0, 2, 1, 3, 4).reshape(H, W, 4, 3)
coarse = B("sh_u2") / 255                                # the 2x2 pass: the real u2 render (its samples are Sobol-stratified; the 640 emulation is not)
fine = B("sh_u4") / 255                                     # the 4x4 refinement
u4_rmse = np.sqrt(((lin_bytes(B("sh_u4")) - ref) ** 2).mean())
def rmse_of(film):
    b = np.floor(np.clip(film, 0, 1) * 255)
    return np.sqrt(((lin_bytes(b) - ref) ** 2).mean()), b
def neighbour_contrast(img, t):
    d = lambda a, b: np.abs(a - b).max(axis=2) > t
    m = np.zeros((H, W), bool)
    m[:, 1:] |= d(img[:, 1:], img[:, :-1]); m[:, :-1] |= d(img[:, :-1], img[:, 1:])
    m[1:, :] |= d(img[1:], img[:-1]);       m[:-1, :] |= d(img[:-1], img[1:])
    return m
spread = (samples.max(axis=2) - samples.min(axis=2)).max(axis=2)
stderr = (samples.std(axis=2, ddof=1) / 2).max(axis=2)
lum = coarse @ np.array([0.2126, 0.7152, 0.0722])
rel_stderr = stderr / (lum + 0.05)
criteria = {
    "4-neighbour contrast (today)": lambda t: neighbour_contrast(coarse, t),
    "within-pixel spread": lambda t: spread > t,
    "std error of the pixel mean": lambda t: stderr > t,
    "relative std error (/(Y+0.05))": lambda t: rel_stderr > t,
}
taus = [0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.5]
best = {}
print(f"target: RMSE of uniform 4x4 = {u4_rmse:.5f}")
for name, crit in criteria.items():
    print(f"-- {name}")
    for t in taus:
        m = crit(t)
        comp = np.where(m[..., None], fine, coarse)
        r, b = rmse_of(comp)
        cost_discard = (4 * N + 16 * m.sum()) / (16 * N)
        cost_reuse = (4 * N + 12 * m.sum()) / (16 * N)
        ok = r <= u4_rmse
        print(f"   t={t:<6} refined {m.mean():6.1%}  RMSE {r:.5f} {'<= u4' if ok else '     '}  camera samples {cost_discard:6.1%} of u4 ({cost_reuse:6.1%} reusing the 4)")
        if ok:
            best[name] = (t, b, cost_discard)
    if name in best:
        t, b, c = best[name]
        Image.fromarray(b.astype(np.uint8)).save(f"emu_{name.split()[0]}_{t}.png")
