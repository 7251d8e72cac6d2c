//! `rtc accuracy` (src/accuracy/, src/cli/accuracy.rs) on tiny scenes: which knobs are swept,
//! that error falls as samples rise, that an identical image measures 0, that an interrupted
//! sweep keeps its points, the reference cache, and the JSON report's shape, pinned by the
//! hand-written tests/data/accuracy/report-shape.json (the schema docs/accuracy.md documents).
//! Nothing here is timed: times are only checked to be positive.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicU64, Ordering};

use rtc::accuracy::knob::PIXEL_LADDER;
use rtc::accuracy::sweep::Sweep;
use rtc::accuracy::{
    Knob, MeasureOptions, Metric, ReferenceChoice, Report, StudyOptions, SweepProgress, study,
};
use rtc::ir::Scene;

/// A point light, two spheres (one a mirror) on a plane: nothing random.
const POINT_LIT: &str = r#"rtc 1
camera { eye: [0, 2, 6], center: [0, 0.5, 0], up: Y, fov: 40deg, resolution: [40, 30] }
point_light { position: [3, 5, 4], color: rgb(1, 1, 1) }
plane(point: [0, 0, 0], normal: Y).material(material { color: rgb(0.8, 0.8, 0.8) })
sphere(center: [-0.8, 0.6, 0], radius: 0.6).material(material { color: rgb(0.9, 0.2, 0.2), reflect: 0.5 })
sphere(center: [0.8, 0.5, 0.5], radius: 0.5).material(material { color: rgb(0.2, 0.3, 0.9) })
render { max_depth: 2, supersampling: 2 }
"#;

/// The same with an area light: soft shadows, so random numbers.
const AREA_LIT: &str = r#"rtc 1
camera { eye: [0, 2, 6], center: [0, 0.5, 0], up: Y, fov: 40deg, resolution: [40, 30] }
area_light { corner: [1, 4, 1], u: [2, 0, 0], v: [0, 0, 2], samples: 2, color: rgb(1, 1, 1) }
plane(point: [0, 0, 0], normal: Y).material(material { color: rgb(0.8, 0.8, 0.8) })
sphere(center: [-0.8, 0.6, 0], radius: 0.6).material(material { color: rgb(0.9, 0.2, 0.2) })
sphere(center: [0.8, 0.5, 0.5], radius: 0.5).material(material { color: rgb(0.2, 0.3, 0.9) })
render { max_depth: 0, supersampling: 1 }
"#;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-accuracy-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write_scene(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("scene.rtc");
    std::fs::write(&path, text).unwrap();
    path
}

fn load(path: &Path) -> Scene {
    let mut sources = rtc::source::SourceMap::new();
    let loaded = rtc::loader::load(path, &mut sources, &rtc::eval::EvalOptions::default());
    assert!(
        !loaded.diagnostics.has_errors(),
        "{:?}",
        loaded.diagnostics.items
    );
    loaded.scene.expect("the scene evaluates")
}

fn options(reference: ReferenceChoice) -> StudyOptions {
    StudyOptions {
        scene_name: "test".into(),
        scale: Some(1.0),
        max_pixels: rtc::accuracy::scale::DEFAULT_MAX_PIXELS,
        reference,
        measure: MeasureOptions {
            repeat: 1,
            seeds: [0, 1],
            threads: 2,
        },
        joint: true,
        metric: Metric::Flip,
        target_error: None,
        time: None,
    }
}

fn no_cache() -> ReferenceChoice {
    ReferenceChoice::Render { cache_dir: None }
}

struct Quiet;
impl SweepProgress for Quiet {}

fn run(text: &str, name: &str, options: &StudyOptions) -> Report {
    let dir = scratch(name);
    let scene = load(&write_scene(&dir, text));
    let report = study(&scene, options, &Quiet).expect("the study runs");
    let _ = std::fs::remove_dir_all(&dir);
    report
}

/// The points of one ladder, cheapest (fewest rays) first.
fn ladder(report: &Report, knob: Knob) -> Vec<&rtc::accuracy::report::Point> {
    let mut on: Vec<_> = report
        .points
        .iter()
        .filter(|p| p.sweeps.contains(&Sweep::Ladder(knob)))
        .collect();
    on.sort_by_key(|p| p.measurement.rays);
    on
}

