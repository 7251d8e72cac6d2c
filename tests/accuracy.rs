//! `rtc accuracy` (src/accuracy/, src/cli/accuracy.rs) on tiny scenes: which knobs are swept,
//! that error falls as samples rise, that an identical image measures 0, that an interrupted
//! sweep keeps its points, the reference cache, and the JSON report's shape, pinned by the
//! hand-written tests/data/accuracy/report-shape.json (the schema docs/accuracy.md documents;
//! the command-line tests are in tests/accuracy/command.rs).
//! Nothing here is timed: times are only checked to be positive.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use rtc::accuracy::knob::PIXEL_LADDER;
use rtc::accuracy::sweep::Sweep;
use rtc::accuracy::{
    Knob, MeasureOptions, Metric, ReferenceChoice, Report, StudyOptions, SweepProgress, study,
};
use rtc::ir::Scene;

/// The command-line tests: `rtc accuracy` as a user runs it, and its JSON report's shape.
#[path = "accuracy/command.rs"]
mod command;

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
        region: None,
        reference,
        measure: MeasureOptions {
            repeat: 1,
            seeds: [0, 1],
            threads: 2,
            region: None,
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
/// The RMSE and the two-seed noise estimate of each point of a stochastic ladder.
fn errors_along(points: &[&rtc::accuracy::report::Point]) -> (Vec<f64>, Vec<f64>) {
    let rmse = points.iter().map(|p| p.measurement.error.rmse).collect();
    let noise = points
        .iter()
        .map(|p| {
            p.measurement
                .noise_rmse
                .expect("a stochastic ladder estimates its noise")
        })
        .collect();
    (rmse, noise)
}

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
    assert_eq!(
        report.knobs,
        vec![
            Knob::PixelSamples,
            Knob::AdaptiveThreshold,
            Knob::MaxDepth,
            Knob::Cutoff
        ],
        "a mirror but no gloss: bounces and the cut-off, no gloss samples; adaptive is offered to a uniform grid"
    );
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
    // Asked for no target: the cheapest setting at the scene's own error (issue 34).
    let [rec] = &report.recommendations[..] else {
        panic!("one default recommendation: {:?}", report.recommendations)
    };
    assert_eq!(rec.goal, "scene_error");
    let own = report.metric.of(&report.points[0].measurement.error);
    assert_eq!(rec.value, own);
    assert!(
        rec.point.is_some() && rec.predicted_error.is_some_and(|e| e <= own),
        "{rec:?}"
    );
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
    assert!(!report.knobs.contains(&Knob::Cutoff), "nothing reflects");
    assert!(
        !report.knobs.contains(&Knob::GlossSamples),
        "nothing is glossy"
    );
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
    let (rmse, noise) = errors_along(&points);
    for w in rmse.windows(2) {
        assert!(w[1] <= 1.02 * w[0], "RMSE along the ladder: {rmse:?}");
    }
    assert!(rmse[4] < 0.67 * rmse[0], "RMSE along the ladder: {rmse:?}");
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
    write_exr(&exr, film.width, film.height, data);
    let mut o = options(ReferenceChoice::File(exr));
    o.joint = false;
    let report = study(&scene, &o, &Quiet).unwrap();
    let own = &report.own().unwrap().measurement.error;
    assert_eq!((own.flip_mean, own.rmse), (0.0, 0.0));
    let _ = std::fs::remove_dir_all(&dir);
}

fn write_exr(path: &Path, width: u32, height: u32, data: Vec<f32>) {
    let img: image::ImageBuffer<image::Rgb<f32>, Vec<f32>> =
        image::ImageBuffer::from_raw(width, height, data).unwrap();
    img.save(path).unwrap();
}

