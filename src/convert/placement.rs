//! How an object is placed and how it moves, as transform methods and `.moving(...)` whose
//! composition in the language gives back the IR's numbers.

use glam::{DAffine3, DMat3, DQuat, DVec3};

use super::exact;
use super::text::{number, vector};
use crate::ir::Motion;

/// The methods that place an object and give its motion, in application order.
pub(crate) fn methods(transform: &DAffine3, motion: Option<&Motion>) -> Vec<String> {
    let Some(m) = motion else {
        return placement(transform);
    };
    let moving = moving(m);
    let frame = m.frame;
    // The motion given after the placement (its frame is the identity), before it (its frame is
    // the placement), or between the part of the placement before it and the part after.
    let (before, after) = if frame == DAffine3::IDENTITY {
        (placement(transform), Vec::new())
    } else if frame == *transform {
        (Vec::new(), placement(transform))
    } else {
        (split(transform, &frame), placement(&frame))
    };
    before
        .into_iter()
        .chain(std::iter::once(moving))
        .chain(after)
        .collect()
}

/// The methods that place an object, read in application order: a per-axis `.scale` when the linear part is diagonal, else `.matrix` of it, then `.translate`.
/// Each reproduces the transform's numbers exactly (the language composes them as products
/// with 0 and 1).
fn placement(t: &DAffine3) -> Vec<String> {
    placed(t).into_iter().map(|(s, _)| s).collect()
}

/// [`placement`]'s methods, each with the transform the language makes of it.
fn placed(t: &DAffine3) -> Vec<(String, DAffine3)> {
    let mut out = Vec::new();
    let m = t.matrix3;
    if m != DMat3::IDENTITY {
        let d = DVec3::new(m.x_axis.x, m.y_axis.y, m.z_axis.z);
        if m == DMat3::from_diagonal(d) {
            let text = if d.x == d.y && d.y == d.z {
                format!(".scale({})", number(d.x))
            } else {
                format!(".scale({})", vector(d))
            };
            out.push((text, DAffine3::from_scale(d)));
        } else {
            out.push((format!(".matrix({})", rows(&m)), DAffine3::from_mat3(m)));
        }
    }
    if t.translation != DVec3::ZERO {
        out.push((
            format!(".translate({})", vector(t.translation)),
            DAffine3::from_translation(t.translation),
        ));
    }
    out
}

/// The placement `a` to write before `.moving` so that the placement `frame` written after it
/// composes to exactly `t`: `frame⁻¹ · t`, or where that misses by rounding, the same with
/// every number rounded to 12 significant digits (a `scale(2)` that the inverse turned into
/// 1.9999999999999998).
fn split(t: &DAffine3, frame: &DAffine3) -> Vec<String> {
    let exact = frame.inverse() * *t;
    let snap = |x: f64| format!("{x:.11e}").parse::<f64>().unwrap_or(x);
    let cells = exact.to_cols_array().map(snap);
    let snapped = DAffine3::from_cols_array(&cells);
    let composes = |a: &DAffine3| {
        let methods: Vec<_> = placed(a).into_iter().chain(placed(frame)).collect();
        composed(&methods) == *t
    };
    let a = if !composes(&exact) && composes(&snapped) {
        snapped
    } else {
        exact
    };
    placement(&a)
}

/// What the language makes of methods applied one after another (each multiplies from the
/// left).
fn composed(methods: &[(String, DAffine3)]) -> DAffine3 {
    methods.iter().fold(DAffine3::IDENTITY, |x, (_, t)| *t * x)
}

/// A linear map as the rows of `matrix([...])`.
fn rows(m: &DMat3) -> String {
    let row = |i: usize| {
        let r = m.row(i);
        format!("[{}, {}, {}, 0]", number(r.x), number(r.y), number(r.z))
    };
    format!("[{}, {}, {}]", row(0), row(1), row(2))
}

/// `.moving(...)` with the arguments that give back `m`'s translation, rotation, scale and spin.
fn moving(m: &Motion) -> String {
    let mut args = Vec::new();
    if m.translate != DVec3::ZERO {
        args.push(format!("translate: {}", vector(m.translate)));
    }
    if m.rotate != DQuat::IDENTITY {
        args.push(format!(
            "rotate: matrix({})",
            rows(&exact::rotation_preimage(m.rotate))
        ));
    }
    if m.scale != DVec3::ONE {
        let s = m.scale;
        if s.x == s.y && s.y == s.z {
            args.push(format!("scale: {}", number(s.x)));
        } else {
            args.push(format!("scale: {}", vector(s)));
        }
    }
    if m.spin != DVec3::ZERO {
        let (axis, angle) = exact::spin_preimage(m.spin);
        args.push(format!(
            "spin: {}rad, axis: {}",
            number(angle),
            vector(axis)
        ));
    }
    format!(".moving({})", args.join(", "))
}
