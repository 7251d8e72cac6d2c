//! The path tracer (issue 39) against rules that hold whatever the renderer: a white furnace,
//! closed forms, Whitted's direct light, agreement of its estimators and determinism. Every
//! expected value is computed here from the physics, never read from a render.

mod common;

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::render::film::Film;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

fn load(src: &str) -> Scene {
    let path = Path::new("gi.rtc");
    let mut sources = SourceMap::default();
    let text = format!("rtc 1.1\n{src}");
    let loaded = load_source(path, &text, &mut sources, &EvalOptions::default());
    common::scene_of(loaded, path)
}

fn render_with(scene: &Scene, threads: usize) -> Film {
    let options = RenderOptions {
        threads,
        ..RenderOptions::default()
    };
    render_scene(scene, &options).unwrap()
}

fn render(scene: &Scene) -> Film {
    render_with(scene, 0)
}

/// Every pixel's colour, row by row.
fn pixels(film: &Film) -> Vec<[f64; 3]> {
    film.color().iter().map(|c| c.to_array()).collect()
}

/// Mean and standard error of one channel over the pixels (each pixel an independent estimate).
fn mean_and_error(values: &[[f64; 3]], c: usize) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().map(|v| v[c]).sum::<f64>() / n;
    let var = values.iter().map(|v| (v[c] - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

/// A white Lambertian sphere and an open box (floor and three walls: concave, so light bounces
/// between them) inside a uniform environment of radiance `env`.
fn furnace(albedo: f64, env: f64, path: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 3, 8], center: [0, 0.5, 0], fov: 40deg, resolution: [32, 24] }}
         let white = material {{ color: rgb({albedo}, {albedo}, {albedo}), ka: 0, kd: 1, ks: 0 }}
         sphere(center: [1.2, 1, 0], radius: 1).material(white)
         quad(corner: [-3, 0, -2], u: [0, 0, 4], v: [3, 0, 0]).material(white)
         quad(corner: [-3, 0, -2], u: [3, 0, 0], v: [0, 2, 0]).material(white)
         quad(corner: [-3, 0, -2], u: [0, 2, 0], v: [0, 0, 4]).material(white)
         render {{ integrator: {path}, background: rgb({env}, {env}, {env}) }}"
    ))
}

#[test]
fn a_white_furnace_is_exactly_the_environment_everywhere() {
    // Albedo 1: light is neither lost nor made, so every pixel sees the environment's
    // radiance however the light bounced (the concave box included). Each path's weight stays
    // exactly 1, so the rule holds per path, not only on average.
    let film = render(&furnace(1.0, 0.75, "path(samples: 4, bounces: 256)"));
    for (k, p) in pixels(&film).iter().enumerate() {
        for c in p {
            assert!((c - 0.75).abs() < 1e-12, "pixel {k}: {p:?}");
        }
    }
}

/// The camera inside a closed sphere whose inner wall has albedo ρ and emits `Le`: every
/// point sees `L = Le + ρ·L`, so `L = Le / (1 − ρ)` (per channel).
fn emitting_enclosure(path: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 0, 0], center: [0, 0, -1], fov: 90deg, resolution: [24, 24] }}
         sphere(center: [1, 2, -3], radius: 10).material(material {{
             color: rgb(0.3, 0.6, 0.8), ka: 0, kd: 1, ks: 0, emission: rgb(0.7, 0.4, 0.2) }})
         render {{ integrator: {path} }}"
    ))
}

/// `Le / (1 − ρ)` for each channel of [`emitting_enclosure`]: the emission is `emission·C`.
const ENCLOSURE: [f64; 3] = [0.7 * 0.3 / 0.7, 0.4 * 0.6 / 0.4, 0.2 * 0.8 / 0.2];

#[test]
fn a_sphere_inside_an_emitting_sphere_sees_le_over_one_minus_rho() {
    // Russian roulette (from bounce 3) ends paths at random; the estimate must stay unbiased:
    // within 4 standard errors of the closed form, channel by channel.
    for path in [
        "path(samples: 16, bounces: 256, roulette: 3)",
        "path(samples: 16, bounces: 256, roulette: 0)",
        "path(samples: 4, bounces: 256, roulette: false)",
    ] {
        let values = pixels(&render(&emitting_enclosure(path)));
        for (c, want) in ENCLOSURE.iter().enumerate() {
            let (mean, err) = mean_and_error(&values, c);
            assert!(
                (mean - want).abs() <= 4.0 * err + 1e-9,
                "{path}: channel {c}: {mean} ± {err}, want {want}"
            );
        }
    }
}

