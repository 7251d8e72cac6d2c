//! Skies and fog from the language (issue 37, environment and atmosphere): an equirectangular
//! camera at the centre of a latitude–longitude sky (Radiance `.hdr` and OpenEXR) returns the
//! picture itself; fog keeps exp(−d/D) of the light along a ray; the effects are named; bad
//! inputs have codes. (POV-Ray twins of the sky and fog: `tests/pov_twins.rs`.)

use rtc::eval::EvalOptions;
use rtc::render::{RenderOptions, render_image, render_scene};
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

fn options() -> RenderOptions {
    RenderOptions {
        threads: 2,
        ..Default::default()
    }
}

/// Texel (i, j) of the test pictures: every channel a multiple of 1/256 in [0.5, 1), which
/// Radiance's shared-exponent RGBE stores exactly (exponent 0, mantissas 128..=255) as EXR's
/// 32-bit floats do, so the expected value is the number written, not a decoder's reading.
fn texel(i: u32, j: u32) -> [f32; 3] {
    let level = |k: u32| (128 + k % 128) as f32 / 256.0;
    [level(i * 5), level(j * 11), level(i * j * 7 + 3)]
}

/// The rule, for `file` (written by `image` in the format its extension names): an
/// equirectangular camera at the origin looking along −Z with +Y up sees the sky picture
/// unchanged, pixel (i, j) of a w × h render showing texel (i, j) (read bilinearly at its
/// centre), with `sky_strength` 2 doubling it.
fn sky_picture_returns_itself(file: &str) {
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (40u32, 20u32);
    let picture = image::Rgb32FImage::from_fn(w, h, |i, j| image::Rgb(texel(i, j)));
    image::DynamicImage::ImageRgb32F(picture)
        .save(dir.path().join(file))
        .unwrap();
    for strength in [1.0, 2.0] {
        let scene = load(
            dir.path(),
            &format!(
                r#"rtc 1.1
camera {{ eye: [0, 0, 0], center: [0, 0, -1], up: Y, projection: "equirectangular", resolution: [{w}, {h}] }}
render {{ max_depth: 0, sky: image(path: "{file}", filter: "bilinear"), sky_strength: {strength} }}
"#
            ),
        )
        .unwrap();
        let film = render_scene(&scene, &options()).unwrap();
        let mut worst = (0.0f64, (0, 0));
        for j in 0..h {
            for i in 0..w {
                let got = film.get(i, j);
                let want = texel(i, j).map(|c| f64::from(c) * strength);
                for (g, t) in [got.x, got.y, got.z].into_iter().zip(want) {
                    if (g - t).abs() > worst.0 {
                        worst = ((g - t).abs(), (i, j));
                    }
                }
            }
        }
        assert!(
            worst.0 < 1e-9,
            "{file}, strength {strength}: pixel {:?} is {} off its texel",
            worst.1,
            worst.0
        );
    }
}

#[test]
fn equirectangular_camera_in_an_hdr_sky_returns_the_picture() {
    sky_picture_returns_itself("sky.hdr");
}

#[test]
fn equirectangular_camera_in_an_exr_sky_returns_the_picture() {
    sky_picture_returns_itself("sky.exr");
}

/// A sky turned by 90° shows along −Z what it showed along +X: the render's column at the
/// image centre is the unturned picture's column three quarters across.
#[test]
fn sky_rotation_turns_the_picture() {
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (40u32, 20u32);
    let picture = image::Rgb32FImage::from_fn(w, h, |i, j| image::Rgb(texel(i, j)));
    image::DynamicImage::ImageRgb32F(picture)
        .save(dir.path().join("sky.exr"))
        .unwrap();
    let scene = load(
        dir.path(),
        &format!(
            r#"rtc 1.1
camera {{ eye: [0, 0, 0], center: [0, 0, -1], up: Y, projection: "equirectangular", resolution: [{w}, {h}] }}
render {{ max_depth: 0, sky: image(path: "sky.exr", filter: "bilinear"), sky_rotation: 90deg }}
"#
        ),
    )
    .unwrap();
    let film = render_scene(&scene, &options()).unwrap();
    for j in 0..h {
        for i in 0..w {
            let want = texel((i + w / 4) % w, j);
            let got = film.get(i, j);
            let off = (got.x - f64::from(want[0]))
                .abs()
                .max((got.y - f64::from(want[1])).abs());
            assert!(off < 1e-9, "pixel ({i}, {j}) is {off} off");
        }
    }
}

