//! Long loops evaluated on several threads (`rtc::eval::split`) make exactly what one thread
//! makes: the same scene (objects in order, materials and textures numbered alike, lights,
//! cameras) and the same findings, with errors and budgets met at the same iteration. The rule
//! is the serial evaluation itself (`LoopParts::Serial`); every case is also run with each
//! loop forced into 2, 3 and 5 parts.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use rtc::eval::{EvalOptions, LoopParts, load_source};
use rtc::ir::Loaded;
use rtc::source::SourceMap;

fn eval(path: &Path, src: &str, opts: &EvalOptions, parts: LoopParts) -> Loaded {
    let opts = EvalOptions {
        loop_parts: parts,
        ..opts.clone()
    };
    let mut sources = SourceMap::new();
    load_source(path, src, &mut sources, &opts)
}

/// Asserts that every forced split of `src` evaluates to what the serial evaluation makes.
fn same_split(path: &Path, src: &str, opts: &EvalOptions) -> Loaded {
    let serial = eval(path, src, opts, LoopParts::Serial);
    for parts in [2, 3, 5] {
        let split = eval(path, src, opts, LoopParts::Always(parts));
        assert_eq!(
            split.diagnostics.items,
            serial.diagnostics.items,
            "{} in {parts} parts: other findings",
            path.display()
        );
        assert!(
            split.scene == serial.scene,
            "{} in {parts} parts: another scene",
            path.display()
        );
        // The memory charged is the same too (the budget stops both at the same place).
        assert_eq!(
            split.scene.as_ref().map(|s| s.memory),
            serial.scene.as_ref().map(|s| s.memory),
            "{} in {parts} parts: other bytes charged",
            path.display()
        );
    }
    serial
}

fn inline(src: &str) -> Loaded {
    inline_with(src, &EvalOptions::default())
}

fn inline_with(src: &str, opts: &EvalOptions) -> Loaded {
    let text = format!(
        "rtc 1\ncamera {{ eye: [0, 2, 8] }}\npoint_light {{ position: [5, 5, 5] }}\n{src}\n"
    );
    same_split(Path::new("tests/lang/inline.rtc"), &text, opts)
}

fn codes(l: &Loaded) -> Vec<&'static str> {
    l.diagnostics.items.iter().map(|d| d.code).collect()
}

#[test]
fn every_scene_and_diagnostic_case_splits_to_the_same_result() {
    let mut files: Vec<PathBuf> = Vec::new();
    for dir in ["scenes", "scenes/looks", "tests/lang", "tests/diagnostics"] {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "rtc") {
                files.push(p);
            }
        }
    }
    files.sort();
    assert!(files.len() > 80, "the corpus is missing: {}", files.len());
    for p in files {
        // A file that is not UTF-8 is refused before evaluation.
        if let Ok(src) = std::fs::read_to_string(&p) {
            same_split(&p, &src, &EvalOptions::default());
        }
    }
}

#[test]
fn materials_and_textures_keep_their_numbers() {
    let l = inline(
        "let shared = material { color: rgb(1, 0, 0) }
         let late = material { texture: checker(size: 2) }
         let never = material { color: rgb(0, 0, 1) }
         for i in 0..12 {
           if i % 4 == 0 {
             sphere(center: [i, 0, 0], radius: 0.5).material(shared)
           } else if i > 8 {
             sphere(center: [i, 0, 0], radius: 0.5).material(late)
           } else {
             sphere(center: [i, 1, 0], radius: 0.5)
               .material(material { color: rgb(i / 12, 0.5, 0.5), texture: stripes(size: i + 1) })
           }
         }
         sphere(center: [0, 5, 0], radius: 1).material(late)
         sphere(center: [0, 6, 0], radius: 1).material(shared with { ks: 0.9 })",
    );
    let scene = l.scene.unwrap();
    assert_eq!(scene.objects.len(), 14);
    // shared, the six per-iteration materials, late, and the `with` copy.
    assert_eq!(scene.materials.len(), 9);
    assert_eq!(scene.textures.len(), 7);
}

#[test]
fn warnings_are_reported_once_as_by_one_thread() {
    let l = inline(
        "let r = 0.5
         for i in 0..20 {
           let r = 0.25
           print(\"made {i}\")
           sphere(center: [i, 0, 0], radius: r)
         }",
    );
    let c = codes(&l);
    assert_eq!(
        c.iter().filter(|c| **c == "rtc::name::shadowed").count(),
        1,
        "{c:?}"
    );
    assert_eq!(c.len(), 21, "{c:?}");
}

#[test]
fn an_error_late_in_the_loop_is_met_where_one_thread_meets_it() {
    let l = inline(
        "for i in 0..30 {
           if i == 23 { sphere(center: [i, 0, 0], radius: -1) } else { sphere(center: [i, 0, 0], radius: 1) }
         }
         sphere(center: [0, 9, 0], radius: 1)",
    );
    assert!(l.diagnostics.items.iter().any(|d| d.is_error()));
    let trace = format!("{:?}", l.diagnostics.items);
    assert!(trace.contains("i = 23"), "{trace}");
}

#[test]
fn budgets_run_out_at_the_same_iteration() {
    let loops = EvalOptions {
        max_loop_iterations: 500,
        ..EvalOptions::default()
    };
    let l = inline_with(
        "for i in 0..40, j in 0..20 { sphere(center: [i, j, 0], radius: 0.1) }",
        &loops,
    );
    assert_eq!(codes(&l), vec!["rtc::budget::loop"]);
    let objects = EvalOptions {
        max_objects: 100,
        ..EvalOptions::default()
    };
    let l = inline_with(
        "for i in 0..30 { [sphere(center: [i, 0, 0], radius: 0.1), sphere(center: [i, 1, 0], radius: 0.1), sphere(center: [i, 2, 0], radius: 0.1), sphere(center: [i, 3, 0], radius: 0.1)] }",
        &objects,
    );
    assert_eq!(codes(&l), vec!["rtc::budget::objects"]);
}