#[test]
fn bounces_truncate_the_series_exactly() {
    // With at most b bounces the enclosure shows Le·(1 + ρ + … + ρ^b) = Le·(1 − ρ^(b+1))/(1 − ρ).
    // Without roulette every path sees exactly that: inside a sphere, cos θ·cos θ'/d² is the
    // same 1/(4r²) for every chord, so light sampling by area, cosine-weighted BSDF sampling
    // and their MIS weights (which sum to 1) each give exactly ρ·Le per bounce.
    for b in [0u32, 1, 2, 5] {
        let film = render(&emitting_enclosure(&format!(
            "path(samples: 1, bounces: {b}, roulette: false)"
        )));
        let rho = [0.3f64, 0.6, 0.8];
        for p in pixels(&film) {
            for c in 0..3 {
                let want = ENCLOSURE[c] * (1.0 - rho[c].powi(b as i32 + 1));
                assert!((p[c] - want).abs() < 1e-12, "bounces {b}: {p:?}");
            }
        }
    }
}

/// A diffuse scene lit by a point light, a spot light and (with `area`) an area light, for
/// comparing direct light.
fn lit_scene(area: bool, render_block: &str) -> Scene {
    let area = if area {
        "area_light { corner: [-4, 5, -1], u: [1, 0, 0], v: [0, 0, 1], samples: [3, 3], color: rgb(0.3, 0.3, 0.5) }"
    } else {
        ""
    };
    load(&format!(
        "camera {{ eye: [0, 4, 9], center: [0, 0.5, 0], fov: 40deg, resolution: [40, 30] }}
         let m = material {{ color: rgb(0.9, 0.5, 0.2), ka: 0, kd: 0.8, ks: 0 }}
         sphere(center: [0, 1, 0], radius: 1).material(m)
         plane(point: [0, 0, 0], normal: Y).material(material {{ color: rgb(0.7, 0.7, 0.7), ka: 0, kd: 1, ks: 0 }})
         point_light {{ position: [4, 6, 3], color: rgb(0.8, 0.8, 0.7) }}
         spot_light {{ position: [-3, 5, 4], target: [0, 0, 0], radius: 20deg, falloff: 30deg, color: rgb(0.2, 0.4, 0.3) }}
         {area}
         {render_block}"
    ))
}

#[test]
fn one_bounce_of_the_path_tracer_is_whitteds_diffuse_light() {
    // A path of one bounce sees the lights through next-event estimation only (the bounce ray
    // meets no emitter and a black background): Lambert's `kd·C/π` times the irradiance `π·Lc·cos`
    // of each light sample, which is Whitted's diffuse term `kd·C·Lc·cos` (to rounding).
    let whitted = pixels(&render(&lit_scene(false, "render { max_depth: 0 }")));
    let path = pixels(&render(&lit_scene(
        false,
        "render { integrator: path(samples: 1, bounces: 1) }",
    )));
    for (k, (w, p)) in whitted.iter().zip(&path).enumerate() {
        for c in 0..3 {
            assert!(
                (w[c] - p[c]).abs() < 1e-12,
                "pixel {k}: Whitted {w:?}, path {p:?}"
            );
        }
    }
}

#[test]
fn the_path_tracer_bytes_do_not_depend_on_the_thread_count() {
    let scene = lit_scene(
        true,
        "render { integrator: path(samples: 4, bounces: 4), supersampling: 2 }",
    );
    let one = render_with(&scene, 1);
    let two = render_with(&scene, 2);
    assert_eq!(pixels(&one), pixels(&two));
}

#[test]
fn noise_falls_as_one_over_the_square_root_of_the_samples() {
    // The enclosure's error against its closed form, root mean square over pixels: 16 times
    // the paths must cut it about 4 times (between 3 and 5.5: a bias floor would stop it).
    let rms = |samples: u32| {
        let values = pixels(&render(&emitting_enclosure(&format!(
            "path(samples: {samples}, bounces: 256)"
        ))));
        let sum: f64 = values
            .iter()
            .map(|p| (0..3).map(|c| (p[c] - ENCLOSURE[c]).powi(2)).sum::<f64>())
            .sum();
        (sum / (3 * values.len()) as f64).sqrt()
    };
    let (coarse, fine) = (rms(4), rms(64));
    let ratio = coarse / fine;
    assert!(
        (3.0..5.5).contains(&ratio),
        "rms {coarse} → {fine}: ratio {ratio}"
    );
}

/// A grey floor under a glowing sphere (radiance `L` = 2, radius 0.5, centre 3 above the
/// floor), seen straight down by an orthographic camera; `light` is the light's material.
fn floor_under_a_sphere_light(light: &str, path: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 50, 0], center: [0, 0, 0], up: -Z, projection: \"orthographic\",
                  height: 8, resolution: [16, 16] }}
         plane(point: [0, 0, 0], normal: Y).material(material {{ color: rgb(0.5, 0.5, 0.5), ka: 0, kd: 1, ks: 0 }})
         sphere(center: [0, 3, 0], radius: 0.5).material({light})
         render {{ integrator: {path} }}"
    ))
}