/// Fog keeps exp(−d/D) of the light along a ray: the centre pixel of a 3 × 3 view of a
/// flat-lit wall at distance d is exp(−d/D)·C + (1 − exp(−d/D))·F, for several d and D.
#[test]
fn fog_transmittance_is_exp_minus_d_over_distance() {
    let dir = tempfile::tempdir().unwrap();
    let (c, f) = ([0.2, 0.5, 0.9], [0.8, 0.7, 0.6]);
    for (d, big_d) in [(1.0f64, 4.0f64), (5.0, 4.0), (12.5, 3.0), (30.0, 100.0)] {
        let scene = load(
            dir.path(),
            &format!(
                r#"rtc 1.1
camera {{ eye: [0, 0, {d}], center: [0, 0, 0], up: Y, fov: 10deg, resolution: [3, 3] }}
point_light {{ position: [0, 0, 50] }}
plane(point: [0, 0, 0], normal: Z).material(material {{ color: rgb({}, {}, {}), ka: 1, kd: 0, ks: 0 }})
render {{ shadows: false, max_depth: 0, fog: fog {{ color: rgb({}, {}, {}), distance: {big_d} }} }}
"#,
                c[0], c[1], c[2], f[0], f[1], f[2]
            ),
        )
        .unwrap();
        let film = render_scene(&scene, &options()).unwrap();
        let got = film.get(1, 1);
        let t = (-d / big_d).exp();
        let want = [0, 1, 2].map(|k| t * c[k] + (1.0 - t) * f[k]);
        for (g, w) in [got.x, got.y, got.z].into_iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "d {d}, D {big_d}: {g} vs {w}");
        }
    }
}

/// A fog pattern thins a segment of length d as POV-Ray's turbulence does, to
/// `d·(1 − exp(−d/D)·min(1, v·depth))`, `v` the pattern's value at the segment's midpoint: a
/// `gradient(axis: Y)` reads the height 0.25 of a level ray.
#[test]
fn fog_pattern_thins_the_fog() {
    let dir = tempfile::tempdir().unwrap();
    let (d, big_d, depth) = (6.0f64, 4.0f64, 0.8f64);
    let scene = load(
        dir.path(),
        &format!(
            r#"rtc 1.1
camera {{ eye: [0, 0.25, {d}], center: [0, 0.25, 0], up: Y, fov: 10deg, resolution: [3, 3] }}
point_light {{ position: [0, 0, 50] }}
plane(point: [0, 0, 0], normal: Z).material(material {{ color: rgb(1, 1, 1), ka: 1, kd: 0, ks: 0 }})
render {{ shadows: false, max_depth: 0, fog: fog {{ color: rgb(0, 0, 0), distance: {big_d}, pattern: gradient(axis: Y), pattern_depth: {depth} }} }}
"#
        ),
    )
    .unwrap();
    let got = render_scene(&scene, &options()).unwrap().get(1, 1).x;
    let width = d * (1.0 - (-d / big_d).exp() * (0.25 * depth));
    let want = (-width / big_d).exp();
    assert!((got - want).abs() < 1e-12, "{got} vs {want}");
}

/// Fog fills the air, not glass: a refracted ray inside a solid is not fogged, so a camera
/// looking through a clear slab sees only the fog in the air before and after it.
#[test]
fn fog_reaches_reflections_but_not_the_inside_of_solids() {
    let dir = tempfile::tempdir().unwrap();
    let wall = |between: &str| {
        format!(
            r#"rtc 1.1
camera {{ eye: [0, 0, 10], center: [0, 0, 0], up: Y, fov: 10deg, resolution: [3, 3] }}
point_light {{ position: [0, 0, 50] }}
plane(point: [0, 0, 0], normal: Z).material(material {{ color: rgb(1, 1, 1), ka: 1, kd: 0, ks: 0 }})
{between}
render {{ shadows: false, fog: fog {{ color: rgb(0, 0, 0), distance: 5 }} }}
"#
        )
    };
    let centre = |source: &str| {
        let scene = load(dir.path(), source).unwrap();
        render_scene(&scene, &options()).unwrap().get(1, 1).x
    };
    let open = centre(&wall(""));
    assert!((open - (-2.0f64).exp()).abs() < 1e-12, "{open}");
    // A clear slab (refract 1, index 1: rays go straight through) from z = 2 to z = 8: the six
    // units inside are not fogged, so the pixel is exp(−4/5).
    let slab = r#"box(min: [-5, -5, 2], max: [5, 5, 8]).material(material { color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, refract: 1, eta: 1 })"#;
    let through = centre(&wall(slab));
    assert!((through - (-0.8f64).exp()).abs() < 1e-9, "{through}");
}

