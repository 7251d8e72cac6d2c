//! Spot, parallel, fading and shadowless lights (issue 37), checked against their stated rules
//! (docs/language.md §17, after POV-Ray 3.7's `Attenuate_Light`): a white diffuse plane
//! (`ka: 0, kd: 1, ks: 0`) seen face on, one world unit per pixel, so that a pixel is
//! `max(0, N·L)` times the light's share at the world point it looks at; every expected value is
//! computed here from the rule, never read from a render.

use std::path::Path;

use glam::DVec3;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::num::Norm;
use rtc::render::film::Film;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

const W: u32 = 96;
const H: u32 = 64;

fn load(src: &str) -> Result<Scene, Vec<String>> {
    let mut sources = SourceMap::default();
    let text = format!("rtc 1.1\n{src}");
    let loaded = load_source(
        Path::new("lights.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    loaded.scene.ok_or_else(|| {
        loaded
            .diagnostics
            .items
            .iter()
            .map(|d| d.code.to_string())
            .collect()
    })
}

/// The white diffuse plane z = 0 seen face on under `lights`, with `extra` objects.
fn plane_under(lights: &str, extra: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                   resolution: [{W}, {H}] }}
         {lights}
         plane(point: [0, 0, 0], normal: Z).material(material {{ color: rgb(1, 1, 1), ka: 0, kd: 1, ks: 0 }})
         {extra}
         render {{ shadows: true, max_depth: 0 }}"
    ))
    .unwrap()
}

fn render(scene: &Scene, threads: usize) -> Film {
    let opts = RenderOptions {
        threads,
        ..Default::default()
    };
    render_scene(scene, &opts).unwrap()
}

/// The world point pixel (i, j) looks at.
fn world(i: u32, j: u32) -> DVec3 {
    DVec3::new(
        f64::from(i) + 0.5 - f64::from(W) / 2.0,
        f64::from(H) / 2.0 - f64::from(j) - 0.5,
        0.0,
    )
}

/// Every pixel's red channel against `expect` at its world point (`None`: not checked).
fn assert_pixels(film: &Film, mut expect: impl FnMut(DVec3) -> Option<f64>) {
    let mut checked = 0;
    for j in 0..H {
        for i in 0..W {
            let p = world(i, j);
            if let Some(want) = expect(p) {
                let got = film.get(i, j).x;
                assert!(
                    (got - want).abs() < 1e-6,
                    "pixel ({i}, {j}) at {p}: got {got}, want {want}"
                );
                checked += 1;
            }
        }
    }
    assert!(
        checked > (W * H) as usize / 2,
        "only {checked} pixels checked"
    );
}

/// POV-Ray's spot share: `cos^tightness`, times the smoothstep of the cosine between the
/// falloff's and the radius's.
fn spot_share(cos: f64, radius: f64, falloff: f64, tightness: f64) -> f64 {
    if cos <= 0.0 {
        return 0.0;
    }
    let (inner, outer) = (radius.to_radians().cos(), falloff.to_radians().cos());
    let base = cos.powf(tightness);
    if cos >= inner {
        base
    } else if cos < outer {
        0.0
    } else {
        let t = (cos - outer) / (inner - outer);
        base * t * t * (3.0 - 2.0 * t)
    }
}

#[test]
fn a_spot_light_is_full_inside_its_radius_and_ends_at_its_falloff() {
    let light = DVec3::new(3.0, -2.0, 40.0);
    let target = DVec3::new(5.0, 1.0, 0.0);
    let axis = (target - light).unit();
    for tightness in [0.0, 3.0] {
        let scene = plane_under(
            &format!(
                "spot_light {{ position: [3, -2, 40], target: [5, 1, 0], radius: 20deg,
                               falloff: 35deg, tightness: {tightness} }}"
            ),
            "",
        );
        let film = render(&scene, 2);
        assert_pixels(&film, |p| {
            let l = (light - p).unit();
            let cos = (-l).dot(axis);
            Some(l.z * spot_share(cos, 20.0, 35.0, tightness))
        });
        // Both edges are in the picture: some pixels full, some dark, some between.
        let reds: Vec<f64> = film.color().iter().map(|c| c.x).collect();
        assert!(reds.contains(&0.0));
        assert!(reds.iter().any(|&r| r > 0.9));
    }
}

