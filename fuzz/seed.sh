#!/usr/bin/env bash
# Builds the seed corpora of every fuzz target from files in the repo into fuzz/seeds/<target>/
# (not committed; the minimised corpora in fuzz/corpus/ are). Run from anywhere.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
out="$here/seeds"
rm -rf "$out"
mkdir -p "$out"/{rtc_eval,legacy_in,course_yaml,obj_mtl,mesh_formats,texture}
cd "$repo"

# .rtc: the diagnostics corpus, language tests, example and course scenes, the standard library,
# and every ```rtc block of docs/language.md.
for f in tests/diagnostics/*.rtc tests/lang/*.rtc scenes/*.rtc scenes/course/*.rtc scenes/bench/*.rtc stdlib/*.rtc; do
  cp "$f" "$out/rtc_eval/$(echo "$f" | tr '/' '_')"
done
awk -v dir="$out/rtc_eval" '
  /^```rtc/ { n++; file = sprintf("%s/docs_language_%03d.rtc", dir, n); inside = 1; next }
  /^```/ { inside = 0; next }
  inside { print > file }
' docs/language.md

# .in and YAML: the compat diagnostics corpus and the course scenes.
for f in tests/compat/*.in tests/data/course/in/*.in; do
  cp "$f" "$out/legacy_in/$(echo "$f" | tr '/' '_')"
done
find tests/compat tests/data/course/yaml scenes -name '*.yaml' | while read -r f; do
  cp "$f" "$out/course_yaml/$(echo "$f" | tr '/' '_')"
done

# OBJ + MTL: flag byte (bit 0 smooth, bit 1 use the MTL), the OBJ with its `mtllib` renamed to
# m.mtl, NUL, the MTL. Large models are cut to their first 16 KiB at a line end.
for f in tests/data/course/models/*.obj; do
  base=$(basename "$f" .obj)
  mtl="tests/data/course/models/$base.mtl"
  for flags in 0 3; do
    {
      printf "\\x0$flags"
      if [ "$(wc -c < "$f")" -le 16384 ]; then cat "$f"; else head -c 16384 "$f" | sed '$d'; fi |
        sed 's/^mtllib .*/mtllib m.mtl/'
      if [ -f "$mtl" ]; then printf '\0'; cat "$mtl"; fi
    } > "$out/obj_mtl/${base}_$flags"
  done
done