/// The effects analysis names the sky, the environment map and both fogs; a scene without
/// them names none of them.
#[test]
fn effects_name_sky_and_fog() {
    let dir = tempfile::tempdir().unwrap();
    image::RgbImage::from_pixel(4, 2, image::Rgb([10, 20, 30]))
        .save(dir.path().join("sky.png"))
        .unwrap();
    let names = |render: &str| {
        let scene = load(
            dir.path(),
            &format!(
                "rtc 1.1\ncamera {{ eye: [0, 0, 5], center: [0, 0, 0] }}\nsphere()\n{render}\n"
            ),
        )
        .unwrap();
        rtc::opt::Effects::of(&scene).to_string()
    };
    let plain = names("");
    for n in ["sky", "environment map", "fog"] {
        assert!(!plain.contains(n), "{plain}");
    }
    assert!(names("render { sky: gradient(axis: Y) }").contains("sky"));
    let env = names(r#"render { sky: image(path: "sky.png") }"#);
    assert!(
        env.contains("environment map") && !env.contains("sky,"),
        "{env}"
    );
    let fog = names("render { fog: fog { color: rgb(1, 1, 1), distance: 3 } }");
    assert!(fog.contains("fog") && !fog.contains("ground fog"), "{fog}");
    let ground = names("render { fog: fog { color: rgb(1, 1, 1), distance: 3, altitude: 1 } }");
    assert!(ground.contains("ground fog"), "{ground}");
}

/// Without a sky or fog, the background is what a miss sees, byte for byte; with a sky of one
/// colour, a miss sees that colour.
#[test]
fn background_stays_the_default() {
    let dir = tempfile::tempdir().unwrap();
    let render = |r: &str| {
        let scene = load(
            dir.path(),
            &format!(
                "rtc 1.1\ncamera {{ eye: [0, 0, 5], center: [0, 0, 0], resolution: [8, 6] }}\n{r}\n"
            ),
        )
        .unwrap();
        render_image(&scene, &options()).unwrap()
    };
    let bg = render("render { background: rgb(0.25, 0.5, 0.75) }");
    assert!(bg.pixels().all(|p| p.0 == bg.get_pixel(0, 0).0));
    let sky = render(
        "render { sky: gradient(axis: Y).colors([rgb(0.25, 0.5, 0.75), rgb(0.25, 0.5, 0.75)]) }",
    );
    assert_eq!(bg.as_raw(), sky.as_raw());
}

/// Bad sky and fog inputs are errors with codes.
#[test]
fn bad_inputs_have_codes() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (r#"sky: image(path: "missing.hdr")"#, "rtc::asset::missing"),
        (
            "sky: gradient(axis: Y), sky_strength: -1",
            "rtc::param::out_of_range",
        ),
        ("sky: marble().uv()", "rtc::render::sky"),
        (
            "fog: fog { color: rgb(1, 1, 1), distance: 0 }",
            "rtc::param::out_of_range",
        ),
        (
            "fog: fog { color: rgb(1, 1, 1), distance: 1, altitude: -2 }",
            "rtc::param::out_of_range",
        ),
        (
            "fog: fog { color: rgb(1, 1, 1), distance: 1, transmit: 2 }",
            "rtc::param::out_of_range",
        ),
        ("fog: 3", "rtc::type::mismatch"),
        (
            "fog: fog { color: rgb(1, 1, 1), distance: 1, pattern: checker() }",
            "rtc::render::fog",
        ),
        (
            "fog: fog { color: rgb(1, 1, 1), distance: 1, pattern: bozo().uv() }",
            "rtc::render::fog",
        ),
        (
            "fog: fog { color: rgb(1, 1, 1), distance: 1, pattern: bozo(), pattern_depth: 2 }",
            "rtc::param::out_of_range",
        ),
    ];
    for (fields, code) in cases {
        let source = format!(
            "rtc 1.1\ncamera {{ eye: [0, 0, 5], center: [0, 0, 0] }}\nrender {{ {fields} }}\n"
        );
        let codes = load(dir.path(), &source).expect_err(fields);
        assert!(codes.iter().any(|c| c == code), "{fields}: {codes:?}");
    }
}

