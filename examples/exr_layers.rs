//! Writes one PNG per layer of an EXR that `rtc render --aov` wrote, for looking at them
//! (docs/aov.md's pictures are made with it).
//!
//! ```text
//! cargo run --release --example exr_layers -- IMAGE.exr OUT_PREFIX
//! ```
//!
//! colour: sRGB-encoded and clamped; depth: inverse depth, the nearest point white, background
//! black; normal: `(N + 1) / 2`; albedo: sRGB; object: a distinct colour per id
//! (background black).

use std::collections::BTreeMap;
use std::path::Path;
use std::process::ExitCode;

use exr::prelude::{FlatSamples, ReadChannels, ReadLayers};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [input, prefix] = args.as_slice() else {
        eprintln!("usage: exr_layers IMAGE.exr OUT_PREFIX");
        return ExitCode::from(2);
    };
    match run(Path::new(input), prefix) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(input: &Path, prefix: &str) -> Result<(), String> {
    let image = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_file(input)
        .map_err(|e| format!("cannot read {}: {e}", input.display()))?;
    let size = image.layer_data.size;
    let (w, h) = (size.0 as u32, size.1 as u32);
    let mut ch: BTreeMap<String, Vec<f64>> = BTreeMap::new();
    for c in &image.layer_data.channel_data.list {
        let v = match &c.sample_data {
            FlatSamples::U32(v) => v.iter().map(|x| f64::from(*x)).collect(),
            other => other.values_as_f32().map(f64::from).collect(),
        };
        ch.insert(c.name.to_string(), v);
    }
    let srgb = |v: f64| {
        let v = v.clamp(0.0, 1.0);
        let e = if v <= 0.0031308 {
            12.92 * v
        } else {
            1.055 * v.powf(1.0 / 2.4) - 0.055
        };
        (255.0 * e + 0.5) as u8
    };
    let save = |name: &str, px: &dyn Fn(usize) -> [u8; 3]| -> Result<(), String> {
        let img = image::RgbImage::from_fn(w, h, |x, y| image::Rgb(px((y * w + x) as usize)));
        let path = format!("{prefix}-{name}.png");
        img.save(&path)
            .map_err(|e| format!("cannot write {path}: {e}"))?;
        println!("wrote {path}");
        Ok(())
    };
    let three = |a: &str, b: &str, c: &str| -> Option<[&Vec<f64>; 3]> {
        Some([ch.get(a)?, ch.get(b)?, ch.get(c)?])
    };
    if let Some([r, g, b]) = three("R", "G", "B") {
        save("color", &|i| [srgb(r[i]), srgb(g[i]), srgb(b[i])])?;
    }
    if let Some(z) = ch.get("Z") {
        // Inverse depth (nearest = white): a ground plane's far end does not wash out the rest.
        let near = z
            .iter()
            .copied()
            .filter(|v| *v > 0.0)
            .fold(f64::INFINITY, f64::min);
        save("depth", &|i| {
            if !z[i].is_finite() || z[i] <= 0.0 {
                return [0; 3];
            }
            [(255.0 * (near / z[i]).clamp(0.0, 1.0)) as u8; 3]
        })?;
    }
    if let Some([x, y, z]) = three("normal.X", "normal.Y", "normal.Z") {
        let q = |v: f64| (255.0 * ((v + 1.0) / 2.0).clamp(0.0, 1.0)) as u8;
        save("normal", &|i| {
            if x[i] == 0.0 && y[i] == 0.0 && z[i] == 0.0 {
                [0; 3]
            } else {
                [q(x[i]), q(y[i]), q(z[i])]
            }
        })?;
    }
    if let Some([r, g, b]) = three("albedo.R", "albedo.G", "albedo.B") {
        save("albedo", &|i| [srgb(r[i]), srgb(g[i]), srgb(b[i])])?;
    }
    if let Some(id) = ch.get("object.id") {
        save("object", &|i| {
            let n = id[i] as u32;
            if n == 0 {
                return [0; 3];
            }
            // A golden-ratio walk around the hue circle keeps neighbouring ids apart.
            let hue = (f64::from(n) * 0.618_033_988_75).fract();
            hsv(hue, 0.65, 0.95)
        })?;
    }
    Ok(())
}

fn hsv(h: f64, s: f64, v: f64) -> [u8; 3] {
    let i = (h * 6.0).floor();
    let f = h * 6.0 - i;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - f * s), v * (1.0 - (1.0 - f) * s));
    let (r, g, b) = match i as u32 % 6 {
        0 => (v, t, p),
        1 => (q, v, p),
        2 => (p, v, t),
        3 => (p, q, v),
        4 => (t, p, v),
        _ => (v, p, q),
    };
    [(r * 255.0) as u8, (g * 255.0) as u8, (b * 255.0) as u8]
}
