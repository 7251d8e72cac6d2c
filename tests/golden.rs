//! Golden images: every official course scene that has a reference render in
//! tests/data/course/reference (see SOURCES.md for which render belongs to which scene and
//! convention), loaded through the YAML front end and rendered with the rules of COURSE.md §2.4–2.5.
//!
//! Bounds: `Exact` is max per-channel difference ≤ 1 (COURSE.md §5 reports an exact reproduction).
//! `Near` states a mean and max difference (in 8-bit levels) and the share of pixels off by more
//! than 1 for references made by other implementations; the numbers measured when the bound was
//! set are in each comment.

mod common;

use common::{Diff, data, diff};
use rtc::ir::{AmbientConvention, DepthRange, RenderMode, Sampling, Scene};
use rtc::render::{Image, RenderOptions, render_image};
use rtc::source::SourceMap;

fn load(yaml: &str) -> Scene {
    let mut sources = SourceMap::default();
    let loaded = rtc::compat::load_yaml(&data(yaml), &mut sources);
    loaded
        .scene
        .unwrap_or_else(|| panic!("{yaml}: {:?}", loaded.diagnostics))
}

fn draw(scene: &Scene) -> Image {
    let opts = RenderOptions {
        threads: 2,
        ..Default::default()
    };
    render_image(scene, &opts).unwrap()
}

fn exact(scene: &Scene, reference: &str) {
    let d = diff(&draw(scene), &data(reference));
    assert!(d.max <= 1, "{reference}: {d:?}");
}

fn near(scene: &Scene, reference: &str, mean: f64, max: u8, over1: f64) {
    let d: Diff = diff(&draw(scene), &data(reference));
    assert!(
        d.mean <= mean && d.max <= max && d.over1 <= over1,
        "{reference}: {d:?}, allowed mean {mean} max {max} over1 {over1}"
    );
}

#[test]
fn scene01_in_every_official_spelling_is_exact() {
    for yaml in [
        "yaml/scene01.yaml",
        "yaml/scene01-phong.yaml",
        "yaml/scene01_dos.yaml",
        "yaml/scene01__mhe-2009-01-03-indented.yaml",
        "yaml/uoit/scene01.yaml",
    ] {
        exact(&load(yaml), "reference/scene01.png");
    }
}

#[test]
fn scene01_normal_is_exact() {
    exact(
        &load("yaml/scene01-normal.yaml"),
        "reference/scene01-normal.png",
    );
}

#[test]
fn scene01_shadows_is_exact() {
    exact(
        &load("yaml/scene01-shadows.yaml"),
        "reference/scene01-shadows.png",
    );
}

#[test]
fn scene01_lights_shadows_ambient_per_light_is_exact() {
    let s = load("yaml/scene01-lights-shadows.yaml");
    assert_eq!(s.settings.ambient, AmbientConvention::PerLight);
    exact(&s, "reference/scene01-lights-shadows.png");
}

#[test]
fn scene01_lights_shadows_ambient_once_is_exact() {
    let mut s = load("yaml/scene01-lights-shadows.yaml");
    s.settings.ambient = AmbientConvention::Once;
    exact(&s, "reference/scene01-lights-shadows__ole.png");
}

#[test]
fn scene02_phong_and_normal_are_exact() {
    for yaml in ["yaml/scene02.yaml", "yaml/uoit/scene02.yaml"] {
        exact(&load(yaml), "reference/scene02.png");
    }
    let mut s = load("yaml/scene02.yaml");
    s.settings.mode = RenderMode::Normal;
    exact(&s, "reference/scene02__normal-mode.png");
}

fn zbuffer(range: DepthRange) -> Scene {
    let mut s = load("yaml/scene01-zbuffer.yaml");
    assert_eq!(s.settings.mode, RenderMode::Depth(DepthRange::Auto));
    s.settings.mode = RenderMode::Depth(range);
    s
}

#[test]
fn zbuffer_fixed_ranges_reproduce_the_student_conventions() {
    // oleobal: 255·(1000 − t)/500, exact.
    let ole = DepthRange::Fixed {
        near: 500.0,
        far: 1000.0,
    };
    exact(&zbuffer(ole), "reference/scene01-zbuffer__ole.png");
    // angeluriot: near 550, far 920 (measured max 1, mean 6e-6).
    let ang = DepthRange::Fixed {
        near: 550.0,
        far: 920.0,
    };
    exact(&zbuffer(ang), "reference/scene01-zbuffer__ang.png");
    // blupiac: ≈ 255·(1 − t/1000), not exactly linear (measured mean 1.15, max 4, 41.7% > 1).
    let blu = DepthRange::Fixed {
        near: 0.0,
        far: 1000.0,
    };
    near(
        &zbuffer(blu),
        "reference/scene01-zbuffer__blu.png",
        1.3,
        4,
        0.45,
    );
}

