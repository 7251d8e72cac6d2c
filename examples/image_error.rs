//! Measures PNG renders against a reference PNG with `rtc::metrics` (a study tool until
//! `rtc accuracy` exists; docs/accuracy-study.md shows it at work).
//!
//! ```text
//! cargo run --release --example image_error -- REFERENCE.png TEST.png... [--maps DIR]
//! cargo run --release --example image_error -- --noise RUN_A.png RUN_B.png
//! ```
//!
//! PNG bytes are taken as the sRGB picture a viewer sees and decoded to linear light, so ꟻLIP
//! judges exactly the file's bytes. The first form prints one tab-separated line per test image
//! (mean ꟻLIP, worst-1% ꟻLIP, RMSE, relMSE, worst-1% squared error) and with `--maps` writes
//! each ꟻLIP map as DIR/NAME.flip.png; the second prints the noise estimate of two runs that
//! differ only in their seed.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use rtc::metrics::{self, LinearRgb, srgb};

/// A decoded PNG: width, height, linear channels.
struct Loaded {
    width: u32,
    height: u32,
    linear: Vec<f32>,
}

impl Loaded {
    fn open(path: &Path) -> Result<Loaded, String> {
        let img = image::open(path)
            .map_err(|e| format!("{}: {e}", path.display()))?
            .into_rgb8();
        Ok(Loaded {
            width: img.width(),
            height: img.height(),
            linear: srgb::decode_all(img.as_raw()),
        })
    }

    fn view(&self) -> Result<LinearRgb<'_>, String> {
        LinearRgb::new(self.width, self.height, &self.linear).map_err(|d| d.message)
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = if args.first().map(String::as_str) == Some("--noise") {
        noise(&args[1..])
    } else {
        compare(&args)
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("image_error: {message}");
            ExitCode::from(2)
        }
    }
}

fn noise(args: &[String]) -> Result<(), String> {
    let [a, b] = args else {
        return Err("usage: image_error --noise RUN_A.png RUN_B.png".into());
    };
    let (a, b) = (Loaded::open(a.as_ref())?, Loaded::open(b.as_ref())?);
    let n = metrics::noise(a.view()?, b.view()?).map_err(|d| d.message)?;
    println!("noise_variance\tnoise_rmse\tflip_between_runs");
    println!(
        "{:.4e}\t{:.6}\t{:.6}",
        n.variance, n.rmse, n.flip_between_runs
    );
    Ok(())
}

fn compare(args: &[String]) -> Result<(), String> {
    let mut maps: Option<PathBuf> = None;
    let mut files = Vec::new();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        if a == "--maps" {
            maps = Some(it.next().ok_or("--maps needs a folder")?.into());
        } else {
            files.push(PathBuf::from(a));
        }
    }
    let Some((reference, tests)) = files.split_first() else {
        return Err("usage: image_error REFERENCE.png TEST.png... [--maps DIR]".into());
    };
    let reference = Loaded::open(reference)?;
    println!("test\tmean_flip\tworst1_flip\trmse\trel_mse\tworst1_sq_err");
    for path in tests {
        let test = Loaded::open(path)?;
        let c = metrics::compare(test.view()?, reference.view()?).map_err(|d| d.message)?;
        let name = path
            .file_stem()
            .map_or_else(String::new, |s| s.to_string_lossy().into());
        println!(
            "{name}\t{:.6}\t{:.6}\t{:.6}\t{:.4e}\t{:.4e}",
            c.flip_mean, c.flip_worst, c.rmse, c.rel_mse, c.squared_error_worst
        );
        if let Some(dir) = &maps {
            let png = c.flip_map.magma_png().map_err(|d| d.message)?;
            let out = dir.join(format!("{name}.flip.png"));
            std::fs::write(&out, png).map_err(|e| format!("{}: {e}", out.display()))?;
        }
    }
    Ok(())
}