# STL and PLY: flag byte (bit 0 smooth, bit 1 PLY), then the file: the small course models
# written as ASCII and binary STL and as ASCII, little- and big-endian PLY (with uvs where the
# model has them, and vertex colours), cut to 64 KiB.
python3 - "$out/mesh_formats" tests/data/course/models/{cube,tetrahedron,dolphins}.obj <<'PY'
import struct, sys
out = sys.argv[1]
for path in sys.argv[2:]:
    name = path.rsplit("/", 1)[1][:-4]
    v, faces = [], []
    for line in open(path):
        w = line.split()
        if w[:1] == ["v"]:
            v.append([float(x) for x in w[1:4]])
        elif w[:1] == ["f"]:
            faces.append([int(c.split("/")[0]) - 1 for c in w[1:]])
    tris = [(f[0], f[k], f[k + 1]) for f in faces for k in range(1, len(f) - 1)]
    ascii_stl = "solid %s\n" % name + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join("vertex %r %r %r\n" % tuple(v[i]) for i in t) + "endloop\nendfacet\n"
        for t in tris) + "endsolid %s\n" % name
    binary_stl = b"\0" * 80 + struct.pack("<I", len(tris)) + b"".join(
        struct.pack("<12fH", 0, 0, 0, *[c for i in t for c in v[i]], 0) for t in tris)
    def ply(fmt, e):
        head = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face %d\n"
                "property list uchar int vertex_indices\nend_header\n" % (fmt, len(v), len(faces))).encode()
        if fmt == "ascii":
            return head + "".join("%r %r %r 200 100 50\n" % tuple(p) for p in v).encode() + "".join(
                "%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces).encode()
        return head + b"".join(struct.pack(e + "3f3B", *p, 200, 100, 50) for p in v) + b"".join(
            struct.pack(e + "B%di" % len(f), len(f), *f) for f in faces)
    files = {"stl_ascii": (0, ascii_stl.encode()), "stl_binary": (1, binary_stl),
             "ply_ascii": (2, ply("ascii", "<")), "ply_le": (3, ply("binary_little_endian", "<")),
             "ply_be": (2, ply("binary_big_endian", ">"))}
    for kind, (flag, data) in files.items():
        with open("%s/%s_%s" % (out, name, kind), "wb") as f:
            f.write(bytes([flag]) + data[:65536])
PY

# glTF: flag byte (bit 2 GLB, bit 3 glTF JSON, bit 4 use_mtl), then the file: a quad with
# texture coordinates, COLOR_0 (normalised bytes) and a 2×2 PNG base colour texture, the image
# in a buffer view of the GLB's binary chunk or as a data: URI.
python3 - "$out/mesh_formats" <<'PY'
import base64, json, struct, sys, zlib
out = sys.argv[1]
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
raw = b"".join(b"\0" + bytes(c for x in range(2) for c in (120 * x, 120 * y, 200)) for y in range(2))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
       + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
pos = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
uv = [(0, 1), (1, 1), (1, 0), (0, 0)]
col = [(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 255, 255)]
bin_ = (b"".join(struct.pack("<3f", *p) for p in pos) + b"".join(struct.pack("<2f", *t) for t in uv)
        + b"".join(bytes(c) for c in col) + struct.pack("<6H", 0, 1, 2, 0, 2, 3))
image_at = len(bin_)
def doc(buffer, image, length):
    return {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "COLOR_0": 2},
                                        "indices": 3, "material": 0}]}],
            "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
            "textures": [{"source": 0}], "images": [image], "buffers": [buffer],
            "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n}
                            for o, n in [(0, 48), (48, 32), (80, 16), (96, 12), (image_at, length)]],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                           "min": [-1, -1, 0], "max": [1, 1, 0]},
                          {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                          {"bufferView": 2, "componentType": 5121, "normalized": True, "count": 4, "type": "VEC4"},
                          {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
def pad(b, fill):
    return b + fill * (-len(b) % 4)
glb_bin = pad(bin_ + png, b"\0")
j = pad(json.dumps(doc({"byteLength": len(glb_bin)}, {"bufferView": 4, "mimeType": "image/png"}, len(png))).encode(), b" ")
glb = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(j) + 8 + len(glb_bin)) + struct.pack("<I", len(j)) + b"JSON" + j \
    + struct.pack("<I", len(glb_bin)) + b"BIN\0" + glb_bin
uri = lambda mime, b: "data:%s;base64,%s" % (mime, base64.b64encode(b).decode())
gltf = json.dumps(doc({"byteLength": len(bin_), "uri": uri("application/octet-stream", bin_)},
                      {"uri": uri("image/png", png)}, 1)).encode()
for name, flag, data in [("quad_glb", 4, glb), ("quad_glb_mtl", 4 | 16, glb),
                         ("quad_gltf", 8, gltf), ("quad_gltf_mtl_smooth", 8 | 16 | 1, gltf)]:
    with open("%s/%s" % (out, name), "wb") as f:
        f.write(bytes([flag]) + data)
PY

# The hostile probe's shapes of input (issue 35), cut to the fuzzers' input sizes: brackets
# nested past the budget, long postfix chains, a long `else if` chain, a union grown by
# `reduce`, a YAML alias tree, an OBJ repeating one face. (Symlinked folders and special files
# are not fuzzable: tests/hostile.rs tests them directly.)
python3 - "$out" <<'PY'
import sys
out = sys.argv[1]
def put(target, name, text):
    with open(f"{out}/{target}/hostile_{name}", "w") as f:
        f.write(text)
put("rtc_eval", "parens.rtc", "rtc 1\nlet a = " + "(" * 260 + "1" + ")" * 260 + "\n")
put("rtc_eval", "index_chain.rtc", "rtc 1\nlet l = [1]\nlet y = l" + "[0]" * 2000 + "\n")
put("rtc_eval", "translate_chain.rtc", "rtc 1\nsphere()" + ".translate(X)" * 500 + "\n")
put("rtc_eval", "else_if.rtc", "rtc 1\nfn g(x: Int) -> Int {\n    if x == 0 { 0 }\n"
    + "".join(f"    else if x == {i} {{ {i} }}\n" for i in range(1, 200)) + "    else { -1 }\n}\nlet y = g(5)\n")
put("rtc_eval", "reduce_union.rtc", "rtc 1\nlet b = for i in 0..500 { sphere(center: [i, 0, 0]) }\n"
    "reduce(b, sphere(), fn(a, x) a | x)\n")
put("rtc_eval", "doubling.rtc", "rtc 1\nfn f(n: Int) -> Int { if n == 0 { 1 } else { f(n - 1) + f(n - 1) } }\nlet x = f(40)\n")
yaml = 'a0: &a0 "' + "x" * 1000 + '"\n' + "".join(
    f"a{k}: &a{k} [*a{k-1}, *a{k-1}, *a{k-1}, *a{k-1}]\n" for k in range(1, 12))
put("course_yaml", "aliases.yaml", yaml)
with open(f"{out}/obj_mtl/hostile_same_face", "w") as f:
    f.write("\x00v 0 0 0\nv 1 0 0\nv 0 1 0\n" + "f 1 2 3\n" * 3000)
PY

# Images: tiny PNG, JPEG, HDR and EXR files of every colour type, and the course textures
# scaled down (needs Python 3 with Pillow).
python3 "$here/image_seeds.py" "$out/texture"
echo "seeds in $out: $(find "$out" -type f | wc -l) files"
