//! Benchmark (not a test): render the five-spheres peer scene A (scenes/five_spheres.yaml:
//! 400×400, 4×4 supersampling, shadows, reflection depth 2) in process and print the median of
//! several runs, per thread count. Run with `cargo bench --bench five_spheres`.
//! The end-to-end comparison with POV-Ray is benches/peers.sh.

use std::path::Path;
use std::time::{Duration, Instant};

use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

fn main() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/five_spheres.yaml");
    let mut sources = SourceMap::default();
    let loaded = rtc::compat::load_yaml(&path, &mut sources);
    let Some(scene) = loaded.scene else {
        eprintln!("cannot load {}: {:?}", path.display(), loaded.diagnostics);
        std::process::exit(1);
    };
    let reps: usize = std::env::var("REPS")
        .ok()
        .and_then(|r| r.parse().ok())
        .unwrap_or(7);
    for threads in [1, 0] {
        let opts = RenderOptions {
            threads,
            ..Default::default()
        };
        let mut times: Vec<Duration> = Vec::with_capacity(reps);
        let mut stats = None;
        for _ in 0..reps {
            let t = Instant::now();
            let film = match render_scene(&scene, &opts) {
                Ok(f) => f,
                Err(d) => {
                    let first = d.items.first().map_or("", |d| d.message.as_str());
                    eprintln!("render failed: {first}");
                    std::process::exit(1);
                }
            };
            times.push(t.elapsed());
            stats = Some(film.stats);
        }
        times.sort();
        let median = times[times.len() / 2];
        let stats = stats.unwrap_or_default();
        let rays = stats.camera_rays + stats.secondary_rays + stats.shadow_rays;
        println!(
            "five_spheres threads={} median {:.3} s (min {:.3}, max {:.3}) over {reps} runs; \
             {} camera + {} secondary + {} shadow rays = {:.2} Mray/s",
            if threads == 0 {
                "all".to_string()
            } else {
                threads.to_string()
            },
            median.as_secs_f64(),
            times[0].as_secs_f64(),
            times[times.len() - 1].as_secs_f64(),
            stats.camera_rays,
            stats.secondary_rays,
            stats.shadow_rays,
            rays as f64 / median.as_secs_f64() / 1e6,
        );
    }
}
