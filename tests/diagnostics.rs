//! The diagnostics corpus: every `tests/diagnostics/NAME.rtc` is checked with the real binary
//! (`rtc check --format short`, run from the crate root) and its stderr must equal
//! `NAME.expected`, which was written and reviewed by hand against the case. Helper modules
//! imported by cases live in `tests/diagnostics/lib/` and are not cases themselves.

use std::path::Path;
use std::process::Command;

fn cases() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir("tests/diagnostics")
        .expect("corpus directory")
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "rtc"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

fn run(name: &str) -> (String, i32) {
    let path = format!("tests/diagnostics/{name}.rtc");
    let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["check", "--format", "short", &path])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("RTC_ASSET_PATH")
        .output()
        .expect("run rtc");
    (
        String::from_utf8_lossy(&out.stderr).into_owned(),
        out.status.code().unwrap_or(-1),
    )
}

#[test]
fn corpus_matches_expected_output() {
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
    let mut failures = Vec::new();
    for name in cases() {
        let (got, code) = run(&name);
        let expected_path = format!("tests/diagnostics/{name}.expected");
        let expected = std::fs::read_to_string(&expected_path).unwrap_or_default();
        if got != expected {
            failures.push(format!("--- {name}: expected\n{expected}--- got\n{got}"));
        }
        let has_error = got.contains(": error[");
        let want_code = if has_error { 1 } else { 0 };
        if code != want_code {
            failures.push(format!("{name}: exit code {code}, expected {want_code}"));
        }
    }
    assert!(
        failures.is_empty(),
        "{} corpus mismatches:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn corpus_is_large_and_covers_several_errors_per_file() {
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
    let names = cases();
    assert!(names.len() >= 40, "only {} cases", names.len());
    for n in &names {
        assert!(
            Path::new(&format!("tests/diagnostics/{n}.expected")).exists(),
            "{n} has no .expected"
        );
    }
    let multi = names
        .iter()
        .filter(|n| {
            let t = std::fs::read_to_string(format!("tests/diagnostics/{n}.expected"))
                .unwrap_or_default();
            t.matches(": error[").count() >= 3
        })
        .count();
    assert!(
        multi >= 2,
        "want at least two cases with three or more errors, found {multi}"
    );
}

#[test]
fn no_message_mentions_a_grammar_rule() {
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
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
    for name in cases() {
        let t = std::fs::read_to_string(format!("tests/diagnostics/{name}.expected"))
            .unwrap_or_default();
        for r in rules {
            assert!(!t.contains(r), "{name} mentions grammar rule {r}");
        }
    }
}
