//! The quality knobs of issue 9: the insignificance cut-off, area-light samples spread over a
//! pixel's samples, aligned refinement blocks, and progressive renders that stop at an error
//! estimate and reproduce from their sample map.

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::{LightSampling, Scene};
use rtc::render::film::CUT_WEIGHT_UNIT;
use rtc::render::film::Film;
use rtc::render::progressive::{self, Budget};
use rtc::render::{RenderOptions, Silent, render_scene};
use rtc::source::SourceMap;

fn scene(src: &str) -> Scene {
    let mut sm = SourceMap::new();
    let l = load_source(
        Path::new("tests/lang/inline.rtc"),
        src,
        &mut sm,
        &EvalOptions::default(),
    );
    assert!(!l.diagnostics.has_errors(), "{:#?}", l.diagnostics);
    l.scene.expect("scene")
}

fn render(s: &Scene, threads: usize) -> Film {
    render_scene(
        s,
        &RenderOptions {
            threads,
            ..Default::default()
        },
    )
    .unwrap()
}

/// A mirror ball inside a mirror ball, both reflecting 0.5: every camera ray bounces until
/// `max_depth`, its k-th bounce weighing exactly 0.5^k.
fn mirror_room(cutoff: &str) -> Scene {
    scene(&format!(
        "rtc 1\n\
         let m = material {{ color: rgb(0.5, 0.5, 0.5), ka: 0.2, kd: 0.3, ks: 0, reflect: 0.5 }}\n\
         sphere(center: [0, 0, 0], radius: 20).material(m)\n\
         sphere(center: [0, 0, -3], radius: 1).material(m)\n\
         camera {{ eye: [0, 0, 5], center: [0, 0, 0], resolution: [32, 24] }}\n\
         point_light {{ position: [3, 5, 5] }}\n\
         render {{ max_depth: 10{cutoff} }}\n"
    ))
}

#[test]
fn cutoff_zero_traces_every_ray_and_changes_no_byte() {
    let all = render(&mirror_room(", cutoff: 0"), 2);
    assert_eq!(all.stats.cut_rays, 0);
    assert_eq!(all.stats.secondary_rays, 10 * all.stats.camera_rays);
    // The smallest weight in the scene is 0.5^10: a cut-off equal to it cuts nothing, so the
    // comparison `weight < cutoff` is the only thing the cut-off adds to a path.
    let at_edge = render(&mirror_room(&format!(", cutoff: {}", 0.5f64.powi(10))), 1);
    assert_eq!(at_edge.stats.cut_rays, 0);
    assert_eq!(all.to_image(), at_edge.to_image());
    assert_eq!(all.color(), at_edge.color());
}

#[test]
fn stats_count_the_cut_rays_and_bound_the_energy_dropped() {
    let all = render(&mirror_room(", cutoff: 0"), 2);
    // 0.5^6 = 0.0156 ≥ 0.01 > 0.5^7: six bounces traced, the seventh cut, per camera ray.
    let cut = render(&mirror_room(", cutoff: 0.01"), 2);
    let camera = cut.stats.camera_rays;
    assert_eq!(cut.stats.secondary_rays, 6 * camera);
    assert_eq!(cut.stats.cut_rays, camera);
    let weight = cut.stats.cut_weight as f64 / CUT_WEIGHT_UNIT;
    assert_eq!(weight, camera as f64 * 0.5f64.powi(7));
    // What was dropped is at most the cut weight times the brightest radiance in the scene; here
    // each pixel loses less than 0.5^7 (radiance < 1).
    for (a, c) in all.color().iter().zip(cut.color()) {
        let d = (*a - *c).max_element();
        assert!((0.0..0.5f64.powi(7)).contains(&d), "{d}");
    }
    assert_ne!(all.color(), cut.color());
}

