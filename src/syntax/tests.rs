//! Grammar unit tests: what parses, what the AST looks like, and what syntax errors say.

use super::ast::*;
use super::parse;
use crate::source::FileId;

fn ok(src: &str) -> File<'_> {
    let (f, d) = parse(FileId(0), src);
    assert!(d.is_empty(), "unexpected diagnostics for {src:?}: {d:#?}");
    f.expect("AST")
}

fn expr(src: &str) -> Expr {
    let text = format!("rtc 1\n{src}\n");
    match ok(&text).into_stmts().into_iter().next() {
        Some(Stmt::Expr(e)) => e,
        other => panic!("not an expression statement: {other:?}"),
    }
}

fn errs(src: &str) -> Vec<(usize, &'static str, String)> {
    let (_, d) = parse(FileId(0), src);
    d.iter()
        .map(|d| {
            (
                d.span.map_or(0, |s| s.start as usize),
                d.code,
                d.message.clone(),
            )
        })
        .collect()
}

#[test]
fn parses_the_proposal_example() {
    let src = include_str!("../../tests/lang/five_spheres_raw.rtc");
    let f = ok(src);
    assert_eq!(f.len(), 18);
    assert_eq!(f.version.map(|v| v.0).as_deref(), Some("1"));
}

#[test]
fn precedence_follows_the_table() {
    // `&` binds tighter than `-`, which binds tighter than `|`.
    let e = expr("a | b - c & d");
    let ExprKind::Binary(BinOp::Union, _, rhs) = e.kind else {
        panic!("{e:?}")
    };
    let ExprKind::Binary(BinOp::Sub, _, rr) = rhs.kind else {
        panic!()
    };
    assert!(matches!(rr.kind, ExprKind::Binary(BinOp::Inter, ..)));
    let e = expr("1 + 2 * 3 == 7 && true");
    assert!(matches!(e.kind, ExprKind::Binary(BinOp::And, ..)));
    let e = expr("0..n + 1 step 2");
    let ExprKind::Range {
        end,
        step,
        inclusive,
        ..
    } = e.kind
    else {
        panic!()
    };
    assert!(matches!(end.kind, ExprKind::Binary(BinOp::Add, ..)));
    assert!(step.is_some() && !inclusive);
}

#[test]
fn literals_and_units() {
    assert!(
        matches!(expr("45deg").kind, ExprKind::Angle(a) if (a - 45f64.to_radians()).abs() < 1e-15)
    );
    assert!(
        matches!(expr("0.5turn").kind, ExprKind::Angle(a) if (a - std::f64::consts::PI).abs() < 1e-15)
    );
    assert!(matches!(expr("1e-3").kind, ExprKind::Float(f) if f == 1e-3));
    assert!(matches!(expr("#ffffff").kind, ExprKind::Color(c) if c == [1.0; 3]));
    let ExprKind::Str(parts) = expr("\"a {x:.2} b\"").kind else {
        panic!()
    };
    assert!(matches!(&parts[1], StrPart::Interp(_, Some(2))));
}

#[test]
fn newlines_end_statements_except_inside_brackets_and_before_dots() {
    let f = ok(
        "rtc 1\nlet a = sphere(\n  radius: 1,\n  center: [0, 0, 0]\n)\n  .scale(2)\n  .translate([1, 0, 0])\nlet b = 1 +\n  2\nb\n",
    );
    assert_eq!(f.len(), 3);
    let f = ok("rtc 1\ncamera {\n  eye: [0, 3, 8]\n  fov: 40deg\n}\n");
    let Stmt::Expr(Expr {
        kind: ExprKind::Call(_, args),
        ..
    }) = &f.into_stmts()[0]
    else {
        panic!()
    };
    let ExprKind::Record(fields) = &args[0].value.kind else {
        panic!()
    };
    assert_eq!(fields.len(), 2);
}

#[test]
fn every_node_has_a_span_inside_the_text() {
    let src = "rtc 1\nfn f(x: Float = 2) -> Float { let y = x * 2\n y }\nfor i in 0..3 if i > 0 { f(i) }\n";
    let f = ok(src);
    let stmts = f.into_stmts();
    let Stmt::Fn(def) = &stmts[0] else { panic!() };
    assert_eq!(
        &src[def.name.span.start as usize..def.name.span.end as usize],
        "f"
    );
    let Stmt::Expr(e) = &stmts[1] else { panic!() };
    assert_eq!(
        &src[e.span.start as usize..e.span.end as usize],
        "for i in 0..3 if i > 0 { f(i) }"
    );
}

#[test]
fn several_syntax_errors_are_reported_in_one_run() {
    let e = errs("rtc 1\nlet x = sphere(center: [0,0,0] radius: 1)\nlet y = \nlet z = 3 +\n");
    assert_eq!(e.len(), 3, "{e:?}");
    assert!(e[0].2.contains("expected `,` or `)`"));
}

#[test]
fn common_slips_have_their_own_codes() {
    assert_eq!(
        errs("rtc 1\ncamera { eye = [0,0,0] }\n")[0].1,
        "rtc::syntax::eq_for_colon"
    );
    assert_eq!(errs("rtc 1\nlet a = 1;\n")[0].1, "rtc::syntax::semicolon");
    assert_eq!(errs("rtc 1\nlet a = (1\n")[0].1, "rtc::syntax::unclosed");
    assert_eq!(errs("rtc 1\n)\n")[0].1, "rtc::syntax::unmatched");
    assert_eq!(errs("let a = 1\n")[0].1, "rtc::syntax::header");
    let deep = format!("rtc 1\nlet a = {}1{}\n", "(".repeat(500), ")".repeat(500));
    assert_eq!(errs(&deep)[0].1, "rtc::budget::nesting");
}
