//! The legacy `.in` front end: rt1.in, the lexical rules of COURSE.md §1.2, and rt2 materials.

use std::path::Path;

use glam::DVec3;
use rtc::compat::{erase_spans, load_in, load_in_source, load_yaml};
use rtc::ir::Loaded;
use rtc::ir::{LightKind, Projection, Scene, Shape};
use rtc::source::SourceMap;

fn parse(text: &str) -> Loaded {
    load_in_source(Path::new("test.in"), text, &mut SourceMap::new())
}

fn scene(text: &str) -> Scene {
    let loaded = parse(text);
    assert!(
        loaded.diagnostics.items.is_empty(),
        "unexpected diagnostics: {:?}",
        loaded.diagnostics.items
    );
    loaded.scene.expect("a scene")
}

fn codes(text: &str) -> Vec<&'static str> {
    parse(text)
        .diagnostics
        .items
        .iter()
        .map(|d| d.code)
        .collect()
}

fn spheres(s: &Scene) -> Vec<(DVec3, f64)> {
    s.objects
        .iter()
        .map(|o| match o.shape {
            Shape::Sphere { center, radius } => (center, radius),
            ref other => panic!("not a sphere: {other:?}"),
        })
        .collect()
}

const MINIMAL: &str = "Eye 200 200 1000\nLight -200 600 1500 1 1 1\nMaterial 0 0 1 .2 .7 .5 64\nSphere 90 320 100 50\n";

#[test]
fn rt1_in_and_scene01_yaml_give_the_same_ir() {
    let mut sources = SourceMap::new();
    let a = load_in(Path::new("tests/data/course/in/rt1.in"), &mut sources);
    let b = load_yaml(
        Path::new("tests/data/course/yaml/scene01.yaml"),
        &mut sources,
    );
    assert!(a.diagnostics.items.is_empty(), "{:?}", a.diagnostics.items);
    assert!(b.diagnostics.items.is_empty(), "{:?}", b.diagnostics.items);
    let (a, b) = (a.scene.expect("rt1 scene"), b.scene.expect("scene01 scene"));
    assert_eq!(erase_spans(&a), erase_spans(&b));
    // And the shared IR is the course scene, number for number.
    assert_eq!(a.objects.len(), 5);
    assert_eq!(a.lights.len(), 1);
    assert_eq!(a.camera.eye, DVec3::new(200.0, 200.0, 1000.0));
    assert_eq!(a.camera.center, DVec3::new(200.0, 200.0, 0.0));
    assert_eq!(a.camera.up, DVec3::Y);
    assert_eq!((a.camera.width, a.camera.height), (400, 400));
    assert_eq!(a.camera.projection, Projection::Course);
    let orange = a.material(a.objects[4].material.expect("material"));
    assert_eq!(orange.color, DVec3::new(1.0, 0.5, 0.0));
    assert_eq!(
        (orange.ka, orange.kd, orange.ks, orange.n),
        (0.2, 0.8, 0.5, 32.0)
    );
    assert_eq!(
        orange.reflect, 0.5,
        "course rule: ks doubles as the mirror weight"
    );
}

#[test]
fn rt1_in_and_scene01_yaml_render_the_same_bytes() {
    let mut sources = SourceMap::new();
    let a = load_in(Path::new("tests/data/course/in/rt1.in"), &mut sources);
    let b = load_yaml(
        Path::new("tests/data/course/yaml/scene01.yaml"),
        &mut sources,
    );
    let options = rtc::render::RenderOptions::default();
    let ia =
        rtc::render::render_image(&a.scene.expect("rt1 scene"), &options).expect("rt1 renders");
    let ib = rtc::render::render_image(&b.scene.expect("scene01 scene"), &options)
        .expect("scene01 renders");
    assert_eq!(ia.dimensions(), (400, 400));
    assert!(
        ia.as_raw() == ib.as_raw(),
        "rt1.in and scene01.yaml render differently"
    );
}

#[test]
fn keywords_are_first_letters_in_any_case() {
    let plain = scene(MINIMAL);
    let odd = scene(
        "elephant 200 200 1000\nLIGHTS -200 600 1500 1 1 1\nm 0 0 1 .2 .7 .5 64\nsPhErE 90 320 100 50\n",
    );
    assert_eq!(erase_spans(&plain), erase_spans(&odd));
    // Letters run straight into the number: the reader skips letters, then reads.
    let glued = scene("Eye200 200 1000 L-200 600 1500 1 1 1 M0 0 1 .2 .7 .5 64 S90 320 100 50");
    assert_eq!(erase_spans(&plain), erase_spans(&glued));
}

