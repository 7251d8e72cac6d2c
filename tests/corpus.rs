//! The diagnostics corpora, through one runner: every `tests/diagnostics/NAME.rtc` (language
//! mistakes; helper modules imported by cases live in `tests/diagnostics/lib/` and are not cases)
//! and every `tests/compat/NAME.in|yaml` (broken course files) is checked with the real binary,
//! `rtc check --format short` run from the crate root, and its stderr (where diagnostics go) must
//! equal `NAME.expected`, written and reviewed by hand against the case, with exit code 1 when
//! that holds an error and 0 otherwise.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The cases in `dir` with one of `extensions`, sorted.
fn cases(dir: &str, extensions: &[&str]) -> Vec<PathBuf> {
    let mut cases: Vec<PathBuf> =
        std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(dir))
            .unwrap_or_else(|e| panic!("{dir}: {e}"))
            .map(|e| e.expect("dir entry").path())
            .filter(|p| {
                p.extension()
                    .is_some_and(|x| extensions.iter().any(|e| x == *e))
            })
            .map(|p| Path::new(dir).join(p.file_name().expect("file name")))
            .collect();
    cases.sort();
    cases
}

/// `rtc check --format short PATH` from the crate root: stderr and exit code.
fn check(path: &Path) -> (String, i32) {
    let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["check", "--format", "short"])
        .arg(path)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("RTC_ASSET_PATH")
        .output()
        .expect("run rtc");
    (
        String::from_utf8_lossy(&out.stderr).into_owned(),
        out.status.code().unwrap_or(-1),
    )
}

fn expected(case: &Path) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(case.with_extension("expected"));
    std::fs::read_to_string(path).unwrap_or_default()
}

/// Every case whose output or exit code differs from what its `.expected` says.
fn mismatches(cases: &[PathBuf]) -> Vec<String> {
    let mut failures = Vec::new();
    for case in cases {
        let (got, code) = check(case);
        let want = expected(case);
        if got != want {
            failures.push(format!(
                "{}:\n--- expected\n{want}--- got\n{got}",
                case.display()
            ));
        }
        let want_code = i32::from(want.contains(": error["));
        if code != want_code {
            failures.push(format!(
                "{}: exit code {code}, expected {want_code}",
                case.display()
            ));
        }
    }
    failures
}

fn language() -> Vec<PathBuf> {
    cases("tests/diagnostics", &["rtc"])
}

fn course() -> Vec<PathBuf> {
    cases("tests/compat", &["in", "yaml"])
}

fn assert_matches(cases: &[PathBuf]) {
    let failures = mismatches(cases);
    assert!(
        failures.is_empty(),
        "{} corpus mismatches:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn language_corpus_matches_expected_output() {
    assert_matches(&language());
}

#[test]
fn course_corpus_matches_expected_output() {
    assert_matches(&course());
}

#[test]
fn corpora_are_large_and_cover_several_errors_per_file() {
    let (language, course) = (language(), course());
    assert!(
        language.len() >= 40,
        "only {} language cases",
        language.len()
    );
    assert!(course.len() >= 20, "only {} course cases", course.len());
    for case in language.iter().chain(&course) {
        assert!(
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join(case.with_extension("expected"))
                .exists(),
            "{} has no .expected",
            case.display()
        );
    }
    let multi = language
        .iter()
        .filter(|c| expected(c).matches(": error[").count() >= 3)
        .count();
    assert!(
        multi >= 2,
        "want at least two cases with three or more errors, found {multi}"
    );
}

#[test]
fn no_message_mentions_a_grammar_rule() {
    let rules = [
        "or_expr",
        "postfix",
        "stmt_line",
        "call_args",
        "record_arg",
        "unary_expr",
        "EOI",
        "ident",
    ];
    for case in language() {
        let t = expected(&case);
        for r in rules {
            assert!(
                !t.contains(r),
                "{} mentions grammar rule {r}",
                case.display()
            );
        }
    }
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
