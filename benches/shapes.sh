#!/usr/bin/env bash
# The shapes of issue 38 against POV-Ray: scenes/bench/shapes.rtc (text, prisms, a cubic lathe,
# two superellipsoids, a sor, a B-spline sphere sweep, a height field and an isosurface, one
# light with shadows on a floor) against its twin benches/pov/shapes.pov, 640×480 with 2×2
# supersampling, both with 2 threads, in one run; then each shape alone over the floor, so the
# table says what each shape costs each renderer (its time minus the floor-only scene's).
# Not a test: the machine is shared; the load average is printed.
#
#   benches/shapes.sh [RUNS]     (default 3 rounds; needs povray, else it says so and stops)
#
# POV-Ray 3.7: povray -D +WT2 +W640 +H480 +A0.0 +AM1 +R2 -J +FN File_Gamma=sRGB (every pixel
#   supersampled on a regular 2×2 grid, shared/peers/README.md's convention).
# rtc: target/release/rtc render FILE -o OUT --threads 2 (the scene says supersampling: 2).
# Each command runs RUNS times in alternating rounds under /usr/bin/time; figures are medians.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-3}"
command -v povray >/dev/null || { echo "shapes.sh: povray is not installed; skipped"; exit 0; }
cargo build --release --locked --quiet
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores; $(povray --version 2>&1 | grep -o 'POV-Ray 3\.[0-9]*\.[0-9]*\.[0-9]*' | head -1); rtc at $(git rev-parse --short HEAD)$(git diff --quiet || echo '+changes')"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 benches/shapes_split.py scenes/bench/shapes.rtc benches/pov/shapes.pov "$OUT"
rtc=$PWD/target/release/rtc
pov="povray -D +WT2 +W640 +H480 +A0.0 +AM1 +R2 -J +FN File_Gamma=sRGB"
: >"$OUT/times"
names=$(cat "$OUT/names")
run() { # name renderer
    local n=$1 who=$2
    if [ "$who" = rtc ]; then
        /usr/bin/time -f "%e" "$rtc" render "$OUT/$n.rtc" -o "$OUT/$n.rtc.png" --threads 2 2>&1 >/dev/null | tail -1
    else
        # shellcheck disable=SC2086
        (cd "$OUT" && /usr/bin/time -f "%e" $pov +I"$n.pov" +O"$n.pov.png" 2>&1 >/dev/null | tail -1)
    fi
}
for n in $names; do run "$n" rtc >/dev/null; run "$n" pov >/dev/null; done  # untimed round
for _ in $(seq "$RUNS"); do
    for n in $names; do
        echo "$n rtc $(run "$n" rtc)" >>"$OUT/times"
        echo "$n pov $(run "$n" pov)" >>"$OUT/times"
    done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$OUT/times" "$RUNS" <<'PY'
import statistics as st, sys
t = {}
for line in open(sys.argv[1]):
    n, who, w = line.split()
    t.setdefault((n, who), []).append(float(w))
W = {k: st.median(v) for k, v in t.items()}
names = list(dict.fromkeys(n for n, _ in t))
print(f"\nmedian wall seconds of {sys.argv[2]} runs, 640x480, 2x2 supersampling, 2 threads\n")
print("| scene | rtc | POV-Ray | POV-Ray ÷ rtc | rtc, shape only | POV-Ray, shape only | ÷, shape only |")
print("|---|---|---|---|---|---|---|")
fr, fp = W[("floor", "rtc")], W[("floor", "pov")]
for n in names:
    r, p = W[(n, "rtc")], W[(n, "pov")]
    extra = ""
    if n not in ("all", "floor"):
        dr, dp = max(r - fr, 1e-3), max(p - fp, 1e-3)
        extra = f"{dr:.3f} | {dp:.3f} | {dp / dr:.1f}×"
    else:
        extra = " | | "
    print(f"| {n} | {r:.3f} | {p:.3f} | {p / r:.2f}× | {extra} |")
ratio = W[("all", "pov")] / W[("all", "rtc")]
print(f"\nwhole scene: POV-Ray wall ÷ rtc wall = {ratio:.2f} (goal ≥ 5: {'met' if ratio >= 5 else 'NOT met'})")
PY
