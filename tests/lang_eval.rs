//! Evaluation tests: source text in, IR (or diagnostics) out.

use rtc::num::Norm;
use std::path::Path;

use glam::DVec3;
use rtc::diag::Severity;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::{CsgOp, Projection, Sampling, Scene, ShadingModel, Shape};
use rtc::source::SourceMap;

const CAM: &str = "camera { eye: [0, 2, 8] }\npoint_light { position: [5, 5, 5] }\n";

fn eval_with(src: &str, opts: &EvalOptions) -> rtc::ir::Loaded {
    let mut sm = SourceMap::new();
    load_source(Path::new("tests/lang/inline.rtc"), src, &mut sm, opts)
}

fn scene(body: &str) -> Scene {
    let src = format!("rtc 1\n{body}\n{CAM}");
    let l = eval_with(&src, &EvalOptions::default());
    let errs: Vec<_> = l
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error())
        .collect();
    assert!(errs.is_empty(), "errors: {errs:#?}");
    l.scene.expect("scene")
}

fn codes(body: &str, opts: &EvalOptions) -> Vec<&'static str> {
    let src = format!("rtc 1\n{body}\n{CAM}");
    eval_with(&src, opts)
        .diagnostics
        .items
        .iter()
        .map(|d| d.code)
        .collect()
}

fn notes(body: &str) -> Vec<String> {
    let src = format!("rtc 1\n{body}\n{CAM}");
    let l = eval_with(&src, &EvalOptions::default());
    l.diagnostics
        .items
        .iter()
        .filter(|d| d.severity == Severity::Note)
        .map(|d| d.message.clone())
        .collect()
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).norm() < 1e-9
}

#[test]
fn method_chains_apply_in_reading_order() {
    let s = scene("sphere().scale(2).translate([1, 0, 0])");
    let t = s.objects[0].transform.affine();
    // scale first, then translate: (1,0,0) → (2,0,0) → (3,0,0)
    assert!(close(
        t.transform_point3(DVec3::X),
        DVec3::new(3.0, 0.0, 0.0)
    ));
    let s = scene("sphere().translate([1, 0, 0]).scale(2)");
    assert!(close(
        s.objects[0].transform.affine().transform_point3(DVec3::X),
        DVec3::new(4.0, 0.0, 0.0)
    ));
}

#[test]
fn then_operator_and_rotate_order() {
    let s = scene("let spin = rotate(z: 90deg) >> translate([0, 1, 0])\nsphere().transform(spin)");
    // X rotated 90° about z is Y, then moved up by 1.
    assert!(close(
        s.objects[0].transform.affine().transform_point3(DVec3::X),
        DVec3::new(0.0, 2.0, 0.0)
    ));
    // rotate(x:, y:) applies x first: Z →(x 90°)→ -Y →(y 90°)→ -Y
    let s = scene("sphere().rotate(x: 90deg, y: 90deg)");
    assert!(close(
        s.objects[0].transform.affine().transform_point3(DVec3::Z),
        DVec3::new(0.0, -1.0, 0.0)
    ));
}

#[test]
fn groups_flatten_and_fill_missing_materials() {
    let s = scene(
        "let red = material { color: rgb(1, 0, 0) }\nlet blue = material { color: rgb(0, 0, 1) }\n\
         group([sphere(), sphere().material(blue)]).material(red).translate([0, 5, 0])",
    );
    assert_eq!(s.objects.len(), 2);
    let m0 = s.material(s.objects[0].material.unwrap()).color;
    let m1 = s.material(s.objects[1].material.unwrap()).color;
    assert_eq!(m0, DVec3::new(1.0, 0.0, 0.0));
    assert_eq!(m1, DVec3::new(0.0, 0.0, 1.0));
    assert!(close(
        s.objects[1].transform.affine().translation,
        DVec3::new(0.0, 5.0, 0.0)
    ));
}

