//! Hostile inputs (issue 35): files, folders and command lines made to hang, exhaust or turn rtc
//! against its user. Each case ends with a coded error (exit code 1, or 2 for a command-line
//! problem) instead of a hang, a crash or a write where it should not. Inputs are scaled down
//! under lowered budgets; the full-size cases run from `benches/hostile.sh`.

mod cli_support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use cli_support::scratch;

use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

/// A small scene that renders in a moment, with `extra` appended.
const SCENE: &str = "rtc 1\ncamera { eye: [0, 0, 5], center: [0, 0, 0], up: Y, resolution: [8, 6] }\n\
                     point_light { position: [5, 5, 5] }\nsphere()\n";

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Runs `rtc args` in `dir`; a run still going after a minute is killed and fails the test
/// (a hang is the defect these cases guard against, so it must not hang the suite too). Its
/// output is read while it runs, so a long message cannot fill the pipe and stall it.
fn rtc_in(dir: &Path, args: &[&str]) -> Output {
    use std::io::Read;
    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the rtc binary runs");
    let drain = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            let _ = r.read_to_end(&mut buf);
            buf
        })
    };
    let out = drain(Box::new(child.stdout.take().unwrap()));
    let err = drain(Box::new(child.stderr.take().unwrap()));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("`rtc {}` did not end within a minute", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Output {
        status,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
    }
}

/// Asserts a run failed with exit code `code` and `what` in its stderr; returns the stderr.
fn fails(run: &Output, code: i32, what: &str) -> String {
    let text = stderr(run);
    assert_eq!(run.status.code(), Some(code), "{text}");
    assert!(text.contains(what), "expected `{what}` in:\n{text}");
    text
}

fn write(path: &Path, text: &str) -> PathBuf {
    std::fs::write(path, text).unwrap();
    path.to_path_buf()
}

#[cfg(unix)]
fn symlink(target: &str, link: &Path) {
    std::os::unix::fs::symlink(target, link).unwrap();
}

#[cfg(unix)]
fn mkfifo(path: &Path) {
    let ok = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(ok.success(), "mkfifo {}", path.display());
}

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
    let run = cli_support::rtc(&["check", dir.join("d.rtc").to_str().unwrap()]);
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

// ---- 6. the temporary file of an atomic write ------------------------------------------------