#[test]
fn a_fading_light_has_its_colour_at_the_fade_distance() {
    let light = DVec3::new(-4.0, 3.0, 10.0);
    for power in [1.0, 2.0] {
        let scene = plane_under(
            &format!(
                "point_light {{ position: [-4, 3, 10], color: rgb(0.5, 0.5, 0.5), fade_distance: 15, fade_power: {power} }}"
            ),
            "",
        );
        assert_pixels(&render(&scene, 2), |p| {
            let d = (light - p).norm();
            let l = (light - p) / d;
            Some(0.5 * l.z * 2.0 / (1.0 + (d / 15.0).powf(power)))
        });
    }
}

/// Whether the ray from `p` along `l` meets the sphere (`centre`, `radius`), and how clearly:
/// the distance of its closest approach from the sphere's surface.
fn shadow_margin(p: DVec3, l: DVec3, centre: DVec3, radius: f64) -> (bool, f64) {
    let t = (centre - p).dot(l).max(0.0);
    let miss = (p + t * l - centre).norm();
    (miss < radius, (miss - radius).abs())
}

#[test]
fn a_parallel_light_lights_everything_alike_and_casts_a_parallel_shadow() {
    // The sun low in +x: a ball out of view at (60, 0, 10) shadows the middle of the picture.
    let l = DVec3::new(6.0, 0.0, 1.0).unit();
    let centre = DVec3::new(60.0, 0.0, 10.0);
    let ball = "sphere(center: [60, 0, 10], radius: 5)";
    for shadows in [true, false] {
        let scene = plane_under(
            &format!("parallel_light {{ direction: [-6, 0, -1], shadows: {shadows} }}"),
            ball,
        );
        let film = render(&scene, 2);
        let mut dark = 0;
        assert_pixels(&film, |p| {
            let (hit, margin) = shadow_margin(p, l, centre, 5.0);
            if margin < 0.05 {
                return None;
            }
            dark += usize::from(hit && shadows);
            Some(if hit && shadows { 0.0 } else { l.z })
        });
        assert_eq!(dark > 100, shadows, "shadow pixels: {dark}");
    }
}

#[test]
fn the_new_lights_render_the_same_bytes_on_one_and_two_threads() {
    let scene = plane_under(
        "spot_light { position: [0, 0, 30], target: [0, 0, 0], radius: 15deg, falloff: 30deg }
         parallel_light { direction: [-6, 0, -1], color: rgb(0.3, 0.3, 0.3) }",
        "sphere(center: [10, 0, 3], radius: 3)",
    );
    assert_eq!(render(&scene, 1).color(), render(&scene, 2).color());
}

#[test]
fn bad_lights_are_refused_with_a_code() {
    let cases = [
        (
            "spot_light { position: [0, 5, 0], target: [0, 5, 0] }",
            "rtc::light::aim",
        ),
        (
            "spot_light { position: [0, 5, 0], target: [0, 0, 0], radius: 30deg, falloff: 20deg }",
            "rtc::light::falloff",
        ),
        (
            "point_light { position: [0, 5, 0], fade_power: 2 }",
            "rtc::light::fade",
        ),
        ("parallel_light { direction: [0, 0, 0] }", "rtc::"),
    ];
    for (light, code) in cases {
        let codes = load(&format!(
            "camera {{ eye: [0, 0, 5], center: [0, 0, 0], up: Y }}\n{light}\nsphere()"
        ))
        .expect_err(light);
        assert!(
            codes.iter().any(|c| c.starts_with(code)),
            "{light}: {codes:?}"
        );
    }
}
