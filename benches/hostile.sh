#!/usr/bin/env bash
# Issue 35's hostile inputs at full size, against the release binary: each case's exit code,
# wall time and peak RSS from /usr/bin/time -v (GNU time), one row per case. Nothing is
# asserted here (tests/hostile.rs holds the scaled-down regression tests); the numbers go into
# the issue's report. Every case runs under `timeout` so a regression shows as exit 124.
#
#   benches/hostile.sh [RTC [CASE...]]  # RTC defaults to target/release/rtc (built if missing);
#                                       # CASEs (numbers, e.g. `7 13`) run only those cases
#
# Needs about 1.2 GB of free space in $TMPDIR for the 10^8-face OBJ.
set -uo pipefail
cd "$(dirname "$0")/.."
rtc="${1:-target/release/rtc}"
[ -x "$rtc" ] || cargo build --release -q
rtc=$(realpath "$rtc")
benches=$(realpath benches)
shift || true
only=" $* "
want() { [ "$only" = "  " ] || [[ "$only" == *" $1 "* ]]; }
work=$(mktemp -d "${TMPDIR:-/tmp}/rtc-hostile.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
scene='rtc 1
camera { eye: [0, 0, 5], center: [0, 0, 0], up: Y, resolution: [8, 6] }
point_light { position: [5, 5, 5] }
sphere()'

printf '%-44s %5s %9s %12s\n' case exit seconds "peak RSS MiB"
run() { # run NAME TIMEOUT COMMAND...
    local name=$1 limit=$2
    shift 2
    /usr/bin/time -v -o time.txt timeout "$limit" "$@" >/dev/null 2>err.txt
    local code=$?
    local wall rss
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + t[i]; print s}' time.txt)
    rss=$(awk -F': ' '/Maximum resident/ {printf "%.0f", $2 / 1024}' time.txt)
    printf '%-44s %5s %9s %12s\n' "$name" "$code" "$wall" "$rss"
}
# `rtc watch` of SCENE (w.rtc) under /usr/bin/time while benches/watch_client.py MODE runs
# against it, then SIGTERM; the last column is what the client saw.
watch_case() { # watch_case NAME MODE [SCENE]
    /usr/bin/time -v -o time.txt "$rtc" watch "${3:-w.rtc}" --port 0 >/dev/null 2>watch.txt &
    local tpid=$! port="" pid seen code wall rss i
    for i in $(seq 100); do
        port=$(grep -o '127.0.0.1:[0-9]*' watch.txt | head -n 1 | cut -d: -f2)
        [ -n "$port" ] && break
        sleep 0.1
    done
    pid=$(ps -o pid= --ppid "$tpid" | tr -d ' ')
    seen=$(timeout 300 python3 "$benches/watch_client.py" "$2" "$port" "$pid" "$work/t.png")
    kill -TERM "$pid"
    wait "$tpid"
    code=$?
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + t[i]; print s}' time.txt)
    rss=$(awk -F': ' '/Maximum resident/ {printf "%.0f", $2 / 1024}' time.txt)
    printf '%-44s %5s %9s %12s  %s\n' "$1" "$code" "$wall" "$rss" "$seen"
}

if want 1; then
# 1. A module importing itself through two symlinked folders.
mkdir imports && (cd imports && ln -s . l1 && ln -s . l2 &&
    printf 'rtc 1\nimport "./l1/a.rtc" as x\nimport "./l2/a.rtc" as y\npub let v = 1\n' >a.rtc &&
    printf '%s\nimport "./a.rtc"\n' "$scene" >s.rtc)
run "1 symlinked imports: check" 60 "$rtc" check imports/s.rtc
fi

if want 2; then
# 2. Long chains.
python3 -c "print('rtc 1\nlet l = [1]\nlet y = l' + '[0]' * 300000)" >index.rtc
python3 -c "import sys; print(sys.argv[1] + '.translate(X)' * 20000)" "$scene" >translate.rtc
run "2 300,000 [0]: check" 60 "$rtc" check index.rtc
run "2 300,000 [0]: render" 60 "$rtc" render index.rtc -o index.png
run "2 20,000 .translate(X): fmt --check" 60 "$rtc" fmt --check translate.rtc
run "2 20,000 .translate(X): check" 60 "$rtc" check translate.rtc
fi