/// Two facing mirrors and a point light: a long chain of ever lighter reflections, so the
/// cut-off drops rays at every rung above 0.
const MIRRORS: &str = r#"rtc 1
camera { eye: [0, 1.5, 5], center: [0, 0.6, 0], up: Y, fov: 50deg, resolution: [32, 24] }
point_light { position: [2, 4, 3], color: rgb(1, 1, 1) }
plane(point: [0, 0, 0], normal: Y).material(material { color: rgb(0.7, 0.7, 0.7), reflect: 0.3 })
sphere(center: [-0.9, 0.7, 0], radius: 0.7).material(material { color: rgb(0.2, 0.2, 0.2), reflect: 0.8 })
sphere(center: [0.9, 0.7, 0], radius: 0.7).material(material { color: rgb(0.2, 0.2, 0.6), reflect: 0.6 })
render { max_depth: 8, supersampling: 1, cutoff: 0.01 }
"#;

#[test]
fn the_cutoff_ladder_runs_from_large_cutoffs_to_zero() {
    // The reference is the scene's own setting with the cut-off at 0, so the ladder's last
    // rung is that very render: error exactly 0. Every ray's contribution is non-negative, so
    // a larger cut-off only removes light: RMSE never falls and rays never rise as it grows.
    let dir = scratch("cutoff");
    let mut scene = load(&write_scene(&dir, MIRRORS));
    let report = study(&scene, &options(no_cache()), &Quiet).unwrap();
    assert!(report.knobs.contains(&Knob::Cutoff));
    assert!(!report.knobs.contains(&Knob::GlossSamples));
    assert_eq!(report.reference.setting.unwrap().cutoff, 0.0);

    scene.settings.cutoff = 0.0;
    let film = rtc::render::render_scene(
        &scene,
        &rtc::render::RenderOptions {
            threads: 2,
            ..Default::default()
        },
    )
    .expect("renders");
    let exr = dir.join("uncut.exr");
    write_exr(
        &exr,
        film.width,
        film.height,
        rtc::accuracy::measure::linear_rgb(&film),
    );
    scene.settings.cutoff = 0.01;
    let mut o = options(ReferenceChoice::File(exr));
    o.joint = false;
    let report = study(&scene, &o, &Quiet).unwrap();
    let mut points: Vec<_> = report
        .points
        .iter()
        .filter(|p| p.sweeps.contains(&Sweep::Ladder(Knob::Cutoff)))
        .collect();
    points.sort_by(|a, b| {
        b.measurement
            .setting
            .cutoff
            .total_cmp(&a.measurement.setting.cutoff)
    });
    let cutoffs: Vec<f64> = points
        .iter()
        .map(|p| p.measurement.setting.cutoff)
        .collect();
    assert_eq!(cutoffs, rtc::accuracy::knob::CUTOFF_LADDER.to_vec());
    let last = &points.last().unwrap().measurement;
    assert_eq!((last.error.rmse, last.error.flip_mean), (0.0, 0.0));
    for w in points.windows(2) {
        let (a, b) = (&w[0].measurement, &w[1].measurement);
        assert!(
            a.error.rmse >= b.error.rmse,
            "{} vs {}",
            a.setting.label(),
            b.setting.label()
        );
        assert!(
            a.rays <= b.rays,
            "{} vs {}",
            a.setting.label(),
            b.setting.label()
        );
    }
    assert!(points[0].measurement.rays < last.rays, "0.1 cuts rays");
    assert!(points[0].measurement.error.rmse > 0.0, "0.1 loses light");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A glossy mirror sphere over a checker plane, point lit: only the lobe draws random numbers.
const GLOSSY: &str = r#"rtc 1
camera { eye: [0, 1.5, 5], center: [0, 0.6, 0], up: Y, fov: 40deg, resolution: [32, 24] }
point_light { position: [2, 4, 3], color: rgb(1, 1, 1) }
plane(point: [0, 0, 0], normal: Y).material(material { color: rgb(0.8, 0.8, 0.8), texture: checker(size: 0.5, a: rgb(0.9, 0.9, 0.9), b: rgb(0.1, 0.1, 0.1)) })
sphere(center: [0, 0.9, 0], radius: 0.9).material(material { color: rgb(0.2, 0.2, 0.2), reflect: 0.8, gloss: 0.3, gloss_samples: 2 })
render { max_depth: 1, supersampling: 2 }
"#;

/// A rectangle inside the glossy sphere of [`GLOSSY`] (32×24 image).
const MIDDLE: &str = "12,6,8,8";

#[test]
fn error_falls_as_gloss_samples_rise_on_a_fixed_seed() {
    // Only the middle of the sphere, where the lobe's noise is the error: the whole image's
    // RMSE is mostly the 2×2 grid's edge aliasing against the 16×16 reference, which gloss
    // samples do not touch.
    let mut o = options(no_cache());
    o.joint = false;
    o.region = Some(rtc::render::Region::parse(MIDDLE).unwrap());
    let report = run(GLOSSY, "gloss", &o);
    assert!(report.stochastic);
    assert!(report.knobs.contains(&Knob::GlossSamples));
    assert_eq!(report.reference.setting.unwrap().gloss_samples, Some(16));
    let points = ladder(&report, Knob::GlossSamples);
    let n: Vec<Option<u32>> = points
        .iter()
        .map(|p| p.measurement.setting.gloss_samples)
        .collect();
    assert_eq!(n, vec![Some(1), Some(2), Some(4), Some(8), Some(16)]);
    // Seeds 0 and 1 are fixed, so these numbers are the same every run (measured: RMSE 0.093,
    // 0.064, 0.042, 0.029, 0.016). The lobe's error is noise, ∝ 1/√n for n rays: RMSE falls
    // by at least 10% from a rung to the next and to under 40% from 1 to 16 rays (1/√16 = 25%
    // with a little floor); the two-seed noise estimate falls by 25% whenever n quadruples.
    let (rmse, noise) = errors_along(&points);
    for w in rmse.windows(2) {
        assert!(w[1] <= 0.9 * w[0], "RMSE along the ladder: {rmse:?}");
    }
    assert!(rmse[4] < 0.4 * rmse[0], "RMSE along the ladder: {rmse:?}");
    for (a, b) in [(0, 2), (1, 3), (2, 4)] {
        assert!(
            noise[b] < 0.75 * noise[a],
            "noise along the ladder: {noise:?}"
        );
    }
}

#[test]
fn a_region_renders_the_pixels_of_the_whole_image() {
    // Pixels keep their full-image coordinates, so their rays and random numbers are the
    // whole render's: the region's film is that rectangle of the whole film, bit for bit.
    let dir = scratch("region");
    let scene = load(&write_scene(&dir, GLOSSY));
    let prepared = rtc::opt::prepare(&scene).unwrap();
    let opts = rtc::render::RenderOptions {
        threads: 2,
        ..Default::default()
    };
    let whole = rtc::render::render(&prepared, &opts, &rtc::render::Silent).unwrap();
    let r = rtc::render::Region::parse(MIDDLE).unwrap();
    let part = rtc::render::render_region(&prepared, &opts, Some(r), &rtc::render::Silent).unwrap();
    assert_eq!((part.width, part.height), (r.width, r.height));
    for y in 0..r.height {
        for x in 0..r.width {
            let full = ((r.y + y) * whole.width + r.x + x) as usize;
            let here = (y * r.width + x) as usize;
            assert_eq!(part.color()[here], whole.color()[full], "pixel {x},{y}");
        }
    }
    // Fewer camera rays: only the region's.
    assert_eq!(part.stats.camera_rays, u64::from(r.width * r.height) * 4);
    let outside = rtc::render::Region::parse("30,20,4,4").unwrap();
    let err = rtc::render::render_region(&prepared, &opts, Some(outside), &rtc::render::Silent)
        .unwrap_err();
    assert_eq!(err.code, rtc::render::region::REGION);
    assert!(err.message.contains("32×24"), "{}", err.message);
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
