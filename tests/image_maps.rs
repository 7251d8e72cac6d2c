//! Image maps (issue 36). Mip-mapped lookup: a floor of one-texel checks seen towards the horizon.
//! The truth is the box filter of each pixel, approximated by 16 × 16 samples per pixel; with
//! one sample per pixel, trilinear lookup over the pixel's footprint must come much closer to
//! it than bilinear lookup (whose far rows alias into moiré), agree with it up close where a
//! pixel covers less than a texel, and give the same bytes on every thread count. Normal maps:
//! a map of one constant normal on a floor lit by a distant light must shade every pixel as
//! that normal, decoded by the stated rule (`2c − 1` in the frame of u, up the picture and
//! the surface normal), whatever way the object is turned.

use std::path::Path;

use glam::DVec3;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::num::Norm;
use rtc::render::film::Film;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

const W: u32 = 64;
const H: u32 = 48;

/// A `n × n` checkerboard of single black and white texels, written as a PNG in `dir`.
fn checks(dir: &Path, n: u32) -> std::path::PathBuf {
    let path = dir.join(format!("checks{n}.png"));
    let img = image::RgbImage::from_fn(n, n, |x, y| {
        if (x + y) % 2 == 0 {
            image::Rgb([0, 0, 0])
        } else {
            image::Rgb([255, 255, 255])
        }
    });
    img.save(&path).unwrap();
    path
}

/// The floor y = 0 wearing the checks (planar mapping: the picture once per unit), flat-lit, seen
/// from one unit above it towards the horizon.
fn floor(texture: &Path, filter: &str, supersampling: u32) -> Scene {
    let src = format!(
        "rtc 1.1
         camera {{ eye: [0, 1, 0], center: [0, 0.2, -10], up: Y, fov: 40deg, resolution: [{W}, {H}] }}
         point_light {{ position: [0, 100, 0] }}
         plane(point: [0, 0, 0], normal: Y).material(material {{
             texture: image(path: {:?}, mapping: planar, filter: {filter:?}), ka: 1, kd: 0, ks: 0 }})
         render {{ shadows: false, max_depth: 0, supersampling: {supersampling} }}",
        texture.display()
    );
    load(&src)
}

/// The scene `src`, which must load.
fn load(src: &str) -> Scene {
    let mut sources = SourceMap::default();
    let loaded = load_source(
        Path::new("scene.rtc"),
        src,
        &mut sources,
        &EvalOptions::default(),
    );
    let codes: Vec<_> = loaded
        .diagnostics
        .items
        .iter()
        .map(|d| format!("{}: {}", d.code, d.message))
        .collect();
    loaded
        .scene
        .unwrap_or_else(|| panic!("the scene loads: {codes:?}"))
}

fn render(scene: &Scene, threads: usize) -> Film {
    let opts = RenderOptions {
        threads,
        ..Default::default()
    };
    render_scene(scene, &opts).unwrap()
}

/// The mean absolute difference of rows `rows` (all channels), in [0, 1].
fn mean_error(a: &Film, b: &Film, rows: std::ops::Range<u32>) -> f64 {
    let mut sum = 0.0;
    let mut n = 0.0;
    for j in rows {
        for i in 0..W {
            let d: DVec3 = (a.get(i, j) - b.get(i, j)).abs();
            sum += d.x + d.y + d.z;
            n += 3.0;
        }
    }
    sum / n
}

#[test]
fn trilinear_lookup_follows_the_box_filtered_truth() {
    let dir = tempfile::tempdir().unwrap();
    let tex = checks(dir.path(), 16);
    let truth = render(&floor(&tex, "bilinear", 16), 2);
    let bilinear = render(&floor(&tex, "bilinear", 1), 2);
    let mipmap = render(&floor(&tex, "mipmap", 1), 2);
    // The floor fills the rows below the horizon (row ~ H/2 + 2); the far half of it is where
    // a pixel covers many texels.
    let far = 27..36;
    let (e_bilinear, e_mipmap) = (
        mean_error(&bilinear, &truth, far.clone()),
        mean_error(&mipmap, &truth, far),
    );
    eprintln!(
        "far rows, mean error against 16×16 samples: bilinear {e_bilinear:.4}, mipmap {e_mipmap:.4}"
    );
    assert!(e_bilinear > 0.1, "the test scene must alias: {e_bilinear}");
    assert!(e_mipmap < 0.5 * e_bilinear, "{e_mipmap} vs {e_bilinear}");
    // With texels a quarter unit wide, the nearest rows cover less than a texel per pixel
    // (about 0.35 at the bottom): level 0, the bilinear lookup itself.
    let coarse = checks(dir.path(), 4);
    let bilinear = render(&floor(&coarse, "bilinear", 1), 2);
    let mipmap = render(&floor(&coarse, "mipmap", 1), 2);
    assert_eq!(mean_error(&mipmap, &bilinear, 44..H), 0.0);
}

