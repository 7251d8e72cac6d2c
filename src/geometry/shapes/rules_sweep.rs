//! The rules of the swept shapes, `sor` and `sphere_sweep` (POV-Ray's): which points they
//! accept, each flaw naming the parameter to blame.

use glam::DVec3;

use crate::diag::number;
use crate::ir::SweepSpline;

use super::flaw::{finite, in_range, positive};
use super::sor::Sor;
use super::sphere_sweep::SphereSweep;
use super::{Leaf, OUT_OF_RANGE, ShapeFlaw};

/// A surface of revolution's rules (POV-Ray's): at least four finite points with `r >= 0`,
/// heights increasing from the second point to the last but one, and the steering points'
/// heights apart from the heights two along.
pub(super) fn sor(points: &[[f64; 2]], open: bool) -> Result<Leaf, ShapeFlaw> {
    let n = points.len();
    if n < 4 {
        return Err(ShapeFlaw::other(
            "points",
            OUT_OF_RANGE,
            format!("a sor needs at least 4 points (the first and last only steer), found {n}"),
            format!("{n} points"),
            "add a steering point before the first and after the last point of the profile",
        ));
    }
    for p in points {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return Err(ShapeFlaw::other(
                "points",
                OUT_OF_RANGE,
                "a sor point is not finite",
                "a coordinate is infinite or not a number",
                "use finite `[r, y]` pairs",
            ));
        }
        in_range(
            p[0] >= 0.0,
            "points",
            "r >= 0 (the profile is right of the axis)",
            p[0],
        )?;
    }
    if let Some(k) = (2..n - 1).find(|&k| points[k][1] <= points[k - 1][1]) {
        return Err(ShapeFlaw::other(
            "points",
            OUT_OF_RANGE,
            "a sor's heights must increase from its second point to its last but one",
            format!(
                "point {} is at height {}, point {} at {}",
                k,
                number(points[k - 1][1]),
                k + 1,
                number(points[k][1])
            ),
            "list the points from bottom to top, each higher than the one before (a profile \
             that turns back down is a `lathe`)",
        ));
    }
    for (a, b) in [(0, 2), (n - 3, n - 1)] {
        if points[a][1] == points[b][1] {
            return Err(ShapeFlaw::other(
                "points",
                OUT_OF_RANGE,
                "a sor's steering point is level with the point two along",
                format!(
                    "points {} and {} are both at height {}",
                    a + 1,
                    b + 1,
                    number(points[a][1])
                ),
                "move the steering point below the second point (or above the last but one)",
            ));
        }
    }
    Ok(Leaf::Sor(Box::new(Sor::new(points, open).ok_or_else(
        || {
            ShapeFlaw::degenerate(
                "points",
                "the sor has no extent",
                "every radius is 0 (or too large to square)",
                "give the profile points a radius above 0, e.g. `[[0, -1], [1, 0], [1, 1], [0, 2]]`",
            )
        },
    )?)))
}

/// A sphere sweep's rules: enough spheres for the spline, each finite with a radius above 0.
pub(super) fn sphere_sweep(
    spline: SweepSpline,
    spheres: &[(DVec3, f64)],
) -> Result<Leaf, ShapeFlaw> {
    let least = spline.min_spheres();
    if spheres.len() < least {
        return Err(ShapeFlaw::other(
            "points",
            OUT_OF_RANGE,
            format!(
                "a `{}` sphere sweep needs at least {least} points, found {}",
                spline.name(),
                spheres.len()
            ),
            format!("{} points", spheres.len()),
            if spline == SweepSpline::Linear {
                "give two or more points, with a radius each".to_owned()
            } else {
                format!(
                    "give at least {least} points (a `{}` sweep's first and last only steer)",
                    spline.name()
                )
            },
        ));
    }
    for (c, r) in spheres {
        finite("points", &[*c])?;
        positive("radii", *r)?;
    }
    Ok(Leaf::SphereSweep(Box::new(
        SphereSweep::new(spheres, spline)
            .ok_or_else(|| ShapeFlaw::range("points", "finite", f64::INFINITY))?,
    )))
}
