//! Number literals to values: the one conversion shared by the pest tree builder and the fast
//! statement path, so both read `0.15000000000000002`, `2e6` or `30deg` to the same bits.

use crate::syntax::ast::ExprKind;

/// Why a literal has no value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum NumberError {
    /// An integer literal past `i64::MAX`.
    IntTooLarge,
    /// A float literal that overflows to infinity.
    TooLarge,
}

/// A number literal's value: the number leaves of [`ExprKind`], without its drop glue (the fast
/// path converts four numbers a line).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Number {
    /// An integer.
    Int(i64),
    /// A float.
    Float(f64),
    /// An angle, in radians.
    Angle(f64),
}

impl From<Number> for ExprKind {
    fn from(n: Number) -> ExprKind {
        match n {
            Number::Int(i) => ExprKind::Int(i),
            Number::Float(f) => ExprKind::Float(f),
            Number::Angle(a) => ExprKind::Angle(a),
        }
    }
}

/// A plain number `3`, `0.5`, `2e6` (no unit, no sign except the one a vector literal carries):
/// `Int` without `.`, `e` or `E`, `Float` otherwise.
pub(crate) fn plain(text: &str) -> Result<Number, NumberError> {
    match quick(text) {
        Quick::Int(i) => return Ok(Number::Int(i)),
        Quick::Float(v) => return Ok(Number::Float(v)),
        Quick::Slow => {}
    }
    if !text.bytes().any(|b| matches!(b, b'.' | b'e' | b'E')) {
        return text
            .parse::<i64>()
            .map(Number::Int)
            .map_err(|_| NumberError::IntTooLarge);
    }
    let v = text.parse::<f64>().unwrap_or(f64::NAN);
    if !v.is_finite() {
        return Err(NumberError::TooLarge);
    }
    Ok(Number::Float(v))
}

/// What one pass over a number's bytes could tell.
enum Quick {
    Int(i64),
    Float(f64),
    /// Not of the quick forms: convert with the standard library.
    Slow,
}

/// Powers of ten that are exact doubles (10²² is the largest).
const EXACT_POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// `[-]digits` of at most 18 digits (an exact `i64`), or `[-]digits.digits` (no exponent) of at
/// most 18 digits: see [`signed`]. [`Quick::Slow`] for anything else.
fn quick(text: &str) -> Quick {
    match signed(text.as_bytes()) {
        Some((len, Some(Number::Int(i)))) if len == text.len() => Quick::Int(i),
        Some((len, Some(Number::Float(v)))) if len == text.len() => Quick::Float(v),
        _ => Quick::Slow,
    }
}

/// The grammar's number without its unit, with an optional `-` (a vector literal's component),
/// at the start of `bytes`: see [`unsigned`].
pub(crate) fn signed(bytes: &[u8]) -> Option<(usize, Option<Number>)> {
    let Some(rest) = bytes.strip_prefix(b"-") else {
        return unsigned(bytes);
    };
    let (len, value) = unsigned(rest)?;
    let negated = value.map(|n| match n {
        Number::Int(i) => Number::Int(-i),
        Number::Float(v) => Number::Float(-v),
        Number::Angle(a) => Number::Angle(-a),
    });
    Some((len + 1, negated))
}

/// The grammar's unsigned number without its unit (`digits ("." digits)? (("e" | "E") ("+" |
/// "-")? digits)?`) at the start of `bytes`: its length, and in the same pass its value when
/// it is one of the quick forms (otherwise `None`: [`plain`] converts it with the standard
/// library). `None` when no such token starts there.
///
/// The quick forms: at most 18 digits without `.` or exponent (an exact `i64`), or
/// `digits.digits` of at most 19 bytes, whose value is `m / 10^k`: when `m ≤ 2⁵³` and `k ≤ 22`,
/// `m` and `10^k` are exact doubles and one IEEE division rounds their quotient correctly
/// (Clinger's fast path), otherwise [`quotient_rounded`] divides exactly. The same bits as
/// `str::parse` for a fraction of its cost (a generated file is mostly such numbers).
pub(crate) fn unsigned(bytes: &[u8]) -> Option<(usize, Option<Number>)> {
    // Wrapping: the mantissa is used only when at most 19 digits were read, which fit.
    let mut mantissa: u64 = 0;
    let digits = |from: usize, m: &mut u64| {
        let mut i = from;
        while let Some(&b) = bytes.get(i).filter(|b| b.is_ascii_digit()) {
            *m = m.wrapping_mul(10).wrapping_add(u64::from(b - b'0'));
            i += 1;
        }
        i
    };
    let mut end = digits(0, &mut mantissa);
    if end == 0 {
        return None;
    }
    let mut fraction_digits = None;
    if bytes.get(end) == Some(&b'.') {
        let after = digits(end + 1, &mut mantissa);
        if after == end + 1 {
            return None;
        }
        fraction_digits = Some(after - end - 1);
        end = after;
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        end += 1;
        if matches!(bytes.get(end), Some(b'+' | b'-')) {
            end += 1;
        }
        let after = digits(end, &mut 0);
        if after == end {
            return None;
        }
        return Some((after, None));
    }
    let value = match fraction_digits {
        None if end <= 18 => Some(Number::Int(mantissa as i64)),
        Some(k) if end <= 19 => Some(Number::Float(
            if mantissa <= 1 << 53 && k < EXACT_POWERS_OF_TEN.len() {
                mantissa as f64 / EXACT_POWERS_OF_TEN[k]
            } else {
                // The 17-digit numbers that shortest round-trip printing (Python's `repr`,
                // Rust's `{:?}`) writes, such as 0.15000000000000002.
                quotient_rounded(mantissa, 10u64.pow(k as u32))
            },
        )),
        _ => None,
    };
    Some((end, value))
}