/// The floor's radiance at (x, z) under the sphere light: a sphere of radius r and radiance L
/// wholly above the horizon gives the irradiance `π·L·(r/D)²·cos θ` (D the distance to its
/// centre, θ from the normal), and the floor returns `ρ/π` of it: `ρ·L·r²·h/D³`.
fn under_sphere(x: f64, z: f64) -> f64 {
    let (rho, l, r, h) = (0.5, 2.0, 0.5, 3.0);
    let d2: f64 = x * x + z * z + h * h;
    rho * l * r * r * h / (d2 * d2.sqrt())
}

/// The pixels that see the floor (outside the sphere's disk), with their expected radiance.
fn floor_pixels(film: &Film) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for j in 0..16 {
        for i in 0..16 {
            // Pixel centres of an 8-unit view: x to the right, z down the image (up is −Z).
            let x = (f64::from(i) + 0.5) / 16.0 * 8.0 - 4.0;
            let z = (f64::from(j) + 0.5) / 16.0 * 8.0 - 4.0;
            if x * x + z * z > 0.7 * 0.7 {
                out.push((film.get(i, j).x, under_sphere(x, z)));
            }
        }
    }
    out
}

#[test]
fn a_sphere_light_lights_the_floor_as_the_closed_form_says() {
    // Direct light only (one bounce). With light sampling the cone the sphere fills is sampled
    // uniformly, so each pixel is within 2% of the closed form at 16 paths; finding the light
    // by BSDF sampling alone (the emission given by a texture, which light sampling skips)
    // must agree on average.
    let light = "material { color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, emission: rgb(2, 2, 2) }";
    let film = render(&floor_under_a_sphere_light(
        light,
        "path(samples: 16, bounces: 1)",
    ));
    for (got, want) in floor_pixels(&film) {
        assert!(
            (got - want).abs() <= 0.02 * want,
            "light sampling: {got} vs {want}"
        );
    }
    let textured = "material { texture: checker(a: rgb(1, 1, 1), b: rgb(1, 1, 1)), ka: 0, kd: 0, ks: 0, emission: rgb(2, 2, 2) }";
    let film = render(&floor_under_a_sphere_light(
        textured,
        "path(samples: 1024, bounces: 1)",
    ));
    let pairs = floor_pixels(&film);
    let got: f64 = pairs.iter().map(|p| p.0).sum();
    let want: f64 = pairs.iter().map(|p| p.1).sum();
    assert!(
        (got - want).abs() <= 0.03 * want,
        "BSDF sampling: {got} vs {want}"
    );
}

/// A closed white box lit by a glowing quad under its ceiling, with red and green walls.
fn small_cornell(light: &str, path: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 1, 3.2], center: [0, 1, 0], fov: 40deg, resolution: [16, 16] }}
         let white = material {{ color: rgb(0.75, 0.75, 0.75), ka: 0, kd: 1, ks: 0 }}
         quad(corner: [-1, 0, -1], u: [0, 0, 2], v: [2, 0, 0]).material(white)
         quad(corner: [-1, 2, -1], u: [2, 0, 0], v: [0, 0, 2]).material(white)
         quad(corner: [-1, 0, -1], u: [2, 0, 0], v: [0, 2, 0]).material(white)
         quad(corner: [-1, 0, -1], u: [0, 2, 0], v: [0, 0, 2]).material(material {{ color: rgb(0.7, 0.1, 0.1), ka: 0, kd: 1, ks: 0 }})
         quad(corner: [1, 0, -1], u: [0, 0, 2], v: [0, 2, 0]).material(material {{ color: rgb(0.1, 0.7, 0.1), ka: 0, kd: 1, ks: 0 }})
         sphere(center: [0.3, 0.4, 0.1], radius: 0.4).material(white)
         quad(corner: [-0.3, 1.99, -0.3], u: [0.6, 0, 0], v: [0, 0, 0.6]).material({light})
         render {{ integrator: {path} }}"
    ))
}