#[test]
fn the_language_default_cutoff_is_half_an_srgb_level_and_course_has_none() {
    let s = mirror_room("");
    assert_eq!(s.settings.cutoff, 0.5 / (255.0 * 12.92));
    assert_eq!(rtc::ir::RenderSettings::course_defaults().cutoff, 0.0);
    let bad = scene_codes("rtc 1\ncamera { eye: [0, 0, 5] }\nrender { cutoff: 2 }\n");
    assert_eq!(bad, ["rtc::param::out_of_range"]);
}

fn scene_codes(src: &str) -> Vec<&'static str> {
    let mut sm = SourceMap::new();
    let l = load_source(
        Path::new("tests/lang/inline.rtc"),
        src,
        &mut sm,
        &EvalOptions::default(),
    );
    l.diagnostics.items.iter().map(|d| d.code).collect()
}

/// A plane under a 4×4 area light seen through a lens: soft shadows and defocus.
fn soft(sampling: &str, spread: bool) -> Scene {
    scene(&format!(
        "rtc 1\n\
         plane(point: [0, 0, 0], normal: Y)\n\
         sphere(center: [0, 1, 0], radius: 1)\n\
         camera {{ eye: [0, 3, 6], center: [0, 0.5, 0], resolution: [40, 30], aperture: 0.05, focus: 6 }}\n\
         area_light {{ corner: [-1, 5, -1], u: [2, 0, 0], v: [0, 0, 2], samples: [4, 4] }}\n\
         render {{ supersampling: {sampling}, spread_light_samples: {spread} }}\n"
    ))
}

#[test]
fn spread_light_samples_cast_one_shadow_ray_per_pixel_sample_at_4x4() {
    let full = render(&soft("4", false), 2);
    let spread = soft("4", true);
    assert_eq!(spread.settings.light_samples, LightSampling::Spread);
    let spread = render(&spread, 2);
    // Without spreading every camera sample that sees a lit surface casts 16 shadow rays; with
    // 16 pixel samples sharing the 16 cells, one (up to cells behind the surface near the
    // sphere's terminator, which cast none).
    assert_eq!(full.stats.camera_rays, spread.stats.camera_rays);
    let ratio = full.stats.shadow_rays as f64 / spread.stats.shadow_rays as f64;
    assert!((ratio - 16.0).abs() < 0.1, "{ratio}");
    // Both estimate the same image: the mean colours agree closely.
    let mean = |f: &Film| f.color().iter().map(|c| c.element_sum()).sum::<f64>();
    let (a, b) = (mean(&full), mean(&spread));
    assert!((a - b).abs() < 0.01 * a, "{a} {b}");
    // The same bytes for any thread count.
    assert_eq!(render(&soft("4", true), 1).to_image(), spread.to_image());
}

fn progressive(s: &Scene, budget: &Budget, threads: usize) -> progressive::Outcome {
    let prepared = rtc::opt::prepare(s).unwrap();
    progressive::render(&prepared, threads, budget, &Silent, &mut |_| true).unwrap()
}

#[test]
fn target_error_stops_below_the_target_and_the_sample_map_reproduces_the_bytes() {
    let s = soft("1", false);
    let target = 0.004;
    let out = progressive(&s, &Budget::TargetError(target), 2);
    assert!(out.last.estimate <= target, "{:?}", out.last);
    assert!(out.last.rounds > 1);
    let (lo, hi) = out.map.sample_range();
    assert!(lo == 4 && hi > 4 * lo, "{lo}..{hi}");
    // Without a clock or an estimate, the map gives the same bytes (on another thread count).
    let text = out.map.to_text();
    let map = progressive::SampleMap::parse(&text).unwrap();
    let again = progressive(&s, &Budget::Samples(map), 1);
    assert_eq!(again.film.to_image(), out.film.to_image());
    assert_eq!(again.map, out.map);
    // A looser target takes fewer samples and has a larger estimate.
    let loose = progressive(&s, &Budget::TargetError(4.0 * target), 2);
    assert!(loose.map.mean_samples() < out.map.mean_samples());
    assert!(loose.last.estimate > out.last.estimate);
}

