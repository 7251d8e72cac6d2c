//! Why a shape cannot be drawn: the diagnostic codes every front end shares, the flaw that
//! names the parameter to blame, and the range checks the shape rules are written with.

use glam::DVec3;

use crate::diag::{Diagnostic, number};
use crate::source::Span;

/// Code of a shape number outside its range.
pub(crate) const OUT_OF_RANGE: &str = "rtc::param::out_of_range";
/// Code of a shape with no surface.
pub(crate) const DEGENERATE: &str = "rtc::param::degenerate";
/// Code of a polygon whose points are not in one plane.
pub(crate) const NOT_PLANAR: &str = "rtc::param::not_planar";
/// Code of a prism outline that does not come back to its start.
pub(crate) const NOT_CLOSED: &str = "rtc::param::not_closed";
/// Code of a CSG node with fewer than two operands.
pub(crate) const CSG_OPERANDS: &str = "rtc::csg::operands";

/// Why a shape cannot be drawn, and which of its parameters to blame.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ShapeFlaw {
    /// The parameter at fault, by its name in the language (`radius`, `max`, `points`...).
    pub(crate) param: &'static str,
    /// What is wrong with it.
    kind: FlawKind,
}

/// The two kinds of flaw: a number outside its range, or anything else.
#[derive(Clone, Debug, PartialEq)]
enum FlawKind {
    /// `param` must be `rule` (such as `> 0`) but is `value` (code [`OUT_OF_RANGE`]).
    Range {
        /// The rule, written after "must be".
        rule: String,
        /// The offending value.
        value: f64,
    },
    /// A flaw described in words.
    Other {
        /// The diagnostic code.
        code: &'static str,
        /// The title.
        message: String,
        /// The label on the parameter.
        label: String,
        /// One concrete fix.
        help: String,
    },
}

impl ShapeFlaw {
    pub(super) fn range(param: &'static str, rule: impl Into<String>, value: f64) -> ShapeFlaw {
        ShapeFlaw {
            param,
            kind: FlawKind::Range {
                rule: rule.into(),
                value,
            },
        }
    }

    pub(super) fn other(
        param: &'static str,
        code: &'static str,
        message: impl Into<String>,
        label: impl Into<String>,
        help: impl Into<String>,
    ) -> ShapeFlaw {
        ShapeFlaw {
            param,
            kind: FlawKind::Other {
                code,
                message: message.into(),
                label: label.into(),
                help: help.into(),
            },
        }
    }

    pub(super) fn degenerate(
        param: &'static str,
        message: &str,
        label: &str,
        help: &str,
    ) -> ShapeFlaw {
        ShapeFlaw::other(param, DEGENERATE, message, label, help)
    }

    /// The diagnostic, with its primary span on `span` (the parameter's, where known).
    pub(crate) fn diagnostic(&self, span: Span) -> Diagnostic {
        match &self.kind {
            FlawKind::Range { rule, value } => {
                let shown = number(*value);
                Diagnostic::error(
                    OUT_OF_RANGE,
                    span,
                    format!("`{}` must be {rule}, but it is {shown}", self.param),
                )
                .with_label(format!("evaluates to {shown}"))
                .with_help(format!("use a value that is {rule}"))
            }
            FlawKind::Other {
                code,
                message,
                label,
                help,
            } => Diagnostic::error(code, span, message.clone())
                .with_label(label.clone())
                .with_help(help.clone()),
        }
    }
}

/// A point as the language writes it.
pub(super) fn vec3(v: DVec3) -> String {
    format!("[{}, {}, {}]", number(v.x), number(v.y), number(v.z))
}

/// `Ok` when `v` satisfies `ok` and is finite, else the range flaw.
pub(super) fn in_range(ok: bool, param: &'static str, rule: &str, v: f64) -> Result<(), ShapeFlaw> {
    if ok && v.is_finite() {
        Ok(())
    } else {
        Err(ShapeFlaw::range(param, rule, v))
    }
}

/// `Ok` for a finite positive `v`.
pub(super) fn positive(param: &'static str, v: f64) -> Result<(), ShapeFlaw> {
    in_range(v > 0.0, param, "> 0", v)
}

/// `Ok` when every point is finite.
pub(super) fn finite(param: &'static str, points: &[DVec3]) -> Result<(), ShapeFlaw> {
    if points.iter().all(|p| p.is_finite()) {
        Ok(())
    } else {
        Err(ShapeFlaw::other(
            param,
            OUT_OF_RANGE,
            format!("`{param}` is not a finite point"),
            "a coordinate is infinite or not a number",
            "use finite coordinates",
        ))
    }
}
