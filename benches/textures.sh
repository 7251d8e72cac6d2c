#!/usr/bin/env bash
# Procedural textures against POV-Ray (issue 36): the pattern-heavy scene
# scenes/bench/textures.rtc (50 objects: marble, granite, wood, crackle, a wrinkles bump; 6
# octaves of turbulence; 640×480, 2×2 supersampling, one light with shadows) against its POV-Ray
# twin benches/pov/textures.pov, both with 2 threads, in one run; and the same scene with plain
# colours (rtc `--set textured=false`, POV-Ray `Declare=Plain=1`), to state what the textures
# cost each renderer, and with the colour patterns but no bumps (rtc `--set bumps=false`,
# POV-Ray `Declare=NoBump=1`), to split that cost. Not a test: the machine is shared; the load
# average is printed.
#
#   benches/textures.sh [RUNS]     (default 5 runs of each of the four renders; needs povray)
#
# POV-Ray 3.7: povray -D +WT2 +W640 +H480 +A0.0 +AM1 +R2 -J +FN File_Gamma=sRGB
#   (anti-aliasing method 1 with threshold 0 supersamples every pixel on a regular 2×2 grid,
#   -J without jitter: shared/peers/README.md's convention; POV-Ray also traces the pixel
#   corners once, (W+1)(H+1) rays, before it supersamples).
# rtc: target/release/rtc render FILE -o OUT --threads 2 (the scene says supersampling: 2).
# With hyperfine installed it times the four commands (each RUNS times in a row); otherwise
# rounds alternate the four commands under /usr/bin/time and the figures are medians.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-5}"
command -v povray >/dev/null || { echo "textures.sh: povray is not installed; skipped"; exit 0; }
cargo build --release --locked --quiet
rtc=$PWD/target/release/rtc
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
scene=scenes/bench/textures.rtc
pov_scene=benches/pov/textures.pov
pov="povray -D +WT2 +W640 +H480 +A0.0 +AM1 +R2 -J +FN File_Gamma=sRGB +I$pov_scene"
declare -A CMD=(
    [rtc_textured]="$rtc render $scene -o $OUT/rtc_textured.png --threads 2"
    [rtc_plain]="$rtc render $scene --set textured=false -o $OUT/rtc_plain.png --threads 2"
    [pov_textured]="$pov +O$OUT/pov_textured.png"
    [pov_plain]="$pov Declare=Plain=1 +O$OUT/pov_plain.png"
    [rtc_nobump]="$rtc render $scene --set bumps=false -o $OUT/rtc_nobump.png --threads 2"
    [pov_nobump]="$pov Declare=NoBump=1 +O$OUT/pov_nobump.png"
)
names="rtc_textured pov_textured rtc_plain pov_plain rtc_nobump pov_nobump"
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores; $(povray --version 2>&1 | grep -o 'POV-Ray 3\.[0-9]*\.[0-9]*\.[0-9]*' | head -1); rtc at $(git rev-parse --short HEAD)$(git diff --quiet || echo '+changes')"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
: >"$OUT/times"
if command -v hyperfine >/dev/null; then
    args=()
    for n in $names; do args+=(--command-name "$n" "${CMD[$n]}"); done
    hyperfine --warmup 1 --runs "$RUNS" --export-json "$OUT/h.json" "${args[@]}" >/dev/null
    python3 - "$OUT/h.json" >"$OUT/times" <<'PY'
import json, sys
# hyperfine keeps each run's wall time but only the mean CPU time of a command.
for r in json.load(open(sys.argv[1]))["results"]:
    for t in r["times"]:
        print(r["command"], t, r["user"] + r["system"])
PY
else
    # One untimed round first (file caches, CPU frequency), then RUNS timed rounds.
    for n in $names; do ${CMD[$n]} >/dev/null 2>&1; done
    for _ in $(seq "$RUNS"); do
        for n in $names; do
            # shellcheck disable=SC2086
            t=$(/usr/bin/time -f "%e %U %S" ${CMD[$n]} 2>&1 >/dev/null | tail -1)
            echo "$n $t" | awk '{print $1, $2, $3 + $4}' >>"$OUT/times"
        done
    done
fi
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$OUT/times" "$RUNS" <<'PY'
import statistics as st, sys
wall, cpu = {}, {}
for line in open(sys.argv[1]):
    n, w, c = line.split()
    wall.setdefault(n, []).append(float(w))
    cpu.setdefault(n, []).append(float(c))
W = {n: st.median(v) for n, v in wall.items()}
C = {n: st.median(v) for n, v in cpu.items()}
rng = lambda n: f"{min(wall[n]):.2f}–{max(wall[n]):.2f}"
print(f"\nmedians of {sys.argv[2]} runs (wall: seconds, min–max; CPU: user + system seconds)\n")
print("| scene | rtc wall | rtc CPU | POV-Ray wall | POV-Ray CPU | POV-Ray ÷ rtc, wall | POV-Ray ÷ rtc, CPU |")
print("|---|---|---|---|---|---|---|")
for kind in ("textured", "nobump", "plain"):
    r, p = f"rtc_{kind}", f"pov_{kind}"
    print(f"| {kind} | {W[r]:.2f} ({rng(r)}) | {C[r]:.2f} | {W[p]:.2f} ({rng(p)}) | {C[p]:.2f} | "
          f"{W[p] / W[r]:.2f}× | {C[p] / C[r]:.2f}× |")
print()
print("| renderer | textured ÷ plain, wall | textured ÷ plain, CPU | textures cost (CPU) | of which colour patterns | of which bumps |")
print("|---|---|---|---|---|---|")
for who, name in (("rtc", "rtc"), ("pov", "POV-Ray")):
    t, p, nb = f"{who}_textured", f"{who}_plain", f"{who}_nobump"
    print(f"| {name} | {W[t] / W[p]:.2f}× | {C[t] / C[p]:.2f}× | +{C[t] - C[p]:.2f} s | "
          f"+{C[nb] - C[p]:.2f} s | +{C[t] - C[nb]:.2f} s |")
ratio = W["pov_textured"] / W["rtc_textured"]
print(f"\ntextured scene: POV-Ray wall ÷ rtc wall = {ratio:.2f} (goal ≥ 5: {'met' if ratio >= 5 else 'NOT met'})")
PY