#[test]
fn progressive_error_falls_as_samples_rise() {
    let s = soft("1", false);
    let mut estimates = Vec::new();
    let prepared = rtc::opt::prepare(&s).unwrap();
    progressive::render(
        &prepared,
        2,
        &Budget::TargetError(0.002),
        &Silent,
        &mut |r| {
            estimates.push(r.estimate);
            r.rounds < 5
        },
    )
    .unwrap();
    assert_eq!(estimates.len(), 5);
    // Each round refines the noisiest pixels; the estimate falls every round.
    assert!(estimates.windows(2).all(|w| w[1] < w[0]), "{estimates:?}");
}

#[test]
fn a_sample_map_of_another_size_is_an_error_not_a_panic() {
    let s = soft("1", false);
    let map = progressive::SampleMap {
        width: 3,
        height: 2,
        levels: vec![0; 6],
    };
    let prepared = rtc::opt::prepare(&s).unwrap();
    let err = progressive::render(&prepared, 1, &Budget::Samples(map), &Silent, &mut |_| true)
        .unwrap_err();
    assert_eq!(err.code, "rtc::render::samples");
}

fn rtc(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the rtc binary runs")
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-converge-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const SOFT_FILE: &str = "rtc 1\n\
    plane(point: [0, 0, 0], normal: Y).material(material { color: rgb(0.5, 0.5, 0.5), reflect: 0.3 })\n\
    sphere(center: [0, 1, 0], radius: 1).material(material { color: rgb(0.8, 0.3, 0.2), reflect: 0.3 })\n\
    camera { eye: [0, 3, 6], center: [0, 0.5, 0], resolution: [24, 16], aperture: 0.05, focus: 6 }\n\
    area_light { corner: [-1, 5, -1], u: [2, 0, 0], v: [0, 0, 2], samples: [2, 2] }\n\
    render { cutoff: 0.2 }\n";

#[test]
fn cli_target_error_then_samples_from_gives_the_same_bytes() {
    let dir = scratch("target");
    let scene = dir.join("soft.rtc");
    std::fs::write(&scene, SOFT_FILE).unwrap();
    let (s, a, b) = (
        scene.to_str().unwrap(),
        dir.join("a.png"),
        dir.join("b.png"),
    );
    let first = rtc(&[
        "render",
        s,
        "-o",
        a.to_str().unwrap(),
        "--target-error",
        "0.01",
    ]);
    let err = String::from_utf8_lossy(&first.stderr);
    assert_eq!(first.status.code(), Some(0), "{err}");
    assert!(
        err.contains("round 1:") && err.contains("reached:"),
        "{err}"
    );
    let map = dir.join("a.png.samples");
    assert!(map.exists(), "{err}");
    let again = rtc(&[
        "render",
        s,
        "-o",
        b.to_str().unwrap(),
        "--samples-from",
        map.to_str().unwrap(),
        "--threads",
        "1",
    ]);
    assert_eq!(again.status.code(), Some(0));
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    // A malformed map is an error at its line and column; the image is left alone.
    std::fs::write(&map, "rtc-samples 1\n24 16\nzz\n").unwrap();
    let bad = rtc(&[
        "render",
        s,
        "-o",
        b.to_str().unwrap(),
        "--samples-from",
        map.to_str().unwrap(),
    ]);
    let text = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(1), "{text}");
    assert!(text.contains("a.png.samples:3:1"), "{text}");
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
}

#[test]
fn cli_stats_report_the_knobs_and_the_cut() {
    let dir = scratch("stats");
    let scene = dir.join("soft.rtc");
    std::fs::write(&scene, SOFT_FILE).unwrap();
    let out = dir.join("o.png");
    let run = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--stats",
    ]);
    let err = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{err}");
    assert!(
        err.contains("stats: quality: supersampling 1×1; area-light cells 4"),
        "{err}"
    );
    // Sphere and plane reflect 0.3: a first bounce (0.3) is traced, a second (0.09) is cut.
    assert!(err.contains("stats: cut-off 2.000e-1: "), "{err}");
    assert!(!err.contains(": 0 secondary rays cut"), "{err}");
}