#[test]
fn lights_cameras_and_render_blocks_from_loops_stay_in_order() {
    inline(
        "for i in 0..9 { point_light { position: [i, 5, 0], color: rgb(i / 9, 1, 1) } }
         for i in 0..4 { if i == 3 { render { shadows: false } } else { sphere(center: [i, 0, 0], radius: 1) } }
         for i in 0..3 { camera { eye: [i, 2, 8] } }",
    );
}

#[test]
fn several_loops_lists_vectors_filters_and_randomness() {
    let l = inline(
        "let rng = random(seed: 7)
         let xs = [1, 2, 3, 5, 8, 13, 21]
         for i in 0..50 if i % 3 != 1 { sphere(center: rng.in_sphere(\"p\", i) * 5, radius: 0.1 + rng.uniform(\"r\", i) * 0.2) }
         for x in xs, y in [0, 1] { box(min: [x, y, 0], max: [x + 0.5, y + 0.5, 0.5]) }
         for c in [1, 2, 3] { for d in 0..c { torus(center: [c, d, 0], major_radius: 1, minor_radius: 0.1) } }
         for i in 0..10 { if i % 2 == 0 { group([sphere(center: [i, 0, 0], radius: 1), sphere(center: [i, 3, 0], radius: 1)]).translate([0, 0, i]) } }
         for i in 0..6 { (sphere(center: [i, 0, 0], radius: 1) | box(min: [i, 0, 0], max: [i + 1, 1, 1])).material(material { color: rgb(1, i / 6, 0) }) }",
    );
    assert!(l.scene.is_some(), "{:?}", l.diagnostics.items);
}

#[test]
fn imported_modules_are_replayed_from_what_was_read() {
    let dir = std::env::temp_dir().join(format!("rtc-split-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("props.rtc"),
        "rtc 1\npub let red = material { color: rgb(1, 0, 0) }\npub fn ball(x) { sphere(center: [x, 0, 0], radius: 0.4).material(red) }\n",
    )
    .unwrap();
    let src = "rtc 1\nimport \"./props.rtc\" as props\nimport std.materials\ncamera { eye: [0, 2, 8] }\npoint_light { position: [5, 5, 5] }\nfor i in 0..16 { if i % 2 == 0 { props.ball(i) } else { sphere(center: [i, 1, 0], radius: 0.3).material(materials.gold) } }\n";
    let l = same_split(&dir.join("scene.rtc"), src, &EvalOptions::default());
    let scene = l.scene.expect("scene");
    assert_eq!(scene.objects.len(), 16);
    assert_eq!(scene.materials.len(), 2);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A small loop program from a few pieces: a prefix, loop headers and bodies that make
/// objects, materials, warnings, prints and errors.
fn program() -> impl Strategy<Value = String> {
    let prefix = prop::sample::select(vec![
        "",
        "let m = material { color: rgb(0.2, 0.4, 0.6) }\n",
        "let m = material { texture: checker(size: 1) }\nlet n = m with { kd: 0.3 }\n",
    ]);
    let header = prop::sample::select(vec![
        "for i in 0..N",
        "for i in 0..N, j in 0..3",
        "for i in 0..N if i % 3 != 0",
        "for i in [2, 4, 6, 8, 10, 12, 14]",
        "for i in 0..=N step 2",
    ]);
    let body = prop::sample::select(vec![
        "sphere(center: [i, 0, 0], radius: 0.5)",
        "sphere(center: [i, 0, 0], radius: 0.5).material(material { color: rgb(1, 0, 0) })",
        "if i % 2 == 0 { sphere(center: [i, 0, 0], radius: 0.5).material(MAT) } else { box(min: [i, 0, 0], max: [i + 1, 1, 1]) }",
        "let r = 0.5\nprint(\"at {i}\")\nsphere(center: [i, 1, 0], radius: r)",
        "if i == K { sphere(center: [i, 0, 0], radius: 0 - 1) } else { sphere(center: [i, 0, 0], radius: 1) }",
        "for k in 0..i { sphere(center: [i, k, 0], radius: 0.2) }",
        "if i == K { point_light { position: [i, 5, 0] } } else { [] }",
    ]);
    (
        prefix,
        prop::collection::vec((header, body, 1..12u32, 0..14u32), 1..4),
    )
        .prop_map(|(prefix, loops)| {
            let mut src = String::from(prefix);
            src.push_str("let r = 2\n");
            for (header, body, n, k) in loops {
                let mat = if src.contains("let m") {
                    "m"
                } else {
                    "material { color: rgb(0, 1, 0) }"
                };
                src.push_str(&header.replace('N', &n.to_string()));
                src.push_str(" {\n");
                src.push_str(&body.replace("MAT", mat).replace('K', &k.to_string()));
                src.push_str("\n}\n");
            }
            src
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn random_loop_programs_split_to_the_same_result(
        src in program(),
        budget in prop::sample::select(vec![30u64, 200, 50_000_000]),
    ) {
        let opts = EvalOptions { max_loop_iterations: budget, max_objects: 60, ..EvalOptions::default() };
        inline_with(&src, &opts);
    }
}
