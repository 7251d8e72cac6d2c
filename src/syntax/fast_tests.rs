//! The fast statement path (fast.rs) against pest: for every input, parsing with the fast path
//! first must give exactly what pest alone gives — the same AST with the same spans, the same
//! diagnostics in the same order. Compared through `Debug`, which prints every field (floats to
//! the last bit, names as text, spans as offsets).

use std::path::{Path as FsPath, PathBuf};

use proptest::prelude::*;

use super::{PARALLEL_LINES, Path, parse_with};
use crate::source::FileId;

/// Parses `text` both ways, fails on any difference, and returns how many statements the fast
/// path read.
fn assert_same(what: &str, text: &str) -> usize {
    let fast = parse_with(FileId(3), text, Path::FastFirst);
    let pest = parse_with(FileId(3), text, Path::PestOnly);
    let (f, p) = (
        format!("{:#?}\n{:#?}", fast.ast, fast.diags),
        format!("{:#?}\n{:#?}", pest.ast, pest.diags),
    );
    if f != p {
        let at = f
            .lines()
            .zip(p.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(0);
        let context = |s: &str| {
            s.lines()
                .skip(at.saturating_sub(12))
                .take(16)
                .collect::<Vec<_>>()
                .join("\n")
        };
        panic!(
            "{what}: the fast path differs from pest at line {at} of the dump\n--- fast\n{}\n--- pest\n{}\n--- input\n{text}",
            context(&f),
            context(&p)
        );
    }
    // Visiting with `next_ref` (which builds into the previous statement's nodes) gives what
    // the iterator (which builds each afresh) gives.
    if let Some(file) = &fast.ast {
        let mut reusing = file.stmts();
        let mut built = Vec::new();
        while let Some(st) = reusing.next_ref() {
            built.push(format!("{st:#?}"));
        }
        let fresh: Vec<String> = file.stmts().map(|st| format!("{st:#?}")).collect();
        assert_eq!(built, fresh, "{what}: building into reused nodes differs");
    }
    fast.fast_statements
}

fn rtc_files(dir: &FsPath, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("corpus directory").flatten() {
        let p = entry.path();
        if p.is_dir() {
            rtc_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rtc") {
            out.push(p);
        }
    }
}

/// The ```rtc blocks of a Markdown file, with the header docs_examples.rs gives them.
fn doc_blocks(doc: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut current: Option<String> = None;
    for line in doc.lines() {
        match current.take() {
            None if line.trim_end().starts_with("```rtc") => current = Some(String::new()),
            None => {}
            Some(block) if line.trim_end() == "```" => {
                let header = if block.starts_with("rtc ") {
                    ""
                } else {
                    "rtc 1.1\n"
                };
                out.push(format!("{header}{block}"));
            }
            Some(mut block) => {
                block.push_str(line);
                block.push('\n');
                current = Some(block);
            }
        }
    }
    out
}

/// The lines of `benches/literal_spheres.py`'s literal file, written the way the script writes
/// them (Python's `repr` of the same doubles is Rust's `{:?}`).
fn literal_spheres(n: usize) -> String {
    let mut s = String::from(
        "rtc 1\nlet m = material { color: rgb(0.8, 0.3, 0.2), ka: 0.2, kd: 0.7, ks: 0.3, n: 16 }\n",
    );
    for k in 0..n {
        let (i, j) = (k / 7, k % 7);
        let x = i as f64 * 0.4 - 20.0;
        let y = (k % 10) as f64 * 0.4;
        let z = j as f64 * 0.4 - 20.0;
        let r = 0.1 + 0.05 * ((i + j + k) % 3) as f64;
        s.push_str(&format!(
            "sphere(center: [{x:?}, {y:?}, {z:?}], radius: {r:?}).material(m)\n"
        ));
    }
    s
}

#[test]
fn generated_sphere_lines_all_take_the_fast_path() {
    let n = 500;
    assert_eq!(
        assert_same("literal spheres", &literal_spheres(n)),
        n,
        "every sphere line of the parse benchmark must skip pest"
    );
}

#[test]
fn the_whole_corpus_parses_the_same_both_ways() {
    let root = FsPath::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["tests", "scenes", "stdlib", "docs"] {
        rtc_files(&root.join(dir), &mut files);
    }
    files.sort();
    assert!(files.len() >= 90, "only {} .rtc files found", files.len());
    let mut fast = 0;
    for f in &files {
        // A few diagnostics cases are not UTF-8 on purpose; they never reach the parser.
        if let Ok(text) = std::fs::read_to_string(f) {
            fast += assert_same(&f.display().to_string(), &text);
        }
    }
    let mut blocks = 0;
    for doc in ["docs/language.md", "README.md"] {
        let text = std::fs::read_to_string(root.join(doc)).expect("document");
        for (k, b) in doc_blocks(&text).iter().enumerate() {
            fast += assert_same(&format!("{doc} block {k}"), b);
            blocks += 1;
        }
    }
    assert!(blocks >= 50, "only {blocks} ```rtc blocks found");
    // The corpus is written by hand, mostly in multi-line records, yet many of its
    // statements are simple: if none took the fast path, this test would compare nothing.
    assert!(
        fast >= 100,
        "only {fast} corpus statements took the fast path"
    );
}

#[test]
fn edge_cases_parse_the_same_both_ways() {
    for (k, c) in EDGE_CASES.iter().enumerate() {
        assert_same(&format!("edge case {k}"), c);
    }
}

/// More distinct names than a tape numbers (254), many sharing a slot of its table, each used
/// again later: every name builds to itself, numbered or not.
#[test]
fn a_tape_with_more_names_than_it_numbers_parses_the_same_both_ways() {
    let mut text = String::from("rtc 1\n");
    for k in 0..600 {
        text.push_str(&format!("let n{k}x = {k}\n"));
    }
    for k in (0..600).rev() {
        text.push_str(&format!(
            "f(a{k}: n{k}x, b: n{}x).m{k}(n0x)\n",
            (k * 7) % 600
        ));
    }
    assert_eq!(assert_same("many names", &text), 1200);
}

/// A file with enough top-level lines to be read on several threads (`PARALLEL_LINES`), with
/// every edge case spread through it, parses as pest alone does; so does the same file cut
/// short by a delimiter error near its end.
#[test]
fn a_file_read_in_parallel_parses_the_same_both_ways() {
    let mut text = String::from("rtc 1\n");
    let mut cases = EDGE_CASES.iter().cycle();
    let mut lines = 0;
    while lines < PARALLEL_LINES + 500 {
        for k in 0..150 {
            text.push_str(&format!("f({k})\n"));
        }
        let case = cases
            .next()
            .expect("cycles")
            .strip_prefix("rtc 1")
            .expect("header");
        // The delimiter cases would cut the file at once: one comes at the end instead.
        if !case.contains("g(2))") && !case.contains("g([2)") {
            text.push_str(case.trim_start_matches(['\r', '\n']));
            text.push('\n');
        }
        lines = text.lines().count();
    }
    let fast = assert_same("long file", &text);
    assert!(fast > PARALLEL_LINES, "only {fast} fast statements");
    text.push_str("g([2)\nh(3)\n");
    assert_same("long file with a delimiter error", &text);
}

const EDGE_CASES: &[&str] = {
    &[
        // Continuations on the next line: pest extends the statement, so must the fast path.
        "rtc 1\nf(1)\n  .g(2)\n",
        "rtc 1\nf(1)\n\n// c\n  .g(2)\nh(3)\n",
        "rtc 1\nlet a = b\n  + 1\n",
        "rtc 1\nlet a = b\n  - 1\n",
        "rtc 1\nlet a = b\n-1\n",
        "rtc 1\nlet a = b\n  with { c: 1 }\n",
        "rtc 1\nlet r = 0..10\n  step 2\n",
        "rtc 1\nlet a = 7\n  div 2\n",
        "rtc 1\nlet a = b\nwithin(1)\nstepper\ndivide\n",
        "rtc 1\nlet a = b\n  ..c\n",
        "rtc 1\nlet a = b\n  == c\n",
        "rtc 1\nlet a = b\n  / 2\n",
        "rtc 1\nlet a = b\n  /* c */ + 2\n",
        "rtc 1\nlet a = b\n  (c)\n  [1, 2, 3]\n",
        // Numbers at their edges.
        "rtc 1\nf(1., 2)\n",
        "rtc 1\nf(1.x)\n",
        "rtc 1\nf(1.5.x)\n",
        "rtc 1\nf(1e, 2)\nf(1e+, 2)\nf(1e+3, 2E-2)\n",
        "rtc 1\nf(30deg, 1rad, 0.25turn, 45°, 2e1deg)\n",
        "rtc 1\nf(3degx)\nf(3x)\nf(0x10)\n",
        "rtc 1\nf(99999999999999999999)\nf(1e999)\n",
        "rtc 1\nf([99999999999999999999, 0, 0])\nf([1e999, 0, 0])\n",
        "rtc 1\nf([-0, -0.0, 007])\nf([1 , 2 ,3 ])\nf([\t1,\t2,\t3\t])\n",
        "rtc 1\nf([1, 2])\nf([1, 2, 3, 4])\nf([1., 2, 3])\nf([1x, 2, 3])\nf([- 1, 2, 3])\n",
        "rtc 1\nf([1, 2, 3].x)\nf([1, 2, 3][0])\nf(3(4))\nf(-3)\nf(- 3)\nf(-3.x)\nf(-x)\n",
        // Names, keywords, arguments.
        "rtc 1\nf(if: 1)\nf(true: 1)\nf(a = 1)\nf(a == 1)\nf(a : 1)\nf(a :1, b: -2)\n",
        "rtc 1\nf(a, b: 1, c)\nf(,)\nf(a,)\nf( )\nf()\nf(a b)\n",
        "rtc 1\ntrue\nfalse.x\nletter(1)\nlet\nlet x\nlet x =\nlet x == 1\nlet(x)\n",
        "rtc 1\nlet x = 1\nlet y: Float = 2\npub let z = 3\nlet w = -4\nlet v = -4 ** 2\n",
        "rtc 1\nlet x = 1   \nlet y = f(2) // why\nlet z = 3\t// c \nlet w = 4  ",
        "rtc 1\nf(a)(b).c(d).e\nf (a)\nf. a\nf.a. b\nf{ a: 1 }\nf {}\nf[0]\n",
        "rtc 1\nfor i in 0..3 { f(i) }\nif a { b }\nimport std.color\n",
        // Lines, comments, carriage returns, the end of the input.
        "rtc 1\n\n   \n\t\nf(1) // comment\n   // only a comment\n  g(2)   \nh(3)",
        "rtc 1\r\nf(1)\r\ng(2)\r\n",
        "rtc 1\nf(1)  ",
        "rtc 1\nf(1)\n   ",
        "rtc 1\nf(/* c */ 1)\n",
        "rtc 1\nf(1); g(2)\n",
        "rtc 1\nf(\n  1)\n",
        "rtc 1\nn // 2\n",
        "rtc 1\nf(é)\nfé\n",
        // A delimiter error cuts the file.
        "rtc 1\nf(1)\ng(2))\nh(3)\n",
        "rtc 1\nf(1)\ng([2)\nh(3)\n",
    ]
};

/// Pieces the generated statements are made of: the fast path's forms and their near misses.
mod near_misses {
    use proptest::prelude::*;

    fn space() -> impl Strategy<Value = &'static str> {
        prop_oneof![
            6 => Just(""),
            3 => Just(" "),
            1 => Just("  "),
            1 => Just("\t"),
            1 => Just(" /* c */ "),
        ]
    }

    fn name() -> impl Strategy<Value = &'static str> {
        prop_oneof![
            8 => prop::sample::select(vec![
                "a", "x1", "_t", "sphere", "material", "m", "center", "radius", "translate",
                "letter", "within", "stepper", "divide", "truex",
            ]),
            2 => prop::sample::select(vec![
                "let", "with", "step", "div", "true", "false", "if", "for", "in", "fn", "pub",
                "import", "as", "rtc", "else",
            ]),
        ]
    }

    fn number() -> impl Strategy<Value = String> {
        let int = prop_oneof![
            5 => (0u32..1000).prop_map(|v| v.to_string()),
            1 => Just("007".to_owned()),
            1 => Just("99999999999999999999".to_owned()),
        ];
        let frac = prop_oneof![
            3 => Just(String::new()),
            3 => (0u32..100_000).prop_map(|v| format!(".{v}")),
            1 => Just(".".to_owned()),
            1 => Just(".15000000000000002".to_owned()),
        ];
        let exp = prop_oneof![
            6 => Just(""),
            1 => Just("e6"),
            1 => Just("E-3"),
            1 => Just("e+2"),
            1 => Just("e"),
            1 => Just("e999"),
        ];
        let unit = prop_oneof![
            8 => Just(""),
            1 => Just("deg"),
            1 => Just("rad"),
            1 => Just("turn"),
            1 => Just("°"),
            1 => Just("x"),
        ];
        (int, frac, exp, unit).prop_map(|(i, f, e, u)| format!("{i}{f}{e}{u}"))
    }

    fn vec_lit() -> impl Strategy<Value = String> {
        let signed = (prop::bool::weighted(0.3), number())
            .prop_map(|(neg, n)| format!("{}{n}", if neg { "-" } else { "" }));
        let pad = || prop::sample::select(vec!["", " ", "  ", "\t"]);
        (prop::collection::vec((pad(), signed, pad()), 2..=4), pad()).prop_map(|(items, sep)| {
            let inner: Vec<String> = items.iter().map(|(a, n, b)| format!("{a}{n}{b}")).collect();
            format!("[{}]", inner.join(&format!(",{sep}")))
        })
    }

    fn leaf() -> impl Strategy<Value = String> {
        prop_oneof![
            4 => name().prop_map(str::to_owned),
            3 => number(),
            3 => vec_lit(),
            1 => number().prop_map(|n| format!("-{n}")),
            1 => number().prop_map(|n| format!("- {n}")),
            1 => Just("\"s\"".to_owned()),
        ]
    }

    fn arg(operand: BoxedStrategy<String>) -> impl Strategy<Value = String> {
        let sep = prop::sample::select(vec![":", " :", ": ", " = ", "="]);
        prop_oneof![
            2 => operand.clone(),
            3 => (name(), sep, space(), operand)
                .prop_map(|(n, s, sp, v)| format!("{n}{s}{sp}{v}")),
        ]
    }

    fn operand() -> impl Strategy<Value = String> {
        leaf().prop_recursive(4, 24, 4, |inner| {
            let inner = inner.boxed();
            prop_oneof![
                4 => (
                    inner.clone(),
                    space(),
                    prop::collection::vec(arg(inner.clone()), 0..4),
                    prop::sample::select(vec![", ", ",", " , "]),
                    prop::sample::select(vec!["", "", "", ","]),
                    space(),
                )
                    .prop_map(|(f, sp, args, sep, trail, sp2)| {
                        format!("{f}{sp}({sp2}{}{trail})", args.join(sep))
                    }),
                3 => (inner.clone(), prop::sample::select(vec![".", ". ", ".."]), name())
                    .prop_map(|(o, dot, n)| format!("{o}{dot}{n}")),
                1 => (inner.clone(), prop::sample::select(vec![" + ", " * ", " ** ", "[0]", " { a: 1 }", " with { a: 1 }"]))
                    .prop_map(|(o, s)| format!("{o}{s}")),
            ]
        })
    }

    pub(crate) fn line() -> impl Strategy<Value = String> {
        let stmt = prop_oneof![
            6 => operand(),
            2 => (name(), space(), space(), operand())
                .prop_map(|(n, a, b, v)| format!("let {n}{a}={b}{v}")),
            1 => operand().prop_map(|v| format!("  {v}")),
            1 => prop::sample::select(vec![
                "  .material(m)", "  + 1", "  - 1", "-1", "  with { a: 1 }", "// note", "",
                "   ", "  step 2", "  div 3", "  == 2", "  ..4", "}", "(1)", "[1, 2, 3]",
            ])
            .prop_map(str::to_owned),
        ];
        let end = prop_oneof![
            8 => Just(""),
            1 => Just("  "),
            1 => Just(" // c"),
            1 => Just("\r"),
        ];
        (stmt, end).prop_map(|(s, e)| format!("{s}{e}"))
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn generated_statements_parse_the_same_both_ways(
        lines in prop::collection::vec(near_misses::line(), 1..8),
        final_newline in any::<bool>(),
    ) {
        let mut text = format!("rtc 1\n{}", lines.join("\n"));
        if final_newline {
            text.push('\n');
        }
        assert_same("generated", &text);
    }
}

