#!/usr/bin/env python3
# Joins hyperfine times (hf_SCENE.json), --stats ray counts (stats/) and image_error metrics into the tables.
"""Joins hyperfine times, --stats ray counts and image_error metrics into the study's tables."""
import json, re, subprocess, sys
scene = sys.argv[1]          # "sh" or "fi"
names = sys.argv[2].split(",")
base = sys.argv[3] if len(sys.argv) > 3 else "u4"
hf = {}
for r in json.load(open(f"hf_{scene}.json"))["results"]:
    n = r["command"].split()[2][len(scene) + 1:-4]
    hf[n] = (r["median"], r["user"])
def rays(n):
    t = open(f"stats/{scene}_{n}.txt").read()
    g = lambda k: int(re.search(r"(\d+) " + k, t).group(1))
    return g("rays ="), g("camera"), g("shadow"), g("refined")
out = subprocess.run(["./image_error", f"{scene}_u16.png"] + [f"{scene}_{n}.png" for n in names],
                     capture_output=True, text=True, check=True).stdout.splitlines()[1:]
m = {l.split("\t")[0][len(scene) + 1:]: [float(v) for v in l.split("\t")[1:]] for l in out}
b_rays = rays(base)[0]; b_user = hf.get(base, (0, 0))[1]
print("| setting | refined px | rays (M) | shadow / camera ray | CPU s (user) | CPU vs " + base + " | rays vs " + base + " | mean ꟻLIP | worst-1% ꟻLIP | RMSE | relMSE |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for n in names:
    r, c, s, ref = rays(n)
    med, user = hf.get(n, (float("nan"), float("nan")))
    f, fw, rmse, rel, sqw = m[n]
    print(f"| {n} | {ref} | {r/1e6:.2f} | {s/c:.1f} | {user:.2f} | {user/b_user:.0%} | {r/b_rays:.0%} | {f:.4f} | {fw:.3f} | {rmse:.5f} | {rel:.2e} |")