#[test]
fn a_scene_without_randomness_gets_no_stochastic_sweep() {
    let report = run(POINT_LIT, "deterministic", &options(no_cache()));
    assert!(!report.stochastic);
    assert_eq!(report.knobs, vec![Knob::PixelSamples, Knob::MaxDepth]);
    assert!(report.complete);
    assert!(report.reference.noise_rmse.is_none());
    for p in &report.points {
        let m = &p.measurement;
        assert_eq!(
            m.runs.len(),
            1,
            "one seed, one repeat: {}",
            m.setting.label()
        );
        assert!(m.noise_rmse.is_none());
        assert_eq!(m.spread.flip_mean, 0.0);
        assert_eq!(m.setting.light_samples, None);
        assert!(m.seconds > 0.0 && m.rays > 0);
    }
    // The scene's own setting comes first; the front is never empty.
    assert_eq!(report.points[0].sweeps[0], Sweep::Scene);
    assert!(report.points.iter().any(|p| p.pareto));
}

#[test]
fn error_falls_as_pixel_samples_rise() {
    let report = run(POINT_LIT, "pixels", &options(no_cache()));
    let points = ladder(&report, Knob::PixelSamples);
    let grids: Vec<u32> = points
        .iter()
        .map(|p| p.measurement.setting.pixel_samples())
        .collect();
    assert_eq!(grids, vec![1, 4, 9, 16, 36, 64]);
    // A regular grid's error is not monotone in f (8×8 can miss the reference's 16×16 sample
    // positions worse than 6×6 does), so the rule is: doubling the samples per axis cuts the
    // RMSE by at least 10%, and the dearest rung has under a quarter of the cheapest's error.
    let rmse: Vec<f64> = points.iter().map(|p| p.measurement.error.rmse).collect();
    let at = |f: u32| rmse[PIXEL_LADDER.iter().position(|&g| g == f).unwrap()];
    for f in [1, 2, 3, 4] {
        assert!(at(2 * f) < 0.9 * at(f), "RMSE along the ladder: {rmse:?}");
    }
    assert!(rmse[5] < 0.25 * rmse[0], "RMSE along the ladder: {rmse:?}");
    let flip: Vec<f64> = points
        .iter()
        .map(|p| p.measurement.error.flip_mean)
        .collect();
    assert!(flip[5] < 0.5 * flip[0], "ꟻLIP along the ladder: {flip:?}");
}

#[test]
fn error_falls_as_light_samples_rise_on_a_fixed_seed() {
    let report = run(AREA_LIT, "lights", &options(no_cache()));
    assert!(report.stochastic);
    assert!(report.knobs.contains(&Knob::LightSamples));
    assert!(!report.knobs.contains(&Knob::MaxDepth), "nothing reflects");
    assert!(report.reference.noise_rmse.is_some_and(|n| n > 0.0));
    let points = ladder(&report, Knob::LightSamples);
    let n: Vec<Option<u32>> = points
        .iter()
        .map(|p| p.measurement.setting.light_samples)
        .collect();
    assert_eq!(n, vec![Some(1), Some(2), Some(3), Some(4), Some(6)]);
    // Seeds 0 and 1 are fixed, so these numbers are the same every run. With one pixel sample
    // the error has a floor (the edges' aliasing against the 16×16 reference), so: RMSE never
    // rises by more than 2% from a rung to the next and falls by a third from 1 to 36
    // samples; the noise share (the two-seed estimate, ∝ 1/n for n×n stratified samples)
    // falls by at least 25% whenever n doubles.
    let rmse: Vec<f64> = points.iter().map(|p| p.measurement.error.rmse).collect();
    for w in rmse.windows(2) {
        assert!(w[1] <= 1.02 * w[0], "RMSE along the ladder: {rmse:?}");
    }
    assert!(rmse[4] < 0.67 * rmse[0], "RMSE along the ladder: {rmse:?}");
    let noise: Vec<f64> = points
        .iter()
        .map(|p| p.measurement.noise_rmse.unwrap())
        .collect();
    for (a, b) in [(0, 1), (1, 3), (2, 4)] {
        assert!(
            noise[b] < 0.75 * noise[a],
            "noise along the ladder: {noise:?}"
        );
    }
    for p in &points {
        assert_eq!(p.measurement.runs.len(), 2, "two seeds");
    }
}