#[test]
fn csg_operators_build_trees_with_inherited_materials() {
    let s = scene(
        "let m = material { ks: 0.1 }\n(box() - sphere(radius: 0.6) - sphere(radius: 0.1) | sphere()).material(m)",
    );
    assert_eq!(s.objects.len(), 1);
    let Shape::Csg { op, children } = &s.objects[0].shape else {
        panic!("not csg")
    };
    assert_eq!(*op, CsgOp::Union);
    assert!(s.objects[0].material.is_some());
    let Shape::Csg {
        op: inner,
        children: diff,
    } = &children[0].shape
    else {
        panic!("not csg")
    };
    assert_eq!(*inner, CsgOp::Difference);
    assert_eq!(diff.len(), 3, "a - b - c flattens into one difference");
    assert!(diff.iter().all(|c| c.material.is_none()));
    // `&` binds tighter than `-`: a - b & c = a - (b & c)
    let s = scene("box() - sphere() & sphere(radius: 0.5)");
    let Shape::Csg { op, children } = &s.objects[0].shape else {
        panic!()
    };
    assert_eq!(*op, CsgOp::Difference);
    assert!(matches!(
        children[1].shape,
        Shape::Csg {
            op: CsgOp::Intersection,
            ..
        }
    ));
    let s = scene("union([sphere(), box()], merge: true)");
    assert!(matches!(
        s.objects[0].shape,
        Shape::Csg {
            op: CsgOp::Merge,
            ..
        }
    ));
}

#[test]
fn comprehensions_with_several_generators_and_filters() {
    let s = scene(
        "for i in 0..4, j in 0..4 if (i + j) % 2 == 0 { sphere(center: [i, 0, j], radius: 0.1) }",
    );
    assert_eq!(s.objects.len(), 8);
    let s = scene("for x in 0..=1 step 0.25 { sphere(center: [x, 0, 0], radius: 0.1) }");
    assert_eq!(s.objects.len(), 5);
    let s = scene("for i in 0..3 { if i == 1 { sphere() } }");
    assert_eq!(s.objects.len(), 1);
    let s = scene("for i in 10..0 step -5 { sphere() }");
    assert_eq!(s.objects.len(), 2);
}

/// A top-level loop over integer-literal ranges reserves its objects at once: the vector ends
/// with room for exactly 1000 (grown by doubling it would hold 1024), and the loop still makes
/// every object, also when its body makes more or fewer than one per iteration.
#[test]
fn literal_range_loops_reserve_their_objects() {
    let s = scene("for i in 0..10, j in 0..=99 { sphere(center: [i, 0, j], radius: 0.1) }");
    assert_eq!(s.objects.len(), 1000);
    assert_eq!(s.objects.capacity(), 1000);
    let s = scene("for i in 0..3 { [sphere(), sphere()] }");
    assert_eq!(s.objects.len(), 6);
    let s = scene("for i in 0..5 { if i == 1 { sphere() } }");
    assert_eq!(s.objects.len(), 1);
    let s = scene("for i in 5..0 { sphere() }");
    assert!(s.objects.is_empty());
}

/// Arithmetic over numbers and names of numbers is computed on a fast path (in registers, no
/// values built); its results are IEEE arithmetic on the same operands (computed here in Rust),
/// Int stays Int (it overflows), and what it leaves to the general operator keeps its error.
#[test]
fn arithmetic_fast_path_agrees_with_the_general_rules() {
    let s = scene(
        "let s = 0.4\n\
         fn at(r) { sphere(center: [r * s - 20.0, -r, 2 - r * r], radius: 0.1 + 0.05 * ((r + 1) % 3)) }\n\
         for i in 0..3 { at(i) }\n\
         sphere(center: [7 / 2, -(3 - 5), 9 % -4], radius: 1 + 2 * 3)",
    );
    for i in 0..3 {
        let r = i as f64;
        let want = DVec3::new(r * 0.4 - 20.0, -r, (2 - i * i) as f64);
        let radius = 0.1 + 0.05 * ((i + 1) % 3) as f64;
        match &s.objects[i as usize].shape {
            Shape::Sphere {
                center,
                radius: got,
            } => {
                assert_eq!((*center, *got), (want, radius), "i = {i}")
            }
            other => panic!("{other:?}"),
        }
    }
    match &s.objects[3].shape {
        // 9 % -4 is Euclidean (1); Int results stay exact.
        Shape::Sphere { center, radius } => {
            assert_eq!((*center, *radius), (DVec3::new(3.5, 2.0, 1.0), 7.0))
        }
        other => panic!("{other:?}"),
    }
    let o = &EvalOptions::default();
    for (expr, code) in [
        ("9223372036854775807 + 1", "rtc::value::overflow"),
        ("-(-9223372036854775807 - 1)", "rtc::value::overflow"),
        ("1.0 / 0", "rtc::value::division_by_zero"),
        ("5 % 0", "rtc::value::division_by_zero"),
    ] {
        let got = codes(&format!("sphere(radius: 1 + {expr})"), o);
        assert!(got.contains(&code), "{expr}: {got:?}");
    }
    // A tree the fast path gives up on (a call at the bottom) is evaluated the general way, at
    // every depth, with the same result.
    let deep = format!("{}sqrt(4.0){}", "1 + (".repeat(40), ")".repeat(40));
    let s = scene(&format!("sphere(radius: {deep})"));
    match &s.objects[0].shape {
        Shape::Sphere { radius, .. } => assert_eq!(*radius, 42.0),
        other => panic!("{other:?}"),
    }
}