/// Statements of exactly the documented fast forms, which must all skip pest.
mod fast_forms {
    use proptest::prelude::*;

    fn name() -> impl Strategy<Value = &'static str> {
        prop::sample::select(vec![
            "a", "x1", "_t", "sphere", "m", "center", "letter", "truex",
        ])
    }

    fn number() -> impl Strategy<Value = String> {
        prop_oneof![
            (0i64..100_000).prop_map(|v| v.to_string()),
            any::<f64>()
                .prop_filter("finite", |v| v.is_finite())
                .prop_map(|v| format!("{:?}", v.abs())),
            (
                0u32..360,
                prop::sample::select(vec!["deg", "rad", "turn", "°"])
            )
                .prop_map(|(v, u)| format!("{v}{u}")),
        ]
    }

    /// A name, number, negated number, vector or boolean.
    pub(crate) fn leaf() -> BoxedStrategy<String> {
        let vec = prop::collection::vec((any::<bool>(), number()), 3).prop_map(|v| {
            let parts: Vec<String> = v
                .iter()
                .map(|(neg, n)| {
                    format!(
                        "{}{}",
                        if *neg { "-" } else { "" },
                        n.trim_end_matches(|c: char| c.is_alphabetic() || c == '°')
                    )
                })
                .collect();
            format!("[{}]", parts.join(", "))
        });
        prop_oneof![
            name().prop_map(str::to_owned),
            number(),
            number().prop_map(|n| format!("-{n}")),
            vec,
            prop::sample::select(vec!["true", "false"]).prop_map(str::to_owned),
        ]
        .boxed()
    }

    fn operand() -> impl Strategy<Value = String> {
        leaf().prop_recursive(3, 16, 3, |inner| {
            prop_oneof![
                (
                    name(),
                    prop::collection::vec((prop::option::of(name()), inner.clone()), 0..4)
                )
                    .prop_map(|(f, args)| {
                        let args: Vec<String> = args
                            .into_iter()
                            .map(|(n, v)| match n {
                                Some(n) => format!("{n}: {v}"),
                                None => v,
                            })
                            .collect();
                        format!("{f}({})", args.join(", "))
                    }),
                (name(), name()).prop_map(|(a, b)| format!("{a}.{b}")),
                (name(), inner, name()).prop_map(|(f, a, m)| format!("{f}({a}).{m}(m)")),
            ]
        })
    }

    pub(crate) fn line() -> impl Strategy<Value = String> {
        prop_oneof![
            3 => operand().prop_filter("not a negative statement", |s| !s.starts_with('-')),
            1 => (name(), operand()).prop_map(|(n, v)| format!("let {n} = {v}")),
        ]
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// Lines of a few shapes with leaves of every kind, so that most statements are built into
    /// the nodes of the one before (`Stmts::next_ref`), and some cannot be (a negated number
    /// where a plain one was, another shape).
    #[test]
    fn lines_of_one_shape_build_the_same_reusing_nodes(
        lines in prop::collection::vec(
            prop_oneof![
                4 => (fast_forms::leaf(), fast_forms::leaf(), fast_forms::leaf()).prop_map(|(a, b, c)| {
                    format!("sphere(center: {a}, radius: {b}).material({c})")
                }),
                1 => (fast_forms::leaf(), fast_forms::leaf()).prop_map(|(a, b)| format!("sphere({a}, r: {b})")),
                1 => fast_forms::leaf().prop_map(|a| format!("let v = {a}")),
            ],
            1..12,
        ),
    ) {
        let text = format!("rtc 1\n{}\n", lines.join("\n"));
        prop_assert_eq!(assert_same("one shape", &text), lines.len());
    }

    #[test]
    fn every_fast_form_skips_pest(lines in prop::collection::vec(fast_forms::line(), 1..10)) {
        let text = format!("rtc 1\n{}\n", lines.join("\n"));
        prop_assert_eq!(assert_same("fast forms", &text), lines.len());
    }
}
