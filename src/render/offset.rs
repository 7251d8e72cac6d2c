//! Where spawned rays start, as pbrt-v4 does it (`OffsetRayOrigin`, `SpawnRay`, `SpawnRayTo`).
//!
//! A hit point is only known to lie within its error box (`SurfaceHit::error`, a per-axis bound
//! the shape computed from its own arithmetic and every transform widened). A ray leaving the
//! surface starts just outside that box, along the geometric normal on the side it travels to,
//! and the start is rounded away from the surface: it cannot re-hit the surface it leaves, yet
//! the offset is as small as the point's own uncertainty — ~1e-16 of the coordinates, never a
//! fraction of the scene's size or a fixed epsilon. A ray towards a point (a light) is aimed from
//! that start, so its line passes through the target.

use glam::DVec3;

use crate::geometry::SurfaceHit;
use crate::geometry::rounding::gamma;

/// A surface point rays can leave from: the point, its per-axis error bound and the surface's
/// geometric normal (either orientation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpawnPoint {
    /// The point as the object computed it.
    pub point: DVec3,
    /// Per-axis bound on its distance from the true surface.
    pub error: DVec3,
    /// Unit geometric normal.
    pub normal: DVec3,
}

/// How far short of its target a shadow ray stops, in units of the coordinates' magnitude: a
/// surface through the target (a light lying on a floor) is found at the target's distance up
/// to the rounding of that intersection, a few ε·(|origin| + |target|) / cos θ for a surface at
/// incidence θ; 2¹⁰ ε covers incidence down to cos θ ≈ 1/100.
const SHADOW_ROUNDING_STEPS: u32 = 1024;

impl SpawnPoint {
    /// Where rays leave the surface of `hit`.
    #[inline(always)]
    pub fn of(hit: &SurfaceHit) -> SpawnPoint {
        SpawnPoint {
            point: hit.surface_point,
            error: hit.error,
            normal: hit.geometric_normal,
        }
    }

    /// The origin of a ray leaving along `dir`: outside the error box on `dir`'s side, rounded
    /// away from the surface. Inlined: called out of line, its vector loads of `dir` and of the
    /// point just stored by the caller stalled on store forwarding (~6% of scene A's time).
    #[inline(always)]
    pub fn origin_towards(&self, dir: DVec3) -> DVec3 {
        let n = if dir.dot(self.normal) < 0.0 {
            -self.normal
        } else {
            self.normal
        };
        let d = n.abs().dot(self.error);
        let o = self.point + d * n;
        // Rounded away from the surface (by the normal's signs, so a point known exactly still
        // leaves its surface by one step).
        DVec3::new(away(o.x, n.x), away(o.y, n.y), away(o.z, n.z))
    }

    /// A ray leaving the surface along unit `dir` (reflection, refraction).
    #[inline]
    pub fn ray(&self, dir: DVec3) -> crate::geometry::Ray {
        crate::geometry::Ray::new(self.origin_towards(dir), dir)
    }

    /// A ray from the surface towards `target` (a light sample), re-aimed from its offset
    /// origin, with the parameter where it must stop short of the target; `None` when the
    /// target is the origin itself.
    #[inline(always)]
    pub fn ray_to(&self, target: DVec3) -> Option<(crate::geometry::Ray, f64)> {
        let origin = self.origin_towards(target - self.point);
        let d = target - origin;
        let dist = d.length();
        if dist.is_nan() || dist <= 0.0 || dist.is_infinite() {
            return None;
        }
        Some((
            crate::geometry::Ray::new(origin, d / dist),
            dist - shadow_margin(origin, target, dist),
        ))
    }
}

