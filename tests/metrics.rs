//! Image error metrics (src/metrics): ꟻLIP against NVIDIA's own implementation, and the
//! properties every metric must have (0 for identical images, growing with noise).
//!
//! Reference numbers: tests/data/flip/reference.tsv, made by tests/data/flip/make_reference.py with
//! the `flip-evaluator` package (NVIDIA's ꟻLIP for Python), independent of rtc's code.

use std::path::PathBuf;

use rtc::metrics::{self, LinearRgb, srgb};

/// The largest difference allowed between rtc's mean ꟻLIP and flip-evaluator's. Both run
/// NVIDIA's C++ on the same 8-bit sRGB values, but nv-flip 0.1.2 bundles an older release of it
/// than flip-evaluator 1.7 and sums in another order: measured differences are at most 1.7e-5
/// (on means from 0.01 to 0.26), so 5e-5 leaves room without hiding a real change (a wrong
/// viewing distance or colour curve moves these means by 1e-3 or more).
const FLIP_MEAN_TOLERANCE: f64 = 5e-5;

/// The same for the mean of the worst 1% of the map (measured: at most 6.3e-5 on values from
/// 0.07 to 0.92); fewer pixels average out less of the per-pixel difference.
const FLIP_WORST_TOLERANCE: f64 = 1.5e-4;

/// The largest difference allowed between rtc's RMSE and numpy's (numpy decodes to f64, rtc to
/// f32, a rounding of at most 3e-8 per channel; measured: at most 5e-8).
const RMSE_TOLERANCE: f64 = 1e-6;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A PNG decoded to linear light: (width, height, channels).
fn load(rel: &str) -> (u32, u32, Vec<f32>) {
    let img = image::open(root().join(rel))
        .unwrap_or_else(|e| panic!("{rel}: {e}"))
        .into_rgb8();
    (img.width(), img.height(), srgb::decode_all(img.as_raw()))
}

fn view(img: &(u32, u32, Vec<f32>)) -> LinearRgb<'_> {
    LinearRgb::new(img.0, img.1, &img.2).expect("a valid image")
}

/// One line of reference.tsv.
struct Reference {
    name: String,
    test: String,
    reference: String,
    mean_flip: f64,
    worst_flip: f64,
    rmse: f64,
}

fn references() -> Vec<Reference> {
    let text = std::fs::read_to_string(root().join("tests/data/flip/reference.tsv"))
        .expect("reference.tsv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            let num = |i: usize| f[i].parse::<f64>().expect("a number");
            Reference {
                name: f[0].into(),
                test: f[1].into(),
                reference: f[2].into(),
                mean_flip: num(3),
                worst_flip: num(4),
                rmse: num(5),
            }
        })
        .collect()
}

#[test]
fn flip_matches_nvidia_flip_evaluator() {
    let refs = references();
    assert_eq!(refs.len(), 8, "every pair of make_reference.py");
    for r in refs {
        let (test, reference) = (load(&r.test), load(&r.reference));
        let c = metrics::compare(view(&test), view(&reference)).expect("same size");
        let near = |ours: f64, theirs: f64, tol: f64| (ours - theirs).abs() <= tol;
        assert!(
            near(c.flip_mean, r.mean_flip, FLIP_MEAN_TOLERANCE),
            "{}: mean ꟻLIP {} vs flip-evaluator {}",
            r.name,
            c.flip_mean,
            r.mean_flip
        );
        assert!(
            near(c.flip_worst, r.worst_flip, FLIP_WORST_TOLERANCE),
            "{}: worst-1% ꟻLIP {} vs flip-evaluator {}",
            r.name,
            c.flip_worst,
            r.worst_flip
        );
        assert!(
            near(c.rmse, r.rmse, RMSE_TOLERANCE),
            "{}: RMSE {} vs numpy {}",
            r.name,
            c.rmse,
            r.rmse
        );
    }
}

#[test]
fn the_magma_map_matches_flip_evaluators_picture() {
    let test = load("tests/data/flip/zoom-1x1.png");
    let reference = load("tests/data/flip/zoom-4x4.png");
    let map = metrics::flip(view(&test), view(&reference)).unwrap();
    let png = map.magma_png().unwrap();
    let ours = image::load_from_memory(&png).unwrap().into_rgb8();
    let theirs = image::open(root().join("tests/data/flip/zoom-1x1-vs-4x4-magma.png"))
        .unwrap()
        .into_rgb8();
    assert_eq!(ours.dimensions(), theirs.dimensions());
    // The same 256-entry table indexed by round(255·error): a map value within 1e-6 of a
    // rounding boundary may pick the neighbouring entry, a step of at most a few levels.
    let worst = ours
        .as_raw()
        .iter()
        .zip(theirs.as_raw())
        .map(|(a, b)| a.abs_diff(*b))
        .max()
        .unwrap();
    assert!(worst <= 4, "largest channel difference {worst}");
}

