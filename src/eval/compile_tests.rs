//! `eval::compile` against the interpreter: every construct that compiles gives the bits the
//! interpreter gives for the same function at the same points, and every construct that does
//! not is `rtc::fn::not_compilable` (or the interpreter's own type error) at the right text.

use std::path::Path;

use glam::DVec3;

use super::args::ArgVal;
use super::error::EvalError;
use super::host::Host;
use super::value::Value;
use super::{EvalOptions, LoopParts};
use crate::diag::Diagnostic;
use crate::ir::Loaded;
use crate::source::{SourceMap, Span};

/// Points the function is compared at: the origin, lattice points, and points off the
/// lattice, negative and large.
fn points() -> Vec<DVec3> {
    let mut out = vec![
        DVec3::ZERO,
        DVec3::new(1.0, 2.0, 3.0),
        DVec3::new(-1.0, 0.0, 1.0),
        DVec3::new(0.5, -0.25, 0.125),
        DVec3::new(123.456, -78.9, 0.001),
        DVec3::new(-3.7, 2.2, -0.4),
    ];
    let mut s: u64 = 0x1234_5678;
    for _ in 0..40 {
        let mut next = || {
            s = s.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            ((s >> 11) as f64 / (1u64 << 53) as f64) * 8.0 - 4.0
        };
        out.push(DVec3::new(next(), next(), next()));
    }
    out
}

/// Evaluates `text` (a scene binding `f`), then hands the interpreter and `f` to `check`.
fn with_f<T>(text: &str, check: impl FnOnce(&mut dyn Host, Value) -> T) -> T {
    let options = EvalOptions {
        loop_parts: LoopParts::Serial,
        ..EvalOptions::default()
    };
    let mut sources = SourceMap::new();
    let mut loaded = Loaded::default();
    let path = Path::new("compile_test.rtc");
    let text = format!("rtc 1.1\n{text}\n");
    let shown = text.clone();
    let Some((mut it, _)) = super::run_root(path, text, &mut sources, &options, None, &mut loaded)
    else {
        let msgs: Vec<&str> = loaded
            .diagnostics
            .items
            .iter()
            .map(|d| d.message.as_str())
            .collect();
        panic!("{shown}: {msgs:?}");
    };
    let errors: Vec<String> = loaded
        .diagnostics
        .items
        .iter()
        .chain(it.take_findings().iter())
        .filter(|d| d.is_error())
        .map(|d| format!("{}: {}", d.code, d.message))
        .collect();
    assert!(errors.is_empty(), "{errors:?}");
    let f = it.item("f").expect("the scene binds `f`");
    check(&mut it, f)
}

/// The function `f` of `text`, compiled and interpreted at every point: the same bits.
fn same(text: &str) {
    with_f(text, |it, f| {
        let Value::Fn(c) = &f else {
            panic!("`f` is not a function")
        };
        let program = match super::compile::compile(c) {
            Ok(p) => p,
            Err(EvalError::Diag(d)) => panic!("{text}: {} {}", d.code, d.message),
            Err(EvalError::Poisoned) => panic!("poisoned"),
        };
        for p in points() {
            let arg = ArgVal {
                name: None,
                value: Value::Vec3(p),
                span: Span::default(),
            };
            let want = it
                .call_value(f.clone(), vec![arg], Span::default(), Span::default())
                .ok()
                .and_then(|v| v.as_f64());
            // Where the interpreter stops (a division by zero), the program gives a value
            // that is not finite or one computed past the error: nothing to compare.
            let Some(want) = want else { continue };
            let got = program.run(p);
            assert_eq!(
                got.to_bits(),
                want.to_bits(),
                "{text} at {p}: compiled {got}, interpreted {want}"
            );
        }
    });
}

/// Compiling `f` of `text` fails with `code`, its primary span over `at`.
fn fails(text: &str, code: &str, at: &str) -> Diagnostic {
    let full = format!("rtc 1.1\n{text}\n");
    with_f(text, |_, f| {
        let Value::Fn(c) = &f else {
            panic!("`f` is not a function")
        };
        let d = match super::compile::compile(c) {
            Ok(_) => panic!("{text}: compiled"),
            Err(EvalError::Diag(d)) => *d,
            Err(EvalError::Poisoned) => panic!("poisoned"),
        };
        assert_eq!(d.code, code, "{text}: {}", d.message);
        let span = d.span.expect("a span");
        let got = &full[span.start as usize..span.end as usize];
        assert_eq!(got.trim(), at, "{text}: {}", d.message);
        assert!(d.label.is_some() && d.help.is_some(), "{d:?}");
        d
    })
}

