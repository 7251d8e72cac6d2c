//! The layout rules of docs/fmt.md, each on a small input whose expected output is written by
//! hand from the rule.

use super::{format, strip_spans};
use crate::source::FileId;

fn fmt(src: &str) -> String {
    let out = format(FileId(0), src).unwrap_or_else(|d| panic!("{src}\n{d:?}"));
    let again = format(FileId(0), &out).expect("formats again");
    assert_eq!(again, out, "not idempotent");
    out
}

#[test]
fn spaces_follow_the_roles_of_tokens() {
    assert_eq!(
        fmt("rtc 1.1\nlet  x:Float=-1+2*  3\nlet v=[ 1,-2 ,3]\nf( a:1 ,b :x[0] )\n"),
        "rtc 1.1\nlet x: Float = -1 + 2 * 3\nlet v = [1, -2, 3]\nf(a: 1, b: x[0])\n"
    );
    assert_eq!(
        fmt("rtc 1\nfn f(xs:List<List<Int>>?=[],n:Int)->Float{ 0..n step 2 }\n"),
        "rtc 1\nfn f(xs: List<List<Int>>? = [], n: Int) -> Float { 0..n step 2 }\n"
    );
    assert_eq!(
        fmt("rtc 1\nlet m=mat.glass with{eta:1.5}\nf{}\nlet g=fn(x)x*2\nlet b=!(a<b)&&c\n"),
        "rtc 1\nlet m = mat.glass with { eta: 1.5 }\nf {}\nlet g = fn(x) x * 2\nlet b = !(a < b) && c\n"
    );
}

#[test]
fn lines_are_indented_by_brackets_and_continuations() {
    let src = "rtc 1\nfn f(x) {\n  let y = x\n      .scale(2)\n  if y {\n  1\n  }\n  else { 2 }\n}\nlet s = a\n- b\n";
    assert_eq!(
        fmt(src),
        // The `if` chain was written over lines: every block of it stands over lines.
        "rtc 1\nfn f(x) {\n    let y = x\n        .scale(2)\n    if y {\n        1\n    } else {\n        2\n    }\n}\nlet s = a\n    - b\n"
    );
}

#[test]
fn a_group_written_over_lines_gets_one_item_per_line() {
    let src = "rtc 1\nf(a, b,\n  c)\ncamera {\n  eye: [0, 0, 1], up: Y,\n  fov: 40deg\n}\nlet l = [\n1, 2, 3]\n";
    assert_eq!(
        fmt(src),
        // Three numbers over lines get no trailing comma: it would make the `Vec3` a `List`.
        "rtc 1\nf(\n    a,\n    b,\n    c,\n)\ncamera {\n    eye: [0, 0, 1]\n    up: Y\n    fov: 40deg\n}\nlet l = [\n    1,\n    2,\n    3\n]\n"
    );
}

#[test]
fn a_list_of_three_numbers_stays_a_list() {
    // `[1, 2, 3,]` is a List of Ints; without the comma it would read as a Vec3.
    assert_eq!(
        fmt("rtc 1\nlet l = [1, 2, 3,]\n"),
        "rtc 1\nlet l = [1, 2, 3,]\n"
    );
    // Without a comma three numbers are a `Vec3` (issue 34): the formatter adds none.
    assert_eq!(
        fmt("rtc 1\nlet l = [1, - 2, 3]\n"),
        "rtc 1\nlet l = [1, -2, 3]\n"
    );
    assert_eq!(
        fmt("rtc 1\nlet l = [a, b, c,]\n"),
        "rtc 1\nlet l = [a, b, c]\n"
    );
}

#[test]
fn long_lines_break_the_outermost_group() {
    let args: Vec<String> = (0..12).map(|i| format!("argument_{i}: {i}")).collect();
    let src = format!("rtc 1\nlet x = f({})\n", args.join(", "));
    let want = format!(
        "rtc 1\nlet x = f(\n{})\n",
        args.iter()
            .map(|a| format!("    {a},\n"))
            .collect::<String>()
    );
    assert_eq!(fmt(&src), want);
    // A single argument ending in a group: that group breaks instead.
    let fields: Vec<String> = (0..8).map(|i| format!("field_{i}: {i}.5")).collect();
    let src = format!("rtc 1\nlet x = g(h {{ {} }})\n", fields.join(", "));
    let want = format!(
        "rtc 1\nlet x = g(h {{\n{}}})\n",
        fields
            .iter()
            .map(|a| format!("    {a}\n"))
            .collect::<String>()
    );
    assert_eq!(fmt(&src), want);
}