if want 3; then
# 3. Special files.
mkfifo fifo.rtc fifo.mtl
printf '%s\nimport "/dev/zero" as z\n' "$scene" >zero.rtc
printf 'mtllib fifo.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >m.obj
printf '%s\nmesh("m.obj", use_mtl: true)\n' "$scene" >mtl.rtc
run "3 import \"/dev/zero\": check" 60 "$rtc" check zero.rtc
run "3 a FIFO as the scene: check" 60 "$rtc" check fifo.rtc
run "3 a FIFO as mtllib: check" 60 "$rtc" check mtl.rtc
fi

if want 8; then
# 8. Garbage and bad lines.
python3 - <<'EOF'
import random
random.seed(1)
kw = ['Eye', 'Light', 'Sphere', 'Plane', 'Triangle', 'Material', 'Viewport', 'Background']
with open('garbage.in', 'w') as f:
    n = 0
    while n < 100_000_000:
        l = random.choice(kw) + ' ' + ' '.join(random.choice(['x', '1', '-', 'zz', '3.5']) for _ in range(random.randint(0, 8))) + '\n'
        f.write(l)
        n += len(l)
with open('bad.rtc', 'w') as f:
    f.write('rtc 1\n' + 'let = \n' * 500_000)
EOF
run "8 100 MB garbage .in: check" 120 "$rtc" check garbage.in
run "8 500,000 bad lines: check" 60 "$rtc" check bad.rtc
fi

if want 13; then
# 13. 10^8 faces (800 MB of OBJ).
{ printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n'; yes 'f 1 2 3' | head -n 100000000; } >big.obj
printf '%s\nmesh("big.obj")\n' "$scene" >big.rtc
run "13 10^8 faces: check" 120 "$rtc" check big.rtc
rm big.obj
fi

if want 15; then
# 15. A 266-byte-ish part that claims 2^32 - 1 rows.
python3 - <<'EOF'
import hashlib, json
payload = bytes(4 * 16 * 24)
h = {"scene": "s", "settings": "t", "width": 4, "height": 4294967295, "channels": ["color"],
     "encoding": "srgb", "shard": [0, 1], "rows": [[0, 16]], "stats": [0] * 6,
     "payload": hashlib.sha256(payload).hexdigest()}
open('p.rtcpart', 'wb').write(b'rtc-part 1\n' + json.dumps(h).encode() + b'\n' + payload)
EOF
run "15 part claiming 2^32-1 rows: merge" 60 "$rtc" merge p.rtcpart -o m.png
fi

if want 12; then
# 12. A scene whose output is outside its folder.
mkdir -p sub && printf '%s\nrender { output: "../victim.png" }\n' "$scene" >sub/s.rtc
run "12 output ../victim.png: render" 60 "$rtc" render sub/s.rtc
fi

if want 7; then
# 7. `rtc watch` against a 300 MiB URL, and against 3,000 connections that never finish their
# request (benches/watch_client.py).
printf '%s\n' "$scene" >w.rtc
watch_case "7 watch: a 300 MiB URL" url
watch_case "7 watch: 3,000 unfinished requests" idle
fi

if want 16; then
# 16. A long `rtc watch` session: a 1024×1024 texture (24 MiB decoded) rewritten 40 times, each
# save rendered to its final frame; the resident memory after the 10th and the 40th.
printf '%s\n' "$scene" | sed 's/^sphere()$/sphere().material(material { texture: image("t.png") })/' >tex.rtc
python3 - <<'EOF'
import struct, zlib
w = h = 1024
row = b"\x00" + bytes([40, 40, 40]) * w
def chunk(kind, data):
    c = struct.pack(">I", len(data)) + kind + data
    return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
body = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
body += chunk(b"IDAT", zlib.compress(row * h, 1)) + chunk(b"IEND", b"")
open("t.png", "wb").write(body)
EOF
watch_case "16 watch: a texture edited 40 times" texture tex.rtc
fi

if want 5; then
# 5. Super-linear work: identical faces in the mesh BVH build, a union grown by `reduce`, a
# formatter on a long `else if` chain, a long evaluation under `--time-limit`.
{ printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n'; yes 'f 1 2 3' | head -n 33334; } >same.obj
printf '%s\nmesh("same.obj")\n' "$scene" >same.rtc
run "5 33,334 identical faces: check" 120 "$rtc" check same.rtc
printf '%s\nlet b = for i in 0..20000 { sphere(center: [i * 0.01, 0, 0], radius: 0.1) }\nreduce(b, sphere(radius: 0.01), fn(a, x) a | x)\n' "$scene" >reduce.rtc
run "5 union of 20,000 by reduce: check" 120 "$rtc" check reduce.rtc
python3 -c "
print('rtc 1\nfn g(x: Int) -> Int {\n    if x == 0 { 0 }')
for i in range(1, 3000): print(f'    else if x == {i} {{ {i} }}')
print('    else { -1 }\n}\nlet y = g(5)')" >elif.rtc
run "5 3,000 else if: fmt --check" 120 "$rtc" fmt --check elif.rtc
printf '%s\nfor i in 0..49000000 { }\n' "$scene" >long.rtc
run "5 49M empty iterations: render --time-limit 1" 120 "$rtc" render long.rtc -o long.png --time-limit 1
python3 -c "
n = 1200
print('\n'.join(f'v {i} {j} {(i * j) % 7}' for i in range(n) for j in range(n)))
print('\n'.join(f'f {i*n+j+1} {i*n+j+2} {(i+1)*n+j+1}\nf {i*n+j+2} {(i+1)*n+j+2} {(i+1)*n+j+1}' for i in range(n - 1) for j in range(n - 1)))" >grid.obj
printf '%s\nmesh("grid.obj")\n' "$scene" >gridmesh.rtc
run "5 2.9M-triangle mesh: render --time-limit 1" 120 "$rtc" render gridmesh.rtc -o gridmesh.png --time-limit 1
rm grid.obj
fi

if want 4; then
# 4 (and issue 34). Memory: four 8192² PNGs, a YAML alias tree over a 1 MB leaf, 2,000 copies of
# a 4 MB string, an `iterate` that never ends, a grid of 25M spheres (default budget of 4 GiB).
python3 - <<'EOF2'
import struct, zlib
def chunk(kind, data):
    return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))