/// `x.next_up()` when `s > 0`, `x.next_down()` when `s < 0`, else `x`, bit for bit; without a
/// branch on either sign for finite non-zero `x`. Why: the signs of a hit's normal are random
/// from one ray to the next, and the mispredicted branches of the plain `if`s made
/// `origin_towards` ~9% of scene A's time.
#[inline(always)]
fn away(x: f64, s: f64) -> f64 {
    let a = x.abs();
    if !(a > 0.0 && a < f64::INFINITY) {
        return away_rare(x, s);
    }
    // +1 towards +∞, −1 towards −∞, 0 to stay (NaN compares false both ways).
    let dir = i64::from(s > 0.0) - i64::from(s < 0.0);
    // A finite non-zero float's neighbour towards +∞ is one more bit pattern when it is
    // positive and one less when it is negative (past f64::MAX it is ∞, as next_up gives).
    let sign = 1 - 2 * (x.to_bits() >> 63) as i64;
    f64::from_bits(x.to_bits().wrapping_add((dir * sign) as u64))
}

/// [`away`] of zeros, infinities and NaN, as the standard library steps them (out of line, so
/// the common case stays small enough to inline).
#[cold]
#[inline(never)]
fn away_rare(x: f64, s: f64) -> f64 {
    if s > 0.0 {
        x.next_up()
    } else if s < 0.0 {
        x.next_down()
    } else {
        x
    }
}

/// How far short of `target` a visibility ray from `origin` (at distance `dist`) stops, so a
/// surface through the target does not count as blocking it.
pub fn shadow_margin(origin: DVec3, target: DVec3, dist: f64) -> f64 {
    gamma(SHADOW_ROUNDING_STEPS) * (origin.abs().max_element() + target.abs().max_element() + dist)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(point: DVec3, error: f64, normal: DVec3) -> SpawnPoint {
        SpawnPoint {
            point,
            error: DVec3::splat(error),
            normal,
        }
    }

    #[test]
    fn the_origin_leaves_the_error_box_on_the_side_it_travels_to() {
        let s = at(DVec3::new(1e8, 0.0, 3.0), 1e-8, DVec3::Y);
        let up = s.origin_towards(DVec3::new(0.3, 1.0, 0.0));
        let down = s.origin_towards(DVec3::new(0.3, -1.0, 0.0));
        assert!(up.y > 1e-8 && up.y < 2e-8, "{up}");
        assert!(down.y < -1e-8 && down.y > -2e-8, "{down}");
        assert_eq!((up.x, up.z), (1e8, 3.0));
    }

    #[test]
    fn an_exact_point_still_moves_off_the_surface() {
        let s = at(DVec3::new(0.5, 1.0, 0.0), 0.0, DVec3::Y);
        assert_eq!(s.origin_towards(DVec3::Y).y, 1.0f64.next_up());
        assert_eq!(s.origin_towards(-DVec3::Y).y, 1.0f64.next_down());
    }

    #[test]
    fn away_steps_exactly_as_next_up_and_next_down() {
        let xs = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            1e-310,
            -1e-310,
            f64::from_bits(1),
            -f64::from_bits(1),
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            123.456,
            -7.0e200,
        ];
        for x in xs {
            for s in [1.0, 0.5, -2.0, -1e-300, 0.0, -0.0, f64::NAN] {
                let want = if s > 0.0 {
                    x.next_up()
                } else if s < 0.0 {
                    x.next_down()
                } else {
                    x
                };
                assert_eq!(away(x, s).to_bits(), want.to_bits(), "{x:e} towards {s}");
            }
        }
    }

    #[test]
    fn a_ray_to_a_target_is_aimed_from_its_origin_and_stops_short() {
        let s = at(DVec3::new(0.0, 1.0, 0.0), 1e-12, DVec3::Y);
        let target = DVec3::new(2.0, 0.0, 1.0);
        let (ray, t_max) = s.ray_to(target).unwrap();
        let end = ray.at(t_max);
        assert!((target - end).length() < 1e-12);
        assert!(((target - ray.origin).normalize() - ray.dir).length() < 1e-15);
        assert!(t_max < (target - ray.origin).length());
    }
}