/// `m / d` rounded to the nearest double (ties to even), by long division in 128 bits: the
/// quotient is taken to at least 55 bits, and the remainder decides the last one. Exact for
/// every `m` and every `d ≥ 1` below 2⁶⁴ (the value then lies far inside the normal range).
fn quotient_rounded(m: u64, d: u64) -> f64 {
    if m == 0 {
        return 0.0;
    }
    let (bits_m, bits_d) = (64 - m.leading_zeros(), 64 - d.leading_zeros());
    // `m·2^shift / d > 2^54`, and `m·2^shift < 2^119` fits.
    let shift = (55 + bits_d).saturating_sub(bits_m);
    let scaled = u128::from(m) << shift;
    let (q, r) = (scaled / u128::from(d), scaled % u128::from(d));
    let drop = 128 - q.leading_zeros() - 53;
    let (mut kept, rest, half) = (q >> drop, q & ((1 << drop) - 1), 1u128 << (drop - 1));
    if rest > half || (rest == half && (r != 0 || kept & 1 == 1)) {
        kept += 1;
    }
    // `kept ≤ 2^53` is exact, and so is scaling it by a power of two in this range.
    let exponent = i64::from(drop) - i64::from(shift);
    kept as f64 * f64::from_bits(((1023 + exponent) as u64) << 52)
}

/// A unit's conversion to radians.
type ToRadians = fn(f64) -> f64;

/// The units a number may carry and their conversions to radians.
const UNITS: [(&str, ToRadians); 4] = [
    ("deg", f64::to_radians),
    ("°", f64::to_radians),
    ("rad", |v| v),
    ("turn", |v| v * std::f64::consts::TAU),
];

/// Splits a `number` token into its digits and the conversion of its unit to radians
/// (`None` for a plain number).
pub(crate) fn split_unit(text: &str) -> (&str, Option<ToRadians>) {
    UNITS
        .iter()
        .find_map(|&(u, f)| Some((text.strip_suffix(u)?, Some(f))))
        .unwrap_or((text, None))
}

/// The unit that `rest` (the text after a number's digits) starts with: its length in bytes and
/// its conversion to radians.
pub(crate) fn unit_at(rest: &[u8]) -> Option<(usize, ToRadians)> {
    UNITS
        .iter()
        .find(|(u, _)| rest.starts_with(u.as_bytes()))
        .map(|&(u, f)| (u.len(), f))
}

/// The value of a plain number read by [`plain`] with the unit [`split_unit`] found.
pub(crate) fn apply_unit(plain: Number, unit: Option<ToRadians>) -> Number {
    match (unit, plain) {
        (Some(to_radians), Number::Int(i)) => Number::Angle(to_radians(i as f64)),
        (Some(to_radians), Number::Float(f)) => Number::Angle(to_radians(f)),
        (_, other) => other,
    }
}

