#!/usr/bin/env bash
# Parse benchmark of issue 11: 100 000 spheres written out literally, the same spheres made by a
# loop, and their POV-Ray twin (benches/literal_spheres.py writes all of them), in one hyperfine
# run each for `check` and for `render` (640×480, one light, shadows), plus the peak memory of a
# 100 000-point list literal.
#
#   benches/parse.sh            # RUNS=3 by default
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/bench-parse
python3 benches/literal_spheres.py "$out"
cargo build --release -q
rtc=$PWD/target/release/rtc
cd "$out"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
runs="${RUNS:-3}"
hyperfine -N -w 1 -r "$runs" --export-markdown check.md \
    "$rtc check spheres_literal.rtc" \
    "$rtc check spheres_loop.rtc"
hyperfine -N -w 1 -r "$runs" --export-markdown render.md \
    "$rtc render spheres_literal.rtc -o literal.png" \
    "$rtc render spheres_loop.rtc -o loop.png" \
    "povray -D +WT2 +W640 +H480 -GA +FN File_Gamma=1.0 +Ispheres_literal.pov +Opov.png"
for f in points_literal spheres_literal spheres_loop; do
    /usr/bin/time -f "$f: check %e s wall, %U s user, peak RSS %M KB" "$rtc" check "$f.rtc" 2>&1 >/dev/null | tail -1
done
cmp literal.png loop.png && echo "literal.png and loop.png are byte-identical"
