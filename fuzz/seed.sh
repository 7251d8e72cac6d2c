#!/usr/bin/env bash
# Builds the seed corpora of every fuzz target from files in the repo into fuzz/seeds/<target>/
# (not committed; the minimised corpora in fuzz/corpus/ are). Run from anywhere.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/.." && pwd)
out="$here/seeds"
rm -rf "$out"
mkdir -p "$out"/{rtc_eval,legacy_in,course_yaml,obj_mtl,texture}
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

# Images: tiny PNG, JPEG, HDR and EXR files of every colour type, and the course textures
# scaled down (needs Python 3 with Pillow).
python3 "$here/image_seeds.py" "$out/texture"
echo "seeds in $out: $(find "$out" -type f | wc -l) files"
