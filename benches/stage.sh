#!/usr/bin/env bash
# Fog + spot light + Fresnel glass against POV-Ray (issue 37): scenes/bench/stage.rtc against
# its POV-Ray twin benches/pov/stage.pov, both with 2 threads, in one run; and each renderer
# with each feature taken away (rtc `--set fogged=false` / `spot=false` / `fresnel=false`,
# POV-Ray `Declare=NoFog=1` / `NoSpot=1` / `NoFresnel=1`), to state what fog, a spot light and
# Fresnel cost each of them. Not a test: the machine is shared; the load average is printed.
#
#   benches/stage.sh [RUNS]     (default 5 rounds; needs povray, skips with a message without)
#
# POV-Ray 3.7: povray -D +WT2 +W640 +H480 +A0.0 +AM1 +R2 -J +FN File_Gamma=sRGB (every pixel
# supersampled on a regular 2×2 grid, as rtc's `supersampling: 2`; shared/peers/README.md).
# rtc: target/release/rtc render FILE -o OUT --threads 2. Rounds alternate the commands under
# /usr/bin/time (one untimed round first); the figures are medians.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS="${1:-5}"
command -v povray >/dev/null || { echo "stage.sh: povray is not installed; skipped"; exit 0; }
cargo build --release --locked --quiet
rtc=$PWD/target/release/rtc
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
scene=scenes/bench/stage.rtc
pov="povray -D +WT2 +W640 +H480 +A0.0 +AM1 +R2 -J +FN File_Gamma=sRGB +Ibenches/pov/stage.pov"
declare -A CMD=(
    [rtc_all]="$rtc render $scene -o $OUT/rtc_all.png --threads 2"
    [rtc_nofog]="$rtc render $scene --set fogged=false -o $OUT/rtc_nofog.png --threads 2"
    [rtc_nospot]="$rtc render $scene --set spot=false -o $OUT/rtc_nospot.png --threads 2"
    [rtc_nofresnel]="$rtc render $scene --set fresnel=false -o $OUT/rtc_nofresnel.png --threads 2"
    [pov_all]="$pov +O$OUT/pov_all.png"
    [pov_nofog]="$pov Declare=NoFog=1 +O$OUT/pov_nofog.png"
    [pov_nospot]="$pov Declare=NoSpot=1 +O$OUT/pov_nospot.png"
    [pov_nofresnel]="$pov Declare=NoFresnel=1 +O$OUT/pov_nofresnel.png"
)
names="rtc_all pov_all rtc_nofog pov_nofog rtc_nospot pov_nospot rtc_nofresnel pov_nofresnel"
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores; $(povray --version 2>&1 | grep -o 'POV-Ray 3\.[0-9]*\.[0-9]*\.[0-9]*' | head -1); rtc at $(git rev-parse --short HEAD)$(git diff --quiet || echo '+changes')"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for n in $names; do ${CMD[$n]} >/dev/null 2>&1; done
: >"$OUT/times"
for _ in $(seq "$RUNS"); do
    for n in $names; do
        # shellcheck disable=SC2086
        t=$(/usr/bin/time -f "%e %U %S" ${CMD[$n]} 2>&1 >/dev/null | tail -1)
        echo "$n $t" | awk '{print $1, $2, $3 + $4}' >>"$OUT/times"
    done
done
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
print(f"\nmedians of {sys.argv[2]} rounds (seconds; CPU = user + system)\n")
print("| variant | rtc wall | rtc CPU | POV-Ray wall | POV-Ray CPU | POV-Ray ÷ rtc, wall | POV-Ray ÷ rtc, CPU |")
print("|---|---|---|---|---|---|---|")
for kind, label in (("all", "fog + spot + Fresnel"), ("nofog", "without fog"),
                    ("nospot", "point light, not spot"), ("nofresnel", "without Fresnel")):
    r, p = f"rtc_{kind}", f"pov_{kind}"
    print(f"| {label} | {W[r]:.2f} | {C[r]:.2f} | {W[p]:.2f} | {C[p]:.2f} | "
          f"{W[p] / W[r]:.2f}× | {C[p] / C[r]:.2f}× |")
print()
print("| renderer | fog costs (CPU) | spot costs (CPU) | Fresnel costs (CPU) |")
print("|---|---|---|---|")
for who, name in (("rtc", "rtc"), ("pov", "POV-Ray")):
    a = C[f"{who}_all"]
    print(f"| {name} | {a - C[f'{who}_nofog']:+.2f} s | {a - C[f'{who}_nospot']:+.2f} s | "
          f"{a - C[f'{who}_nofresnel']:+.2f} s |")
ratio = W["pov_all"] / W["rtc_all"]
print(f"\nfog + spot + Fresnel: POV-Ray wall ÷ rtc wall = {ratio:.2f} (goal ≥ 5: {'met' if ratio >= 5 else 'NOT met'})")
PY