#[test]
fn comments_stay_where_they_were() {
    let src = "// head\nrtc 1 // version\n\n\n\n/* block\n   two lines */\nlet a = f( // first\n  1, /* one */ 2) // end\n{\n}\n// tail\n";
    assert_eq!(
        fmt(src),
        "// head\nrtc 1 // version\n\n/* block\n   two lines */\nlet a = f( // first\n    1, /* one */\n    2,\n) // end\n{\n}\n// tail\n"
    );
}

#[test]
fn a_minus_at_a_line_start_keeps_its_meaning() {
    // `-y` on its own line is a new statement (a warning), `- y` subtracts.
    let src = "rtc 1\nlet x = 1\n-x\nlet y = 2\n  - 1\n";
    assert_eq!(fmt(src), "rtc 1\nlet x = 1\n-x\nlet y = 2\n    - 1\n");
}

#[test]
fn syntax_errors_are_reported_not_formatted() {
    let d = format(FileId(0), "rtc 1\nlet = 3\n").expect_err("syntax error");
    assert!(d.iter().any(|d| d.is_error() && d.code.contains("syntax")));
}

#[test]
fn spans_are_stripped() {
    assert_eq!(
        strip_spans("A { span: Span { file: FileId(0), start: 1, end: 2 }, b: 3 }"),
        "A { span: Span, b: 3 }"
    );
}

#[test]
fn long_chains_break_before_operators_and_method_calls() {
    let src = format!(
        "rtc 1\nlet s = {}\n",
        ["shape_number_one(1)"; 6].join(" | ")
    );
    let want = format!(
        "rtc 1\nlet s = shape_number_one(1){}\n",
        "\n    | shape_number_one(1)".repeat(5)
    );
    assert_eq!(fmt(&src), want);
    // Only the lowest precedence breaks: `a * b` stays whole.
    let src = format!(
        "rtc 1\nlet s = {}\n",
        ["long_name_a * long_name_b"; 4].join(" + ")
    );
    let want = format!(
        "rtc 1\nlet s = long_name_a * long_name_b{}\n",
        "\n    + long_name_a * long_name_b".repeat(3)
    );
    assert_eq!(fmt(&src), want);
    let src = "rtc 1\nlet o = box(min: [-0.6, -0.6, -0.6], max: [0.6, 0.6, 0.6]).rotate(x: 35deg, y: 45deg).material(some_long_material)\n";
    assert_eq!(
        fmt(src),
        "rtc 1\nlet o = box(min: [-0.6, -0.6, -0.6], max: [0.6, 0.6, 0.6])\n    .rotate(x: 35deg, y: 45deg)\n    .material(some_long_material)\n"
    );
    // One written break breaks the whole chain.
    assert_eq!(
        fmt("rtc 1\nx.f().g()\n  .h()\n"),
        "rtc 1\nx\n    .f()\n    .g()\n    .h()\n"
    );
}

/// Issue 34: an `else if` chain written over lines stays over lines (it was joined into one
/// line), and a chain too long for its line breaks its blocks, not the `==` in its conditions.
#[test]
fn else_if_chains_break_their_blocks_together() {
    let src = "rtc 1\nfn size(n) {\n  if n < 2 { 1 }\n  else if n < 5 { 2 }\n  else { 3 }\n}\n";
    assert_eq!(
        fmt(src),
        "rtc 1\nfn size(n) {\n    if n < 2 {\n        1\n    } else if n < 5 {\n        2\n    } else {\n        3\n    }\n}\n"
    );
    let long = "rtc 1\nlet colour = if size(3) == 1 { #ff0000 } else if size(3) == 2 { #00ff00 } else if size(3) == 3 { #0000ff } else { #ffffff }\n";
    assert_eq!(
        fmt(long),
        "rtc 1\nlet colour = if size(3) == 1 {\n    #ff0000\n} else if size(3) == 2 {\n    #00ff00\n} else if size(3) == 3 {\n    #0000ff\n} else {\n    #ffffff\n}\n"
    );
    // Short chains on one line stay there; formatting is idempotent.
    let short = "rtc 1\nlet r = if big { 2 } else { 1 }\n";
    assert_eq!(fmt(short), short);
    assert_eq!(fmt(&fmt(long)), fmt(long));
}