#[test]
fn an_identical_image_measures_zero() {
    // The reference given as a file is the scene's own render: the scene's point measures 0.
    let dir = scratch("identical");
    let scene = load(&write_scene(&dir, POINT_LIT));
    let film = rtc::render::render_scene(
        &scene,
        &rtc::render::RenderOptions {
            threads: 2,
            ..Default::default()
        },
    )
    .expect("renders");
    let data = rtc::accuracy::measure::linear_rgb(&film);
    let view = rtc::metrics::LinearRgb::new(film.width, film.height, &data).unwrap();
    let same = rtc::metrics::compare(view, view).unwrap();
    assert_eq!(same.flip_mean, 0.0);
    assert_eq!(same.flip_worst, 0.0);
    assert_eq!(same.rmse, 0.0);
    assert_eq!(same.rel_mse, 0.0);

    let exr = dir.join("own.exr");
    let img: image::ImageBuffer<image::Rgb<f32>, Vec<f32>> =
        image::ImageBuffer::from_raw(film.width, film.height, data).unwrap();
    img.save(&exr).unwrap();
    let mut o = options(ReferenceChoice::File(exr));
    o.joint = false;
    let report = study(&scene, &o, &Quiet).unwrap();
    let own = &report.own().unwrap().measurement.error;
    assert_eq!((own.flip_mean, own.rmse), (0.0, 0.0));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Cancels once `after` renders are done.
struct CancelAfter {
    done: AtomicU64,
    after: u64,
}

impl SweepProgress for CancelAfter {
    fn render_done(&self) {
        self.done.fetch_add(1, Ordering::SeqCst);
    }
    fn cancelled(&self) -> bool {
        self.done.load(Ordering::SeqCst) >= self.after
    }
}

#[test]
fn an_interrupted_sweep_keeps_the_points_measured() {
    let dir = scratch("interrupt");
    let scene = load(&write_scene(&dir, POINT_LIT));
    // One render for the reference, then three points of one render each.
    let stop = CancelAfter {
        done: AtomicU64::new(0),
        after: 4,
    };
    let report = study(&scene, &options(no_cache()), &stop).unwrap();
    assert!(!report.complete);
    assert_eq!(report.points.len(), 3);
    assert_eq!(report.to_json()["complete"], serde_json::json!(false));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_reference_is_cached_by_content() {
    let dir = scratch("cache");
    let scene = load(&write_scene(&dir, AREA_LIT));
    let cached = ReferenceChoice::Render {
        cache_dir: Some(dir.join("cache")),
    };
    let mut o = options(cached);
    o.joint = false;
    let first = study(&scene, &o, &Quiet).unwrap();
    assert_eq!(
        first.reference.source,
        rtc::accuracy::reference::Source::Rendered
    );
    let second = study(&scene, &o, &Quiet).unwrap();
    assert!(matches!(
        second.reference.source,
        rtc::accuracy::reference::Source::Cached(ref files) if files.len() == 2
    ));
    assert_eq!(first.reference.noise_rmse, second.reference.noise_rmse);
    let errors =
        |r: &Report| -> Vec<f64> { r.points.iter().map(|p| p.measurement.error.rmse).collect() };
    assert_eq!(errors(&first), errors(&second));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Whether `value` has the shape `shape` (report-shape.json's notation: a string names the
/// allowed JSON types joined by `|`, an object lists exactly the keys, an array's one element
/// is every element's shape).
fn matches_shape(
    value: &serde_json::Value,
    shape: &serde_json::Value,
    at: &str,
) -> Result<(), String> {
    use serde_json::Value;
    match shape {
        Value::String(types) => {
            let kind = match value {
                Value::Null => "null",
                Value::Bool(_) => "bool",
                Value::Number(_) => "number",
                Value::String(_) => "string",
                Value::Array(_) => "array",
                Value::Object(_) => "object",
            };
            if types.split('|').any(|t| t == kind) {
                Ok(())
            } else {
                Err(format!("{at}: a {kind}, the schema says {types}"))
            }
        }
        Value::Object(fields) => {
            let Value::Object(got) = value else {
                return Err(format!("{at}: not an object"));
            };
            let want: Vec<&String> = fields.keys().collect();
            let have: Vec<&String> = got.keys().collect();
            if want != have {
                return Err(format!("{at}: keys {have:?}, the schema says {want:?}"));
            }
            for (k, s) in fields {
                matches_shape(&got[k], s, &format!("{at}.{k}"))?;
            }
            Ok(())
        }
        Value::Array(one) => {
            let Value::Array(items) = value else {
                return Err(format!("{at}: not an array"));
            };
            if items.is_empty() {
                return Err(format!("{at}: empty, so its shape is not checked"));
            }
            items
                .iter()
                .enumerate()
                .try_for_each(|(i, v)| matches_shape(v, &one[0], &format!("{at}[{i}]")))
        }
        _ => Err(format!("{at}: the schema file has a {shape}")),
    }
}

#[test]
fn the_command_writes_the_report_the_plot_and_the_map_and_json_has_the_documented_shape() {
    let dir = scratch("cli");
    let scene = write_scene(&dir, AREA_LIT);
    let out = dir.join("out");
    let accuracy = |extra: &[&str]| {
        let run = Command::new(env!("CARGO_BIN_EXE_rtc"))
            .args(["accuracy", scene.to_str().unwrap(), "--no-joint"])
            .args(["--threads", "2"])
            .args(extra)
            .arg("--out-dir")
            .arg(&out)
            .env("RTC_CACHE_DIR", dir.join("cache"))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr).into_owned();
        assert_eq!(run.status.code(), Some(0), "{stderr}");
        String::from_utf8_lossy(&run.stdout).into_owned()
    };
    // The first run renders and caches the reference and prints the table.
    let text = accuracy(&[]);
    assert!(text.contains("swept at 40×30\n"), "{text}");
    assert!(
        text.contains("light samples") && text.contains('*'),
        "{text}"
    );
    assert_eq!(std::fs::read_dir(dir.join("cache")).unwrap().count(), 2);
    // The second reads the cache (so `reference.files` is not empty) and prints JSON.
    let json = accuracy(&["--format", "json", "--target-error", "1", "--time", "1h"]);
    let doc: serde_json::Value = serde_json::from_str(&json).expect("JSON on stdout");
    let shape: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string("tests/data/accuracy/report-shape.json").unwrap(),
    )
    .unwrap();
    matches_shape(&doc, &shape, "$").unwrap();
    assert_eq!(doc["schema"], "rtc-accuracy/1");
    assert_eq!(doc["reference"]["source"], "cache");
    let on_disk: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(on_disk, doc);
    // Both goals are met by some point: every point is within an error of 1 and an hour.
    for r in doc["recommendations"].as_array().unwrap() {
        let block = r["render_block"].as_str().unwrap();
        assert!(block.starts_with("render { supersampling: "), "{block}");
    }
    let svg = std::fs::read_to_string(out.join("plot.svg")).unwrap();
    assert!(svg.contains("light samples"), "one curve per knob");
    assert!(
        svg.contains("scene&apos;s setting (grid 1, depth 0)"),
        "the scene's own setting"
    );
    let map = image::open(out.join("flip-map.png")).unwrap();
    assert_eq!((map.width(), map.height()), (40, 30));
    // A reduced size is reported.
    let half = accuracy(&["--scale", "0.5"]);
    assert!(
        half.contains("swept at 20×15 (scale 0.500 of 40×30)"),
        "{half}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_reference_of_the_wrong_size_is_a_clear_error() {
    let dir = scratch("badref");
    let scene = write_scene(&dir, POINT_LIT);
    let png = dir.join("small.png");
    image::RgbImage::new(4, 4).save(&png).unwrap();
    let run = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["accuracy", scene.to_str().unwrap(), "--reference"])
        .arg(&png)
        .arg("--out-dir")
        .arg(dir.join("out"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("rtc::accuracy::reference_size"), "{stderr}");
    assert!(stderr.contains("40×30"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}
