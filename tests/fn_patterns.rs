//! Patterns from user functions (`pattern(f)`, issue 36): a compiled function that computes a
//! built-in pattern's value renders the built-in's pixels, under the same modifiers, colour
//! map and bump; renders are the same on one thread and two; what cannot be compiled stops
//! `rtc check` with `rtc::fn::not_compilable`.

mod cli_support;

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

fn load(src: &str) -> Result<Scene, String> {
    let mut sources = SourceMap::default();
    let text = format!("rtc 1.1\n{src}");
    let loaded = load_source(
        Path::new("test.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    loaded.scene.ok_or_else(|| {
        loaded
            .diagnostics
            .items
            .iter()
            .map(|d| format!("{}: {}", d.code, d.message))
            .collect::<Vec<_>>()
            .join(", ")
    })
}

/// A lit sphere on a plane, both wearing `material`, 64×48 pixels.
fn scene(material: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 2, -6], center: [0, 0.5, 0], up: Y, fov: 50deg, resolution: [64, 48] }}
         point_light {{ position: [-4, 6, -5] }}
         plane().material({material})
         sphere().translate([0, 1, 0]).material({material})"
    ))
    .unwrap()
}

/// Every pixel of `scene` on `threads` threads, as bits.
fn pixels(scene: &Scene, threads: usize) -> Vec<[u64; 3]> {
    let options = RenderOptions {
        threads,
        ..Default::default()
    };
    let film = render_scene(scene, &options).unwrap();
    film.color()
        .iter()
        .map(|c| [c.x.to_bits(), c.y.to_bits(), c.z.to_bits()])
        .collect()
}

/// The function texture and the built-in one render the same pixels.
fn same_pixels(function: &str, builtin: &str) {
    let a = pixels(&scene(function), 2);
    let b = pixels(&scene(builtin), 2);
    let mut distinct = a.clone();
    distinct.sort_unstable();
    distinct.dedup();
    assert!(
        distinct.len() > 20,
        "{function}: only {} colours",
        distinct.len()
    );
    let differing = a.iter().zip(&b).filter(|(x, y)| x != y).count();
    assert_eq!(differing, 0, "{function} against {builtin}");
}

const MAP: &str = ".colors([rgb(0.9, 0.2, 0.1), rgb(0.1, 0.3, 0.8)])";

#[test]
fn a_function_of_the_point_renders_as_the_built_in_pattern_it_computes() {
    same_pixels(
        &format!("material {{ texture: pattern(fn(p) {{ p.x - floor(p.x) }}){MAP}.scale(0.3) }}"),
        &format!("material {{ texture: gradient(axis: X){MAP}.scale(0.3) }}"),
    );
    same_pixels(
        &format!("material {{ texture: pattern(fn(p) {{ noise(p, seed: 4) }}){MAP}.scale(0.4) }}"),
        &format!("material {{ texture: bozo(seed: 4){MAP}.scale(0.4) }}"),
    );
}

#[test]
fn a_function_pattern_takes_every_modifier_as_a_built_in_does() {
    let mods = ".turbulence(0.4, octaves: 3).wave(\"sine\").frequency(2).phase(0.1)\
                .warp(\"cylindrical\").scale(0.5).rotate(y: 20deg)";
    same_pixels(
        &format!("material {{ texture: pattern(fn(p) {{ noise(p) }}){mods}{MAP} }}"),
        &format!("material {{ texture: bozo(){mods}{MAP} }}"),
    );
    // As a bump and in a material map. A function's bump takes central differences, a bare
    // bozo's its analytic gradient (docs/textures.md); behind a turbulence warp both take
    // differences, so the two bumps must agree to the bit.
    same_pixels(
        "material { color: rgb(0.7, 0.7, 0.7), bump: pattern(fn(p) { noise(p) }).turbulence(0.3).scale(0.2), bump_scale: 0.5 }",
        "material { color: rgb(0.7, 0.7, 0.7), bump: bozo().turbulence(0.3).scale(0.2), bump_scale: 0.5 }",
    );
    let stops = "[[0, material { color: rgb(1, 0, 0) }], [1, material { color: rgb(0, 0, 1) }]]";
    same_pixels(
        &format!("material_map(pattern(fn(p) {{ noise(p) }}).scale(0.5), {stops})"),
        &format!("material_map(bozo().scale(0.5), {stops})"),
    );
}

#[test]
fn a_function_pattern_renders_the_same_on_one_thread_and_two() {
    let s = scene(
        "material { texture: pattern(fn(p) {
             let r = sqrt(p.x * p.x + p.z * p.z)
             if r < 1 { fbm(p * 4, octaves: 5) } else { worley(p * 2, form: \"edges\") }
         }).colors([rgb(0, 0, 0), rgb(1, 0.8, 0.5)]) }",
    );
    assert_eq!(pixels(&s, 1), pixels(&s, 2));
}

#[test]
fn what_cannot_be_compiled_stops_rtc_check_with_its_code() {
    let dir = cli_support::scratch("fn_patterns");
    let file = dir.join("bad.rtc");
    std::fs::write(
        &file,
        "rtc 1.1\ncamera { eye: [0, 0, -5] }\nsphere().material(material { texture: pattern(fn(p) { len([p.x, 1, 2, 3]) }) })\n",
    )
    .unwrap();
    let out = cli_support::rtc(&["check", file.to_str().unwrap()]);
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("rtc::fn::not_compilable"), "{text}");
    assert!(text.contains("len"), "{text}");
}

#[test]
fn the_pattern_is_named_function_where_patterns_are_named() {
    let s = scene("material { texture: pattern(fn(p) { p.y }) }");
    let name = s
        .textures
        .iter()
        .find_map(|t| match t {
            rtc::ir::Texture::Pattern(pt) => Some(pt.name()),
            _ => None,
        })
        .unwrap();
    assert_eq!(name, "function");
}