#[test]
fn arithmetic_and_comparisons() {
    same("let f = fn(p) { p.x - floor(p.x) }");
    same("let f = fn(p) { p.x * 2 + p.y / 3 - p.z % 0.7 }");
    same("let f = fn(p) { -p.x ** 2 + 2 ** 3 + 7 div 2 + 7 % 3 }");
    same("let f = fn(p) { if p.x < p.y && !(p.z >= 1) || p.x == 0 { 1 } else { 0.25 } }");
    same("let f = fn(p) { if p.x <= 0 { 1 } else if p.y > 0.5 { 2 } else { p.z * 3 } }");
    same("let f = fn(p) { if (p.z != 1) == true { 1.5 } else { 2 } }");
}

#[test]
fn vectors_members_and_lets() {
    same("let f = fn(p) { let q = p * 2 - [1, 0.5, 0.25]\nq.x * q.y + q.z }");
    same(
        "let f = fn(p) { let q = 3 * p / 2\nlet r = -q + p * p\ndot(q, r) + length(cross(p, r)) }",
    );
    same("let f = fn(p) { distance(p, [1, 2, 3]) + normalize(p + [0.1, 0, 0]).y }");
    same(
        "let f = fn(p) { let v = [p.x, 2, p.z * p.y]\nv.zyx.x + (if p == p { 1 } else { 0 }) + (if p != p * 2 { 2 } else { 0 }) }",
    );
    same("let f = fn(p) { let a = if p.x > 0 { let b = p.x\nb * b } else { 0 }\na + 1 }");
}

#[test]
fn maths_built_ins() {
    same("let f = fn(p) { sin(p.x * 1rad) + cos(30deg) * tan(p.y * 1deg) }");
    same("let f = fn(p) { asin(p.x / 5) / 1rad + acos(0.5) / 1deg + atan(p.z) / 1rad }");
    same(
        "let f = fn(p) { atan2(p.y, p.x) / 1rad + sqrt(abs(p.z)) + exp(p.x / 4) + ln(abs(p.y) + 1) }",
    );
    same("let f = fn(p) { floor(p.x) + ceil(p.y) + round(p.z) + int(p.x * 3) + float(2) }");
    same(
        "let f = fn(p) { pow(abs(p.x), 1.5) + min(p.x, p.y, 2) + max(p.z, 0) + min(p) + max(1, 2) }",
    );
    same("let f = fn(p) { abs(-30deg) / 1deg + abs(-2) + abs(p.x) }");
}

#[test]
fn noise_built_ins() {
    same("let f = fn(p) { noise(p) + snoise(p * 2, seed: 3) + vnoise(p).y }");
    same(
        "let f = fn(p) { fbm(p, octaves: 4) + turbulence(p, octaves: 3, omega: 0.6, lambda: 2.5, seed: 9) }",
    );
    same(
        "let f = fn(p) { worley(p) + worley(p, form: \"f2\") + worley(p, form: \"edges\", seed: 2) }",
    );
    same("let oct = 5\nlet f = fn(p) { fbm(p * 4, octaves: oct) }");
}

#[test]
fn calls_captures_and_modules() {
    same("let k = 2.5\nlet c = [1, 2, 3]\nlet f = fn(p) { (p.x + k) * c.y }");
    same("fn sq(x) { x * x }\nlet f = fn(p) { sq(p.x) + sq(p.y) }");
    same(
        "fn ring(p, r: Float = 1) -> Float { let d = sqrt(p.x * p.x + p.z * p.z)\nif d < r { fbm(p * 4, octaves: 5) } else { 0.5 } }\nlet f = ring",
    );
    same(
        "import std.math { clamp, smoothstep, fract }\nlet f = fn(p) { clamp(p.x, 0, 1) + smoothstep(0, 1, p.y) + fract(p.z) }",
    );
    same("import std.math as m\nlet f = fn(p) { m.lerp(0, 1, p.x) }");
    same("let f = fn(p) { let g = fn(x) x * 3\nfn h(y) { g(y) + 1 }\n h(p.x) }");
    same("let mk = fn(s) fn(p) p.x * s\nlet f = mk(4)");
    same("let f = fn(p, s = 3) { p.y * s }");
    same("let on = true\nlet f = fn(p) { if on { p.x } else { [1, 2, 3] } }");
    same(
        "let f = fn(p) { let g = if true { let a = p.x * 2\nfn(x) x + a } else { 0 }\nlet b = p.y * 3 + p.z\ng(b) }",
    );
}