/// A component of a vector literal `[x, y, z]` as the vector stores it.
pub(crate) fn component(plain: Number) -> f64 {
    match plain {
        Number::Int(i) => i as f64,
        Number::Float(f) | Number::Angle(f) => f,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A seeded 64-bit LCG's top 53 bits: reproducible generated digits.
    fn lcg(seed: u64) -> impl FnMut() -> u64 {
        let mut seed = seed;
        move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 11
        }
    }

    /// The fast path gives `str::parse`'s bits (the reference) wherever it answers, on
    /// generated decimals of every length and on the edges of its range.
    #[test]
    fn exact_decimals_match_the_standard_parser() {
        let mut next = lcg(7);
        let mut texts: Vec<String> = [
            "0.0",
            "-0.0",
            "0.1",
            "0.15000000000000002",
            "-19.6",
            "9007199254740992.0",
            "9007199254740993.0",
            "0.9007199254740993",
            "1.0000000000000000000001",
            "0.0000000000000000000001",
            "0.00000000000000000000001",
            "123456789.123456789",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        for _ in 0..20_000 {
            let int_digits = 1 + next() % 12;
            let frac_digits = 1 + next() % 14;
            let int: String = (0..int_digits)
                .map(|_| char::from(b'0' + (next() % 10) as u8))
                .collect();
            let frac: String = (0..frac_digits)
                .map(|_| char::from(b'0' + (next() % 10) as u8))
                .collect();
            let sign = if next().is_multiple_of(2) { "-" } else { "" };
            texts.push(format!("{sign}{int}.{frac}"));
        }
        let mut answered = 0;
        for t in &texts {
            if let Quick::Float(v) = quick(t) {
                answered += 1;
                assert_eq!(v.to_bits(), t.parse::<f64>().unwrap().to_bits(), "{t}");
            }
            let Number::Float(v) = plain(t).unwrap() else {
                panic!("{t} is a float")
            };
            assert_eq!(v.to_bits(), t.parse::<f64>().unwrap().to_bits(), "{t}");
        }
        // The fast path must actually be taken on typical numbers, or it is dead code.
        assert!(answered > texts.len() / 2, "{answered} of {}", texts.len());
        assert!(matches!(quick("12345678901234567.89"), Quick::Slow));
        assert!(matches!(quick("1e5"), Quick::Slow));
    }

    /// The long division gives the standard parser's bits (the reference) on numbers of 15 to
    /// 18 digits with every position of the point, halfway cases included.
    #[test]
    fn long_division_matches_the_standard_parser() {
        let mut next = lcg(11);
        let mut texts = vec![
            "0.15000000000000002".to_string(),
            "1.2000000000000002".to_string(),
            "9007199254740993.0".to_string(), // 2^53 + 1: a tie, to even
            "9007199254740995.0".to_string(), // a tie, to even (up)
            "18014398509481985.0".to_string(),
            "0.000000000000000001".to_string(),
            "999999999999999999.".to_string() + "0",
        ];
        for _ in 0..50_000 {
            let digits = 15 + (next() % 4) as usize;
            let all: String = (0..digits)
                .map(|_| char::from(b'0' + (next() % 10) as u8))
                .collect();
            let point = 1 + (next() as usize) % (digits - 1);
            texts.push(format!("{}.{}", &all[..point], &all[point..]));
        }
        let mut long = 0;
        for t in &texts {
            let want = t.parse::<f64>().unwrap();
            let Quick::Float(v) = quick(t) else {
                assert!(t.len() > 19, "{t} should be read quickly");
                continue;
            };
            long += usize::from(t.len() > 17);
            assert_eq!(v.to_bits(), want.to_bits(), "{t}: {v} != {want}");
        }
        assert!(long > 10_000, "only {long} numbers took the long division");
    }

    /// Integers read quickly are the standard parser's, up to the edges of `i64`, and numbers
    /// too large for a value have none.
    #[test]
    fn integers_and_overflows_agree_with_the_standard_parser() {
        for t in [
            "0",
            "-0",
            "7",
            "-7",
            "999999999999999999",
            "-999999999999999999",
            "9223372036854775807",
            "9223372036854775808",
            "-9223372036854775808",
            "99999999999999999999999",
            "1e308",
            "1e309",
            "1.5e-400",
            "2E6",
        ] {
            // (is an integer, bits): ExprKind has no equality.
            let want = if t.contains(['.', 'e', 'E']) {
                t.parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .map(|v| (false, v.to_bits()))
            } else {
                t.parse::<i64>().ok().map(|i| (true, i as u64))
            };
            let got = match plain(t) {
                Ok(Number::Int(i)) => Some((true, i as u64)),
                Ok(Number::Float(v)) => Some((false, v.to_bits())),
                Ok(_) => panic!("{t}: a plain number has no unit"),
                Err(_) => None,
            };
            assert_eq!(got, want, "{t}");
        }
        let long_float = format!("{}.5", "9".repeat(320));
        assert!(plain(&long_float).is_err(), "10^320 overflows");
    }
}
