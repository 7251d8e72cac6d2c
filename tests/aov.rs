//! `rtc render --aov`: the EXR layers hold what a stated rule says they must (distances and
//! normals of an analytic sphere, the material's colour, the object's source line), the colour
//! layer is unchanged by asking for layers, and shards merge to the same file.

mod cli_support;

use std::path::Path;

use cli_support::{rtc, scratch};
use exr::prelude::{FlatSamples, ReadChannels, ReadLayers};

/// A 33×33 view down −z from z = 10 at a sphere of radius 2 at the origin (line 6), so the
/// centre pixel (16, 16) looks exactly along the axis and the corners see only background.
const SCENE: &str = "rtc 1
camera { eye: [0, 0, 10], center: [0, 0, 0], up: Y, fov: 30deg, resolution: [33, 33] }
point_light { position: [5, 5, 20], color: rgb(1, 1, 1) }
let paint = material { color: rgb(0.2, 0.4, 0.6), ka: 0.1, kd: 0.8, ks: 0.3, n: 16 }
// the one object
sphere(center: [0, 0, 0], radius: 2).material(paint)
render { supersampling: 2 }
";

/// Every channel of an EXR file by name, as f64 (u32 ids converted).
fn channels(path: &Path) -> Vec<(String, Vec<f64>)> {
    let image = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_file(path)
        .expect("the EXR reads back");
    image
        .layer_data
        .channel_data
        .list
        .iter()
        .map(|c| {
            let values = match &c.sample_data {
                FlatSamples::U32(v) => v.iter().map(|x| f64::from(*x)).collect(),
                other => other.values_as_f32().map(f64::from).collect(),
            };
            (c.name.to_string(), values)
        })
        .collect()
}

fn get<'a>(chs: &'a [(String, Vec<f64>)], name: &str) -> &'a [f64] {
    &chs.iter()
        .find(|(n, _)| n == name)
        .unwrap_or_else(|| panic!("no channel {name}"))
        .1
}

#[test]
fn layers_hold_distance_normal_albedo_and_object_of_an_analytic_sphere() {
    let dir = scratch("aov-layers");
    let scene = dir.join("ball.rtc");
    std::fs::write(&scene, SCENE).unwrap();
    let (with, without) = (dir.join("with.exr"), dir.join("without.exr"));
    let s = scene.to_str().unwrap();
    let out = rtc(&[
        "render",
        s,
        "-o",
        with.to_str().unwrap(),
        "--aov",
        "depth,normal,albedo,object",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = rtc(&["render", s, "-o", without.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );

    let a = channels(&with);
    let names: Vec<&str> = a.iter().map(|(n, _)| n.as_str()).collect();
    for n in [
        "R",
        "G",
        "B",
        "Z",
        "normal.X",
        "normal.Y",
        "normal.Z",
        "albedo.R",
        "albedo.G",
        "albedo.B",
        "object.id",
    ] {
        assert!(names.contains(&n), "{n} missing from {names:?}");
    }
    // Asking for layers changes no colour value.
    let b = channels(&without);
    for n in ["R", "G", "B"] {
        assert_eq!(get(&a, n), get(&b, n), "colour channel {n}");
    }
    // Readers that take only RGB (the `image` crate, which `rtc accuracy --reference` uses)
    // find the colour among the layers.
    let rgb = image::open(&with)
        .expect("image reads the EXR")
        .into_rgb32f();
    let red: Vec<f64> = rgb.pixels().map(|p| f64::from(p.0[0])).collect();
    assert_eq!(red, get(&a, "R"));
    let centre = 16 * 33 + 16;
    // The 2×2 samples of the centre pixel are a quarter pixel off the axis: the front of the
    // sphere is 8 units from the eye there to within 1e-3.
    assert!(
        (get(&a, "Z")[centre] - 8.0).abs() < 1e-3,
        "{}",
        get(&a, "Z")[centre]
    );
    assert!(get(&a, "normal.Z")[centre] > 0.999);
    assert!(get(&a, "normal.X")[centre].abs() < 0.02);
    for (n, v) in [("albedo.R", 0.2), ("albedo.G", 0.4), ("albedo.B", 0.6)] {
        assert!((get(&a, n)[centre] - v).abs() < 1e-6, "{n}");
    }
    assert_eq!(get(&a, "object.id")[centre], 1.0);
    // A corner sees only background: infinitely far, no normal, no colour, object 0.
    assert_eq!(get(&a, "Z")[0], f64::INFINITY);
    assert_eq!(get(&a, "normal.Z")[0], 0.0);
    assert_eq!(get(&a, "albedo.G")[0], 0.0);
    assert_eq!(get(&a, "object.id")[0], 0.0);
    // Depth never mixes background into an edge pixel: every finite depth lies on the sphere's
    // front half, between 8 and 10 units away.
    assert!(
        get(&a, "Z")
            .iter()
            .all(|z| z.is_infinite() || (7.99..=10.0).contains(z))
    );

    // The sidecar names object 1 and the line that made it.
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("with.objects.json")).unwrap())
            .unwrap();
    assert_eq!(json["schema"], "rtc-objects/1");
    assert_eq!(json["objects"][0]["id"], 1);
    assert_eq!(json["objects"][0]["kind"], "sphere");
    assert_eq!(json["objects"][0]["source"]["line"], 6);
    assert!(
        json["objects"][0]["source"]["text"]
            .as_str()
            .unwrap()
            .starts_with("sphere(")
    );
}

#[test]
fn sharded_layers_merge_to_the_single_render() {
    let dir = scratch("aov-shards");
    let scene = dir.join("ball.rtc");
    std::fs::write(&scene, SCENE).unwrap();
    let s = scene.to_str().unwrap();
    let ok = |out: std::process::Output| {
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    let single = dir.join("single.exr");
    ok(rtc(&[
        "render",
        s,
        "-o",
        single.to_str().unwrap(),
        "--aov",
        "object,depth",
    ]));
    let mut parts = Vec::new();
    for k in 0..3 {
        let shard = format!("{k}/3");
        let part = dir
            .join(format!("p{k}.rtcpart"))
            .to_str()
            .unwrap()
            .to_string();
        ok(rtc(&[
            "render",
            s,
            "-o",
            &part,
            "--aov",
            "object,depth",
            "--shard",
            &shard,
        ]));
        parts.push(part);
    }
    let merged = dir.join("merged.exr");
    let mut args = vec!["merge", "-o", merged.to_str().unwrap()];
    args.extend(parts.iter().map(String::as_str));
    ok(rtc(&args));
    assert_eq!(
        std::fs::read(&single).unwrap(),
        std::fs::read(&merged).unwrap()
    );
    // The parts carried the sidecar; the merge wrote it for its own image name.
    let read = |p: &str| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(dir.join(p)).unwrap()).unwrap()
    };
    let (mut a, b) = (read("single.objects.json"), read("merged.objects.json"));
    assert_eq!(b["image"], "merged.exr");
    a["image"] = b["image"].clone();
    assert_eq!(a, b);
}

#[test]
fn layers_need_an_exr_and_known_names_and_keep_an_existing_image() {
    let dir = scratch("aov-errors");
    let scene = dir.join("ball.rtc");
    std::fs::write(&scene, SCENE).unwrap();
    let png = dir.join("keep.png");
    std::fs::write(&png, b"old bytes").unwrap();
    let out = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        png.to_str().unwrap(),
        "--aov",
        "depth",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("keep.exr"), "{err}");
    assert_eq!(std::fs::read(&png).unwrap(), b"old bytes");
    let out = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        "x.exr",
        "--aov",
        "nromal",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("did you mean `normal`"), "{err}");
}
