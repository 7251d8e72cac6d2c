//! Phong, normal and depth images of hand-built course scenes against the consensus references.

mod common;

use common::{data, diff, scene01, scene01_shadows};
use rtc::ir::{DepthRange, RenderMode};
use rtc::render::{RenderOptions, render_image};

fn opts() -> RenderOptions {
    RenderOptions {
        threads: 2,
        ..Default::default()
    }
}

#[test]
fn scene01_phong_is_exact() {
    let img = render_image(&scene01(), &opts()).unwrap();
    let d = diff(&img, &data("reference/scene01.png"));
    assert!(d.max <= 1, "{d:?}");
}

#[test]
fn scene01_shadows_is_exact() {
    let img = render_image(&scene01_shadows(), &opts()).unwrap();
    let d = diff(&img, &data("reference/scene01-shadows.png"));
    assert!(d.max <= 1, "{d:?}");
}

#[test]
fn scene01_normal_is_within_one_level() {
    let mut s = scene01();
    s.settings.mode = RenderMode::Normal;
    let img = render_image(&s, &opts()).unwrap();
    let d = diff(&img, &data("reference/scene01-normal.png"));
    assert!(d.max <= 1, "{d:?}");
}

#[test]
fn scene01_zbuffer_fixed_range_matches_oleobal() {
    let mut s = scene01();
    s.settings.mode = RenderMode::Depth(DepthRange::Fixed {
        near: 500.0,
        far: 1000.0,
    });
    let img = render_image(&s, &opts()).unwrap();
    let d = diff(&img, &data("reference/scene01-zbuffer__ole.png"));
    assert!(d.max <= 1, "{d:?}");
}