#[test]
fn optional_delimiters_around_triples() {
    let plain = scene(MINIMAL);
    let bracketed = scene(
        "Eye (200 200 1000)\nLight ( -200 600 1500 ) < 1 1 1 >\nMaterial <0 0 1> .2 .7 .5 64\nSphere [90 320 100] 50\n",
    );
    assert_eq!(erase_spans(&plain), erase_spans(&bracketed));
}

#[test]
fn records_span_lines_and_share_lines_with_comments_between() {
    let plain = scene(MINIMAL);
    let spread = scene(
        "# header\nEye\n200\n200 # a comment inside a record\n1000 Light -200 600 1500\n1 1 1\n\n#x\nMaterial 0 0 1\t.2 .7 .5 64 Sphere 90 320 100 50 # tail",
    );
    assert_eq!(erase_spans(&plain), erase_spans(&spread));
}

#[test]
fn crlf_line_ends_and_c_style_numbers() {
    let plain = scene(MINIMAL);
    let crlf = scene(&MINIMAL.replace('\n', "\r\n"));
    assert_eq!(erase_spans(&plain), erase_spans(&crlf));
    let c = scene(
        "Eye +2e2 200. 1e3\nLight -200 600 1500 1 1 1\nMaterial 0 0 1 0.2 .7 5e-1 64\nSphere 90 320 100 50",
    );
    assert_eq!(erase_spans(&plain), erase_spans(&c));
}

#[test]
fn the_last_record_need_not_be_a_sphere_nor_end_with_a_newline() {
    let s = scene("Material 1 1 1 .2 .8 0 1 Sphere 0 0 0 1 Eye 0 0 10 Light 0 0 0 1 1 1");
    assert_eq!(s.lights.len(), 1);
    assert_eq!(spheres(&s), vec![(DVec3::ZERO, 1.0)]);
    let trailing_material =
        scene("Eye 0 0 10 Material 1 1 1 .2 .8 0 1 Sphere 0 0 0 1 Material 0 0 0 0 0 0 0");
    assert_eq!(trailing_material.objects.len(), 1);
}

#[test]
fn material_is_state_for_the_following_spheres() {
    let s = scene(
        "Eye 0 0 10 Material 1 0 0 .1 .2 .3 4 Sphere 0 0 0 1 Sphere 5 0 0 1 Material 0 1 0 .1 .2 .3 4 Sphere 9 0 0 1",
    );
    let colors: Vec<DVec3> = s
        .objects
        .iter()
        .map(|o| s.material(o.material.expect("material")).color)
        .collect();
    assert_eq!(colors, vec![DVec3::X, DVec3::X, DVec3::Y]);
}

#[test]
fn rt2_materials_take_three_optional_trailing_numbers() {
    let s = scene(
        "Eye 0 0 10 Material 1 1 1 .2 .8 .5 16 .9 .3 1.5 Sphere 0 0 0 1 Material 1 1 1 .2 .8 .5 16 .25 Sphere 3 0 0 1",
    );
    let m0 = s.material(s.objects[0].material.expect("material"));
    assert_eq!((m0.reflect, m0.refract, m0.eta), (0.9, 0.3, 1.5));
    let m1 = s.material(s.objects[1].material.expect("material"));
    assert_eq!((m1.reflect, m1.refract, m1.eta), (0.25, 0.0, 1.0));
    // Without trailing numbers: reflect = ks, refract 0, eta 1.
    let plain = scene(MINIMAL);
    let m = plain.material(plain.objects[0].material.expect("material"));
    assert_eq!((m.reflect, m.refract, m.eta), (0.5, 0.0, 1.0));
}

#[test]
fn light_positions_and_colours_are_read_in_order() {
    let s = scene(MINIMAL);
    assert_eq!(
        s.lights[0].kind,
        LightKind::Point {
            position: DVec3::new(-200.0, 600.0, 1500.0)
        }
    );
    assert_eq!(s.lights[0].color, DVec3::ONE);
}

#[test]
fn errors_keep_going_after_the_first() {
    let found = codes(
        "Eye 0 0 10\nQuux 1 2 3\nMaterial 1 1 1 .2 .8 0 1\nSphere 0 0 nope 1\nSphere 0 0 0 -1\n",
    );
    assert_eq!(
        found,
        vec![
            "rtc::in::unknown_record",
            "rtc::in::expected_number",
            "rtc::compat::out_of_range"
        ]
    );
}

#[test]
fn missing_eye_and_sphere_before_material_are_errors() {
    assert_eq!(
        codes("Material 1 1 1 .2 .8 0 1 Sphere 0 0 0 1"),
        vec!["rtc::compat::no_camera"]
    );
    assert_eq!(
        codes("Eye 0 0 1 Sphere 0 0 0 1"),
        vec!["rtc::in::no_material"]
    );
    assert!(parse("").scene.is_none());
}
