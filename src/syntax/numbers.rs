//! Number literals to values: the one conversion shared by the pest tree builder and the fast
//! statement path, so both read `0.15000000000000002`, `2e6` or `30deg` to the same bits.

use crate::syntax::ast::ExprKind;

/// Why a literal has no value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumberError {
    /// An integer literal past `i64::MAX`.
    IntTooLarge,
    /// A float literal that overflows to infinity.
    TooLarge,
}

/// A plain number `3`, `0.5`, `2e6` (no unit, no sign except the one a vector literal carries):
/// `Int` without `.`, `e` or `E`, `Float` otherwise.
pub fn plain(text: &str) -> Result<ExprKind, NumberError> {
    if !text.bytes().any(|b| matches!(b, b'.' | b'e' | b'E')) {
        return text
            .parse::<i64>()
            .map(ExprKind::Int)
            .map_err(|_| NumberError::IntTooLarge);
    }
    let v = text.parse::<f64>().unwrap_or(f64::NAN);
    if !v.is_finite() {
        return Err(NumberError::TooLarge);
    }
    Ok(ExprKind::Float(v))
}

/// A unit's conversion to radians.
pub type ToRadians = fn(f64) -> f64;

/// Splits a `number` token into its digits and the conversion of its unit to radians
/// (`None` for a plain number).
pub fn split_unit(text: &str) -> (&str, Option<ToRadians>) {
    if let Some(d) = text.strip_suffix("deg").or_else(|| text.strip_suffix('°')) {
        (d, Some(f64::to_radians))
    } else if let Some(d) = text.strip_suffix("rad") {
        (d, Some(|v| v))
    } else if let Some(d) = text.strip_suffix("turn") {
        (d, Some(|v| v * std::f64::consts::TAU))
    } else {
        (text, None)
    }
}

/// The value of a plain number read by [`plain`] with the unit [`split_unit`] found.
pub fn apply_unit(plain: ExprKind, unit: Option<ToRadians>) -> ExprKind {
    match (unit, plain) {
        (Some(to_radians), ExprKind::Int(i)) => ExprKind::Angle(to_radians(i as f64)),
        (Some(to_radians), ExprKind::Float(f)) => ExprKind::Angle(to_radians(f)),
        (_, other) => other,
    }
}

/// A component of a vector literal `[x, y, z]` as the vector stores it.
pub fn component(plain: &ExprKind) -> f64 {
    match *plain {
        ExprKind::Int(i) => i as f64,
        ExprKind::Float(f) => f,
        _ => 0.0,
    }
}
