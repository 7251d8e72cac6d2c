//! Patterns that are distances and angles: gradient, radial, onion, spherical, cylindrical,
//! boxed, planar and the two spirals, after POV-Ray 3.7's definitions.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use glam::DVec3;

use crate::num::Norm;

use super::turbulence::Turbulence;

/// POV-Ray's `CLIP_DENSITY` on a distance `r ≥ 0`: `1 − r` inside the unit, 0 beyond.
#[inline(always)]
fn falloff(r: f64) -> f64 {
    (1.0 - r).max(0.0)
}

/// `gradient axis`: the coordinate `v = p · axis` along the unit vector `axis`, as POV-Ray
/// gives it to the wave: above 1 its remainder modulo 1, otherwise `v` itself (negative values
/// too), in (−∞, 1]. The wave wraps what is left after its frequency and phase, so the colour
/// map reads the fractional coordinate, and at a fractional frequency the same value as
/// POV-Ray's on both sides of 0. POV-Ray normalises the direction it is given, and so does
/// [`super::Pattern::gradient`]; given a longer `axis`, this function reads `p · axis` as it is.
#[inline]
pub fn gradient(p: DVec3, axis: DVec3) -> f64 {
    let v = p.dot(axis);
    if v > 1.0 { v % 1.0 } else { v }
}

/// `radial`: the angle about the y axis as a fraction of a turn, as POV-Ray gives it to the
/// wave: `0.25 + (atan2(x, z) + π) / 2π` in [0.25, 1.25], rising from 0.25 on −z through 0.5
/// on −x, 0.75 on +z and 1 on +x to 1.25 just before −z again (the wave wraps it, so the colour
/// map reads 1 on +x and 0 just past it). Within 0.001 of the axis, where the angle is noise,
/// 0.25 (POV-Ray's rule).
#[inline]
pub fn radial(p: DVec3) -> f64 {
    if p.x.abs() < 0.001 && p.z.abs() < 0.001 {
        return 0.25;
    }
    0.25 + (libm::atan2(p.x, p.z) + PI) / TAU
}

/// `onion`: the fractional part of the distance from the origin, in [0, 1): concentric shells.
#[inline]
pub fn onion(p: DVec3) -> f64 {
    let r = p.norm();
    r - r.floor()
}

/// `spherical`: 1 at the origin falling linearly to 0 at distance 1, 0 beyond.
#[inline]
pub fn spherical(p: DVec3) -> f64 {
    falloff(p.norm())
}

/// `cylindrical`: 1 on the y axis falling linearly to 0 at distance 1 from it, 0 beyond.
#[inline]
pub fn cylindrical(p: DVec3) -> f64 {
    falloff((p.x * p.x + p.z * p.z).sqrt())
}

/// `boxed`: 1 at the origin falling linearly to 0 on the cube |x|, |y|, |z| ≤ 1, 0 outside.
#[inline]
pub fn boxed(p: DVec3) -> f64 {
    falloff(p.x.abs().max(p.y.abs()).max(p.z.abs()))
}

/// `planar`: 1 on the plane y = 0 falling linearly to 0 at |y| = 1, 0 beyond.
#[inline]
pub fn planar(p: DVec3) -> f64 {
    falloff(p.y.abs())
}

/// The spirals' angle about the z axis in [0, 2π): 0 towards −y, π/2 towards +x (POV-Ray's
/// `asin` construction, which is `atan2(y, x) + π/2`); 0 on the axis.
#[inline(always)]
fn spiral_angle(p: DVec3, r: f64) -> f64 {
    if r == 0.0 {
        0.0
    } else {
        (libm::atan2(p.y, p.x) + FRAC_PI_2).rem_euclid(TAU)
    }
}

/// `spiral1 arms`: `z + r + arms·φ/2π + turbulence`, `r` the distance from the z axis and `φ` the
/// angle about it: `arms` spiral arms winding along z. Unbounded (a triangle wave folds it by
/// default).
#[inline]
pub fn spiral1(p: DVec3, arms: f64, turbulence: &Turbulence) -> f64 {
    let r = (p.x * p.x + p.y * p.y).sqrt();
    p.z + r + arms * spiral_angle(p, r) / TAU + turbulence.scalar(p)
}

/// `spiral2 arms`: `triangle(r) + triangle(spiral1)`, two spirals winding opposite ways
/// crossed; in [0, 2] (a triangle wave folds it by default).
#[inline]
pub fn spiral2(p: DVec3, arms: f64, turbulence: &Turbulence) -> f64 {
    let r = (p.x * p.x + p.y * p.y).sqrt();
    let along = p.z + r + arms * spiral_angle(p, r) / TAU + turbulence.scalar(p);
    triangle(r) + triangle(along)
}

/// POV-Ray's `Triangle_Wave`: 0 at whole numbers, 1 halfway between, linear in between.
#[inline(always)]
pub fn triangle(v: f64) -> f64 {
    let f = v - v.floor();
    if f < 0.5 { 2.0 * f } else { 2.0 * (1.0 - f) }
}
