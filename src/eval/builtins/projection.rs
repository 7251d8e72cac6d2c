//! `camera { projection: .. }`: how the camera's fields size each projection's view, and the
//! rules that keep them meaningful (docs/language.md §18).

use glam::DVec3;
use std::f64::consts::{PI, TAU};

use crate::eval::args::Params;
use crate::eval::error::{R, error, suggest};
use crate::eval::host::Host;
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::Projection;
use crate::num::Norm;
use crate::source::Span;

/// The projections' names, as `projection:` spells them.
const NAMES: [&str; 5] = [
    "perspective",
    "orthographic",
    "equirectangular",
    "fisheye",
    "cylindrical",
];

/// The projection of a `camera { .. }`: its `projection`, `fov` (read as `fov` at `fov_span`),
/// `height` and `aperture` fields checked together; `view` is `center − eye`; `given` says
/// whether `fov` was written and where `aperture` was.
pub(super) fn projection(
    it: &mut dyn Host,
    p: &mut Params,
    course: bool,
    (fov, fov_span): (f64, Span),
    view: DVec3,
    (aperture, given): (f64, (bool, Option<Span>)),
) -> R<Projection> {
    let (fov_given, aperture_span) = given;
    let name = match p.get("projection") {
        None => None,
        Some((Value::Str(s), sp)) => Some((s, sp)),
        Some((other, sp)) => return Err(types::mismatch(it, "String", &other, sp).into()),
    };
    let height = p.float_opt(it, "height")?;
    let conflict = |span: Span, message: String, label: &str, help: &str| {
        Err(error("rtc::camera::conflict", span, message)
            .with_label(label.to_string())
            .with_help(help.to_string())
            .into())
    };
    if course {
        if let Some((_, sp)) = &name {
            return conflict(
                *sp,
                "`projection` and `course: true` both choose the projection".into(),
                "not used by the course camera",
                "remove `projection`, or `course: true`",
            );
        }
        if let Some((_, sp)) = height {
            return conflict(
                sp,
                "`height` sizes an orthographic view, not the course camera".into(),
                "not used by the course camera",
                "remove `height` (`up`'s length sizes the course camera's view)",
            );
        }
        return Ok(Projection::Course);
    }
    let kind = match &name {
        None => "perspective",
        Some((s, sp)) => match NAMES.iter().find(|n| **n == &**s) {
            Some(n) => n,
            None => {
                let list = NAMES.map(|n| format!("\"{n}\"")).join(", ");
                let help = suggest(s, NAMES)
                    .map(|h| format!("{h}; the projections are {list}"))
                    .unwrap_or_else(|| format!("the projections are {list}"));
                return Err(error(
                    "rtc::camera::projection",
                    *sp,
                    format!("there is no \"{s}\" projection"),
                )
                .with_label(format!("one of {list}"))
                .with_help(help)
                .into());
            }
        },
    };
    if let Some((_, sp)) = height
        && kind != "orthographic"
    {
        return conflict(
            sp,
            format!("`height` sizes an orthographic view, not a {kind} one"),
            "only for `projection: \"orthographic\"`",
            "remove `height`, or write `projection: \"orthographic\"`",
        );
    }
    if aperture > 0.0 && !matches!(kind, "perspective" | "orthographic") {
        let sp = aperture_span.unwrap_or(fov_span);
        return conflict(
            sp,
            format!("a {kind} camera has no lens (`aperture` > 0)"),
            "depth of field needs a perspective or orthographic camera",
            "remove `aperture` (a panorama is sharp everywhere)",
        );
    }
    let view_error = |span: Span, message: String, help: &str| {
        Err(error("rtc::camera::view", span, message)
            .with_label("out of range for this projection")
            .with_help(help.to_string())
            .into())
    };
    match kind {
        "perspective" => {
            p.declared_range("fov", fov, fov_span)?;
            Ok(Projection::Perspective { fov_y: fov })
        }
        "orthographic" => {
            let (h, sp) = match height {
                Some(h) => h,
                None => {
                    p.declared_range("fov", fov, fov_span)?;
                    (2.0 * view.norm() * libm::tan(0.5 * fov), fov_span)
                }
            };
            if !(h > 0.0 && h.is_finite()) {
                return view_error(
                    sp,
                    format!("an orthographic view {h} units tall shows nothing"),
                    "give `height` the view's height in world units, e.g. `height: 4`",
                );
            }
            Ok(Projection::Orthographic { height: h })
        }
        "equirectangular" => {
            if fov_given {
                return conflict(
                    fov_span,
                    "an equirectangular panorama always spans 360° × 180°".into(),
                    "not used by the panorama",
                    "remove `fov` (the image's width is 360°, its height 180°)",
                );
            }
            Ok(Projection::Equirectangular)
        }
        _ => {
            let fisheye = kind == "fisheye";
            let angle = match (fov_given, fisheye) {
                (true, _) => fov,
                (false, true) => PI,
                (false, false) => TAU,
            };
            if !(angle > 0.0 && angle <= TAU) {
                return view_error(
                    fov_span,
                    format!(
                        "a {kind} camera's `fov` must be in (0deg, 360deg], not {}deg",
                        crate::eval::value::fmt_f(angle.to_degrees())
                    ),
                    if fisheye {
                        "use e.g. `fov: 180deg` (a hemisphere across the circle)"
                    } else {
                        "use e.g. `fov: 360deg` (all around)"
                    },
                );
            }
            Ok(if fisheye {
                Projection::Fisheye { fov: angle }
            } else {
                Projection::Cylindrical { fov: angle }
            })
        }
    }
}
