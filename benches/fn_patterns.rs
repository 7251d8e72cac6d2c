//! Function patterns against built-in ones (not a timed test): each pattern's value at a
//! million points, the compiled program of `pattern(fn(p) ..)` next to the built-in pattern it
//! computes. Run with `cargo bench --bench fn_patterns`.

use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use glam::DVec3;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Texture;
use rtc::pattern::Field;
use rtc::source::SourceMap;

/// The field of the pattern texture `texture`.
fn field(texture: &str) -> Field {
    let text = format!(
        "rtc 1.1\ncamera {{ eye: [0, 0, -5] }}\nsphere().material(material {{ texture: {texture} }})\n"
    );
    let loaded = load_source(
        Path::new("bench.rtc"),
        &text,
        &mut SourceMap::new(),
        &EvalOptions::default(),
    );
    let scene = loaded.scene.expect("the bench scene evaluates");
    match scene.textures.into_iter().next() {
        Some(Texture::Pattern(pt)) => pt.field,
        _ => panic!("{texture} is no pattern"),
    }
}

/// Nanoseconds per evaluation of `texture` over `points` (best of three).
fn time(texture: &str, points: &[DVec3]) -> f64 {
    let f = field(texture);
    let mut best = f64::MAX;
    for _ in 0..3 {
        let t = Instant::now();
        let mut sum = 0.0;
        for p in points {
            sum += f.eval(black_box(*p));
        }
        black_box(sum);
        best = best.min(t.elapsed().as_secs_f64() * 1e9 / points.len() as f64);
    }
    best
}

fn main() {
    let mut s: u64 = 1;
    let mut next = || {
        s = s
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((s >> 11) as f64 / (1u64 << 53) as f64) * 20.0 - 10.0
    };
    let points: Vec<DVec3> = (0..1_000_000)
        .map(|_| DVec3::new(next(), next(), next()))
        .collect();
    let pairs = [
        ("pattern(fn(p) { p.x - floor(p.x) })", "gradient(axis: X)"),
        ("pattern(fn(p) { noise(p) })", "bozo()"),
        ("pattern(fn(p) { worley(p, form: \"edges\") })", "crackle()"),
        (
            "pattern(fn(p) { let r = sqrt(p.x * p.x + p.z * p.z)\n if r < 1 { fbm(p * 4, octaves: 5) } else { 0.5 } })",
            "granite()",
        ),
    ];
    for (function, builtin) in pairs {
        let (a, b) = (time(function, &points), time(builtin, &points));
        println!("{a:7.1} ns  {function:?}\n{b:7.1} ns  {builtin}\n");
    }
}
