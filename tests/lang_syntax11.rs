//! Language 1.1 syntax rules (issue 11): the `-` line rule, `//` after a value, wrapped `for`
//! headers, `f {}`, the `rtc 1.1` header, and several syntax errors reported in file order.

use std::path::Path;

use rtc::diag::Severity;
use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

/// (severity, code, line) of every diagnostic of a scene (a camera is appended).
fn diags(src: &str) -> Vec<(Severity, &'static str, usize)> {
    let text = format!("{src}\ncamera {{ eye: [0, 0, 10] }}\n");
    let mut sources = SourceMap::default();
    let loaded = load_source(
        Path::new("t.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    loaded
        .diagnostics
        .items
        .iter()
        .filter(|d| d.code != "rtc::print")
        .map(|d| {
            let line = d
                .span
                .map_or(0, |s| text[..s.start as usize].lines().count());
            (d.severity, d.code, line)
        })
        .collect()
}

#[test]
fn both_headers_name_the_same_language() {
    for header in ["rtc 1", "rtc 1.1"] {
        assert!(
            diags(&format!("{header}\nassert(7 div 2 == 3)")).is_empty(),
            "{header}"
        );
    }
    assert_eq!(diags("rtc 1.2\n")[0].1, "rtc::syntax::version");
}

#[test]
fn a_minus_line_subtracts_only_with_a_space() {
    assert!(diags("rtc 1.1\nlet a = 10\n  - 4\nassert(a == 6)").is_empty());
    let d = diags("rtc 1.1\nfn f(v: Vec3) {\n  let w = v\n  -w\n}\nassert(f(X) == [-1, 0, 0])");
    assert_eq!(
        d,
        vec![(Severity::Warning, "rtc::syntax::ambiguous_minus", 4)]
    );
    // At the start of a block, or in parentheses, nothing is ambiguous.
    assert!(diags("rtc 1.1\nfn g(v: Vec3) {\n  -v\n}\nlet x = 1\nprint((-x))").is_empty());
}

#[test]
fn a_comment_after_a_value_is_warned_only_when_it_reads_as_division() {
    let d =
        diags("rtc 1.1\nlet n = 8\nlet h = n // 2\nlet r = 0.5 // radius\nlet k = n // 2 spheres");
    assert_eq!(
        d,
        vec![(Severity::Warning, "rtc::syntax::comment_division", 3)]
    );
}

#[test]
fn for_headers_wrap_and_empty_records_call() {
    assert!(
        diags("rtc 1.1\nlet l = for i in 0..6\n  if i % 2 == 0\n{ i }\nassert(len(l) == 3)")
            .is_empty()
    );
    assert!(diags("rtc 1.1\nlet m = material {}\nassert(m.kd == 0.8)").is_empty());
    // In an `if` head `{}` is still the empty block.
    assert!(diags("rtc 1.1\nlet c = true\nlet v = if c {} else { 1 }").is_empty());
}

#[test]
fn syntax_errors_come_in_file_order_before_an_unclosed_bracket() {
    let d = diags("rtc 1.1\nlet a = 1;\nlet b = 2 +\nlet c = (3\n");
    let codes: Vec<(&str, usize)> = d.iter().map(|x| (x.1, x.2)).collect();
    assert_eq!(
        codes,
        vec![
            ("rtc::syntax::semicolon", 2),
            ("rtc::syntax::unexpected", 3),
            ("rtc::syntax::unclosed", 4)
        ]
    );
}

#[test]
fn precedence_of_the_new_operators() {
    let src = "rtc 1.1\nassert(-2 ** 2 == -4 && 2 ** 3 ** 2 == 512 && 2 * 3 ** 2 == 18)\nassert(-7 div 2 == -4 && 7 div 2 * 2 == 6 && 1 + 7 div 2 == 4)";
    assert!(diags(src).is_empty());
    assert_eq!(
        diags("rtc 1.1\nlet x = 0\nassert(0 < x < 1)")[0].1,
        "rtc::syntax::unexpected"
    );
}