#[test]
fn mipmapped_pixels_do_not_depend_on_the_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let tex = checks(dir.path(), 16);
    let scene = floor(&tex, "mipmap", 2);
    let (one, two) = (render(&scene, 1), render(&scene, 2));
    assert_eq!(one.color(), two.color());
}

/// A `4 × 4` picture of one colour, written as a PNG in `dir`.
fn constant(dir: &Path, name: &str, c: [u8; 3]) -> std::path::PathBuf {
    let path = dir.join(name);
    image::RgbImage::from_pixel(4, 4, image::Rgb(c))
        .save(&path)
        .unwrap();
    path
}

/// A diffuse floor (kd 0.5, no ambient or highlight) turned `turn` about y, wearing `bump`,
/// lit from far away in direction `light`, seen from above.
fn lit_floor(bump: &str, turn: f64, light: [f64; 3]) -> Scene {
    let far = light.map(|c| c * 1e7);
    let src = format!(
        "rtc 1.1
         camera {{ eye: [0, 5, 0.001], center: [0, 0, 0], up: Y, fov: 20deg, resolution: [16, 16] }}
         point_light {{ position: [{}, {}, {}] }}
         plane(point: [0, 0, 0], normal: Y).rotate(y: {turn}deg).material(material {{
             color: rgb(1, 1, 1), ka: 0, kd: 0.5, ks: 0 {bump} }})
         render {{ shadows: false, max_depth: 0 }}",
        far[0], far[1], far[2]
    );
    load(&src)
}

/// The normal a texel encodes: `2c − 1`, c = byte / 255.
fn decoded(c: [u8; 3]) -> DVec3 {
    DVec3::new(f64::from(c[0]), f64::from(c[1]), f64::from(c[2])) * (2.0 / 255.0) - DVec3::ONE
}

#[test]
fn a_constant_normal_map_shades_as_its_normal_in_the_frame_of_u() {
    let dir = tempfile::tempdir().unwrap();
    // m ≈ (0.6, 0, 0.8): tilted towards increasing u.
    let texel = [204, 128, 230];
    let m = decoded(texel);
    let map = constant(dir.path(), "tilt.png", texel);
    let bump = format!(
        ", bump: normal_map(path: {:?}, mapping: planar)",
        map.display()
    );
    // Planar mapping: u along the object's x, v along its z (so up the picture is −z). Turned
    // 0° the object's x is the world's +x; turned 90° about y it is the world's −z.
    for (turn, u_dir, up_dir) in [
        (0.0, DVec3::X, DVec3::NEG_Z),
        (90.0, DVec3::NEG_Z, DVec3::NEG_X),
    ] {
        let normal = (m.x * u_dir + m.y * up_dir + m.z * DVec3::Y).unit();
        for light in [
            [1.0, 1.0, 0.0],
            [-1.0, 1.0, 0.0],
            [0.0, 1.0, 1.0],
            [0.0, 1.0, -1.0],
        ] {
            let l = DVec3::from_array(light).unit();
            let flat = render(&lit_floor("", turn, light), 2);
            let mapped = render(&lit_floor(&bump, turn, light), 2);
            let want = 0.5 * normal.dot(l).max(0.0);
            for (i, j) in [(8, 8), (2, 3), (13, 12)] {
                assert!((flat.get(i, j).x - 0.5 * l.y).abs() < 1e-6);
                let got = mapped.get(i, j).x;
                assert!(
                    (got - want).abs() < 1e-6,
                    "turned {turn}°, light {light:?}, pixel ({i}, {j}): {got} vs {want}"
                );
            }
        }
    }
}
