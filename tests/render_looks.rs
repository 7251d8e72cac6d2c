//! Lens flare, glossy reflection, light through glass and hatching (issue 13), on small scenes
//! written in the language. Expected values come from stated rules (where a ghost must be, what
//! is brighter than what, a spacing ratio), never from the renderer's own output.

use std::path::Path;

use proptest::prelude::*;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::opt::Effects;
use rtc::render::{RenderOptions, render_image, render_scene};
use rtc::source::SourceMap;

fn scene(src: &str) -> Scene {
    let mut sources = SourceMap::default();
    let text = format!("rtc 1\n{src}");
    let loaded = load_source(
        Path::new("test.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    loaded
        .scene
        .unwrap_or_else(|| panic!("{:?}", loaded.diagnostics))
}

fn opts() -> RenderOptions {
    RenderOptions {
        threads: 2,
        ..Default::default()
    }
}

// ---- lens flare ------------------------------------------------------------------------------

/// A dim floor, a light in view at a known place, and optionally a wall between it and the eye.
fn flare_scene(wall: bool, flare: &str) -> Scene {
    let wall = if wall {
        "quad(corner: [-1, -1, -3], u: [2, 0, 0], v: [0, 2, 0])"
    } else {
        ""
    };
    scene(&format!(
        "plane(point: [0, -2, 0], normal: Y)
         {wall}
         camera {{ eye: [0, 0, 0], center: [0, 0, -1], fov: 60deg, resolution: [120, 80] }}
         point_light {{ position: [-0.6, 0.4, -5], color: rgb(1, 1, 1) }}
         render {{ background: rgb(0, 0, 0)
                  {flare} }}"
    ))
}

#[test]
fn flare_puts_ghosts_on_the_line_through_the_centre() {
    let flare = "flare: flare { ghosts: 3, dispersal: 0.5, halo: 0, streaks: 0, threshold: 0 }";
    let plain = render_scene(&flare_scene(false, ""), &opts()).unwrap();
    let flared = render_scene(&flare_scene(false, flare), &opts()).unwrap();
    // The light's image position by the pinhole rule: x = w/2 + (X/−Z)/tan(30°)·h/2.
    let half_h = 40.0 / (30f64.to_radians().tan());
    let at = (60.0 + -0.6 / 5.0 * half_h, 40.0 - 0.4 / 5.0 * half_h);
    let centre = (60.0, 40.0);
    let added = |x: f64, y: f64| {
        let (px, py) = (x.floor() as u32, y.floor() as u32);
        (flared.get(px, py) - plain.get(px, py)).element_sum()
    };
    for i in 1..=3 {
        let k = 0.5 * f64::from(i);
        let g = (at.0 + (centre.0 - at.0) * k, at.1 + (centre.1 - at.1) * k);
        assert!(added(g.0, g.1) > 0.05, "ghost {i} at {g:?}");
    }
    // Off the line, far from the light and the ghosts: nothing added.
    assert_eq!(added(110.0, 5.0), 0.0);
    assert_eq!(added(10.0, 75.0), 0.0);
}

#[test]
fn an_occluded_light_flares_not_and_no_flare_changes_nothing() {
    let flare = "flare: flare";
    let hidden = render_image(&flare_scene(true, flare), &opts()).unwrap();
    let hidden_plain = render_image(&flare_scene(true, ""), &opts()).unwrap();
    assert_eq!(hidden, hidden_plain);
    let asked_off = render_scene(&flare_scene(false, "flare: false"), &opts()).unwrap();
    let never = render_scene(&flare_scene(false, ""), &opts()).unwrap();
    assert_eq!(asked_off.to_image(), never.to_image());
    assert_eq!(asked_off.stats, never.stats);
    let s = flare_scene(false, flare);
    assert!(Effects::of(&s).flare);
    assert!(!Effects::of(&flare_scene(false, "")).flare);
}

#[test]
fn a_half_hidden_area_light_gives_half_the_flare() {
    let make = |wall: &str, flare: &str| {
        scene(&format!(
            "{wall}
             camera {{ eye: [0, 0, 0], center: [0, 0, -1], fov: 60deg, resolution: [60, 40] }}
             area_light {{ corner: [-0.5, -0.25, -6], u: [1, 0, 0], v: [0, 0.5, 0], samples: [4, 2], color: rgb(1, 1, 1) }}
             render {{ background: rgb(0, 0, 0)
                  {flare} }}"
        ))
    };
    // The wall hides the left half of the light from the eye (x < 0 at z = −6).
    let wall = "quad(corner: [-3, -3, -3], u: [3, 0, 0], v: [0, 6, 0])";
    let flare = "flare: flare { threshold: 0 }";
    let full = render_scene(&make("", flare), &opts()).unwrap();
    let half = render_scene(&make(wall, flare), &opts()).unwrap();
    let base_full = render_scene(&make("", ""), &opts()).unwrap();
    let base_half = render_scene(&make(wall, ""), &opts()).unwrap();
    // A pixel that only the flare lights (the light is at the centre: ghosts, glow and star).
    let (x, y) = (33, 20);
    let f = (full.get(x, y) - base_full.get(x, y)).element_sum();
    let h = (half.get(x, y) - base_half.get(x, y)).element_sum();
    assert!(f > 0.0);
    assert!((h / f - 0.5).abs() < 1e-9, "{h} / {f}");
}

// ---- glossy reflection -----------------------------------------------------------------------

fn glossy_scene(material: &str, background: &str) -> Scene {
    scene(&format!(
        "sphere(center: [0, 0, -3], radius: 1).material({material})
         plane(point: [0, -1, 0], normal: Y)
         camera {{ eye: [0, 0.5, 1], center: [0, 0, -3], fov: 45deg, resolution: [48, 32] }}
         point_light {{ position: [2, 4, 2], color: rgb(1, 1, 1) }}
         render {{ background: {background}, max_depth: 3 }}"
    ))
}

#[test]
fn zero_gloss_is_the_mirror_byte_for_byte() {
    let bg = "rgb(0.3, 0.5, 0.8)";
    let mirror = glossy_scene("material { reflect: 0.8, kd: 0.2 }", bg);
    let zero = glossy_scene(
        "material { reflect: 0.8, kd: 0.2, gloss: 0, gloss_samples: 32 }",
        bg,
    );
    let a = render_scene(&mirror, &opts()).unwrap();
    let b = render_scene(&zero, &opts()).unwrap();
    assert_eq!(a.to_image(), b.to_image());
    assert_eq!(a.stats, b.stats);
    assert!(!Effects::of(&zero).glossy);
    // A glossy one differs, costs its lobe's rays, and is the same on any thread count.
    let glossy = glossy_scene("material { reflect: 0.8, kd: 0.2, gloss: 0.3 }", bg);
    assert!(Effects::of(&glossy).glossy);
    let c = render_scene(&glossy, &opts()).unwrap();
    assert_ne!(a.to_image(), c.to_image());
    assert!(c.stats.secondary_rays > 4 * a.stats.secondary_rays);
    let one = render_scene(
        &glossy,
        &RenderOptions {
            threads: 1,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(one.to_image(), c.to_image());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A glossy mirror under a uniform sky (no lights, no local shading) reflects at most
    /// `reflect` of it: the lobe redistributes light, it never adds any. Two glossy spheres
    /// facing each other reflect one another and still stay below the sky.
    #[test]
    fn glossy_energy_never_grows(
        gloss in 0.0f64..1.0,
        reflect in 0.0f64..1.0,
        refract in 0.0f64..1.0,
        samples in 1u32..12,
        sky in 0.05f64..1.0,
    ) {
        let refract = refract * (1.0 - reflect);
        let m = format!(
            "material {{ ka: 0, kd: 0, ks: 0, reflect: {reflect}, refract: {refract}, eta: 1.4, gloss: {gloss}, gloss_samples: {samples} }}"
        );
        let s = scene(&format!(
            "sphere(center: [-0.6, 0, -3], radius: 0.5).material({m})
             sphere(center: [0.6, 0, -3], radius: 0.5).material({m})
             camera {{ eye: [0, 0, 0], center: [0, 0, -3], fov: 40deg, resolution: [16, 12] }}
             render {{ background: rgb({sky}, {sky}, {sky}), max_depth: 6, shadows: false }}"
        ));
        let film = render_scene(&s, &opts()).unwrap();
        for y in 0..12 {
            for x in 0..16 {
                let c = film.get(x, y);
                prop_assert!(c.max_element() <= sky * (1.0 + 1e-12), "{x},{y}: {c:?}");
            }
        }
    }
}

// ---- light through glass ---------------------------------------------------------------------

fn shadow_scene(glass: bool, shadows: &str) -> Scene {
    let m = if glass {
        "material { color: rgb(1, 0.3, 0.2), ka: 0, kd: 0, refract: 0.9, eta: 1.5 }"
    } else {
        "material { color: rgb(1, 0.3, 0.2) }"
    };
    // The light, up and to the right, throws the sphere's shadow onto the floor around
    // x = −1.2, clear of the sphere as the eye above sees it.
    scene(&format!(
        "plane(point: [0, 0, 0], normal: Y).material(material {{ color: rgb(1, 1, 1), ka: 0.1, kd: 0.9 }})
         sphere(center: [0, 1, 0], radius: 0.5).material({m})
         camera {{ eye: [0, 8, 0], center: [0, 0, 0], up: Z, fov: 40deg, resolution: [48, 48] }}
         point_light {{ position: [6, 6, 0], color: rgb(1, 1, 1) }}
         render {{ {shadows}, max_depth: 0 }}"
    ))
}

#[test]
fn a_glass_sphere_casts_a_lighter_tinted_shadow() {
    let shade =
        |glass: bool, shadows: &str| render_scene(&shadow_scene(glass, shadows), &opts()).unwrap();
    let lit = shade(false, "shadows: false");
    let opaque = shade(false, "glass_shadows: true");
    let glass = shade(true, "glass_shadows: true");
    let glass_off = shade(true, "glass_shadows: false");
    assert!(Effects::of(&shadow_scene(true, "glass_shadows: true")).glass_shadows);
    assert!(!Effects::of(&shadow_scene(true, "glass_shadows: false")).glass_shadows);
    // The umbra: floor pixels the opaque sphere darkens to the ambient term alone.
    let mut umbra = 0;
    for y in 0..48 {
        for x in 0..48 {
            let (l, o, g, off) = (
                lit.get(x, y),
                opaque.get(x, y),
                glass.get(x, y),
                glass_off.get(x, y),
            );
            if (o - glam::DVec3::splat(0.1)).abs().max_element() > 1e-9 || l.x <= 0.2 {
                continue;
            }
            umbra += 1;
            // Lighter than the opaque shadow, darker than the lit floor, and red like the glass.
            assert!(g.x > o.x + 0.2 && g.x < l.x, "{x},{y}: {g:?}");
            assert!(g.x > 2.0 * g.y && g.y > 0.99 * g.z, "{x},{y}: {g:?}");
            // Without the setting, glass casts the opaque shadow (what the course files keep).
            assert_eq!(off, o, "{x},{y}");
        }
    }
    assert!(umbra > 20, "{umbra} umbra pixels");
}

// ---- hatching --------------------------------------------------------------------------------

/// Mean distance in pixels between the strokes crossing image column `x` in rows `rows`: the
/// window's length over the number of ink runs (pixels at least 35 % covered) in it.
fn stroke_spacing(film: &rtc::render::film::Film, x: u32, rows: std::ops::Range<u32>) -> f64 {
    let ink = |y: u32| 1.0 - film.get(x, y).x > 0.35;
    let mut runs = 0;
    let mut inside = false;
    for y in rows.clone() {
        let now = ink(y);
        runs += usize::from(now && !inside);
        inside = now;
    }
    assert!(runs >= 3, "only {runs} strokes in {rows:?}");
    f64::from(rows.end - rows.start) / runs as f64
}

#[test]
fn hatching_keeps_its_stroke_spacing_from_the_pole_to_the_equator() {
    // A sphere lit evenly (ambient only: one layer of strokes along its latitudes), seen from
    // above the equator so its pole is in view, foreshortened 4.5× more than the equator.
    let s = scene(
        "sphere(radius: 1)
         camera { eye: [0, 2, 5], center: [0, 0, 0], fov: 30deg, resolution: [240, 240] }
         point_light { position: [0, 10, 10], color: rgb(1, 1, 1) }
         render { shading: hatching, background: rgb(1, 1, 1), shadows: false,
                  material: material { color: rgb(1, 1, 1), ka: 0.75, kd: 0 } }",
    );
    let film = render_scene(&s, &opts()).unwrap();
    let cam = rtc::render::camera::Camera::new(&s.camera);
    let (px, pole) = cam.project(glam::DVec3::Y).unwrap();
    let (_, equator) = cam.project(glam::DVec3::Z).unwrap();
    let x = px.floor() as u32;
    let pole = pole.ceil() as u32;
    let equator = equator.floor() as u32;
    let near_pole = stroke_spacing(&film, x, pole + 2..pole + 26);
    let near_equator = stroke_spacing(&film, x, equator - 24..equator);
    let ratio = near_pole.max(near_equator) / near_pole.min(near_equator);
    assert!(
        ratio < 1.5,
        "pole {near_pole} px, equator {near_equator} px"
    );
    // The strokes are anti-aliased: some pixels are grey, between ink and paper.
    let grey = (0..240)
        .flat_map(|y| (0..240).map(move |x| (x, y)))
        .filter(|&(x, y)| (0.1..0.9).contains(&film.get(x, y).x))
        .count();
    assert!(grey > 500, "{grey} grey pixels");
}

#[test]
fn hatching_is_darker_in_the_shade() {
    let s = scene(
        "sphere(radius: 1)
         camera { eye: [0, 0, 5], center: [0, 0, 0], fov: 30deg, resolution: [120, 120] }
         point_light { position: [-10, 10, 10], color: rgb(1, 1, 1) }
         render { shading: hatching, background: rgb(1, 1, 1),
                  material: material { color: rgb(1, 1, 1), ka: 0.05, kd: 0.95 } }",
    );
    let film = render_scene(&s, &opts()).unwrap();
    // Mean ink over the lit upper left and the shaded lower right quarter of the disc.
    let mut ink = [0.0; 2];
    for y in 0..120 {
        for x in 0..120 {
            let (dx, dy) = (f64::from(x) - 59.5, f64::from(y) - 59.5);
            if dx * dx + dy * dy < 40.0 * 40.0 && dx.abs() > 8.0 && (dx > 0.0) == (dy > 0.0) {
                ink[usize::from(dx > 0.0)] += 1.0 - film.get(x, y).x;
            }
        }
    }
    assert!(ink[1] > 2.0 * ink[0], "{ink:?}");
}
