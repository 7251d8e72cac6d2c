//! `rtc fmt`: formatting never changes what a file means (the evaluated scene and its findings
//! are the same, positions aside, over every scene, stdlib module, language-test file and docs
//! example that parses), formatting twice changes nothing, comments are kept, and the command
//! line's `--check`, in-place writing and syntax-error behaviour.

mod cli_support;

use std::path::{Path, PathBuf};

use cli_support::{files_below, rtc, scratch};
use rtc::eval::{EvalOptions, load_source};
use rtc::source::{FileId, SourceMap};
use rtc::syntax::format::{INTERNAL, format, strip_spans};

/// The ```rtc blocks of docs/language.md that must evaluate cleanly, as whole files.
fn doc_examples(root: &Path) -> Vec<(PathBuf, String)> {
    let doc = std::fs::read_to_string(root.join("docs/language.md")).unwrap();
    let mut out = Vec::new();
    let mut current: Option<(usize, String)> = None;
    for (i, l) in doc.lines().enumerate() {
        match current.as_mut() {
            None if l.trim_end() == "```rtc" => current = Some((i + 1, String::new())),
            None => {}
            Some(_) if l.trim_end() == "```" => {
                let (line, text) = current.take().unwrap();
                let header = text
                    .lines()
                    .any(|l| l.trim() == "rtc 1" || l.trim() == "rtc 1.1");
                let text = if header {
                    text
                } else {
                    format!("rtc 1.1\n{text}")
                };
                out.push((root.join(format!("docs/language.md.line{line}.rtc")), text));
            }
            Some((_, text)) => {
                text.push_str(l);
                text.push('\n');
            }
        }
    }
    out
}

/// What a file means: its scene (positions removed) and its findings' severities and codes.
fn meaning(path: &Path, text: &str) -> String {
    let mut sources = SourceMap::default();
    let loaded = load_source(path, text, &mut sources, &EvalOptions::default());
    let findings: Vec<String> = loaded
        .diagnostics
        .items
        .iter()
        .map(|d| format!("{:?} {}", d.severity, d.code))
        .collect();
    strip_spans(&format!("{:?}\n{findings:?}", loaded.scene))
}

#[test]
fn formatting_keeps_the_meaning_of_every_file_and_is_idempotent() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in [
        "scenes",
        "stdlib",
        "tests/lang",
        "tests/diagnostics",
        "docs/examples",
    ] {
        files.extend(files_below(&root.join(dir), &["rtc"]));
    }
    let mut inputs: Vec<(PathBuf, String)> = files
        .into_iter()
        .filter_map(|f| Some((f.clone(), std::fs::read_to_string(&f).ok()?)))
        .collect();
    let docs = doc_examples(&root);
    assert!(docs.len() >= 40, "only {} docs examples", docs.len());
    inputs.extend(docs);
    let (mut formatted, mut refused) = (0, 0);
    let mut failures = Vec::new();
    for (path, text) in &inputs {
        let name = path
            .strip_prefix(&root)
            .unwrap_or(path)
            .display()
            .to_string();
        let out = match format(FileId(0), text) {
            Ok(out) => out,
            Err(diags) => {
                if diags.iter().any(|d| d.code == INTERNAL) {
                    failures.push(format!("{name}: refused: {diags:?}"));
                }
                refused += 1;
                continue;
            }
        };
        formatted += 1;
        match format(FileId(0), &out) {
            Ok(again) if again == out => {}
            _ => failures.push(format!("{name}: formatting again changes it")),
        }
        if out.lines().any(|l| l != l.trim_end()) || !out.ends_with('\n') {
            failures.push(format!("{name}: trailing spaces or no final newline"));
        }
        if meaning(path, text) != meaning(path, &out) {
            failures.push(format!("{name}: the evaluated scene changed"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // The corpus holds syntax-error files on purpose; most files must still be formatted.
    assert!(formatted >= 120, "formatted {formatted}, refused {refused}");
    assert!(
        refused >= 10,
        "the syntax-error corpus should be refused ({refused})"
    );
}

#[test]
fn every_comment_is_kept_in_order() {
    let src = "// a\nrtc 1 // b\n/* c */ let x = [ // d\n  1, /* e */ 2 // f\n] // g\nfn f(/* h */) { // i\n  x // j\n  // k\n}\n// l\n";
    let out = format(FileId(0), src).unwrap();
    let mut rest = out.as_str();
    for c in [
        "// a", "// b", "/* c */", "// d", "/* e */", "// f", "// g", "/* h */", "// i", "// j",
        "// k", "// l",
    ] {
        let at = rest
            .find(c)
            .unwrap_or_else(|| panic!("`{c}` missing or out of order:\n{out}"));
        rest = &rest[at + c.len()..];
    }
}

#[test]
fn check_shows_a_diff_and_fails_writing_nothing() {
    let dir = scratch("fmt-check");
    let file = dir.join("a.rtc");
    let messy = "rtc 1\nlet  x=1\n";
    std::fs::write(&file, messy).unwrap();
    let run = rtc(&["fmt", "--check", file.to_str().unwrap()]);
    assert_eq!(run.status.code(), Some(1));
    let diff = String::from_utf8_lossy(&run.stdout);
    assert!(diff.contains("-let  x=1\n+let x = 1\n"), "{diff}");
    assert!(diff.contains("@@ -1,2 +1,2 @@"), "{diff}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), messy);

    // In place: the file is rewritten and named; then `--check` passes on the directory.
    let run = rtc(&["fmt", dir.to_str().unwrap()]);
    assert_eq!(run.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&run.stdout).contains("a.rtc"));
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        "rtc 1\nlet x = 1\n"
    );
    let run = rtc(&["fmt", "--check", dir.to_str().unwrap()]);
    assert_eq!(run.status.code(), Some(0));
    assert!(run.stdout.is_empty());
}

#[test]
fn a_file_with_syntax_errors_is_reported_and_left_alone() {
    let dir = scratch("fmt-syntax");
    let file = dir.join("bad.rtc");
    let bad = "rtc 1\nlet = 3\nlet  y = 2\n";
    std::fs::write(&file, bad).unwrap();
    for check in [false, true] {
        let mut args = vec!["fmt", "--format", "short", file.to_str().unwrap()];
        if check {
            args.insert(1, "--check");
        }
        let run = rtc(&args);
        assert_eq!(run.status.code(), Some(1));
        let err = String::from_utf8_lossy(&run.stderr);
        assert!(err.contains("bad.rtc:2:"), "{err}");
        assert!(err.contains("rtc::syntax::"), "{err}");
        assert_eq!(std::fs::read_to_string(&file).unwrap(), bad);
    }
}

#[test]
fn the_repository_scenes_and_stdlib_are_formatted() {
    let run = rtc(&["fmt", "--check", "scenes", "stdlib"]);
    assert_eq!(
        run.status.code(),
        Some(0),
        "run `rtc fmt scenes stdlib`:\n{}",
        String::from_utf8_lossy(&run.stdout)
    );
}
