//! Every ```rtc block of docs/language.md evaluates as the document says.
//!
//! Rules (stated at the top of the document): a block without the `rtc 1.1` header gets one
//! prepended, a block that writes no `camera` gets `camera { eye: [0, 0, 10] }` appended. A
//! ```rtc block must produce no errors; a ```rtc,error block must produce at least one. Every
//! `error[CODE]` or `warning[CODE]` written in a block must be reported with that code and
//! severity on that very line, and a ```rtc,error block must name at least one error.

use std::path::PathBuf;

use rtc::diag::Severity;
use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

struct Block {
    /// 1-based line of the opening fence in the document.
    line: usize,
    error: bool,
    text: String,
}

fn blocks(doc: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut current: Option<Block> = None;
    for (i, l) in doc.lines().enumerate() {
        match current.take() {
            None => {
                let info = l.trim_end().strip_prefix("```");
                match info {
                    Some("rtc") => {
                        current = Some(Block {
                            line: i + 1,
                            error: false,
                            text: String::new(),
                        })
                    }
                    Some("rtc,error") => {
                        current = Some(Block {
                            line: i + 1,
                            error: true,
                            text: String::new(),
                        })
                    }
                    Some(other) if other.starts_with("rtc") => {
                        panic!("line {}: unknown fence `{l}`", i + 1)
                    }
                    _ => {}
                }
            }
            Some(mut b) => {
                if l.trim_end() == "```" {
                    out.push(b);
                } else {
                    b.text.push_str(l);
                    b.text.push('\n');
                    current = Some(b);
                }
            }
        }
    }
    assert!(current.is_none(), "an unclosed ```rtc block");
    out
}

/// `(line within the block, severity, code)` for every `error[..]` / `warning[..]` annotation.
fn expectations(text: &str) -> Vec<(usize, Severity, String)> {
    let mut out = Vec::new();
    for (i, l) in text.lines().enumerate() {
        let Some(comment) = l.find("//").map(|c| &l[c..]) else {
            continue;
        };
        for (tag, sev) in [("error[", Severity::Error), ("warning[", Severity::Warning)] {
            let mut rest = comment;
            while let Some(p) = rest.find(tag) {
                let after = &rest[p + tag.len()..];
                let end = after.find(']').expect("annotation closed with `]`");
                out.push((i + 1, sev, after[..end].to_owned()));
                rest = &after[end..];
            }
        }
    }
    out
}

fn has_header(text: &str) -> bool {
    text.lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && !l.starts_with("//"))
        .is_some_and(|l| l == "rtc 1" || l == "rtc 1.1")
}

fn line_of(text: &str, byte: usize) -> usize {
    text[..byte.min(text.len())].matches('\n').count() + 1
}

#[test]
fn every_example_in_the_language_reference_behaves_as_documented() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let doc = std::fs::read_to_string(root.join("docs/language.md")).expect("docs/language.md");
    let all = blocks(&doc);
    assert!(all.len() >= 40, "only {} rtc blocks found", all.len());
    assert!(
        all.iter().filter(|b| b.error).count() >= 15,
        "too few error examples"
    );
    let mut failures = Vec::new();
    for b in &all {
        let header = !has_header(&b.text);
        let mut src = String::new();
        if header {
            src.push_str("rtc 1.1\n");
        }
        src.push_str(&b.text);
        if !b.text.contains("camera {") && !b.text.contains("camera(") {
            src.push_str("camera { eye: [0, 0, 10] }\n");
        }
        let offset = usize::from(header);
        let path = root
            .join("docs")
            .join(format!("language.md.line{}.rtc", b.line));
        let mut sources = SourceMap::default();
        let loaded = load_source(&path, &src, &mut sources, &EvalOptions::default());
        let found: Vec<(usize, Severity, &str)> = loaded
            .diagnostics
            .items
            .iter()
            .map(|d| {
                (
                    d.span.map_or(0, |s| line_of(&src, s.start as usize)),
                    d.severity,
                    d.code,
                )
            })
            .collect();
        let shown = || format!("{found:?}");
        let errors = found.iter().filter(|f| f.1 == Severity::Error).count();
        let expected = expectations(&b.text);
        let where_ = format!("docs/language.md:{}", b.line);
        if b.error {
            if errors == 0 {
                failures.push(format!("{where_}: expected an error, got {}", shown()));
            }
            if !expected.iter().any(|e| e.1 == Severity::Error) {
                failures.push(format!(
                    "{where_}: an error block must name its error with `// error[CODE]`"
                ));
            }
        } else if errors > 0 {
            failures.push(format!("{where_}: unexpected errors {}", shown()));
        }
        for (line, sev, code) in &expected {
            let at = line + offset;
            if !found
                .iter()
                .any(|f| f.0 == at && f.1 == *sev && f.2 == code)
            {
                failures.push(format!(
                    "{where_}: no {sev:?} `{code}` on block line {line}; got {}",
                    shown()
                ));
            }
        }
        if b.error {
            // Errors the block does not announce would make the example misleading.
            for f in found.iter().filter(|f| f.1 == Severity::Error) {
                if !expected.iter().any(|e| e.0 + offset == f.0 && e.2 == f.2) {
                    failures.push(format!("{where_}: unannounced error {f:?}"));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failing examples:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn the_block_reader_sees_fences_and_annotations() {
    let doc = "text\n```rtc\nlet a = 1\n```\n```rtc,error\nx  // error[rtc::name::unknown]\n```\n";
    let b = blocks(doc);
    assert_eq!(b.len(), 2);
    assert!(!b[0].error && b[1].error);
    assert_eq!(b[1].line, 5);
    assert_eq!(
        expectations(&b[1].text),
        vec![(1, Severity::Error, "rtc::name::unknown".to_owned())]
    );
    assert!(has_header("// c\nrtc 1\n") && !has_header("let a = 1\nrtc 1\n"));
    assert!(has_header("rtc 1.1\n"));
}
