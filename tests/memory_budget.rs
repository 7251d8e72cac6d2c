//! The memory budget of one scene load (issue 35 §4, docs/language.md §24): the evaluation's
//! strings, lists and objects, the course YAML reader's nodes, then the textures and meshes
//! the preparation loads are charged to one budget before they are built, so a file that asks
//! for more stops with `rtc::budget::memory` at what asked, whatever the per-item budgets
//! allow. Scaled down here under small budgets; `benches/hostile.sh` runs the full-size cases.

mod cli_support;

use std::path::Path;

use cli_support::{rtc, scratch};

use rtc::eval::{EvalOptions, LoopParts, load_source};
use rtc::ir::limits::{MEMORY_BUDGET_CODE, parse_bytes};
use rtc::source::SourceMap;

const CAMERA: &str = "rtc 1\ncamera { eye: [0, 0, 5], center: [0, 0, 0], up: Y, resolution: [8, 6] }\n\
                      point_light { position: [5, 5, 5] }\n";

/// Evaluates `text` under a memory budget of `bytes`; the memory error's line and label, if
/// the evaluation stopped on one.
fn memory_error(text: &str, bytes: u64, parts: LoopParts) -> Option<(usize, String)> {
    let opts = EvalOptions {
        max_memory: bytes,
        loop_parts: parts,
        ..EvalOptions::default()
    };
    let mut sources = SourceMap::new();
    let loaded = load_source(Path::new("memory.rtc"), text, &mut sources, &opts);
    let d = loaded
        .diagnostics
        .items
        .iter()
        .find(|d| d.code == MEMORY_BUDGET_CODE)?;
    assert!(loaded.scene.is_none(), "an error still gave a scene");
    assert!(
        d.help
            .as_deref()
            .is_some_and(|h| h.contains("--memory-budget")),
        "{d:?}"
    );
    let span = d.span.expect("the error has a place");
    let (line, _) = sources.get(span.file).line_col(span.start as usize);
    Some((line, d.label.clone().unwrap_or_default()))
}

/// Strings each within the string budget, kept together in a list, pass the memory budget
/// (2,000 × a 4 MB string aborted the process before); the same scene fits a larger budget.
#[test]
fn strings_within_their_own_budget_still_count_against_memory() {
    let scene = "rtc 1\nlet big = for i in 0..12 { \"0123456789abcdef\" }\n\
                 fn grow(s: String, n: Int) -> String { if n == 0 { s } else { grow(s + s, n - 1) } }\n\
                 let kb = grow(\"0123456789abcdef\", 6)\n\
                 let all = for i in 0..2000 { kb + str(i) }\n";
    let (line, label) = memory_error(scene, 1 << 20, LoopParts::Serial).expect("refused");
    assert_eq!(line, 5, "{label}");
    assert!(label.contains("string"), "{label}");
    assert!(memory_error(scene, 64 << 20, LoopParts::Serial).is_none());
}

/// An `iterate` that never ends stops at the memory budget once its list passes it, long
/// before the list budget (10 million elements) or the loop budget.
#[test]
fn a_list_that_never_stops_growing_meets_the_memory_budget() {
    let scene = "rtc 1\nlet x = iterate(0, fn(i) i + 1, fn(i) true)\n";
    let (line, label) = memory_error(scene, 1 << 20, LoopParts::Serial).expect("refused");
    assert_eq!(line, 2);
    assert!(label.contains("iterate"), "{label}");
}

/// A grid of objects is stopped by the memory its objects take, at the loop that makes them,
/// and at the same place whether the loop is evaluated on one thread or in parts.
#[test]
fn objects_are_charged_and_the_place_does_not_depend_on_threads() {
    let scene =
        format!("{CAMERA}for i in 0..200 {{ for j in 0..200 {{ sphere(center: [i, j, 0]) }} }}\n");
    let serial = memory_error(&scene, 2 << 20, LoopParts::Serial).expect("refused");
    assert_eq!(serial.0, 4);
    assert!(serial.1.contains("objects"), "{}", serial.1);
    let parts = memory_error(&scene, 2 << 20, LoopParts::Always(3)).expect("refused");
    assert_eq!(parts, serial, "in parts");
    assert!(memory_error(&scene, 64 << 20, LoopParts::Always(3)).is_none());
}

/// Runs `rtc ARGS`, which must stop at the memory budget (exit 1, its code); its stderr.
fn refused(args: &[&str]) -> String {
    let run = rtc(args);
    let text = String::from_utf8_lossy(&run.stderr).into_owned();
    assert_eq!(run.status.code(), Some(1), "{args:?}: {text}");
    assert!(text.contains(MEMORY_BUDGET_CODE), "{text}");
    text
}

