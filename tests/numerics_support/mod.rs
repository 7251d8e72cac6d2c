//! Shared helpers of the numerics tests: render a scene written in rtc, compare images.
#![allow(dead_code)]

use std::path::Path;

use rtc::eval::{EvalOptions, load_source};
use rtc::render::{Image, RenderOptions, render_image};
use rtc::source::SourceMap;

/// Renders `src` (an rtc scene) single-threaded.
pub fn render_rtc(src: &str) -> Image {
    let mut sources = SourceMap::default();
    let loaded = load_source(
        Path::new("tests/numerics.rtc"),
        src,
        &mut sources,
        &EvalOptions::default(),
    );
    let scene = loaded
        .scene
        .unwrap_or_else(|| panic!("scene evaluates: {:?}\n{src}", loaded.diagnostics.items));
    render_image(
        &scene,
        &RenderOptions {
            threads: 1,
            ..Default::default()
        },
    )
    .expect("renders")
}

/// Pixels whose bytes differ (the images must have one size).
pub fn differing(a: &Image, b: &Image) -> usize {
    assert_eq!(a.dimensions(), b.dimensions());
    a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count()
}

/// Pixels whose channels differ by more than `tolerance` of 255.
pub fn differing_by(a: &Image, b: &Image, tolerance: u8) -> usize {
    assert_eq!(a.dimensions(), b.dimensions());
    a.pixels()
        .zip(b.pixels())
        .filter(|(p, q)| p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > tolerance))
        .count()
}

/// Fraction of the image's pixels in `count`.
pub fn share(img: &Image, count: usize) -> f64 {
    count as f64 / f64::from(img.width() * img.height())
}

/// A point written for a scene scaled by `s` and moved by `shift`: `[s·x + sx, ...]`.
pub fn at(s: f64, shift: [f64; 3], p: [f64; 3]) -> String {
    format!(
        "[{:e}, {:e}, {:e}]",
        s * p[0] + shift[0],
        s * p[1] + shift[1],
        s * p[2] + shift[2]
    )
}

/// Renders `scene(s)` at each scale `s` and at 1, and asserts that at most 0.1 % of the pixels
/// differ from the scale-1 image by more than one level (printing each scale's count): the
/// scale-invariance check of the numerics suite.
pub fn assert_same_at_scales(scales: &[f64], scene: impl Fn(f64) -> String) {
    let reference = render_rtc(&scene(1.0));
    let mut report = Vec::new();
    let mut worst: f64 = 0.0;
    for &s in scales {
        let img = render_rtc(&scene(s));
        let n = differing_by(&reference, &img, 1);
        worst = worst.max(share(&reference, n));
        report.push(format!("{s:e}: {n} pixels differ"));
    }
    println!("{}", report.join("\n"));
    assert!(worst <= 0.001, "{}", report.join("\n"));
}