/// `.material(m)` takes its one argument positionally or as `material:` (a fast path matches
/// those without the schema); anything else is the schema's error, as for every built-in.
#[test]
fn material_method_forms_and_errors() {
    let s = scene(
        "let red = material { color: rgb(1, 0, 0) }\nlet blue = material { color: rgb(0, 0, 1) }\n\
         sphere().material(red)\nsphere().material(material: blue)\n\
         for i in 0..3 { sphere(center: [i, 0, 0]).material(if i == 1 { blue } else { red }) }",
    );
    let colors: Vec<_> = s
        .objects
        .iter()
        .map(|o| s.material(o.material.unwrap()).color.to_array())
        .collect();
    let (r, b) = ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    assert_eq!(colors, vec![r, b, r, b, r]);
    let opts = EvalOptions::default();
    let m = "let m = material { ks: 0.1 }\n";
    assert_eq!(
        codes(&format!("{m}sphere().material(mat: m)"), &opts),
        vec!["rtc::arg::unknown"]
    );
    assert_eq!(
        codes(&format!("{m}sphere().material(m, m)"), &opts),
        vec!["rtc::arg::too_many"]
    );
    assert_eq!(
        codes("sphere().material(1)", &opts),
        vec!["rtc::type::mismatch"]
    );
    assert_eq!(
        codes("sphere().material()", &opts),
        vec!["rtc::arg::missing"]
    );
}

#[test]
fn functions_defaults_recursion_and_closures() {
    let n = notes(
        "fn fib(n: Int) -> Int { if n < 2 { n } else { fib(n - 1) + fib(n - 2) } }\n\
         fn scaled(x: Float, k: Float = 2) { x * k }\n\
         let triple = fn(x) x * 3\n\
         let k = 10\nlet addk = fn(x) x + k\n\
         print(fib(15), scaled(1.5), scaled(1, k: 4), triple(7), addk(1), [1, 2, 3, 4].map(triple))",
    );
    assert_eq!(n, vec!["610 3 4 21 11 [3, 6, 9, 12]"]);
}

#[test]
fn values_strings_and_units() {
    let n = notes(
        "let a = 90deg\nlet v = [1, 2, 3]\nlet r = { w: 2, h: 3 }\nlet r2 = r with { h: 5 }\n\
         print(\"{sin(a)} {a.deg} {v.zx} {v.xyz} {r2.h} {7 / 2} {7 % 3} {pi:.3} {0.25turn.deg}\")",
    );
    assert_eq!(n, vec!["1 90 [3, 1] [1, 2, 3] 5 3.5 1 3.142 90"]);
}

#[test]
fn materials_with_checks_copies() {
    let s = scene(
        "let glass = material { refract: 0.9, eta: 1.5 }\nsphere().material(glass with { eta: 1.33 })",
    );
    let m = s.material(s.objects[0].material.unwrap());
    assert_eq!((m.refract, m.eta), (0.9, 1.33));
    assert_eq!(
        codes(
            "let g = material { eta: 1.5 } with { eta: -1 }",
            &EvalOptions::default()
        ),
        vec!["rtc::param::out_of_range"]
    );
}

#[test]
fn one_material_value_is_stored_once() {
    let s = scene(
        "let m = material { kd: 0.5 }\nfor i in 0..100 { sphere(center: [i, 0, 0]).material(m) }",
    );
    assert_eq!(s.objects.len(), 100);
    assert_eq!(s.materials.len(), 1);
}

