//! Values of the standard library (`stdlib/*.rtc`) against rules that can be checked by hand:
//! each `assert` below states the expected value, derived from the function's definition.

use std::path::PathBuf;

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::source::SourceMap;

fn eval(body: &str) -> Scene {
    let src = format!("rtc 1\n{body}\ncamera {{ eye: [0, 0, 10] }}\n");
    let mut sources = SourceMap::default();
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("stdlib_probe.rtc");
    let loaded = load_source(&path, &src, &mut sources, &EvalOptions::default());
    let problems: Vec<String> = loaded
        .diagnostics
        .items
        .iter()
        .filter(|d| d.severity != rtc::diag::Severity::Note)
        .map(|d| {
            let line = d
                .span
                .map_or(0, |s| src[..s.start as usize].matches('\n').count() + 1);
            format!("line {line}: {} {}", d.code, d.message)
        })
        .collect();
    assert!(problems.is_empty(), "{problems:#?}");
    loaded.scene.expect("a scene")
}

#[test]
fn math() {
    eval(
        r#"
import std.math as m
assert(m.lerp(2, 4, 0.25) == 2.5 && m.lerp(0deg, 90deg, 0.5) == 45deg)
assert(m.clamp(5, 0, 1) == 1 && m.clamp(-1, 0, 1) == 0 && m.saturate(0.5) == 0.5)
assert(m.smoothstep(0, 1, 0.5) == 0.5 && m.smoothstep(0, 1, -1) == 0 && m.smoothstep(0, 1, 2) == 1)
assert(m.remap(5, 0, 10, 100, 200) == 150)
assert(m.sign(-3) == -1 && m.sign(0) == 0 && m.sign(0.1) == 1)
assert(m.fract(2.25) == 0.25 && m.fract(-0.25) == 0.75 && m.sq(3) == 9)
assert(m.degrees(90) == 90deg && abs((m.radians(pi) - 180deg).rad) < 1e-12)
assert(distance(m.polar(2, 90deg), [0, 0, 2]) < 1e-12)
assert(distance(m.spherical(1, 0deg, 90deg), Y) < 1e-12 && distance(m.spherical(2, 90deg, 0deg), [0, 0, 2]) < 1e-12)
assert(m.midpoint([0, 0, 0], [2, 4, 6]) == [1, 2, 3] && m.reflect([1, -1, 0], Y) == [1, 1, 0])
assert(m.bezier3([0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], 0) == [0, 0, 0])
assert(m.bezier3([0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], 1) == [0, 1, 0])
assert(m.bezier2([0, 0, 0], [1, 2, 0], [2, 0, 0], 0.5) == [1, 1, 0])
assert(m.mean([1, 2, 3, 4]) == 2.5 && m.e > 2.71828 && m.phi * m.phi - m.phi - 1 < 1e-12)
"#,
    );
}

#[test]
fn color() {
    eval(
        r#"
import std.color as c
assert(c.gray(0.5) == rgb(0.5) && c.mix(rgb(0), rgb(1), 0.25) == rgb(0.25))
assert(c.scaled(rgb(1, 0.5, 0), 2) == rgb(2, 1, 0) && c.clamped(rgb(2, 0.5, 3)) == rgb(1, 0.5, 1))
assert(abs(c.luminance(rgb(1, 1, 1)) - 1) < 1e-12)
assert(c.white == rgb(1, 1, 1) && c.black == rgb(0) && c.red == rgb(1, 0, 0) && c.blue == rgb(0, 0, 1))
// Hues pass through degrees, so compare with a tolerance.
fn near(a: Color, b: Color) -> Bool { abs(a.r - b.r) < 1e-9 && abs(a.g - b.g) < 1e-9 && abs(a.b - b.b) < 1e-9 }
assert(c.rgb(1, 0, 0) == rgb(1, 0, 0) && near(c.hsv(120deg, 1, 1), rgb(0, 1, 0)))
// At 6600 K (t = 66) the fit gives r = 255, g = 99.47·ln 66 − 161.12 ≈ 255.6 → 255, b = 255.
assert(c.kelvin(6600) == rgb(1, 1, 1))
// At 1000 K (t = 10) blue is 0 and red is the brightest channel.
assert(c.kelvin(1000).b == 0 && c.kelvin(1000).r == 1 && c.kelvin(1000).g < 0.1)
let r = c.rainbow(3, s: 1, v: 1)
assert(len(r) == 3 && near(r[0], rgb(1, 0, 0)) && near(r[1], rgb(0, 1, 0)) && near(r[2], rgb(0, 0, 1)))
let g = c.gradient(c.black, c.white, 3)
assert(len(g) == 3 && g[1] == rgb(0.5) && g[2] == rgb(1))
assert(c.course_yellow == rgb(1, 0.8, 0))
"#,
    );
}

