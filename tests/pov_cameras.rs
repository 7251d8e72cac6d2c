//! POV-Ray camera twins (issue 37, cameras): every `tests/data/pov_cameras/NAME.rtc` rendered
//! by rtc against `NAME.png`, POV-Ray 3.7's render of its twin `NAME.pov` (made by `render.sh`
//! there and committed, so POV-Ray is not needed here), with the rule of `tests/pov_twins.rs`:
//! a pixel differs when one of its channels is more than 2 levels off, and at most 0.5 % of a
//! twin's pixels may differ. Each twin is one flat-lit scene of coloured spheres over a checker
//! floor seen through one projection (orthographic, equirectangular, fisheye, cylindrical).

use std::path::{Path, PathBuf};

use rtc::eval::EvalOptions;
use rtc::render::{Image, RenderOptions, render_image};
use rtc::source::SourceMap;

/// A channel more than this many levels off makes a pixel differ.
const LEVELS: i32 = 2;
/// The largest share of differing pixels a twin may have.
const SHARE: f64 = 0.005;

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pov_cameras")
}

/// Every twin's name: the `NAME.rtc` files of the directory, sorted.
fn twins() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir())
        .expect("tests/data/pov_cameras is readable")
        .filter_map(|e| {
            let path = e.ok()?.path();
            (path.extension()? == "rtc").then(|| path.file_stem()?.to_str().map(String::from))?
        })
        .collect();
    names.sort();
    names
}

/// rtc's render of `NAME.rtc`, the bytes its PNG output would hold.
fn render(name: &str) -> Image {
    let path = dir().join(format!("{name}.rtc"));
    let mut sources = SourceMap::default();
    let loaded = rtc::loader::load(&path, &mut sources, &EvalOptions::default());
    assert!(
        !loaded.diagnostics.has_errors(),
        "{name}.rtc: {:?}",
        loaded.diagnostics.items
    );
    let scene = loaded.scene.expect("the twin evaluates");
    let options = RenderOptions {
        threads: 2,
        ..Default::default()
    };
    render_image(&scene, &options).expect("the twin renders")
}

/// The number of pixels more than [`LEVELS`] off, the largest difference and where it is.
fn compare(name: &str, ours: &Image) -> (usize, i32, (u32, u32)) {
    let png = dir().join(format!("{name}.png"));
    let theirs = image::open(&png)
        .unwrap_or_else(|e| {
            panic!(
                "{name}: no reference {}: {e} (run render.sh)",
                png.display()
            )
        })
        .to_rgb8();
    assert_eq!(
        ours.dimensions(),
        theirs.dimensions(),
        "{name}: sizes differ"
    );
    let (mut differing, mut worst, mut at) = (0, 0, (0, 0));
    for (x, y, a) in ours.enumerate_pixels() {
        let b = theirs.get_pixel(x, y);
        let d = (0..3)
            .map(|c| (i32::from(a.0[c]) - i32::from(b.0[c])).abs())
            .max()
            .unwrap_or(0);
        differing += usize::from(d > LEVELS);
        if d > worst {
            (worst, at) = (d, (x, y));
        }
    }
    (differing, worst, at)
}

#[test]
fn every_camera_twin_matches_its_povray_render() {
    let names = twins();
    assert!(
        names.len() >= 8,
        "expected the twins in {}",
        dir().display()
    );
    let mut failures = Vec::new();
    for name in &names {
        let ours = render(name);
        let (differing, worst, at) = compare(name, &ours);
        let pixels = (ours.width() * ours.height()) as usize;
        let share = differing as f64 / pixels as f64;
        eprintln!(
            "{name:24} {differing:5} of {pixels} pixels differ ({:.3} %), largest difference {worst} levels at {at:?}",
            100.0 * share
        );
        if share > SHARE {
            failures.push(format!(
                "{name}: {differing} of {pixels} pixels differ ({:.2} % > {:.1} %), the largest by {worst} levels at {at:?}",
                100.0 * share,
                100.0 * SHARE
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