#[test]
fn camera_and_render_settings() {
    let src = "rtc 1\ncamera { eye: [0, 3, 8], center: [0, 0, 0], fov: 60deg, resolution: [320, 200], aperture: 0.1 }\n\
               render { supersampling: adaptive(min: 1, max: 8, threshold: 0.05), shading: gooch { alpha: 0.2 }, \
               max_depth: 3, shadows: false, background: #ffffff, seed: 9 }\n";
    let l = eval_with(src, &EvalOptions::default());
    let s = l.scene.expect("scene");
    assert_eq!((s.camera.width, s.camera.height), (320, 200));
    let Projection::Perspective { fov_y } = s.camera.projection else {
        panic!()
    };
    assert!((fov_y - 60f64.to_radians()).abs() < 1e-12);
    assert!((s.camera.focus_distance - DVec3::new(0.0, 3.0, 8.0).norm()).abs() < 1e-12);
    assert_eq!(
        s.settings.sampling,
        Sampling::Adaptive {
            min: 1,
            max: 8,
            threshold: 0.05
        }
    );
    let ShadingModel::Gooch(g) = s.settings.shading else {
        panic!()
    };
    assert_eq!(g.alpha, 0.2);
    assert_eq!(
        (s.settings.max_depth, s.settings.shadows, s.settings.seed),
        (3, false, 9)
    );
    assert_eq!(
        s.settings.background,
        DVec3::ONE,
        "#ffffff is sRGB white = linear 1"
    );
    let l = eval_with(
        "rtc 1\ncamera { eye: [0, 3, 8] }\n",
        &EvalOptions::default(),
    );
    let s = l.scene.unwrap();
    assert_eq!((s.camera.width, s.camera.height), (640, 480));
    assert_eq!(
        s.camera.projection,
        Projection::Perspective {
            fov_y: 40f64.to_radians()
        }
    );
}

#[test]
fn shapes_have_object_space_parameters() {
    let s = scene(
        "cylinder(radius: 0.5, height: 2, axis: X)\ncone(base: [0, 0, 0], top: [0, 2, 0], base_radius: 1)\ntorus(major_radius: 2, minor_radius: 0.5)",
    );
    assert_eq!(
        s.objects[0].shape,
        Shape::Cylinder {
            base: DVec3::new(-1.0, 0.0, 0.0),
            top: DVec3::new(1.0, 0.0, 0.0),
            radius: 0.5,
            capped: true
        }
    );
    assert!(matches!(
        s.objects[1].shape,
        Shape::Cone {
            top_radius: 0.0,
            ..
        }
    ));
    assert!(s.objects[2].transform.is_identity());
}

#[test]
fn bounds_are_queryable() {
    let n = notes(
        "let b = sphere(radius: 2).translate([0, 1, 0]).bounds\nprint(b.min, b.max, b.top_center)",
    );
    assert_eq!(n, vec!["[-2, -1, -2] [2, 3, 2] [0, 3, 0]"]);
}

#[test]
fn budgets_stop_runaway_scenes() {
    let small = EvalOptions {
        max_loop_iterations: 1000,
        max_recursion_depth: 16,
        max_objects: 50,
        max_list_len: 100,
        max_string_len: 1000,
        ..EvalOptions::default()
    };
    assert!(codes("for i in 0..2000 { }", &small).contains(&"rtc::budget::loop"));
    assert!(codes("let l = for i in 0..500 { i }", &small).contains(&"rtc::budget::list"));
    let doubling = "fn d(s: String, n: Int) -> String { if n == 0 { s } else { d(s + s, n - 1) } }";
    assert!(
        codes(&format!("{doubling}\nlet s = d(\"ab\", 9)"), &small)
            .contains(&"rtc::budget::string")
    );
    let s = format!("{doubling}\nlet s = d(\"ab\", 8)\nlet t = \"{{s}}{{s}}\"");
    assert!(codes(&s, &small).contains(&"rtc::budget::string"));
    assert!(codes("for i in 0..60 { sphere() }", &small).contains(&"rtc::budget::objects"));
    assert!(codes("fn f(n: Int) { f(n + 1) }\nf(0)", &small).contains(&"rtc::budget::recursion"));
}

#[test]
fn errors_recover_per_statement_and_do_not_cascade() {
    let c = codes(
        "let a = nope\nlet b = a + 1\nlet c = sphere(radius: 0)\nsphere(radius: 1)",
        &EvalOptions::default(),
    );
    assert_eq!(c, vec!["rtc::name::unknown", "rtc::param::out_of_range"]);
}

