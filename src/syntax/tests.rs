//! Grammar unit tests: what parses, what the AST looks like, and what syntax errors say.

use super::ast::*;
use super::parse;
use crate::source::FileId;

fn ok(src: &str) -> File {
    let (f, d) = parse(FileId(0), src);
    assert!(d.is_empty(), "unexpected diagnostics for {src:?}: {d:#?}");
    f.expect("AST")
}

fn errs(src: &str) -> Vec<String> {
    let (_, d) = parse(FileId(0), src);
    d.iter().map(|d| format!("{}:{}: {}", d.span.map_or(0, |s| s.start), d.code, d.message)).collect()
}

#[test]
fn parses_the_proposal_example() {
    let src = include_str!("../../tests/lang/five_spheres_raw.rtc");
    let f = ok(src);
    assert_eq!(f.version.map(|v| v.0), Some(1));
    assert_eq!(f.stmts.len(), 18);
}

#[test]
fn debug_errors() {
    for s in ["rtc 1\nlet x = sphere(center: [0,0,0] radius: 1)\nlet y = \nlet z = 3 +\n", "rtc 1\ncamera { eye = [0,0,0] }\n"] {
        eprintln!("{:#?}", errs(s));
    }
}