/// Runs `rtc ARGS`, which must succeed.
fn passes(args: &[&str]) {
    let run = rtc(args);
    assert_eq!(
        run.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
}

/// Writes a `w`×`h` PNG of one colour.
fn png(path: &Path, w: u32, h: u32) {
    image::RgbImage::from_pixel(w, h, image::Rgb([200, 100, 50]))
        .save(path)
        .unwrap();
}

/// Textures each within the pixel budget are charged from their headers before decoding:
/// the one that passes the budget is refused at its own place, by `check` and `render` alike,
/// and the existing image is kept.
#[test]
fn textures_are_charged_before_they_are_decoded() {
    let dir = scratch("memory-textures");
    // 256² texels of 24 bytes: 1.5 MiB each decoded.
    for name in ["a.png", "b.png", "c.png", "d.png"] {
        png(&dir.join(name), 256, 256);
    }
    let mut scene = String::from(CAMERA);
    for (i, name) in ["a.png", "b.png", "c.png", "d.png"].iter().enumerate() {
        scene.push_str(&format!(
            "sphere(center: [{i}, 0, 0]).material(material {{ texture: image(\"{name}\") }})\n"
        ));
    }
    let file = dir.join("s.rtc");
    std::fs::write(&file, scene).unwrap();
    let out = dir.join("out.png");
    std::fs::write(&out, b"precious").unwrap();
    let f = file.to_str().unwrap();
    let o = out.to_str().unwrap();
    for args in [
        vec!["check", f, "--memory-budget", "4MiB"],
        vec!["render", f, "-o", o, "--memory-budget", "4MiB"],
    ] {
        let text = refused(&args);
        assert!(
            text.contains(&format!("{f}:6:")),
            "the third texture: {text}"
        );
        assert!(text.contains("c.png"), "{text}");
    }
    assert_eq!(std::fs::read(&out).unwrap(), b"precious");
    passes(&["check", f, "--memory-budget", "8MiB"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A mesh is charged its file's data before its BVH is built.
#[test]
fn meshes_are_charged_when_they_load() {
    let dir = scratch("memory-mesh");
    let mut obj = String::new();
    for i in 0..2000 {
        let x = i as f64;
        obj.push_str(&format!("v {x} 0 0\nv {x} 1 0\nv {} 0 1\n", x + 0.5));
    }
    for i in 0..2000 {
        obj.push_str(&format!("f {} {} {}\n", 3 * i + 1, 3 * i + 2, 3 * i + 3));
    }
    std::fs::write(dir.join("m.obj"), obj).unwrap();
    let file = dir.join("s.rtc");
    std::fs::write(&file, format!("{CAMERA}mesh(path: \"m.obj\")\n")).unwrap();
    let f = file.to_str().unwrap();
    let text = refused(&["check", f, "--memory-budget", "32KiB"]);
    assert!(
        text.contains(&format!("{f}:4:1")) && text.contains("m.obj"),
        "{text}"
    );
    passes(&["check", f, "--memory-budget", "16MiB"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A YAML alias tree is charged its scalars' bytes as it expands: few nodes, each a long
/// leaf, no longer pass (the node budget alone let a 1 MB leaf ask for 111 GB).
#[test]
fn yaml_aliases_are_charged_by_the_bytes_they_copy() {
    let dir = scratch("memory-yaml");
    let leaf = "x".repeat(10_000);
    let mut yaml = format!("a: &a \"{leaf}\"\n");
    let mut prev = "a".to_string();
    for level in 0..8 {
        let name = format!("l{level}");
        yaml.push_str(&format!(
            "{name}: &{name} [*{prev}, *{prev}, *{prev}, *{prev}]\n"
        ));
        prev = name;
    }
    let path = dir.join("bomb.yaml");
    std::fs::write(&path, yaml).unwrap();
    let mut sources = SourceMap::new();
    let loaded = rtc::compat::load_yaml_within(&path, &mut sources, 64 << 20);
    let codes: Vec<_> = loaded.diagnostics.items.iter().map(|d| d.code).collect();
    assert!(codes.contains(&MEMORY_BUDGET_CODE), "{codes:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The command line reads sizes with units and refuses nonsense as a usage error.
#[test]
fn the_memory_budget_option_reads_sizes() {
    assert_eq!(parse_bytes("512MiB"), Ok(512 << 20));
    let dir = scratch("memory-option");
    let file = dir.join("s.rtc");
    std::fs::write(&file, format!("{CAMERA}sphere()\n")).unwrap();
    let f = file.to_str().unwrap();
    let run = rtc(&["check", f, "--memory-budget", "lots"]);
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("not a size"));
    let run = rtc(&["check", f, "--memory-budget", "1GiB"]);
    assert_eq!(run.status.code(), Some(0));
    std::fs::remove_dir_all(&dir).unwrap();
}
