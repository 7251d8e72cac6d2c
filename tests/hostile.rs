//! Hostile inputs (issue 35), what rtc reads: files, folders and text made to hang, exhaust or
//! crash it. Each case ends with a coded error (exit code 1, or 2 for a file that cannot be
//! read) instead of a hang or a crash. Inputs are scaled down under lowered budgets; the
//! full-size cases run from `benches/hostile.sh`. What rtc writes is in `hostile_output.rs`.

mod hostile_support;

use std::path::Path;

use hostile_support::*;

use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

// ---- 1. imports through symlinked folders -------------------------------------------------

/// `ln -s . l1; ln -s . l2` and a module that imports itself through both links: each path
/// names the same file, so it is one module and the import closes a cycle, at once.
#[cfg(unix)]
#[test]
fn a_module_reached_through_symlinked_folders_is_one_module() {
    let dir = scratch("symlinked-imports");
    symlink(".", &dir.join("l1"));
    symlink(".", &dir.join("l2"));
    write(
        &dir.join("a.rtc"),
        "rtc 1\nimport \"./l1/a.rtc\" as x\nimport \"./l2/a.rtc\" as y\npub let v = 1\n",
    );
    write(&dir.join("s.rtc"), &format!("{SCENE}import \"./a.rtc\"\n"));
    let text = fails(&rtc_in(&dir, &["check", "s.rtc"]), 1, "rtc::module::cycle");
    assert!(text.contains("a.rtc → a.rtc"), "{text}");

    // Without the cycle, a diamond of links is read once: two links to one library.
    write(&dir.join("lib.rtc"), "rtc 1\npub let v = 2\n");
    write(
        &dir.join("d.rtc"),
        &format!(
            "{SCENE}import \"./l1/lib.rtc\" as x\nimport \"./l2/l1/lib.rtc\" as y\nassert(x.v + y.v == 4)\n"
        ),
    );
    let run = rtc_in(&dir, &["check", "d.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Evaluates `scene` (in `dir`) under `opts`; the codes of its errors.
fn error_codes(dir: &Path, scene: &str, opts: &EvalOptions) -> Vec<&'static str> {
    let mut sources = SourceMap::new();
    let loaded = load_source(&dir.join("scene.rtc"), scene, &mut sources, opts);
    loaded
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect()
}

#[test]
fn imports_have_a_budget_of_files_and_of_nesting() {
    let dir = scratch("import-budget");
    // m0 imports m1 imports ... m7: eight nested levels, eight files.
    for i in 0..8 {
        let next = if i < 7 {
            format!("import \"./m{}.rtc\" as next\n", i + 1)
        } else {
            String::new()
        };
        write(
            &dir.join(format!("m{i}.rtc")),
            &format!("rtc 1\n{next}pub let v = {i}\n"),
        );
    }
    let scene = format!("{SCENE}import \"./m0.rtc\"\n");
    let opts = |files, depth| EvalOptions {
        max_imports: files,
        max_import_depth: depth,
        ..EvalOptions::default()
    };
    assert_eq!(error_codes(&dir, &scene, &opts(8, 8)), Vec::<&str>::new());
    assert!(error_codes(&dir, &scene, &opts(8, 4)).contains(&"rtc::budget::imports"));
    assert!(error_codes(&dir, &scene, &opts(5, 8)).contains(&"rtc::budget::imports"));
    let d = EvalOptions::default();
    assert!(d.max_imports >= 1000 && d.max_import_depth >= 32);
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 3. special files -----------------------------------------------------------------------

/// A device, a FIFO or a folder named as a scene, an import, a mesh, its `mtllib` or a texture
/// is refused from its metadata: nothing is read from it, nothing waits for a writer.
#[cfg(unix)]
#[test]
fn special_files_are_refused_before_reading() {
    let dir = scratch("special-files");
    mkfifo(&dir.join("fifo"));
    mkfifo(&dir.join("fifo.rtc"));
    mkfifo(&dir.join("fifo.obj"));
    mkfifo(&dir.join("fifo.png"));
    mkfifo(&dir.join("fifo.in"));
    symlink("/dev/zero", &dir.join("zero.obj"));
    symlink("/dev/zero", &dir.join("zero.rtc"));

    fails(
        &rtc_in(&dir, &["check", "fifo.rtc"]),
        2,
        "not a regular file",
    );
    fails(&rtc_in(&dir, &["check", "zero.rtc"]), 2, "a device");
    fails(
        &rtc_in(&dir, &["check", "fifo.in"]),
        2,
        "not a regular file",
    );
    fails(
        &rtc_in(&dir, &["fmt", "--check", "fifo.rtc"]),
        2,
        "not a regular file",
    );
    for import in ["/dev/zero", "./fifo.rtc", "./fifo"] {
        write(
            &dir.join("s.rtc"),
            &format!("{SCENE}import \"{import}\" as m\n"),
        );
        let text = fails(
            &rtc_in(&dir, &["check", "s.rtc"]),
            1,
            "rtc::module::not_found",
        );
        assert!(text.contains("not a regular file"), "{text}");
    }
    // The asset search takes only regular files: a special one is not a mesh or an image.
    for mesh in ["fifo.obj", "zero.obj"] {
        write(&dir.join("s.rtc"), &format!("{SCENE}mesh(\"{mesh}\")\n"));
        fails(&rtc_in(&dir, &["check", "s.rtc"]), 1, "rtc::asset::missing");
    }
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}sphere().material(material {{ texture: image(\"fifo.png\") }})\n"),
    );
    fails(&rtc_in(&dir, &["check", "s.rtc"]), 1, "rtc::asset::missing");
    // Behind the search, the readers refuse them too (a name replaced after the search).
    let e = rtc::assets::MeshAsset::load(&dir.join("fifo.obj"), false).unwrap_err();
    assert!(e.message.contains("not a regular file"), "{e:?}");
    let e = rtc::assets::Picture::load(&dir.join("fifo.png")).unwrap_err();
    assert!(e.message.contains("not a regular file"), "{e:?}");

    // An OBJ whose material library is a FIFO: the library is unusable (a warning), the mesh
    // loads.
    write(
        &dir.join("m.obj"),
        "mtllib fifo\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    );
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}mesh(\"m.obj\", use_mtl: true)\n"),
    );
    let run = rtc_in(&dir, &["check", "s.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 2. long chains and deep nesting ------------------------------------------------------------

/// A chain of suffixes as long as the budget allows is checked and formatted (the formatter
/// recursed on the main thread's stack and aborted); one more is `rtc::budget::nesting` at the
/// expression, from `check` and `fmt` alike, for calls and for indexing.
#[test]
fn chains_at_the_budget_are_handled_and_longer_ones_are_refused() {
    let dir = scratch("long-chains");
    // `.translate(X)` is two suffixes (a member and a call), `sphere()` one.
    let at_budget = format!("{SCENE}sphere(){}\n", ".translate(X)".repeat(4_999));
    write(&dir.join("ok.rtc"), &at_budget);
    let run = rtc_in(&dir, &["check", "ok.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let run = rtc_in(&dir, &["fmt", "--check", "ok.rtc"]);
    assert!(matches!(run.status.code(), Some(0 | 1)), "{}", stderr(&run));
    assert!(stderr(&run).contains("of 1 file"), "{}", stderr(&run));

    let calls = format!("{SCENE}sphere(){}\n", ".translate(X)".repeat(5_000));
    let index = format!("rtc 1\nlet l = [1]\nlet y = l{}\n", "[0]".repeat(10_001));
    for (name, text) in [("calls.rtc", calls), ("index.rtc", index)] {
        write(&dir.join(name), &text);
        for cmd in [&["check", name][..], &["fmt", "--check", name]] {
            let text = fails(&rtc_in(&dir, cmd), 1, "rtc::budget::nesting");
            assert!(text.contains("operators and suffixes"), "{text}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 8. a cap on diagnostics -------------------------------------------------------------------

/// Lines of keyword-shaped garbage in a course `.in` file: the report shows the first 100
/// errors and counts the rest (the front end keeps only the first 100 too).
#[test]
fn garbage_in_a_course_file_shows_the_first_errors_and_counts_the_rest() {
    let dir = scratch("diag-cap-in");
    let garbage: String = (0..3000)
        .map(|i| {
            [
                "Sphere x 1 -\n",
                "Light zz\n",
                "Eye 1\n",
                "Material - - -\n",
            ][i % 4]
        })
        .collect();
    write(&dir.join("g.in"), &garbage);
    for format in ["human", "short"] {
        let text = fails(
            &rtc_in(&dir, &["check", "--format", format, "g.in"]),
            1,
            "rtc::diag::omitted",
        );
        let shown = text.matches("error[").count() + text.matches("× ").count();
        assert!(shown <= 100 + 1, "{format}: {shown} errors shown");
        let last = text.trim_end().lines().last().unwrap_or("");
        let total: usize = last.split(' ').next().unwrap().parse().unwrap_or(0);
        assert!(total > 1000, "{format}: {last}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A scene file of bad lines: syntax errors stop being read after 100, with a note saying
/// where.
#[test]
fn a_file_of_bad_lines_stops_after_the_first_syntax_errors() {
    let dir = scratch("diag-cap-rtc");
    write(
        &dir.join("bad.rtc"),
        &format!("rtc 1\n{}", "let = \n".repeat(5000)),
    );
    let text = fails(
        &rtc_in(&dir, &["check", "--format", "short", "bad.rtc"]),
        1,
        "rtc::diag::omitted",
    );
    assert_eq!(text.matches("error[").count(), 100, "{text}");
    assert!(text.contains("not read past line 101"), "{text}");
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 13. the OBJ triangle budget is counted while reading ----------------------------------------

#[test]
fn an_obj_over_the_triangle_budget_is_refused_while_reading() {
    use rtc::assets::obj_count::{Counted, read_counted};
    let dir = scratch("obj-count");
    let obj = write(
        &dir.join("m.obj"),
        &format!(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n{}",
            "f 1 2 3 4\n".repeat(500)
        ),
    );
    assert!(matches!(
        read_counted(&obj, u64::MAX, 1000).unwrap(),
        Counted::Text(_)
    ));
    match read_counted(&obj, u64::MAX, 999).unwrap() {
        Counted::TooMany(e) => {
            assert!(e.too_large, "{e:?}");
            assert!(e.message.contains("more than 999 triangles"), "{e:?}");
        }
        Counted::Text(_) => panic!("1000 triangles passed a budget of 999"),
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 5. super-linear work ----------------------------------------------------------------------

/// A union grown one object at a time by `reduce`, and a difference likewise, become one CSG
/// node each with every operand (the operator extends its left operand's shared list:
/// `eval::operands`; 20,000 objects took 34 s when each step copied the list).
#[test]
fn a_union_grown_by_reduce_is_one_flat_node() {
    let dir = scratch("reduce-csg");
    let scene = format!(
        "{SCENE}let balls = for i in 0..3000 {{ sphere(center: [i * 0.001, 0, 0], radius: 0.1) }}\n\
         let u = reduce(balls, sphere(radius: 0.01), fn(a, b) a | b)\n\
         let d = reduce(balls, box(min: [-1, -1, -1], max: [1, 1, 1]), fn(a, b) a - b)\n\
         u.translate(X)\nd\n"
    );
    write(&dir.join("s.rtc"), &scene);
    let run = rtc_in(&dir, &["check", "s.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(
        stderr(&run).contains("3 objects (1 sphere, 2 CSG objects)"),
        "{}",
        stderr(&run)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// 20,000 copies of one OBJ face load, build and render (the builder pairs identical boxes
/// one couple per pass, so the copies are built as one and spliced back:
/// `geometry::bvh::ties`; 33,334 copies took 26 s).
#[test]
fn a_mesh_of_one_face_repeated_builds_and_renders() {
    let dir = scratch("same-face");
    let mut obj = String::from("v -1 -1 0\nv 1 -1 0\nv 0 1 0\n");
    obj.push_str(&"f 1 2 3\n".repeat(20_000));
    write(&dir.join("same.obj"), &obj);
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}mesh(path: \"same.obj\")\n"),
    );
    let run = rtc_in(&dir, &["render", "s.rtc", "-o", "out.png"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(dir.join("out.png").is_file());
    std::fs::remove_dir_all(&dir).unwrap();
}
