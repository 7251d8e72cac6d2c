//! The bad-input corpus for the course front ends: every `tests/compat/NAME.in|yaml` is checked
//! with `rtc check --format short` and must print exactly `NAME.expected` (reviewed by hand), with
//! exit code 1 when it contains an error and 0 otherwise.

use std::path::{Path, PathBuf};
use std::process::Command;

fn cases() -> Vec<PathBuf> {
    let mut cases: Vec<PathBuf> = std::fs::read_dir("tests/compat")
        .expect("tests/compat")
        .map(|e| e.expect("dir entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "in" || x == "yaml"))
        .collect();
    cases.sort();
    cases
}

fn check(path: &Path) -> (String, i32) {
    let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["check", "--format", "short"])
        .arg(path)
        .output()
        .expect("run rtc");
    (
        String::from_utf8_lossy(&out.stderr).into_owned(),
        out.status.code().unwrap_or(-1),
    )
}

#[test]
fn corpus_matches_the_reviewed_diagnostics() {
    let cases = cases();
    assert!(cases.len() >= 20, "only {} cases", cases.len());
    let mut failures = Vec::new();
    for case in cases {
        let expected_path = case.with_extension("expected");
        let (got, code) = check(&case);
        let expected = std::fs::read_to_string(&expected_path).unwrap_or_default();
        if got != expected {
            failures.push(format!(
                "{}:\n--- expected\n{expected}--- got\n{got}",
                case.display()
            ));
        }
        let want = if expected.contains(": error[") { 1 } else { 0 };
        if code != want {
            failures.push(format!(
                "{}: exit code {code}, expected {want}",
                case.display()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_missing_scene_file_is_an_io_error() {
    for name in [
        "tests/compat/does-not-exist.in",
        "tests/compat/does-not-exist.yaml",
    ] {
        let (out, code) = check(Path::new(name));
        assert_eq!(code, 2, "{out}");
        assert!(out.contains("error[rtc::io]: cannot read"), "{out}");
    }
}

#[test]
fn check_prints_a_summary_for_the_course_scenes() {
    for name in [
        "tests/data/course/yaml/scene01.yaml",
        "tests/data/course/in/rt1.in",
    ] {
        let (out, code) = check(Path::new(name));
        assert_eq!(code, 0, "{out}");
        assert!(out.starts_with(&format!("{name}: ok: ")), "{out}");
    }
}
