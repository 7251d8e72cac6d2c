//! Bicubic Bézier patches: `bicubic_patch(points)` (POV-Ray's `bicubic_patch`;
//! docs/language.md). A surface: CSG takes none.

use glam::DVec3;

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::{R, error};
use crate::eval::host::Host;
use crate::eval::schema::{Group, Param, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::Shape;
use crate::source::Span;

use super::common::checked;

/// `bicubic_patch(points)`.
pub(super) static BICUBIC_PATCH: Sig = Sig::new(
    "bicubic_patch",
    Group::Shape,
    "A bicubic Bézier patch (POV-Ray's `bicubic_patch`): a curved surface through its four \
     corner points, shaped by the other twelve; traced exactly, not tessellated. \
     uv: u along a row, v across the rows.",
    &[Param::new(
        "points",
        Ty::ListOf(&Ty::ListOf(&Ty::Vec3)),
        "4 rows of 4 control points, in POV-Ray's order (the corners are the first and last \
         points of the first and last rows)",
    )
    .unit(Unit::Length)],
    "Object",
)
.examples(&[
    "bicubic_patch(points: [[[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], [[0, 0, 1], [1, 2, 1], [2, 2, 1], [3, 0, 1]], [[0, 0, 2], [1, 2, 2], [2, 2, 2], [3, 0, 2]], [[0, 0, 3], [1, 0, 3], [2, 0, 3], [3, 0, 3]]])",
]);

/// Makes a patch from its 4 × 4 control points.
pub(super) fn bicubic_patch(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &BICUBIC_PATCH, a)?;
    let (v, ps) = p.req("points")?;
    let rows = list(it, &v, ps)?;
    let mut points = [[DVec3::ZERO; 4]; 4];
    if rows.len() != 4 {
        let found = if rows.len() == 16 {
            "16 items in one list: POV-Ray's flat order, not 4 rows".to_owned()
        } else {
            format!("{} rows", rows.len())
        };
        return Err(grid_error(ps, found).into());
    }
    for (i, row) in rows.iter().enumerate() {
        let Value::List(row) = row else {
            let found = format!(
                "row {} is a `{}`, not a list of 4 points",
                i + 1,
                row.type_name()
            );
            return Err(grid_error(ps, found).into());
        };
        if row.len() != 4 {
            return Err(grid_error(ps, format!("row {} has {} points", i + 1, row.len())).into());
        }
        for (k, x) in row.iter().enumerate() {
            points[i][k] = types::vec3(it, x, ps)?;
        }
    }
    checked(
        Shape::BicubicPatch {
            points: Box::new(points),
        },
        s,
        &[("points", ps)],
    )
}

/// The items of a list value.
fn list(it: &dyn Host, v: &Value, span: Span) -> R<Vec<Value>> {
    match v {
        Value::List(items) => Ok(items.to_vec()),
        other => Err(types::mismatch(it, "List", other, span).into()),
    }
}

/// `rtc::bicubic::points`: the control points are not 4 rows of 4.
fn grid_error(span: Span, found: String) -> crate::diag::Diagnostic {
    error(
        "rtc::bicubic::points",
        span,
        "a bicubic patch needs 4 rows of 4 control points",
    )
    .with_label(found)
    .with_help(
        "write `points: [[p00, p01, p02, p03], [p10, ..], [p20, ..], [p30, .., p33]]`, \
         the corners first and last in the first and last rows",
    )
}