#[test]
fn identical_images_score_zero_on_every_metric() {
    for rel in [
        "tests/data/flip/scene02-crop.png",
        "tests/data/course/reference/scene01-lights-shadows.png",
    ] {
        let img = load(rel);
        let c = metrics::compare(view(&img), view(&img)).unwrap();
        assert_eq!(c.flip_mean, 0.0, "{rel}");
        assert_eq!(c.flip_worst, 0.0, "{rel}");
        assert_eq!(c.rmse, 0.0, "{rel}");
        assert_eq!(c.rel_mse, 0.0, "{rel}");
        assert_eq!(c.squared_error_worst, 0.0, "{rel}");
        assert!(c.flip_map.values().iter().all(|&v| v == 0.0));
        let n = metrics::noise(view(&img), view(&img)).unwrap();
        assert_eq!((n.variance, n.rmse, n.flip_between_runs), (0.0, 0.0, 0.0));
    }
}

/// Every metric of `test` against `reference`, in the order of the assertions below.
fn all_metrics(test: LinearRgb<'_>, reference: LinearRgb<'_>) -> [f64; 5] {
    let c = metrics::compare(test, reference).unwrap();
    [
        c.flip_mean,
        c.flip_worst,
        c.rmse,
        c.rel_mse,
        c.squared_error_worst,
    ]
}

const NAMES: [&str; 5] = ["mean ꟻLIP", "worst ꟻLIP", "RMSE", "relMSE", "worst squared"];

#[test]
fn error_grows_with_the_committed_noise_amplitude() {
    let reference = load("tests/data/flip/scene02-crop.png");
    let mut last = [0.0; 5];
    for amplitude in [4, 16, 48] {
        let test = load(&format!("tests/data/flip/scene02-noise-{amplitude}.png"));
        let now = all_metrics(view(&test), view(&reference));
        for i in 0..5 {
            assert!(
                now[i] > last[i],
                "{} at amplitude {amplitude}: {} after {}",
                NAMES[i],
                now[i],
                last[i]
            );
        }
        last = now;
    }
}

/// A smooth test image (a colour gradient with a bright disc) with uniform noise of `amplitude`
/// in linear light, from a fixed hash, so the test is deterministic.
fn gradient(width: u32, height: u32, amplitude: f32, key: u32) -> Vec<f32> {
    let mut out = Vec::with_capacity((width * height * 3) as usize);
    for y in 0..height {
        for x in 0..width {
            let (u, v) = (x as f32 / width as f32, y as f32 / height as f32);
            let disc = if (u - 0.5).powi(2) + (v - 0.5).powi(2) < 0.05 {
                0.6
            } else {
                0.0
            };
            for (c, base) in [0.2 + 0.6 * u, 0.1 + 0.5 * v, 0.3 + disc]
                .into_iter()
                .enumerate()
            {
                let n = unit_noise((y * width + x) * 3 + c as u32, key);
                out.push((base + amplitude * n).max(0.0));
            }
        }
    }
    out
}

/// A value in [-1, 1) from Wellons' lowbias32 hash of (i, key).
fn unit_noise(i: u32, key: u32) -> f32 {
    let mut x = i ^ key.wrapping_mul(0x9e37_79b9);
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    (f64::from(x) / 2f64.powi(31) - 1.0) as f32
}

#[test]
fn error_grows_with_linear_noise_amplitude() {
    let (w, h) = (96, 64);
    let clean = gradient(w, h, 0.0, 0);
    let reference = LinearRgb::new(w, h, &clean).unwrap();
    let mut last = [0.0; 5];
    for amplitude in [0.005, 0.02, 0.08, 0.3] {
        let noisy = gradient(w, h, amplitude, 1);
        let now = all_metrics(LinearRgb::new(w, h, &noisy).unwrap(), reference);
        for i in 0..5 {
            assert!(now[i] > last[i], "{} at {amplitude}", NAMES[i]);
        }
        last = now;
    }
}

