//! Camera projections from the language (issue 37, cameras): an equirectangular camera at the
//! centre of a sphere wearing an image with `mapping: spherical` returns the image itself, and
//! the projections' diagnostics. (The rays' geometry is checked in `src/render/camera.rs` and
//! `src/render/panorama.rs`; the mappings against POV-Ray in `tests/pov_cameras.rs`.)

use rtc::eval::EvalOptions;
use rtc::render::{RenderOptions, render_image};
use rtc::source::SourceMap;

/// Loads `source` written to `dir/scene.rtc`; the diagnostics' codes when it has errors.
fn load(dir: &std::path::Path, source: &str) -> Result<rtc::ir::Scene, Vec<String>> {
    let path = dir.join("scene.rtc");
    std::fs::write(&path, source).unwrap();
    let mut sources = SourceMap::default();
    let loaded = rtc::loader::load(&path, &mut sources, &EvalOptions::default());
    if loaded.diagnostics.has_errors() {
        return Err(loaded
            .diagnostics
            .items
            .iter()
            .map(|d| d.code.to_string())
            .collect());
    }
    Ok(loaded.scene.expect("the scene evaluates"))
}

/// The rule: an equirectangular camera at the centre of a sphere mirrored in x
/// (`.scale([-1, 1, 1])`, so its inside reads as its outside) looking along +x with `up: Y`
/// sees the sphere's `mapping: spherical` image unchanged: pixel (i, j) of a w × h render shows
/// texel (i, j) of a w × h image (read bilinearly, at the texel's centre), within a level (an
/// image's bytes are read as linear values, so the render writes them back with
/// `encoding: linear`, `trunc(255·c)`).
#[test]
fn equirectangular_inside_a_textured_sphere_returns_the_image() {
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (48u32, 24u32);
    let texel =
        |i: u32, j: u32| image::Rgb([(i * 5) as u8, (j * 10) as u8, ((i * j * 7) % 251) as u8]);
    let picture = image::RgbImage::from_fn(w, h, texel);
    picture.save(dir.path().join("world.png")).unwrap();
    let scene = load(
        dir.path(),
        &format!(
            r#"rtc 1.1
camera {{ eye: [0, 0, 0], center: [1, 0, 0], projection: "equirectangular", resolution: [{w}, {h}] }}
point_light {{ position: [0, 0, 0] }}
sphere(center: [0, 0, 0], radius: 100).scale([-1, 1, 1]).material(material {{
  texture: image(path: "world.png", mapping: spherical, filter: "bilinear")
  ka: 1
  kd: 0
  ks: 0
}})
render {{ shadows: false, max_depth: 0, encoding: linear }}
"#
        ),
    )
    .unwrap();
    let options = RenderOptions {
        threads: 2,
        ..Default::default()
    };
    let img = render_image(&scene, &options).unwrap();
    let mut worst = (0, (0, 0));
    for (x, y, p) in img.enumerate_pixels() {
        let t = texel(x, y);
        let d = (0..3)
            .map(|c| (i32::from(p.0[c]) - i32::from(t.0[c])).abs())
            .max()
            .unwrap();
        if d > worst.0 {
            worst = (d, (x, y));
        }
    }
    assert!(
        worst.0 <= 1,
        "pixel {:?} is {} levels off its texel",
        worst.1,
        worst.0
    );
}

/// Each projection's rules have their codes (docs/language.md §18, §25).
#[test]
fn projection_rules_have_codes() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (r#"projection: "fisheye", fov: 400deg"#, "rtc::camera::view"),
        (
            r#"projection: "cylindrical", fov: 0deg"#,
            "rtc::camera::view",
        ),
        (
            r#"projection: "orthographic", height: 0"#,
            "rtc::camera::view",
        ),
        (
            r#"projection: "orthographic", height: -2"#,
            "rtc::camera::view",
        ),
        (r#"projection: "orthogonal""#, "rtc::camera::projection"),
        (
            r#"projection: "equirectangular", fov: 90deg"#,
            "rtc::camera::conflict",
        ),
        (
            r#"projection: "fisheye", aperture: 0.1"#,
            "rtc::camera::conflict",
        ),
        (r#"height: 3"#, "rtc::camera::conflict"),
        (
            r#"projection: "orthographic", course: true"#,
            "rtc::camera::conflict",
        ),
    ];
    for (fields, code) in cases {
        let source = format!("rtc 1.1\ncamera {{ eye: [0, 0, 5], {fields} }}\n");
        let codes = load(dir.path(), &source).expect_err(fields);
        assert!(
            codes.iter().any(|c| c == code),
            "{fields}: {codes:?}, expected {code}"
        );
    }
    for fields in [
        r#"projection: "fisheye", fov: 360deg"#,
        r#"projection: "cylindrical""#,
        r#"projection: "orthographic", aperture: 0.1, focus: 4"#,
        r#"projection: "perspective", fov: 60deg"#,
    ] {
        let source = format!("rtc 1.1\ncamera {{ eye: [0, 0, 5], {fields} }}\n");
        assert!(load(dir.path(), &source).is_ok(), "{fields}");
    }
}