#[test]
fn modules_are_evaluated_once_and_exports_checked() {
    let src = "rtc 1\nimport \"lib/counted.rtc\" as a\nimport \"lib/counted.rtc\" { tint }\nsphere().material(material { color: tint })\n";
    let mut sm = SourceMap::new();
    let l = load_source(
        Path::new("tests/lang/mods.rtc"),
        format!("{src}{CAM}"),
        &mut sm,
        &EvalOptions::default(),
    );
    let prints: Vec<_> = l
        .diagnostics
        .items
        .iter()
        .filter(|d| d.code == "rtc::print")
        .collect();
    assert_eq!(prints.len(), 1, "{:#?}", l.diagnostics.items);
    assert!(l.scene.is_some());
}

/// Lists that share their items describe a tree of 2^60 leaves in 60 steps; `print`, `str` and
/// error traces show it in bounded text (before, printing 2^26 leaves took 107 s and 5 GB).
#[test]
fn showing_a_shared_list_tree_stays_small() {
    let n = notes(
        "fn tree(x, n: Int) { if n == 0 { x } else { tree([x, x], n - 1) } }\n\
         let t = tree(1, 60)\nprint(t)\nprint(str(t) == str(t))\nprint(\"{t}\" == str(t))",
    );
    assert_eq!(n.len(), 3, "{n:?}");
    assert!(
        n[0].starts_with("[[[[") && n[0].ends_with("..."),
        "{}",
        &n[0][..80]
    );
    assert!(n[0].len() <= rtc::eval::SHOW_LIMIT + 3, "{}", n[0].len());
    assert_eq!(&n[1..], ["true", "true"]);
}

#[test]
fn stdlib_modules_are_embedded() {
    let n = notes(
        "import std.prelude as p\nprint(p.lerp(0, 10, 0.25), p.clamp(5, 0, 1), p.smoothstep(0, 1, 0.5))",
    );
    assert_eq!(n, vec!["2.5 1 0.5"]);
}

#[test]
fn missing_assets_are_reported_with_resolved_paths() {
    let l = eval_with(
        "rtc 1\nsphere().material(material { texture: image(\"nope.png\") })\n",
        &EvalOptions::default(),
    );
    let d = &l.diagnostics.items[0];
    assert_eq!(d.code, "rtc::asset::missing");
    assert!(d.message.contains("tests/lang/nope.png"), "{}", d.message);
}

#[test]
fn random_streams_are_keyed_and_pinned() {
    // Values from an independent Python implementation of the algorithm documented in
    // src/eval/rng.rs; FNV-1a("a") = 0xaf63dc4c8601ec8c is the published test vector.
    assert_eq!(rtc::eval::rng::fnv(""), 0xcbf29ce484222325);
    assert_eq!(rtc::eval::rng::fnv("a"), 0xaf63dc4c8601ec8c);
    assert_eq!(rtc::eval::rng::mix(1), 0x5692161d100b05e5);
    assert_eq!(rtc::eval::rng::bits(7, "jitter", 0, 0), 0xbab976810bd308f8);
    assert_eq!(rtc::eval::rng::bits(7, "jitter", 3, 0), 0x3ec0520f4de64af3);
    assert_eq!(rtc::eval::rng::bits(7, "hue", -1, 0), 0xc5c7ea836ff7c342);
    assert_eq!(rtc::eval::rng::unit(7, "jitter", 1, 0), 0.8933723091336052);
    let n = notes(
        "let r = random(seed: 7)\nprint(r.uniform(\"jitter\", 0), r.uniform(\"jitter\", 0) == random(seed: 7).uniform(\"jitter\", 0))",
    );
    assert_eq!(n, vec!["0.729392 true"]);
    let p = rtc::eval::rng::sphere_point(3, "k", 5, false);
    assert!((p.norm() - 1.0).abs() < 1e-12);
}

#[test]
fn the_language_md_example_evaluates() {
    let path = Path::new("tests/lang/five_spheres.rtc");
    let mut sm = SourceMap::new();
    let l = rtc::eval::load_file(path, &mut sm, &EvalOptions::default());
    assert!(!l.diagnostics.has_errors(), "{:#?}", l.diagnostics.items);
    let s = l.scene.unwrap();
    assert_eq!(s.objects.len(), 8);
    assert_eq!(s.lights.len(), 2);
    assert_eq!((s.camera.width, s.camera.height), (1280, 720));
    assert!(s.objects.iter().any(|o| matches!(
        o.shape,
        Shape::Csg {
            op: CsgOp::Difference,
            ..
        }
    )));
    assert!(s.objects.iter().all(|o| o.span.end > o.span.start));
}