/// A symlink planted at the name the old temporary file had (`.NAME.PID.tmp`, PID this
/// process) to a victim file: the write goes to a fresh file of a random name, created
/// exclusively, and the victim is untouched.
#[cfg(unix)]
#[test]
fn a_planted_symlink_at_a_temporary_name_is_never_followed() {
    let dir = scratch("temp-symlink");
    let victim = write(&dir.join("victim.txt"), "precious");
    let planted = dir.join(format!(".out.png.{}.tmp", std::process::id()));
    symlink(victim.to_str().unwrap(), &planted);
    let out = dir.join("out.png");
    for _ in 0..3 {
        rtc::render::output::write_atomically(&out, b"image bytes").unwrap();
    }
    assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
    assert_eq!(std::fs::read(&out).unwrap(), b"image bytes");
    // Only the output, the victim and the planted link: no temporary file left behind.
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 3, "{names:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 9. `rtc fmt` in place -------------------------------------------------------------------

#[cfg(unix)]
#[test]
fn fmt_in_place_keeps_permissions_and_writes_through_a_symlink() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("fmt-in-place");
    let messy = "rtc 1\nlet   x =   1\nassert(x==1)\n";
    let file = write(&dir.join("real.rtc"), messy);
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
    symlink("real.rtc", &dir.join("link.rtc"));
    let run = rtc_in(&dir, &["fmt", "link.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let link = std::fs::symlink_metadata(dir.join("link.rtc")).unwrap();
    assert!(
        link.file_type().is_symlink(),
        "the link was replaced by a file"
    );
    let formatted = std::fs::read_to_string(&file).unwrap();
    assert_ne!(formatted, messy, "the target was not formatted");
    let mode = std::fs::metadata(&file).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 11. the output is checked before rendering ------------------------------------------------

/// An output rtc cannot write is refused before the render (which here would take minutes), so
/// the run ends at once.
#[cfg(unix)]
#[test]
fn the_output_is_checked_before_the_render() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("output-first");
    // 4000×4000 at 64 samples per pixel axis: far beyond a minute if it started.
    let slow = SCENE.replace("[8, 6]", "[4000, 4000]") + "render { supersampling: 64 }\n";
    write(&dir.join("s.rtc"), &slow);
    fails(
        &rtc_in(&dir, &["render", "s.rtc", "-o", "x.jpg"]),
        2,
        "unknown image format",
    );
    fails(
        &rtc_in(&dir, &["render", "s.rtc", "-o", "none/x.png"]),
        2,
        "does not exist",
    );
    std::fs::create_dir(dir.join("ro")).unwrap();
    std::fs::set_permissions(dir.join("ro"), std::fs::Permissions::from_mode(0o555)).unwrap();
    // Root writes anywhere: the read-only case only means something for other users.
    if std::fs::write(dir.join("ro/probe"), b"").is_err() {
        fails(
            &rtc_in(&dir, &["render", "s.rtc", "-o", "ro/x.png"]),
            2,
            "not writable",
        );
    }
    std::fs::set_permissions(dir.join("ro"), std::fs::Permissions::from_mode(0o755)).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 12. a scene's `output` stays in its folder ------------------------------------------------

#[cfg(unix)]
#[test]
fn a_scene_output_outside_its_folder_is_refused() {
    let root = scratch("output-confined");
    let dir = root.join("scenes");
    std::fs::create_dir_all(dir.join("out")).unwrap();
    let victim = write(&root.join("victim.png"), "precious");
    symlink(root.to_str().unwrap(), &dir.join("up"));
    let outside = [
        victim.to_str().unwrap().to_owned(),
        "../victim.png".into(),
        "out/../../victim.png".into(),
        "up/victim.png".into(),
    ];
    for output in &outside {
        write(
            &dir.join("s.rtc"),
            &format!("{SCENE}render {{ output: \"{output}\" }}\n"),
        );
        let text = fails(
            &rtc_in(&dir, &["render", "s.rtc"]),
            1,
            "rtc::render::output",
        );
        assert!(text.contains("s.rtc:5:"), "{text}");
        assert!(text.contains("-o"), "{text}");
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious", "{output}");
    }
    // Inside the folder, as before; and `-o` is the user's choice.
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}render {{ output: \"out/a.png\" }}\n"),
    );
    let run = rtc_in(&dir, &["render", "s.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(dir.join("out/a.png").is_file());
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}render {{ output: \"../victim.png\" }}\n"),
    );
    let run = rtc_in(&dir, &["render", "s.rtc", "-o", "mine.png"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(dir.join("mine.png").is_file());
    std::fs::remove_dir_all(&root).unwrap();
}

// ---- 15. `rtc merge` checks a part's header against its length ---------------------------------

/// A part file: the magic line, `header` with the payload's fingerprint, and the payload.
fn part_bytes(mut header: serde_json::Value, payload: &[u8]) -> Vec<u8> {
    header["payload"] = rtc::opt::fingerprint::bytes(payload).into();
    let mut out = format!("rtc-part 1\n{header}\n").into_bytes();
    out.extend_from_slice(payload);
    out
}

#[test]
fn a_part_header_that_claims_more_than_the_file_holds_is_refused() {
    let header = |height: u32, rows: serde_json::Value| {
        serde_json::json!({
            "scene": "s", "settings": "t", "width": 4, "height": height,
            "channels": ["color"], "encoding": "srgb", "shard": [0, 1], "rows": rows,
            "stats": [0, 0, 0, 0, 0, 0],
        })
    };
    let payload = vec![0u8; 4 * 16 * 24];
    let path = Path::new("p.rtcpart");
    let good = part_bytes(header(16, serde_json::json!([[0, 16]])), &payload);
    rtc::render::part::Part::from_bytes(&good, path).expect("a sound part reads");
    let cases = [
        // 2³² − 1 rows: refused from the header, before 2²⁸ bands are made.
        (
            header(u32::MAX, serde_json::json!([[0, 16]])),
            "larger than rtc renders",
        ),
        // 64 rows are four bands of 16, the header lists one.
        (
            header(64, serde_json::json!([[0, 16]])),
            "rows are not those",
        ),
        // Rows that need more pixel data than the file has.
        (
            header(32, serde_json::json!([[0, 16], [16, 32]])),
            "claims 3072 bytes of pixels",
        ),
    ];
    for (h, why) in cases {
        let e = rtc::render::part::Part::from_bytes(&part_bytes(h, &payload), path).unwrap_err();
        assert_eq!(e.code, "rtc::merge::malformed");
        assert!(e.message.contains(why), "{}", e.message);
    }
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

// ---- 17. the settings fingerprint of shards ---------------------------------------------------

/// Shards rendered with the same options in another order, and `--set a=1` against
/// `--set a=1.0` for a `Float` parameter, merge; a different value of the parameter does not.
#[test]
fn shards_merge_whatever_the_order_of_their_options() {
    let dir = scratch("shard-order");
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}param a = 0.5\nsphere(radius: a).translate([2, 0, 0])\n"),
    );
    let shard = |k: &str, args: &[&str]| {
        let mut all = args.to_vec();
        all.extend(["--shard", k, "-o"]);
        all.push(if k == "0/2" {
            "p0.rtcpart"
        } else {
            "p1.rtcpart"
        });
        let run = rtc_in(&dir, &all);
        assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    };
    shard("0/2", &["render", "--frame", "0", "--set", "a=1", "s.rtc"]);
    shard(
        "1/2",
        &["render", "s.rtc", "--set", "a=1.0", "--frame", "0"],
    );
    let run = rtc_in(&dir, &["merge", "p0.rtcpart", "p1.rtcpart", "-o", "m.png"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    shard("1/2", &["render", "s.rtc", "--set", "a=0.75"]);
    fails(
        &rtc_in(&dir, &["merge", "p0.rtcpart", "p1.rtcpart", "-o", "m.png"]),
        1,
        "rtc::merge::mismatch",
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 10. the accuracy cache -------------------------------------------------------------------

/// A cached reference whose bytes were changed fails its checksum and is rendered again (with
/// a note), giving the same reference as before; a cache that cannot be written is a note, not
/// a failure, and leaves no partial file.
#[test]
fn a_damaged_or_unwritable_accuracy_cache_is_a_miss_with_a_note() {
    use rtc::accuracy::reference::{Source, rendered};
    let dir = scratch("accuracy-cache");
    let mut sources = SourceMap::new();
    let loaded = load_source(
        &dir.join("s.rtc"),
        SCENE,
        &mut sources,
        &EvalOptions::default(),
    );
    let mut scene = rtc::opt::prepare(&loaded.scene.expect("the scene loads")).unwrap();
    let options = rtc::accuracy::MeasureOptions {
        repeat: 1,
        seeds: [0, 1],
        threads: 1,
        region: None,
    };
    let cache = dir.join("cache");
    let mut run = |cache: &Path| {
        rendered(
            &mut scene,
            &options,
            Some((cache, "h")),
            &rtc::render::Silent,
        )
        .unwrap()
    };
    let first = run(&cache);
    assert_eq!(first.source, Source::Rendered);
    assert!(first.notes.is_empty(), "{:?}", first.notes);
    assert!(matches!(run(&cache).source, Source::Cached(_)));

    // One flipped byte in the middle of the cached EXR.
    let entry = cache.join("h-seed0.exr");
    let mut bytes = std::fs::read(&entry).unwrap();
    let mid = bytes.len() / 2;
    bytes[mid] ^= 0x40;
    std::fs::write(&entry, &bytes).unwrap();
    let again = run(&cache);
    assert_eq!(again.source, Source::Rendered);
    assert!(
        again.notes.iter().any(|n| n.contains("checksum")),
        "{:?}",
        again.notes
    );
    assert_eq!(again.data, first.data);
    assert!(
        matches!(run(&cache).source, Source::Cached(_)),
        "the entry was written anew"
    );

    // A file where the cache folder should be: the reference is rendered, the run goes on.
    let blocked = write(&dir.join("blocked"), "not a folder");
    let r = run(&blocked.join("sub"));
    assert_eq!(r.data, first.data);
    assert!(
        r.notes.iter().any(|n| n.contains("could not be cached")),
        "{:?}",
        r.notes
    );
    let leftovers: Vec<_> = std::fs::read_dir(&cache)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".exr") && !n.ends_with(".sha256"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
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

// ---- 7. `rtc watch` and DNS rebinding -------------------------------------------------------------

/// Sends one request with the given `Host` header to `addr`; the status line of the answer.
fn status_for_host(addr: &str, host: Option<&str>) -> String {
    use std::io::{BufRead, Write};
    let mut s = std::net::TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    let host = host.map_or(String::new(), |h| format!("Host: {h}\r\n"));
    write!(s, "GET / HTTP/1.1\r\n{host}Connection: close\r\n\r\n").unwrap();
    let mut line = String::new();
    std::io::BufReader::new(s).read_line(&mut line).unwrap();
    line
}

/// A page on another site whose name was rebound to 127.0.0.1 sends its own `Host`: refused
/// (403); the loopback names with the right port are answered.
#[test]
fn rtc_watch_answers_only_its_loopback_host() {
    use std::io::{BufRead, BufReader};
    let dir = scratch("watch-host");
    let scene = write(&dir.join("s.rtc"), SCENE);
    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["watch", scene.to_str().unwrap(), "--port", "0"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
    let first = lines.next().and_then(Result::ok).unwrap_or_default();
    std::thread::spawn(move || lines.for_each(drop));
    let addr = first
        .split("http://")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .unwrap_or("")
        .to_string();
    let port = addr.rsplit(':').next().unwrap().to_string();
    for good in [
        addr.clone(),
        format!("localhost:{port}"),
        format!("LOCALHOST:{port}"),
    ] {
        assert!(
            status_for_host(&addr, Some(&good)).contains("200"),
            "{good}"
        );
    }
    for bad in [
        Some(format!("evil.example:{port}")),
        Some("127.0.0.1:1".into()),
        Some("127.0.0.1".into()),
        None,
    ] {
        let line = status_for_host(&addr, bad.as_deref());
        assert!(line.contains("403"), "{bad:?}: {line}");
    }
    let _ = child.kill();
    let _ = child.wait();
    std::fs::remove_dir_all(&dir).unwrap();
}