#[test]
fn what_cannot_compile_is_named_at_its_text() {
    let nc = super::compile::CODE;
    fails(
        "let f = fn(p) { [p.x, p.y, p.z, 1].len() }",
        nc,
        "[p.x, p.y, p.z, 1]",
    );
    fails(
        "let f = fn(p) { let xs = [1, 2, 3, 4]\np.x }",
        nc,
        "[1, 2, 3, 4]",
    );
    fails("let f = fn(p) { \"{p.x}\" }", nc, "\"{p.x}\"");
    fails("let f = fn(p) { sphere().radius }", nc, "sphere");
    fails(
        "let f = fn(p) { for i in 0..3 { i } }",
        nc,
        "for i in 0..3 { i }",
    );
    fails("let f = fn(p) { print(p.x)\n p.x }", nc, "print(p.x)");
    fails("fn g(x) { g(x) }\nlet f = fn(p) { g(p.x) }", nc, "g(x)");
    fails("let f = fn(p) { p }", nc, "p");
    fails("let f = fn(p) { if p.x > 0 { 1 } }", nc, "if p.x > 0 { 1 }");
    fails(
        "let f = fn(p) { fbm(p, octaves: floor(p.x)) }",
        nc,
        "floor(p.x)",
    );
    fails("let f = fn(p) { p.xy }", nc, "xy");
    fails("let f = fn(p) { if p.x > 0 { p } else { 1 } }", nc, "{ 1 }");
    fails("let f = fn() { 1 }", nc, "fn() { 1 }");
    fails("let f = fn(p, q) { 1 }", nc, "q");
    fails("let f = fn(p) { p.length() }", nc, "p.length");
    fails("let f = fn(p) { rgb(1, 0, 0) }", nc, "rgb");
}

#[test]
fn type_errors_are_the_interpreters() {
    fails("let f = fn(p) { sin(p.x) }", "rtc::type::mismatch", "p.x");
    fails("let f = fn(p) { p + 1 }", "rtc::type::operator", "1");
    fails(
        "let f = fn(p) { fbm(p, octaves: 40) }",
        "rtc::param::out_of_range",
        "40",
    );
    fails(
        "let f = fn(p) { worley(p, form: \"f3\") }",
        "rtc::texture::choice",
        "\"f3\"",
    );
}

#[test]
fn programs_stay_small() {
    with_f(
        "let f = fn(p) { let a = p.x * 2\nlet b = a + p.y\nlet c = b * b\nc - a }",
        |_, f| {
            let Value::Fn(c) = &f else { panic!() };
            let Ok(program) = super::compile::compile(c) else {
                panic!()
            };
            assert!(program.registers() <= 16, "{}", program.registers());
            assert!(program.ops().len() <= 8, "{:?}", program.ops());
        },
    );
}

#[test]
fn noise_built_ins_are_the_pattern_modules_noises() {
    use crate::pattern::{Fractal, cells, fbm, noise};
    let fractal = Fractal {
        octaves: 3,
        omega: 0.6,
        lambda: 2.5,
    };
    type Noise = fn(DVec3, &Fractal) -> DVec3;
    let cases: [(&str, Noise); 6] = [
        ("noise(p, seed: 7)", |p, _| DVec3::splat(noise::unit(p, 7))),
        ("snoise(p, seed: 7)", |p, _| {
            DVec3::splat(noise::signed(p, 7))
        }),
        ("vnoise(p, seed: 7)", |p, _| noise::vector(p, 7)),
        (
            "fbm(p, octaves: 3, omega: 0.6, lambda: 2.5, seed: 7)",
            |p, f| DVec3::splat(fbm::fbm(p, f, 7)),
        ),
        (
            "turbulence(p, octaves: 3, omega: 0.6, lambda: 2.5, seed: 7)",
            |p, f| DVec3::splat(fbm::turbulence(p, f, 7)),
        ),
        ("worley(p, form: \"edges\", seed: 7)", |p, _| {
            let d = cells::worley(p, 7);
            DVec3::splat(d.f2 - d.f1)
        }),
    ];
    for (call, want) in cases {
        with_f(&format!("let f = fn(p) {{ {call} }}"), |it, f| {
            for p in points() {
                let arg = ArgVal {
                    name: None,
                    value: Value::Vec3(p),
                    span: Span::default(),
                };
                let got = it
                    .call_value(f.clone(), vec![arg], Span::default(), Span::default())
                    .unwrap_or(Value::Unit);
                let got = match got {
                    Value::Vec3(v) => v,
                    other => DVec3::splat(other.as_f64().expect("a number")),
                };
                let want = want(p, &fractal);
                assert_eq!(
                    got.to_array().map(f64::to_bits),
                    want.to_array().map(f64::to_bits),
                    "{call} at {p}"
                );
            }
        });
    }
}

#[test]
fn a_value_that_is_not_finite_reads_as_zero() {
    with_f(
        "let f = fn(p) { sqrt(p.x - 1000) + 1 / (p.y - p.y) }",
        |_, f| {
            let Value::Fn(c) = &f else { panic!() };
            let Ok(program) = super::compile::compile(c) else {
                panic!()
            };
            let p = DVec3::new(1.0, 2.0, 3.0);
            assert!(program.run(p).is_nan());
            assert_eq!(program.eval(p), 0.0);
        },
    );
}
