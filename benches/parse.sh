#!/usr/bin/env bash
# Parse benchmark of issue 11: 100 000 spheres written out literally, the same spheres made by a
# loop, and their POV-Ray twins (benches/literal_spheres.py writes all of them): `rtc check` of
# both files, `rtc render` of both and POV-Ray's renders of the literal file and of its `#while`
# loop (issue 12's 100k row) (640×480, one light, shadows), in
# alternating rounds (benches/alternate.sh), plus the peak memory of a 100 000-point list literal.
#
#   benches/parse.sh            # RUNS=5 by default
set -euo pipefail
cd "$(dirname "$0")/.."
source benches/alternate.sh
out=target/bench-parse
python3 benches/literal_spheres.py "$out"
cargo build --release -q
rtc=$PWD/target/release/rtc
cd "$out"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
runs="${RUNS:-5}"
alternate "$runs" \
    "check-literal::$rtc check spheres_literal.rtc" \
    "check-loop::$rtc check spheres_loop.rtc" \
    "check-points::$rtc check points_literal.rtc"
cases=("render-literal::$rtc render spheres_literal.rtc -o literal.png"
    "render-loop::$rtc render spheres_loop.rtc -o loop.png")
if command -v povray >/dev/null; then
    pov="povray -D +WT2 +W640 +H480 -GA +FN File_Gamma=1.0"
    cases+=("povray-literal::$pov +Ispheres_literal.pov +Opov.png"
        "povray-while::$pov +Ispheres_loop.pov +Opov_loop.png")
else
    echo "povray not installed (../shared/peers/setup.sh installs it): its row is skipped"
fi
alternate "$runs" "${cases[@]}"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
cmp literal.png loop.png && echo "literal.png and loop.png are byte-identical"
