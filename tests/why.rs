//! `rtc why X Y`: the explanation names the loop iteration and call that made the object hit,
//! the occluder of a shadow, the mirror's child ray with its weight, and ends in the colour the
//! render gives the pixel; course files work; bad pixels are diagnostics. Expected values come
//! from the scene files (line numbers, coefficients) and stated rules (Whitted's combination,
//! a point of a sphere is its centre plus radius times normal), not from `rtc why` itself.

mod cli_support;

use rtc::num::Norm;
use std::path::Path;

use cli_support::{rtc, scratch};
use glam::DVec3;
use serde_json::Value;

const TOWERS: &str = "tests/data/why/towers.rtc";

/// `rtc why FILE X Y --format json` (plus `extra`), parsed.
fn why(file: &str, x: u32, y: u32, extra: &[&str]) -> Value {
    let (xs, ys) = (x.to_string(), y.to_string());
    let mut args = vec!["why", file, &xs, &ys, "--format", "json"];
    args.extend_from_slice(extra);
    let run = rtc(&args);
    assert_eq!(
        run.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    serde_json::from_slice(&run.stdout).expect("rtc why prints JSON")
}

fn v3(v: &Value) -> DVec3 {
    let a: Vec<f64> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    DVec3::new(a[0], a[1], a[2])
}

/// The 1-based line of the first line of `file` containing `text`.
fn line_of(file: &str, text: &str) -> u64 {
    let src = std::fs::read_to_string(file).unwrap();
    src.lines().position(|l| l.contains(text)).unwrap() as u64 + 1
}

fn keys(v: &Value) -> Vec<&str> {
    let mut k: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    k.sort_unstable();
    k
}

#[test]
fn the_trace_names_the_iteration_and_the_call() {
    let d = why(TOWERS, 32, 22, &[]);
    let hit = &d["ray"]["hit"];
    assert_eq!(hit["object"]["kind"], "sphere");
    // Which sphere: its centre is the hit point minus radius 0.5 along the normal; towers
    // stack spheres at y = 0.5 + i, and `tower(0)` puts them at x = 0.
    let centre = v3(&hit["point"]) - 0.5 * v3(&hit["normal"]);
    let i = (centre.y - 0.5).round();
    assert!((centre.x - 0.0).abs() < 1e-9, "{centre}");
    let trace = &hit["object"]["trace"];
    assert_eq!(trace.as_array().unwrap().len(), 1, "{trace}");
    let chain = trace[0].as_array().unwrap();
    assert_eq!(chain.len(), 2, "{trace}");
    assert_eq!(chain[0]["kind"], "iteration");
    assert_eq!(chain[0]["bindings"], format!("i = {i}"));
    assert_eq!(chain[0]["span"]["line"], line_of(TOWERS, "for i in 0..3"));
    assert_eq!(chain[1]["kind"], "call");
    assert_eq!(chain[1]["name"], "tower");
    assert_eq!(chain[1]["span"]["line"], line_of(TOWERS, "tower(0)"));
    assert_eq!(
        hit["object"]["trace_text"],
        format!(
            "iteration i = {i} of the `for` at {TOWERS}:{}, called from `tower()` at {TOWERS}:{}",
            line_of(TOWERS, "for i in 0..3"),
            line_of(TOWERS, "tower(0)")
        )
    );
    assert_eq!(
        hit["object"]["span"]["line"],
        line_of(TOWERS, "sphere(center: [x")
    );
    assert_eq!(hit["material"]["span"]["line"], line_of(TOWERS, "let red"));
    // The human text shows the same facts next to the source.
    let run = rtc(&["why", TOWERS, "32", "22"]);
    let text = String::from_utf8_lossy(&run.stdout);
    assert!(
        text.contains(&format!("in iteration i = {i} of this `for`")),
        "{text}"
    );
    assert!(text.contains("in call of `tower`"), "{text}");
    assert!(
        text.contains("sphere(center: [x, 0.5 + i, 0], radius: 0.5)"),
        "{text}"
    );
}

#[test]
fn a_shadowed_pixel_names_the_occluder() {
    let d = why(TOWERS, 20, 30, &[]);
    let ray = &d["ray"];
    assert_eq!(ray["hit"]["object"]["kind"], "plane");
    let light = &ray["lights"][0];
    assert_eq!(light["blocked"], 1);
    assert_eq!(v3(&light["diffuse"]), DVec3::ZERO);
    assert_eq!(light["span"]["line"], line_of(TOWERS, "point_light"));
    let occ = &light["occluder"];
    assert_eq!(occ["object"]["kind"], "sphere");
    assert_eq!(
        occ["object"]["span"]["line"],
        line_of(TOWERS, "sphere(center: [x")
    );
    // The occluder lies on the segment from the shaded point to the light.
    let p = v3(&ray["hit"]["point"]);
    let to_light = DVec3::new(-6.0, 10.0, 6.0) - p;
    let to_occ = v3(&occ["point"]) - p;
    assert!(to_occ.cross(to_light.unit()).norm() < 1e-6);
    assert!(to_occ.dot(to_light) > 0.0 && to_occ.norm() < to_light.norm());
    // Only the ambient term is left: the local colour is ka·C·Lc (0.1·0.8).
    assert!((v3(&ray["local"]) - DVec3::splat(0.08)).norm() < 1e-12);
}

#[test]
fn a_mirror_pixel_shows_its_reflected_child_with_the_weight() {
    let d = why(TOWERS, 43, 23, &[]);
    let ray = &d["ray"];
    assert_eq!(
        ray["hit"]["material"]["span"]["line"],
        line_of(TOWERS, "let mirror")
    );
    let kids = ray["children"].as_array().unwrap();
    assert_eq!(kids.len(), 1);
    let child = &kids[0];
    assert_eq!(child["branch"], "reflected");
    assert_eq!(child["k"], 0.8, "the mirror material's `reflect`");
    assert_eq!(child["weight"], 0.8);
    assert_eq!(child["depth"], 1);
    assert_eq!(child["hit"]["object"]["kind"], "sphere");
    // The mirror direction about the normal.
    let (d0, n) = (v3(&ray["direction"]), v3(&ray["hit"]["normal"]));
    let r = d0 - 2.0 * d0.dot(n) * n;
    assert!((v3(&child["direction"]) - r).norm() < 1e-12);
    // Whitted: colour = local + reflect · child.
    let expect = v3(&ray["local"]) + 0.8 * v3(&child["color"]);
    assert!((v3(&ray["color"]) - expect).norm() < 1e-12);
}

fn rendered(file: &str, name: &str) -> image::RgbImage {
    let out = scratch("why").join(name);
    let run = rtc(&["render", file, "-o", out.to_str().unwrap()]);
    assert_eq!(
        run.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    image::open(&out).unwrap().to_rgb8()
}

#[test]
fn the_final_colour_is_the_rendered_pixel() {
    let img = rendered(TOWERS, "towers.png");
    for (x, y) in [(32, 22), (20, 30), (43, 23), (0, 0), (63, 47)] {
        let d = why(TOWERS, x, y, &[]);
        assert_eq!(d["samples_per_pixel"], 1);
        assert_eq!(
            d["color"], d["pixel_color"],
            "one sample: the centre is the pixel"
        );
        assert_eq!(d["color"]["linear"], d["ray"]["color"]);
        let bytes: Vec<u64> = d["color"]["bytes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b.as_u64().unwrap())
            .collect();
        let px = img.get_pixel(x, y).0.map(u64::from);
        assert_eq!(bytes, px, "pixel ({x}, {y})");
    }
}

#[test]
fn a_supersampled_pixel_explains_its_centre_or_a_chosen_sample() {
    let file = "tests/data/course/yaml/scene01-ss.yaml";
    let img = rendered(file, "ss.png");
    let d = why(file, 90, 80, &[]);
    assert_eq!(d["sample"], Value::Null);
    assert_eq!(d["offset"], serde_json::json!([0.5, 0.5]));
    let n = d["samples_per_pixel"].as_u64().unwrap();
    assert!(n > 1);
    let bytes: Vec<u64> = d["pixel_color"]["bytes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b.as_u64().unwrap())
        .collect();
    assert_eq!(bytes, img.get_pixel(90, 80).0.map(u64::from));
    let last = (n - 1).to_string();
    let s = why(file, 90, 80, &["--sample", &last]);
    assert_eq!(s["sample"], n - 1);
    let f = (n as f64).sqrt();
    let off = (f - 0.5) / f;
    assert_eq!(s["offset"], serde_json::json!([off, off]));
    let past = rtc(&["why", file, "90", "80", "--sample", &n.to_string()]);
    assert_eq!(past.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&past.stderr).contains("rtc::why::sample"));
}

#[test]
fn course_files_point_into_themselves() {
    let file = "tests/data/course/yaml/scene01-reflect-lights-shadows.yaml";
    let d = why(file, 90, 80, &[]);
    let hit = &d["ray"]["hit"];
    // The blue sphere is the first object (`position: [90,320,100]`).
    assert_eq!(hit["object"]["index"], 0);
    assert_eq!(hit["object"]["span"]["file"], file);
    assert_eq!(
        hit["object"]["span"]["line"],
        line_of(file, "position: [90,320,100]") - 1
    );
    assert_eq!(hit["object"]["trace"], serde_json::json!([]));
    assert_eq!(d["ray"]["lights"].as_array().unwrap().len(), 2);
    assert_eq!(
        d["ray"]["lights"][1]["span"]["line"],
        line_of(file, "position: [600,600,1500]")
    );
    let kids = d["ray"]["children"].as_array().unwrap();
    assert_eq!(kids[0]["k"], 0.5, "the course's mirror weight is ks");
    let run = rtc(&[
        "why",
        "tests/data/course/in/rt1.in",
        "90",
        "80",
        "--format",
        "short",
    ]);
    assert_eq!(run.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&run.stdout).contains("tests/data/course/in/rt1.in:"));
}

#[test]
fn a_pixel_outside_the_image_is_a_diagnostic() {
    for (x, y) in [("64", "0"), ("0", "48"), ("-1", "3")] {
        let run = rtc(&["why", TOWERS, x, y, "--format", "short"]);
        assert_eq!(run.status.code(), Some(1), "({x}, {y})");
        let err = String::from_utf8_lossy(&run.stderr);
        let camera = line_of(TOWERS, "camera {");
        assert!(
            err.contains(&format!("{TOWERS}:{camera}:1: error[rtc::why::pixel]")),
            "{err}"
        );
        assert!(err.contains("outside the 64×48 image"), "{err}");
        assert!(
            err.contains("from 0 to 63") && err.contains("from 0 to 47"),
            "{err}"
        );
        assert!(run.stdout.is_empty());
    }
}

#[test]
fn the_json_shape_is_pinned() {
    let d = why(TOWERS, 20, 30, &[]);
    assert_eq!(
        keys(&d),
        [
            "color",
            "encoding",
            "flare",
            "image",
            "offset",
            "pixel",
            "pixel_color",
            "ray",
            "refined",
            "sample",
            "samples_per_pixel"
        ]
    );
    assert_eq!(keys(&d["color"]), ["bytes", "linear"]);
    let ray = &d["ray"];
    assert_eq!(
        keys(ray),
        [
            "ambient",
            "branch",
            "children",
            "color",
            "cut",
            "depth",
            "direction",
            "hit",
            "k",
            "lights",
            "local",
            "origin",
            "rays",
            "total_internal_reflection",
            "weight"
        ]
    );
    assert_eq!(
        keys(&ray["hit"]),
        ["material", "normal", "object", "patterns", "point", "t"]
    );
    assert_eq!(keys(&ray["hit"]["material"]), ["index", "source", "span"]);
    assert_eq!(
        keys(&ray["hit"]["object"]),
        ["index", "kind", "span", "trace", "trace_text"]
    );
    assert_eq!(
        keys(&ray["hit"]["object"]["span"]),
        ["column", "end_column", "end_line", "file", "line"]
    );
    assert_eq!(
        keys(&ray["lights"][0]),
        [
            "ambient", "behind", "blocked", "diffuse", "index", "occluder", "samples", "span",
            "specular", "tinted"
        ]
    );
    assert_eq!(
        keys(&ray["lights"][0]["occluder"]),
        ["object", "point", "t"]
    );
}

#[test]
fn provenance_is_kept_only_when_asked_and_groups_add_their_chain() {
    let text = "rtc 1\ncamera { eye: [0, 0, 10] }\n\
        fn ball(r) { sphere(radius: r) }\n\
        let g = group(children: [ball(1), ball(2)])\n\
        for k in 0..2 { g.translate([k * 5, 0, 0]) }\n";
    let path = Path::new("prov.rtc");
    let mut sources = rtc::source::SourceMap::new();
    let plain =
        rtc::eval::load_source(path, text, &mut sources, &rtc::eval::EvalOptions::default());
    assert!(plain.scene.is_some() && plain.provenance.is_none());
    let opts = rtc::eval::EvalOptions {
        provenance: true,
        ..Default::default()
    };
    let loaded = rtc::eval::load_source(path, text, &mut sources, &opts);
    let scene = loaded.scene.unwrap();
    let prov = loaded.provenance.unwrap();
    assert_eq!(scene.objects.len(), 4);
    assert_eq!(prov.objects.len(), 4, "indexed like the scene's objects");
    for (i, expect_k) in [(0, 0), (1, 0), (2, 1), (3, 1)] {
        let chains = prov.trace(i);
        assert_eq!(
            chains.len(),
            2,
            "made in `ball`, placed in the loop: {chains:?}"
        );
        assert!(matches!(
            &chains[0][0].kind,
            rtc::ir::provenance::StepKind::Call { name, .. } if name == "ball"
        ));
        assert!(matches!(
            &chains[1][0].kind,
            rtc::ir::provenance::StepKind::Iteration { bindings, .. } if *bindings == format!("k = {expect_k}")
        ));
    }
}

/// Issue 34: an object made directly in a function reads "made in `ball()` called at ...",
/// not "made in in".
#[test]
fn a_call_made_object_reads_made_in_the_call() {
    let dir = scratch("why-call");
    let file = dir.join("ball.rtc");
    std::fs::write(
        &file,
        "rtc 1.1\ncamera { eye: [0, 0, 5], resolution: [16, 12] }\npoint_light { position: [2, 5, 5] }\nfn ball() { sphere(radius: 1) }\nball()\n",
    )
    .unwrap();
    let run = rtc(&["why", file.to_str().unwrap(), "8", "6"]);
    let text = String::from_utf8_lossy(&run.stdout);
    assert!(!text.contains("made in in"), "{text}");
    assert!(text.contains("made in `ball()` called at"), "{text}");
}

#[test]
fn a_pattern_pixel_gives_the_value_and_the_colour_map_stop() {
    // A face-on plane z = 0 wearing a gradient along x over 40 units from x = −20, seen from
    // z = 1000 with one unit per pixel: pixel (30, 10) looks at x = 30.5 − 20 = 10.5, where the
    // value is (10.5 + 20) / 40 = 0.7625, in the third stop (at 0.75) of four.
    let dir = scratch("why-pattern");
    let file = dir.join("pattern.rtc");
    std::fs::write(
        &file,
        "rtc 1.1
camera { eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan(10 / 1000), resolution: [40, 20] }
point_light { position: [0, 0, 1000] }
plane(point: [0, 0, 0], normal: Z).material(material {
  texture: gradient(axis: X).colors([[0, rgb(0, 0, 0)], [0.5, rgb(1, 0, 0)], [0.75, rgb(0, 1, 0)], [1, rgb(0, 0, 1)]])
    .scale(40).translate([-20, 0, 0])
  bump: wrinkles(), bump_scale: 0 })
",
    )
    .unwrap();
    let d = why(file.to_str().unwrap(), 30, 10, &[]);
    let patterns = d["ray"]["hit"]["patterns"].as_array().unwrap();
    assert_eq!(patterns.len(), 2, "the texture and the bump");
    let tex = &patterns[0];
    assert_eq!(tex["role"], "texture");
    assert_eq!(tex["name"], "gradient");
    assert!((tex["value"].as_f64().unwrap() - 0.7625).abs() < 1e-12);
    assert_eq!(tex["stop"]["index"], 2);
    assert_eq!(tex["stop"]["at"], 0.75);
    assert_eq!(tex["stop"]["of"], 4);
    assert_eq!(patterns[1]["role"], "bump");
    assert_eq!(patterns[1]["name"], "wrinkles");
    assert!(patterns[1]["stop"].is_null());
    // The text form says the same.
    let run = rtc(&["why", file.to_str().unwrap(), "30", "10"]);
    let text =
        String::from_utf8_lossy(&run.stderr).to_string() + &String::from_utf8_lossy(&run.stdout);
    assert!(
        text.contains(
            "texture pattern `gradient` = 0.7625, in the colour map's stop 3 of 4 (at 0.75)"
        ),
        "{text}"
    );
}
