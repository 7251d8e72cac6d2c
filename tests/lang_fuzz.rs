//! Property: parsing and evaluating arbitrary input never panics and always terminates (small
//! budgets keep each case quick). Two generators: raw text, and token soup built from the
//! language's own vocabulary so that many cases get past the parser into evaluation.

use std::path::Path;

use proptest::prelude::*;
use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

const TOKENS: &[&str] = &[
    "rtc 1\n",
    "let ",
    "fn ",
    "for ",
    " in ",
    "if ",
    "else ",
    "import ",
    " as ",
    "pub ",
    " with ",
    "step ",
    "true",
    "false",
    "x",
    "y",
    "f",
    "i",
    "sphere",
    "box",
    "plane",
    "cylinder",
    "torus",
    "group",
    "union",
    "camera",
    "render",
    "point_light",
    "material",
    "rgb",
    "hsv",
    "translate",
    "rotate",
    "scale",
    "random",
    "print",
    "assert",
    "sin",
    "normalize",
    "mesh",
    "image",
    ".bounds",
    ".x",
    ".material",
    ".scale",
    ".rotate",
    "(",
    ")",
    "[",
    "]",
    "{",
    "}",
    ",",
    ":",
    "=",
    "==",
    "+",
    "-",
    "*",
    "/",
    "%",
    "|",
    "&",
    ">>",
    "..",
    "..=",
    ".",
    "->",
    "0",
    "1",
    "2.5",
    "-1",
    "30deg",
    "1rad",
    "#ff8800",
    "\"s {x}\"",
    "\"./a.rtc\"",
    "std.prelude",
    "\n",
    " ",
    "// c\n",
    "/*",
    "*/",
    "radius: ",
    "center: ",
    "eye: ",
    "fov: ",
    "X",
    "Y",
    "[0, 1, 2]",
    "1e400",
    "9999999999999999999999",
    "°",
    "é",
];

fn opts() -> EvalOptions {
    EvalOptions {
        max_loop_iterations: 2_000,
        max_recursion_depth: 32,
        max_objects: 500,
        max_list_len: 2_000,
        max_string_len: 20_000,
        ..EvalOptions::default()
    }
}

/// The codes of every diagnostic `src` gets.
fn codes(src: &str) -> Vec<&'static str> {
    let mut sm = SourceMap::new();
    let loaded = load_source(Path::new("tests/lang/fuzz.rtc"), src, &mut sm, &opts());
    loaded.diagnostics.items.iter().map(|d| d.code).collect()
}

fn run(src: &str) {
    if std::env::var("FUZZ_TRACE").is_ok() {
        eprintln!("CASE {src:?}");
    }
    let mut sm = SourceMap::new();
    let loaded = load_source(Path::new("tests/lang/fuzz.rtc"), src, &mut sm, &opts());
    // Every diagnostic's span must lie inside a known file.
    for d in &loaded.diagnostics.items {
        if let Some(s) = d.span {
            let f = sm.get(s.file);
            assert!(s.end as usize <= f.text.len(), "span past end: {d:?}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1000, .. ProptestConfig::default() })]

    #[test]
    fn arbitrary_text_never_panics(src in "\\PC{0,200}") {
        run(&src);
        run(&format!("rtc 1\n{src}"));
    }

    #[test]
    fn token_soup_never_panics(toks in proptest::collection::vec(0..TOKENS.len(), 0..60)) {
        let src: String = toks.iter().map(|&i| TOKENS[i]).collect();
        run(&format!("rtc 1\n{src}"));
    }

    /// The shapes of input the hostile probe used (issue 35), at random sizes around their
    /// budgets: brackets nested deep, long postfix chains, long `else if` chains and unions
    /// grown one object at a time. Each ends in its result or a coded error; past the
    /// nesting budget (200 brackets) it is the nesting error.
    #[test]
    fn hostile_shapes_never_panic(shape in 0..5usize, n in 0..600usize) {
        let src = match shape {
            0 => format!("rtc 1\nlet a = {}1{}\n", "(".repeat(n), ")".repeat(n)),
            1 => format!("rtc 1\nlet a = {}1{}\n", "[".repeat(n), "]".repeat(n)),
            2 => format!("rtc 1\nlet l = [1]\nlet y = l{}\n", "[0]".repeat(n)),
            3 => {
                let arms: String = (1..n).map(|i| format!(" else if x == {i} {{ {i} }}")).collect();
                format!("rtc 1\nfn g(x: Int) -> Int {{ if x == 0 {{ 0 }}{arms} else {{ -1 }} }}\nlet y = g(3)\n")
            }
            _ => format!(
                "rtc 1\nlet b = for i in 0..{n} {{ sphere(center: [i, 0, 0]) }}\n\
                 let u = reduce(b, sphere(), fn(a, x) a | x)\n"
            ),
        };
        run(&src);
        if shape < 2 && n > 200 {
            prop_assert!(codes(&src).contains(&"rtc::budget::nesting"), "{shape} {n}");
        }
    }
}

/// Inputs built to exhaust a stack, a loop or memory end in one clear error each (with its
/// code), not a crash or a hang.
#[test]
fn adversarial_inputs_are_rejected_cleanly() {
    let cases: [(String, &[&str]); 8] = [
        (
            format!("rtc 1\nlet a = {}1\n", "-".repeat(100_000)),
            &["rtc::budget::nesting"],
        ),
        (
            format!("rtc 1\nlet a = 1{}\n", " + 1".repeat(50_000)),
            &["rtc::budget::nesting"],
        ),
        // Ten thousand open brackets: the parser may report the nesting or the missing `]`.
        (
            format!("rtc 1\nlet a = {}\n", "[".repeat(10_000)),
            &["rtc::syntax::unclosed", "rtc::budget::nesting"],
        ),
        (
            "rtc 1\nfn f(n) { f(n) + f(n) }\nf(1)\n".into(),
            &["rtc::budget::recursion"],
        ),
        (
            "rtc 1\nfor i in 0..1000000000000 { }\n".into(),
            &["rtc::budget::loop"],
        ),
        (
            "rtc 1\nlet l = for i in 0..100000 { [i, i] }\n".into(),
            &["rtc::budget::loop"],
        ),
        (
            "rtc 1\nlet r = 0..1 step 0\n".into(),
            &["rtc::value::range_step"],
        ),
        // A literal too large for a Float is refused where it is written.
        (
            "rtc 1\nsphere(radius: 1e400)\n".into(),
            &["rtc::syntax::number"],
        ),
    ];
    for (src, expected) in &cases {
        run(src);
        let got = codes(src);
        let shown = &src[..src.len().min(40)];
        assert_eq!(got.len(), 1, "{shown:?}: {got:?}");
        assert!(
            expected.contains(&got[0]),
            "{shown:?}: {got:?}, expected one of {expected:?}"
        );
    }
}
