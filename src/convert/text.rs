//! How values are spelled in the rtc language by `rtc convert`: numbers that read back to the
//! same bits, vectors, colours, angles and strings.

use glam::DVec3;

/// A number the language reads back to exactly `v`: Rust's shortest round-trip digits, in
/// plain or exponent form (whichever is shorter; the language reads `2e-7` as a `Float`), an
/// integral value without a point (an `Int` widens to the same `Float`), and `-0.0` kept
/// negative (`-0` would be the integer 0).
pub(crate) fn number(v: f64) -> String {
    if v == 0.0 {
        return if v.is_sign_negative() { "-0.0" } else { "0" }.to_string();
    }
    let plain = format!("{v}");
    let exp = format!("{v:e}");
    // Integers read best plain, up to 15 digits: longer ones would be `Int` literals past what
    // the number holds exactly (or past i64), so they take the exponent form (a `Float`).
    let integral = !plain.contains('.');
    let long = plain.trim_start_matches('-').len() > 15;
    if (integral && long) || (!integral && exp.len() < plain.len()) {
        exp
    } else {
        plain
    }
}

/// `[x, y, z]`.
pub(crate) fn vector(v: DVec3) -> String {
    format!("[{}, {}, {}]", number(v.x), number(v.y), number(v.z))
}

/// A unit direction the language normalises (`normal:`): the vector whose unit vector is
/// exactly `n`, with the axis constants where it is one.
pub(crate) fn unit_direction(n: DVec3) -> String {
    direction(super::exact::unit_preimage(n))
}

/// A direction, using the axis constants `X`, `Y`, `Z` where `v` is one.
pub(crate) fn direction(v: DVec3) -> String {
    match (v.x, v.y, v.z) {
        (1.0, 0.0, 0.0) if no_negative_zero(v) => "X".into(),
        (0.0, 1.0, 0.0) if no_negative_zero(v) => "Y".into(),
        (0.0, 0.0, 1.0) if no_negative_zero(v) => "Z".into(),
        _ => vector(v),
    }
}

fn no_negative_zero(v: DVec3) -> bool {
    !v.to_array()
        .iter()
        .any(|c| *c == 0.0 && c.is_sign_negative())
}

/// A linear colour: `rgb(v)` for a grey, else `rgb(r, g, b)`.
pub(crate) fn color(c: DVec3) -> String {
    if c.x.to_bits() == c.y.to_bits() && c.y.to_bits() == c.z.to_bits() {
        format!("rgb({})", number(c.x))
    } else {
        format!("rgb({}, {}, {})", number(c.x), number(c.y), number(c.z))
    }
}

/// A string literal: `"` and `\` escaped, and `{` `}` (which would interpolate).
pub(crate) fn string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' | '\\' | '{' | '}' => {
                out.push('\\');
                out.push(c);
            }
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            _ => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A comment line's text as an rtc `//` comment (the course marker `#` and surrounding blanks
/// removed; an empty text gives a bare `//`).
pub(crate) fn comment(text: &str) -> String {
    let t = text.trim();
    if t.is_empty() {
        "//".into()
    } else {
        format!("// {t}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_exactly() {
        for v in [
            0.2,
            0.7,
            64.0,
            -200.0,
            1e-7,
            1.5e-300,
            123456.789,
            1e12,
            0.1 + 0.2,
            -1e20,
            2.5e15,
        ] {
            let s = number(v);
            let back: f64 = s.parse().unwrap();
            assert_eq!(back.to_bits(), v.to_bits(), "{v} written as {s}");
        }
        assert_eq!(number(64.0), "64");
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(1e-7), "1e-7");
        assert_eq!(number(-0.0), "-0.0");
        assert_eq!(number(-1e20), "-1e20");
        assert_eq!(number(1000.0), "1000");
    }

    #[test]
    fn colours_vectors_and_strings() {
        assert_eq!(color(DVec3::new(1.0, 0.8, 0.0)), "rgb(1, 0.8, 0)");
        assert_eq!(color(DVec3::splat(0.4)), "rgb(0.4)");
        assert_eq!(direction(DVec3::Y), "Y");
        assert_eq!(direction(DVec3::new(0.0, 2.0, 0.0)), "[0, 2, 0]");
        assert_eq!(string(r#"a"b\{c}"#), r#""a\"b\\\{c\}""#);
        assert_eq!(comment("  Blue sphere "), "// Blue sphere");
    }
}