w = h = 8192
row = b'\x00' + b'\x80\x40\x20' * w
raw = zlib.compress(row * h, 9)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) + chunk(b'IDAT', raw) + chunk(b'IEND', b'')
for name in 'abcd':
    open(f'{name}.png', 'wb').write(png)
leaf = 'x' * 1_000_000
lines = [f'a0: &a0 "{leaf}"']
for k in range(1, 12):
    lines.append(f'a{k}: &a{k} [*a{k-1}, *a{k-1}, *a{k-1}, *a{k-1}]')
open('bomb.yaml', 'w').write('\n'.join(lines) + '\n')
EOF2
{ printf '%s\n' "$scene"; for t in a b c d; do printf 'sphere().material(material { texture: image("%s.png") })\n' $t; done; } >pngs.rtc
run "4 four 8192x8192 PNGs: check" 120 "$rtc" check pngs.rtc
run "4 YAML aliases over a 1 MB leaf: check" 120 "$rtc" check bomb.yaml
printf '%s\nfn grow(s: String, n: Int) -> String { if n == 0 { s } else { grow(s + s, n - 1) } }\nlet big = grow("0123456789abcdef", 18)\nlet all = for i in 0..2000 { big + str(i) }\n' "$scene" >strings.rtc
run "4 2,000 x (4 MB string + str(i)): check" 120 "$rtc" check strings.rtc
printf 'rtc 1\nlet x = iterate(0, fn(i) i + 1, fn(i) true)\n' >iterate.rtc
run "34 iterate that never ends: check" 120 "$rtc" check iterate.rtc
run "34 ... under --memory-budget 128MiB" 120 "$rtc" check iterate.rtc --memory-budget 128MiB
printf '%s\nfor i in 0..5000 { for j in 0..5000 { sphere(center: [i, j, 0], radius: 0.1) } }\n' "$scene" >grid.rtc
run "34 grid of 25M spheres: check" 120 "$rtc" check grid.rtc
run "34 ... under --memory-budget 512MiB" 120 "$rtc" check grid.rtc --memory-budget 512MiB
fi