/// `render { alpha: true }`: the film gets an alpha channel, the share of each pixel's camera
/// samples that meet something (1 inside the ball, 0 in the corners, between at its rim), the
/// colour is premultiplied (0 where nothing is met, whatever the background), and the PNG is
/// RGBA. Without it there is no alpha channel and no RGBA image.
#[test]
fn alpha_is_the_share_of_samples_that_hit() {
    let dir = tempfile::tempdir().unwrap();
    let source = |alpha: bool| {
        format!(
            r#"rtc 1.1
camera {{ eye: [0, 0, 5], center: [0, 0, 0], fov: 30deg, resolution: [24, 24] }}
point_light {{ position: [0, 0, 10] }}
sphere(radius: 0.8).material(material {{ color: rgb(0.2, 0.6, 0.9), ka: 1, kd: 0, ks: 0 }})
render {{ shadows: false, supersampling: 4, background: rgb(1, 0, 0), alpha: {alpha} }}
"#
        )
    };
    let plain = render_scene(&load(dir.path(), &source(false)).unwrap(), &options()).unwrap();
    assert!(plain.to_rgba().is_none());
    let film = render_scene(&load(dir.path(), &source(true)).unwrap(), &options()).unwrap();
    let rgba = film.to_rgba().expect("an alpha channel");
    assert_eq!(rgba.get_pixel(12, 12).0[3], 255);
    assert_eq!(rgba.get_pixel(0, 0).0, [0, 0, 0, 0]);
    assert_eq!(film.get(0, 0), glam::DVec3::ZERO);
    // A rim pixel: partly covered, its straight colour the ball's (the background left out).
    let rim = (0..24)
        .map(|x| rgba.get_pixel(x, 12).0)
        .find(|p| p[3] > 0 && p[3] < 255)
        .expect("a partly covered pixel on the middle row");
    let inside = rgba.get_pixel(12, 12).0;
    for c in 0..3 {
        assert!(
            (i32::from(rim[c]) - i32::from(inside[c])).abs() <= 1,
            "{rim:?} vs {inside:?}"
        );
    }
    // Covered pixels keep their bytes: the colour is the same as without alpha.
    assert_eq!(
        plain.to_image().get_pixel(12, 12).0,
        [inside[0], inside[1], inside[2]]
    );
}

/// Shards of a render with a sky, fog and alpha merge into the single render, every channel
/// byte for byte.
#[test]
fn sharded_sky_fog_and_alpha_merge_into_the_single_render() {
    use rtc::render::merge::merge;
    use rtc::render::part::Part;
    use rtc::render::shard::Shard;
    let dir = tempfile::tempdir().unwrap();
    let scene = load(
        dir.path(),
        r#"rtc 1.1
camera { eye: [0, 1, 6], center: [0, 0.5, 0], fov: 40deg, resolution: [37, 29] }
point_light { position: [3, 4, 5] }
plane(point: [0, -1, 0], normal: Y).material(material { color: rgb(0.8, 0.8, 0.8), reflect: 0.3 })
sphere(center: [0, 0.5, 0], radius: 0.6).material(material { color: rgb(0.9, 0.2, 0.2), reflect: 0.4 })
render {
    supersampling: 2
    alpha: true
    sky: bozo().colors([rgb(0.3, 0.5, 0.9), rgb(1, 1, 1)]).scale(0.3)
    fog: fog { color: rgb(0.7, 0.7, 0.75), distance: 9, offset: 0, altitude: 1 }
}
"#,
    )
    .unwrap();
    let single = render_scene(&scene, &options()).unwrap();
    let fp = rtc::opt::fingerprint::scene(&scene);
    for n in [2, 5] {
        let parts: Vec<_> = (0..n)
            .map(|k| {
                let s = Shard::new(k, n).unwrap();
                let opts = RenderOptions {
                    shard: Some(s),
                    ..options()
                };
                let film = render_scene(&scene, &opts).unwrap();
                let bytes = Part::of_film(&film, s, fp.clone(), "settings".into()).to_bytes();
                let path = std::path::PathBuf::from(format!("p{k}"));
                (path.clone(), Part::from_bytes(&bytes, &path).unwrap())
            })
            .collect();
        let merged = merge(&parts).unwrap();
        assert_eq!(
            merged.to_rgba().unwrap().as_raw(),
            single.to_rgba().unwrap().as_raw()
        );
        assert_eq!(merged.color(), single.color());
    }
}
