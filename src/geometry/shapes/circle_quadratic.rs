//! The ray–circle quadratic shared by spheres and cylinders, in the form that keeps its hits
//! when the ray starts far away.
//!
//! `|p + t·v|² = r²` has the discriminant `(p·v)² − |v|²·(|p|² − r²)`. Formed that way, both
//! terms are ~|p|²·|v|² and their difference, ~r²·|v|², drowns in their rounding once |p|/r
//! reaches ~10⁷ (a sphere seen from 10⁸ radii loses two thirds of its pixels). The same number
//! is `|v|²·(r² − |p⊥|²)`, where `p⊥ = p − (p·v/|v|²)·v` is the line's closest approach to the
//! centre: a vector of the circle's size, computed with an error of a few ulps of |p|, which is
//! the accuracy of the ray's own points (pbrt-v4's spheres and cylinders; "Precision Improvements
//! for Ray/Sphere Intersection", Ray Tracing Gems, ch. 7).

use glam::DVec3;

/// `|v|²` of a ray direction and its reciprocal, which hot callers compute once per ray (the
/// reciprocal turns two divisions per test into multiplications).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DirSquared {
    /// `|v|²`.
    a: f64,
    /// `1 / |v|²`.
    pub(crate) inv: f64,
}

impl DirSquared {
    /// The squared length of `v` and its reciprocal.
    #[inline]
    pub(crate) fn of(v: DVec3) -> DirSquared {
        let a = v.length_squared();
        DirSquared { a, inv: 1.0 / a }
    }
}

/// Both parameters `t` where `p + t·v` lies at distance `r` from the origin, in increasing order
/// (equal for a tangent), or `None` when the line passes farther away. `d` is
/// [`DirSquared::of`]`(v)`; a zero `v` finds nothing.
///
/// `p` and `v` may be projections onto a plane (a cylinder's cross-section): only dot products
/// are used.
#[inline]
pub(crate) fn roots(p: DVec3, v: DVec3, d: DirSquared, r: f64) -> Option<(f64, f64)> {
    let half_b = p.dot(v);
    let closest = p - (half_b * d.inv) * v;
    let rr = r * r;
    let gap = rr - closest.length_squared();
    // NaN comes from a zero or non-finite direction.
    if gap < 0.0 || gap.is_nan() {
        return None;
    }
    Some(roots_past_gap(p, half_b, gap, d, rr))
}

/// The end of [`roots`] once the line is known to meet the circle (`gap ≥ 0`), from its
/// intermediate values `half_b = p·v`, `gap` and `rr = r·r` (shared with the sphere lanes of
/// `crate::geometry::lanes::spheres`, which compute the gap of several spheres at once).
#[inline]
pub(crate) fn roots_past_gap(
    p: DVec3,
    half_b: f64,
    gap: f64,
    d: DirSquared,
    rr: f64,
) -> (f64, f64) {
    // The root whose two terms add (no cancellation) gives the other through the product c/a.
    let q = -half_b - (d.a * gap).sqrt().copysign(half_b);
    if q == 0.0 {
        // A tangent touching at t = 0 (half_b = 0 and disc = 0).
        return (0.0, 0.0);
    }
    let (t0, t1) = (q * d.inv, (p.length_squared() - rr) / q);
    if t0 <= t1 { (t0, t1) } else { (t1, t0) }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots_of(p: DVec3, v: DVec3, r: f64) -> Option<(f64, f64)> {
        roots(p, v, DirSquared::of(v), r)
    }

    #[test]
    fn roots_from_far_away_are_exact_to_the_rays_own_precision() {
        // From 1e8 along +z, passing 0.6 from the centre: hits at 1e8 ∓ 0.8.
        let p = DVec3::new(0.6, 0.0, 1e8);
        let v = DVec3::new(0.0, 0.0, -1.0);
        let (t0, t1) = roots_of(p, v, 1.0).expect("the line passes within the radius");
        let ulp = 1e8 * f64::EPSILON;
        assert!((t0 - (1e8 - 0.8)).abs() <= 2.0 * ulp, "{t0}");
        assert!((t1 - (1e8 + 0.8)).abs() <= 2.0 * ulp, "{t1}");
        // Just outside: 1 + 1e-7 from the centre misses.
        assert!(roots_of(DVec3::new(1.0 + 1e-7, 0.0, 1e8), v, 1.0).is_none());
    }

    #[test]
    fn degenerate_directions_find_nothing() {
        assert!(roots_of(DVec3::ONE, DVec3::ZERO, 1.0).is_none());
        assert!(roots_of(DVec3::ONE, DVec3::splat(f64::NAN), 1.0).is_none());
    }

    #[test]
    fn tangent_at_the_origin_of_the_ray_is_a_double_root_at_zero() {
        let v = DVec3::new(1.0, 0.0, 0.0);
        assert_eq!(
            roots_of(DVec3::new(0.0, 1.0, 0.0), v, 1.0),
            Some((0.0, 0.0))
        );
    }
}