#[test]
fn zbuffer_auto_range_spans_nearest_to_farthest_hit() {
    let img = draw(&zbuffer(DepthRange::Auto));
    let grey: Vec<u8> = img.pixels().map(|p| p[0]).collect();
    assert_eq!(grey.iter().max(), Some(&255), "nearest hit is white");
    // The farthest hit is black; the background is black too, so look at the hit pixels'
    // minimum via the oleobal mask: every non-background pixel of the fixed render.
    let fixed = draw(&zbuffer(DepthRange::Fixed {
        near: 500.0,
        far: 1000.0,
    }));
    let hit_min = img
        .pixels()
        .zip(fixed.pixels())
        .filter(|(_, f)| f[0] > 0)
        .map(|(a, _)| a[0])
        .min();
    assert!(hit_min <= Some(1), "{hit_min:?}");
    // Close to angeluriot's near 550 / far 920 (scene01's hits span 553.3..912.6):
    // measured mean 0.87, max 6.
    near(
        &zbuffer(DepthRange::Auto),
        "reference/scene01-zbuffer__ang.png",
        1.0,
        6,
        0.35,
    );
}

#[test]
fn reflection_depth_two_matches_within_edge_tolerance() {
    // fwh's render, convention A: measured mean 0.29, 2.8% of pixels > 1 (edges, acne in the
    // reference), max 98 at silhouettes seen in mirrors.
    let s = load("yaml/scene01-reflect-lights-shadows.yaml");
    near(
        &s,
        "reference/scene01-reflect-lights-shadows.png",
        0.35,
        100,
        0.03,
    );
    // oleobal's render, convention B: measured mean 0.13, 0.65% > 1, max 81.
    let mut s = s;
    s.settings.ambient = AmbientConvention::Once;
    near(
        &s,
        "reference/scene01-reflect-lights-shadows__ole.png",
        0.16,
        90,
        0.008,
    );
}

#[test]
fn zoom_camera_with_supersampling_matches() {
    // 800×400, |up| = 0.75, 4×4 grid: measured mean 0.054, 1.6% > 1, max 52 (edges).
    let s = load("yaml/scene01-zoom-ss-reflect-lights-shadows.yaml");
    assert_eq!(s.settings.sampling, Sampling::Grid { factor: 4 });
    near(
        &s,
        "reference/scene01-zoom-ss-reflect-lights-shadows.png",
        0.07,
        60,
        0.02,
    );
}

#[test]
fn camera_block_equal_to_the_default_view_renders_identically() {
    // No reference render exists; COURSE.md §2.4: the Camera block is the default view, so the
    // image must equal scene01-reflect-lights-shadows with 4×4 supersampling, byte for byte.
    let camera = load("yaml/scene01-camera-ss-reflect-lights-shadows.yaml");
    let mut plain = load("yaml/scene01-reflect-lights-shadows.yaml");
    plain.settings.sampling = Sampling::Grid { factor: 4 };
    assert!(draw(&camera) == draw(&plain));
}

#[test]
fn gooch_matches() {
    // Tlospock's render: measured mean 0.125, 1.1% > 1, max 57 (silhouettes).
    near(
        &load("yaml/scene01-gooch.yaml"),
        "reference/scene01-gooch.png",
        0.15,
        60,
        0.015,
    );
}

#[test]
fn fwh_texture_scene_is_close_outside_the_texture() {
    // Single-source render with fwh's own texture orientation, which COURSE.md §2.5 says the
    // data cannot pin down; ours shows another part of the map on the textured sphere.
    // Measured mean 6.94, max 233, 17% of pixels > 1 (nearly all on the textured sphere).
    let s = load("yaml/scene01-texture-ss-reflect-lights-shadows__fwh.yaml");
    near(
        &s,
        "reference/scene01-texture-ss-reflect-lights-shadows__fwh.png",
        7.5,
        240,
        0.18,
    );
}

#[test]
fn blue_earth_silhouette_matches_at_astronomical_scale() {
    // fwh's render uses a grey background, another light colour treatment and map orientation,
    // so colours are not comparable (measured mean 37). What must agree is the camera model at
    // 1.5e8 units from the origin: which pixels see the Earth.
    let img = draw(&load("yaml/blue-earth__fwh.yaml"));
    let want = image::open(data("reference/blue-earth__fwh.png"))
        .unwrap()
        .to_rgb8();
    let bg = *want.get_pixel(0, 0);
    let (mut differ, mut earth) = (0, 0);
    for (a, b) in img.pixels().zip(want.pixels()) {
        let ours = a.0 != [0, 0, 0];
        let theirs = b.0.iter().zip(bg.0).any(|(x, y)| x.abs_diff(y) > 3);
        earth += usize::from(theirs);
        differ += usize::from(ours != theirs);
    }
    assert!(earth > 80_000, "{earth}");
    assert!(differ * 200 < earth, "{differ} of {earth} pixels disagree");
}