#[test]
fn noise_estimate_recovers_a_known_variance() {
    // Two "renders" of one image with independent uniform noise of amplitude a: the per-channel
    // variance is a²/3. 96·64·3 = 18 432 channel pairs put the estimate within ~2% (1σ ≈ 1%).
    let (w, h, a) = (96, 64, 0.05f32);
    let (run_a, run_b) = (gradient(w, h, a, 11), gradient(w, h, a, 12));
    let n = metrics::noise(
        LinearRgb::new(w, h, &run_a).unwrap(),
        LinearRgb::new(w, h, &run_b).unwrap(),
    )
    .unwrap();
    let expected = f64::from(a * a) / 3.0;
    assert!(
        (n.variance / expected - 1.0).abs() < 0.04,
        "σ̂² = {} for σ² = {expected}",
        n.variance
    );
    assert!((n.rmse - n.variance.sqrt()).abs() < 1e-15);
    assert!(n.flip_between_runs > 0.0);
}

#[test]
fn rel_mse_uses_the_stated_epsilon() {
    // One channel off by 0.1 on a reference of 0.5: 0.01 / (0.25 + ε), averaged over 3 channels.
    let reference = [0.5f32, 0.5, 0.5];
    let test = [0.6f32, 0.5, 0.5];
    let r = metrics::rel_mse(
        LinearRgb::new(1, 1, &test).unwrap(),
        LinearRgb::new(1, 1, &reference).unwrap(),
    )
    .unwrap();
    let d = f64::from(0.6f32) - 0.5;
    let expected = d * d / (0.25 + metrics::REL_MSE_EPSILON) / 3.0;
    assert!((r - expected).abs() < 1e-12, "{r} vs {expected}");
    assert_eq!(metrics::REL_MSE_EPSILON, 0.01);
}

#[test]
fn worst_squared_error_is_the_mean_of_the_worst_pixels() {
    // 200 pixels, one wrong by 1 in every channel, one by 0.5: the worst 1% is 2 pixels.
    let reference = vec![0.25f32; 200 * 3];
    let mut test = reference.clone();
    test[..3].fill(1.25);
    test[3..6].fill(0.75);
    let c = metrics::compare(
        LinearRgb::new(20, 10, &test).unwrap(),
        LinearRgb::new(20, 10, &reference).unwrap(),
    )
    .unwrap();
    assert!((c.squared_error_worst - (1.0 + 0.25) / 2.0).abs() < 1e-12);
}

#[test]
fn bad_input_is_a_diagnostic_not_a_panic() {
    let small = vec![0.5f32; 2 * 2 * 3];
    let big = vec![0.5f32; 3 * 2 * 3];
    let code = |r: Result<LinearRgb<'_>, rtc::diag::Diagnostic>| r.unwrap_err().code;
    assert_eq!(code(LinearRgb::new(2, 3, &small)), metrics::BUFFER_SIZE);
    assert_eq!(code(LinearRgb::new(0, 3, &[])), metrics::EMPTY);
    // Checked before the buffer: no 17 GB buffer is needed to hit the budget.
    assert_eq!(
        code(LinearRgb::new(65536, 32768, &small)),
        metrics::TOO_LARGE
    );
    let mut nan = small.clone();
    nan[7] = f32::NAN;
    let d = LinearRgb::new(2, 2, &nan).unwrap_err();
    assert_eq!(d.code, metrics::NOT_FINITE);
    assert!(d.message.contains("pixel (0, 1)"), "{}", d.message);
    let (a, b) = (
        LinearRgb::new(2, 2, &small).unwrap(),
        LinearRgb::new(3, 2, &big).unwrap(),
    );
    assert_eq!(
        metrics::compare(a, b).unwrap_err().code,
        metrics::SIZE_MISMATCH
    );
    assert_eq!(
        metrics::noise(a, b).unwrap_err().code,
        metrics::SIZE_MISMATCH
    );
    assert!(metrics::rmse(a, b).unwrap_err().help.is_some());
}

#[test]
fn tiny_images_work() {
    let one = [0.2f32, 0.4, 0.6];
    let other = [0.3f32, 0.4, 0.6];
    let c = metrics::compare(
        LinearRgb::new(1, 1, &other).unwrap(),
        LinearRgb::new(1, 1, &one).unwrap(),
    )
    .unwrap();
    assert!(c.flip_mean > 0.0 && c.flip_mean <= 1.0);
    assert_eq!(c.flip_mean, c.flip_worst);
}
