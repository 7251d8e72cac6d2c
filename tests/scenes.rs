//! Every example scene in `scenes/` passes `rtc check` (run through the binary, as a user would),
//! and every standard-library module in `stdlib/` is a clean library: importing it reports
//! nothing at all, and it is registered under `std.NAME`.

use std::path::{Path, PathBuf};
use std::process::Command;

use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn rtc_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rtc_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rtc") {
            out.push(p);
        }
    }
}

#[test]
fn every_scene_passes_check() {
    let mut files = Vec::new();
    rtc_files(&root().join("scenes"), &mut files);
    assert!(
        files.len() >= 12,
        "expected the example scenes, found {files:?}"
    );
    let mut failures = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(root()).expect("inside the crate");
        // The benchmark scenes' large models live outside the repository (../shared/models,
        // or target/models where benches/meshes.sh makes bunny-x16.obj).
        let models = std::env::join_paths([
            root().join("../shared/models"),
            root().join("target/models"),
        ])
        .expect("model path");
        let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
            .current_dir(root())
            .env("RTC_ASSET_PATH", models)
            .args(["check", "--format", "short"])
            .arg(rel)
            .output()
            .expect("run rtc");
        let stdout = String::from_utf8_lossy(&out.stderr);
        let errors: Vec<&str> = stdout.lines().filter(|l| l.contains(": error[")).collect();
        if rel.starts_with("scenes/bench")
            && !errors.is_empty()
            && errors
                .iter()
                .all(|l| l.contains("error[rtc::asset::missing]"))
        {
            println!("skipped {}: its model is absent\n{stdout}", rel.display());
            continue;
        }
        // Exit status 0 means no errors (warnings are allowed); `: error[` is the short format's
        // error line, checked as well so a wrong exit code cannot hide one.
        if !out.status.success() || stdout.contains(": error[") {
            failures.push(format!(
                "{}: exit {:?}\n{stdout}",
                rel.display(),
                out.status.code()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_stdlib_module_imports_cleanly() {
    let mut files = Vec::new();
    rtc_files(&root().join("stdlib"), &mut files);
    for name in ["math", "color", "materials", "textures", "layout", "shapes"] {
        assert!(
            files
                .iter()
                .any(|f| f.file_stem().is_some_and(|s| s == name)),
            "stdlib/{name}.rtc is missing"
        );
    }
    for f in &files {
        let name = f
            .file_stem()
            .and_then(|s| s.to_str())
            .expect("utf-8 file name");
        let on_disk = std::fs::read_to_string(f).expect("read stdlib file");
        assert_eq!(
            rtc::eval::modules::stdlib(name),
            Some(on_disk.as_str()),
            "stdlib/{name}.rtc is not registered as `std.{name}` in src/eval/modules.rs"
        );
        // Imported as a library: any emission, error or warning inside it is reported here.
        let scene = format!("rtc 1\nimport std.{name} as lib\ncamera {{ eye: [0, 0, 10] }}\n");
        let mut sources = SourceMap::default();
        let loaded = load_source(
            &root().join("probe.rtc"),
            &scene,
            &mut sources,
            &EvalOptions::default(),
        );
        let found: Vec<String> = loaded
            .diagnostics
            .items
            .iter()
            .map(|d| format!("{:?} {}: {}", d.severity, d.code, d.message))
            .collect();
        assert!(found.is_empty(), "std.{name}: {found:?}");
        assert!(
            loaded.scene.is_some_and(|s| s.objects.is_empty()),
            "std.{name} must not emit"
        );
    }
}
