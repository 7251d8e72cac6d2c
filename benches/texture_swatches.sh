#!/usr/bin/env bash
# Renders the swatches of docs/textures.md into docs/images/textures/: one small picture per
# pattern and per modifier, each a flat-lit floor seen from above (pixel colour = texture colour),
# the pattern's x–z plane filling the square [-2, 2]². Patterns that live in the x–y plane (the
# spirals, wood's rings, agate's bands) are turned onto the floor with `.rotate(x: 90deg)`.
# Usage: benches/texture_swatches.sh [RTC_BINARY]   (default target/release/rtc, built if missing)
set -euo pipefail
cd "$(dirname "$0")/.."
rtc=${1:-target/release/rtc}
[ -x "$rtc" ] || cargo build --release --locked -q
out=docs/images/textures
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The two colours most swatches read their value through: dark blue-grey to warm white.
map='[[0, rgb(0.05, 0.07, 0.12)], [1, rgb(0.95, 0.9, 0.8)]]'
tiles='[rgb(0.8, 0.2, 0.15), rgb(0.95, 0.85, 0.3), rgb(0.2, 0.45, 0.8), rgb(0.25, 0.65, 0.3), rgb(0.6, 0.3, 0.7), rgb(0.9, 0.9, 0.9)]'

swatch() { # name texture-expression
  cat >"$tmp/$1.rtc" <<SCENE
rtc 1.1
camera { eye: [0, 1000, 0], center: [0, 0, 0], up: -Z, fov: 2 * atan(2 / 1000), resolution: [96, 96] }
point_light { position: [0, 1000, 0] }
plane(point: [0, 0, 0], normal: Y).material(material { texture: $2, ka: 1, kd: 0, ks: 0 })
render { shadows: false, max_depth: 0, supersampling: 3 }
SCENE
  "$rtc" render "$tmp/$1.rtc" -o "$out/$1.png" >/dev/null
}

# Patterns.
swatch gradient "gradient(axis: [1, 0, 1]).colors($map).scale(2)"
swatch checker "checker().colors([rgb(0.9, 0.9, 0.85), rgb(0.1, 0.1, 0.15)]).scale(0.5)"
swatch hexagon "hexagon().colors($tiles).scale(0.5)"
swatch brick "brick(size: [1, 0.5, 0.5], mortar: 0.06).colors([rgb(0.8, 0.78, 0.72), rgb(0.6, 0.22, 0.15)]).translate([0, 0.25, 0])"
swatch radial "radial().colors($map)"
swatch onion "onion().colors($map).scale(0.8)"
swatch spherical_falloff "spherical_falloff().colors($map).scale(1.9)"
swatch cylindrical_falloff "cylindrical_falloff().colors($map).rotate(x: 90deg).scale(1.9)"
swatch boxed "boxed().colors($map).scale(1.9)"
swatch planar_falloff "planar_falloff().colors($map).rotate(z: 90deg).scale(1.9)"
swatch square "square().colors($tiles).scale(0.5)"
swatch triangular "triangular().colors($tiles).scale(0.8)"
swatch spiral1 "spiral1(arms: 3).colors($map).rotate(x: 90deg)"
swatch spiral2 "spiral2(arms: 3).colors($map).rotate(x: 90deg)"
swatch agate "agate().colors($map).rotate(x: 90deg)"
swatch bozo "bozo().colors($map).scale(0.5)"
swatch granite "granite().colors($map).scale(2)"
swatch marble "marble().turbulence(0.8).colors([[0, rgb(0.92, 0.9, 0.86)], [0.6, rgb(0.7, 0.7, 0.72)], [1, rgb(0.15, 0.15, 0.2)]])"
swatch wood "wood().turbulence(0.05).colors([[0, rgb(0.75, 0.5, 0.25)], [1, rgb(0.45, 0.25, 0.1)]]).rotate(x: 90deg).scale(0.3)"
swatch leopard "leopard().colors($map).scale(0.15)"
swatch ripples "ripples(frequency: 4).colors($map).scale(2)"
swatch waves "waves(frequency: 2).colors($map).scale(2)"
swatch wrinkles "wrinkles().colors($map).scale(1.5)"
swatch dents "dents().colors($map).scale(0.5)"
swatch crackle "crackle().colors($map).scale(0.6)"
swatch crackle-f1 "crackle(form: \"f1\").colors($map).scale(0.6)"
swatch cells "cells().colors($map).scale(0.5)"
swatch function "pattern(fn(p) {
  let r = sqrt(p.x * p.x + p.z * p.z)
  if r < 1.2 { 0.5 + 0.6 * fbm(p * 3, octaves: 5) } else { 2 * worley(p * 2, form: \"edges\") }
}).colors($map)"

# Modifiers, on onion (a plain ramp of distance) or bozo.
swatch mod-frequency "onion().frequency(3).colors($map)"
swatch mod-phase "onion().phase(0.5).colors($map)"
for w in triangle sine scallop cubic; do
  swatch "mod-wave-$w" "onion().wave(\"$w\").colors($map)"
done
swatch mod-wave-poly "onion().wave(\"poly\", exponent: 4).colors($map)"
swatch mod-turbulence "onion().turbulence(0.4).colors($map)"
swatch mod-turbulence-octaves "onion().turbulence(0.4, octaves: 1).colors($map)"
swatch mod-repeat "bozo().colors($map).scale(0.3).repeat(X, width: 1, flip: X)"
swatch mod-warp-spherical "checker().colors([rgb(0.9, 0.9, 0.85), rgb(0.1, 0.1, 0.15)]).scale([0.125, 0.25, 1]).warp(\"spherical\")"
swatch mod-transform "gradient(axis: X).colors($map).scale(0.5).rotate(y: 30deg)"
swatch mod-stops-sharp "bozo().colors([[0, rgb(0.1, 0.2, 0.5)], [0.5, rgb(0.1, 0.2, 0.5)], [0.5, rgb(0.9, 0.85, 0.6)], [1, rgb(0.9, 0.85, 0.6)]]).scale(0.5)"
echo "wrote $(ls "$out" | wc -l) swatches into $out"
