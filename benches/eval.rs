//! Evaluation benchmark (not a timed test): procedural scenes of 100 000 and 1 000 000 objects
//! built with loops, parsed and evaluated to the IR. Targets: < 0.1 s and < 1 s.
//! Run with `cargo bench --bench eval`; `cargo bench --bench eval -- FILE...` instead times the
//! front end (parse + evaluate, no preparation) on scene files, e.g. the generated ones of
//! `benches/parse.sh` and `benches/million.sh`, to split `rtc check` into its stages.

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

fn time(name: &str, src: &str, expect: Option<usize>, reps: u32) {
    let mut best = Duration::MAX;
    let mut best_cpu = f64::MAX;
    let mut objects = 0;
    for _ in 0..reps {
        let cpu = cpu_seconds();
        let mut sm = SourceMap::new();
        let t = Instant::now();
        let loaded = load_source(
            Path::new("bench.rtc"),
            src,
            &mut sm,
            &EvalOptions::default(),
        );
        let dt = t.elapsed();
        best_cpu = best_cpu.min(cpu_seconds() - cpu);
        let n = loaded.scene.as_ref().map_or(0, |s| s.objects.len());
        let errors = loaded.diagnostics.items.iter().any(|d| d.is_error());
        assert!(!errors, "{:#?}", loaded.diagnostics.items.first());
        assert!(
            expect.is_none_or(|e| e == n),
            "{n} objects, expected {expect:?}"
        );
        drop(loaded);
        best = best.min(dt);
        objects = n;
    }
    println!(
        "{name}: {objects} objects, best of {reps}: {:.3} s wall, {best_cpu:.2} s CPU",
        best.as_secs_f64()
    );
}

/// The process's user + system CPU time from /proc/self/stat (Linux; clock ticks of 10 ms), so a
/// loaded machine's waiting is not counted; NaN elsewhere.
fn cpu_seconds() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return f64::NAN;
    };
    // Fields after the command name (which is in parentheses): utime and stime are 14 and 15.
    let rest = stat.rsplit_once(')').map_or("", |(_, r)| r);
    let f: Vec<&str> = rest.split_whitespace().collect();
    let tick = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok());
    match (tick(11), tick(12)) {
        (Some(u), Some(s)) => (u + s) / 100.0,
        _ => f64::NAN,
    }
}

fn main() {
    let files: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    if !files.is_empty() {
        for f in &files {
            let src = std::fs::read_to_string(f).unwrap_or_else(|e| panic!("{f}: {e}"));
            time(f, &src, None, 5);
        }
        return;
    }
    time("eval_100k", &scene(1000, 100), Some(100_000), 5);
    time("eval_1m", &scene(1000, 1000), Some(1_000_000), 3);
}