#[test]
fn light_sampling_with_mis_and_bsdf_sampling_alone_agree() {
    // The same box, its light found with multiple importance sampling or (its emission given
    // by a texture of one colour, which light sampling skips) by BSDF sampling alone: the
    // image means agree within 4 standard errors, channel by channel.
    let plain = "material { color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, emission: rgb(8, 8, 8), emission_sides: 1 }";
    let textured = "material { texture: checker(a: rgb(1, 1, 1), b: rgb(1, 1, 1)), ka: 0, kd: 0, ks: 0, emission: rgb(8, 8, 8), emission_sides: 1 }";
    let mis = pixels(&render(&small_cornell(
        plain,
        "path(samples: 64, bounces: 8)",
    )));
    let bsdf = pixels(&render(&small_cornell(
        textured,
        "path(samples: 256, bounces: 8)",
    )));
    for c in 0..3 {
        let (a, ea) = mean_and_error(&mis, c);
        let (b, eb) = mean_and_error(&bsdf, c);
        // The pixels differ from each other by more than noise, so the spread over pixels
        // overstates each mean's error; the bound stays honest as a comparison of estimators.
        let bound = 4.0 * (ea * ea + eb * eb).sqrt();
        assert!(
            (a - b).abs() <= bound.max(0.01 * a),
            "channel {c}: MIS {a}, BSDF {b} (±{bound})"
        );
    }
}

#[test]
fn a_floor_under_a_gradient_sky_returns_its_irradiance() {
    // A sky of radiance L(θ) = c0 + (c1 − c0)·cos θ above the horizon (a `gradient` along +Y)
    // gives a horizontal floor the irradiance π·c0 + (2π/3)·(c1 − c0); a Lambertian floor of
    // albedo ρ shows ρ·(c0 + 2(c1 − c0)/3). The sky is sampled by its brightness and by the
    // BSDF, weighed by MIS: the mean over the image within 4 standard errors.
    let scene = load(
        "camera { eye: [0, 50, 0], center: [0, 0, 0], up: -Z, projection: \"orthographic\",
                  height: 8, resolution: [16, 16] }
         plane(point: [0, 0, 0], normal: Y).material(material { color: rgb(0.5, 0.5, 0.5), ka: 0, kd: 1, ks: 0 })
         render { integrator: path(samples: 16, bounces: 1),
                  sky: gradient(axis: Y).colors([rgb(0.2, 0.4, 1.0), rgb(1.0, 0.6, 0.2)]) }",
    );
    let values = pixels(&render(&scene));
    let (c0, c1) = ([0.2, 0.4, 1.0], [1.0, 0.6, 0.2]);
    for c in 0..3 {
        let want = 0.5 * (c0[c] + 2.0 * (c1[c] - c0[c]) / 3.0);
        let (mean, err) = mean_and_error(&values, c);
        assert!(
            (mean - want).abs() <= 4.0 * err + 1e-3 * want,
            "channel {c}: {mean} ± {err}, want {want}"
        );
    }
}

#[test]
fn a_furnace_under_a_sampled_sky_has_no_bias_block_by_block() {
    // The furnace again, its uniform environment given as a `sky` (a one-colour checker), so
    // the sky is also sampled by brightness and each path's estimate varies (MIS between sky
    // and BSDF samples): the truth is still exactly 0.75 everywhere. Over 8 × 6 blocks of 4 × 4
    // pixels at 256 paths, each block's mean and the image's must be within 4 standard errors
    // of it, and 4 standard errors of the image's mean must be under 0.2 % of it, so an
    // estimator biased by 0.2 % overall fails.
    let scene = load(
        "camera { eye: [0, 3, 8], center: [0, 0.5, 0], fov: 40deg, resolution: [32, 24] }
         let white = material { color: rgb(1, 1, 1), ka: 0, kd: 1, ks: 0 }
         sphere(center: [1.2, 1, 0], radius: 1).material(white)
         quad(corner: [-3, 0, -2], u: [0, 0, 4], v: [3, 0, 0]).material(white)
         quad(corner: [-3, 0, -2], u: [3, 0, 0], v: [0, 2, 0]).material(white)
         quad(corner: [-3, 0, -2], u: [0, 2, 0], v: [0, 0, 4]).material(white)
         render { integrator: path(samples: 256, bounces: 256),
                  sky: checker(a: rgb(0.75, 0.75, 0.75), b: rgb(0.75, 0.75, 0.75)) }",
    );
    let values = pixels(&render(&scene));
    let varies = values.iter().any(|p| (p[0] - 0.75).abs() > 1e-9);
    assert!(varies, "the estimate should vary from path to path here");
    let (mean, err) = mean_and_error(&values, 1);
    assert!((mean - 0.75).abs() <= 4.0 * err, "image: {mean} ± {err}");
    assert!(
        4.0 * err < 0.002 * 0.75,
        "too noisy to see a 0.2 % bias: ± {err}"
    );
    for by in 0..6 {
        for bx in 0..8 {
            let block: Vec<[f64; 3]> = (0..16)
                .map(|k| values[(by * 4 + k / 4) * 32 + bx * 4 + k % 4])
                .collect();
            let (m, e) = mean_and_error(&block, 1);
            assert!(
                (m - 0.75).abs() <= 4.0 * e.max(1e-6),
                "block ({bx}, {by}): {m} ± {e}"
            );
        }
    }
}
