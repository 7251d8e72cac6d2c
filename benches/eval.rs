//! Evaluation benchmark (not a timed test): procedural scenes of 100 000 and 1 000 000 objects
//! built with loops, parsed and evaluated to the IR. Targets: < 0.1 s and < 1 s.
//! Run with `cargo bench --bench eval`.

use std::path::Path;
use std::time::{Duration, Instant};

use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

fn scene(rows: u32, cols: u32) -> String {
    format!(
        "rtc 1
let m = material {{ color: rgb(0.8, 0.3, 0.2), kd: 0.7, ks: 0.2 }}
let rng = random(seed: 1)
for i in 0..{rows}, j in 0..{cols} {{
  let h = rng.uniform(\"h\", i * {cols} + j)
  sphere(center: [i, 0, j], radius: 0.4).material(m).translate([0, h, 0])
}}
camera {{ eye: [0, 50, -50], center: [{rows} / 2, 0, {cols} / 2] }}
point_light {{ position: [0, 100, 0] }}
"
    )
}

fn time(name: &str, src: &str, expect: usize, reps: u32) {
    let mut best = Duration::MAX;
    for _ in 0..reps {
        let mut sm = SourceMap::new();
        let t = Instant::now();
        let loaded = load_source(
            Path::new("bench.rtc"),
            src,
            &mut sm,
            &EvalOptions::default(),
        );
        let dt = t.elapsed();
        let n = loaded.scene.as_ref().map_or(0, |s| s.objects.len());
        assert_eq!(n, expect, "{:#?}", loaded.diagnostics.items.first());
        drop(loaded);
        best = best.min(dt);
    }
    println!(
        "{name}: {expect} objects, best of {reps}: {:.3} s",
        best.as_secs_f64()
    );
}

fn main() {
    time("eval_100k", &scene(1000, 100), 100_000, 5);
    time("eval_1m", &scene(1000, 1000), 1_000_000, 3);
}