#[test]
fn layout() {
    eval(
        r#"
import std.layout as l
let g = l.grid(2, 2, spacing: 2)
assert(len(g) == 4 && g[0] == [-1, 0, -1] && g[1] == [1, 0, -1] && g[3] == [1, 0, 1])
let lat = l.lattice(2, 2, 2, spacing: 1, center: [0, 5, 0])
assert(len(lat) == 8 && lat[0] == [-0.5, 4.5, -0.5] && lat[7] == [0.5, 5.5, 0.5])
let r = l.ring(4, 2, center: [1, 0, 0])
assert(len(r) == 4 && r[0] == [3, 0, 0] && distance(r[1], [1, 0, 2]) < 1e-12)
let s = l.spiral(3, 1, 2, turns: 1, height: 4)
assert(s[0] == [1, 0, 0] && distance(s[2], [2, 4, 0]) < 1e-12)
assert(l.along(fn(t) [t, 2 * t, 0], 5)[4] == [1, 2, 0])
let rng = random(seed: 3)
let pts = l.scatter(rng, "p", 50, [0, 0, 0], [1, 2, 3])
assert(len(for p in pts if p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 2 && p.z >= 0 && p.z < 3 { p }) == 50)
assert(pts[7] == l.scatter(rng, "p", 50, [0, 0, 0], [1, 2, 3])[7])
let d = l.scatter_disk(rng, "d", 50, 2, center: [0, 1, 0])
assert(len(for p in d if p.y == 1 && distance(p, [0, 1, 0]) <= 2 { p }) == 50)
let top = l.on_top_of(sphere(radius: 1), box(min: [0, 0, 0], max: [2, 2, 2]))
assert(top.bounds.bottom_center == [1, 2, 1])
assert(l.stand_at(sphere(radius: 0.5), [3, 0, 0]).bounds.center == [3, 0.5, 0])
assert(l.center_at(box(min: [0, 0, 0], max: [2, 2, 2]), [5, 5, 5]).bounds.min == [4, 4, 4])
let row = l.row([box(), box().scale(2), box()], gap: 1)
assert(row[0].bounds.min.x == 0 && row[1].bounds.min.x == 2 && row[2].bounds.min.x == 5)
assert(len(l.copies(sphere(radius: 0.1), l.grid(3, 1))) == 3)
"#,
    );
}

#[test]
fn materials_and_textures() {
    let s = eval(
        r#"
import std.materials as mat
import std.textures as tex
assert(mat.ior.water == 1.333 && mat.ior.diamond == 2.417 && mat.ior.glass == 1.5)
sphere().material(mat.course(rgb(0, 0, 1), 0.2, 0.5, 0.4, 64))
sphere().material(mat.water)
sphere().material(mat.dielectric(mat.ior.sapphire))
sphere().material(mat.matte with { texture: tex.tiles(size: 2) })
sphere().material(mat.gooch_default)
point_light { position: [0, 5, 5] }
"#,
    );
    let m = |i: usize| &s.materials[s.objects[i].material.expect("a material").0 as usize];
    assert_eq!(
        (m(0).ks, m(0).reflect, m(0).n, m(0).kd, m(0).ka),
        (0.4, 0.4, 64.0, 0.5, 0.2)
    );
    assert_eq!((m(1).eta, m(1).refract), (1.333, 0.9));
    assert_eq!(m(2).eta, 1.77);
    let t = m(3).texture.expect("a texture").0 as usize;
    assert_eq!(
        s.textures[t],
        rtc::ir::Texture::Checker {
            a: glam::DVec3::splat(0.9),
            b: glam::DVec3::splat(0.15),
            size: 2.0
        }
    );
    assert!(matches!(
        m(4).shading,
        Some(rtc::ir::ShadingModel::Gooch(_))
    ));
}

#[test]
fn shapes() {
    let s = eval(
        r#"
import std.shapes as sh
let c = sh.capsule([0, 0, 0], [0, 2, 0], 0.5)
assert(c.bounds.min == [-0.5, -0.5, -0.5] && c.bounds.max == [0.5, 2.5, 0.5])
let t = sh.tube(1, 0.1, 2)
assert(t.bounds.min == [-1, 0, -1] && t.bounds.max == [1, 2, 1])
let rb = sh.rounded_box([0, 0, 0], [2, 1, 3], 0.2)
assert(rb.bounds.min == [0, 0, 0] && rb.bounds.max == [2, 1, 3])
let ar = sh.arrow([0, 0, 0], [0, 2, 0], 0.1)
assert(abs(ar.bounds.max.y - 2) < 1e-12 && abs(ar.bounds.max.x - 0.2) < 1e-12)
assert(len(sh.axes()) == 3)
let st = sh.stairs(4, rise: 0.25)
assert(len(st) == 4 && st[3].bounds.max.y == 1 && st[3].bounds.max.z == 1.2)
assert(sh.pedestal(r: 0.5, height: 1).bounds.max == [0.625, 1, 0.625])
c
sh.axes()
"#,
    );
    // The capsule is one union of three; the axes are three arrows, each a union of two.
    assert_eq!(s.objects.len(), 4);
    assert!(s.objects.iter().all(|o| o.shape.kind_name() == "csg"));
    assert_eq!(s.materials.len(), 3, "each axis arrow has its own colour");
}
