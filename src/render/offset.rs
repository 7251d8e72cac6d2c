//! Where spawned rays start, as pbrt-v4 does it (`OffsetRayOrigin`, `SpawnRay`, `SpawnRayTo`).
//!
//! A hit point is only known to lie within its error box (`SurfaceHit::error`, a per-axis bound
//! the shape computed from its own arithmetic and every transform widened). A ray leaving the
//! surface starts just outside that box, along the geometric normal on the side it travels to,
//! and the start is rounded away from the surface: it cannot re-hit the surface it leaves, yet
//! the offset is as small as the point's own uncertainty — ~1e-16 of the coordinates, never a
//! fraction of the scene's size or a fixed epsilon. A ray towards a point (a light) is aimed from
//! that start, so its line passes through the target.

use crate::num::Norm;
use glam::DVec3;

use crate::geometry::SurfaceHit;
use crate::geometry::lanes::RayLanes;
use crate::geometry::rounding::gamma;
use crate::lanes::{self, Lanes, Mask, V3};

/// A surface point rays can leave from: the point, its per-axis error bound and the surface's
/// geometric normal (either orientation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpawnPoint {
    /// The point as the object computed it.
    pub(crate) point: DVec3,
    /// Per-axis bound on its distance from the true surface.
    pub(crate) error: DVec3,
    /// Unit geometric normal.
    pub(crate) normal: DVec3,
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
    pub(crate) fn ray_to(&self, target: DVec3) -> Option<(crate::geometry::Ray, f64)> {
        let origin = self.origin_towards(target - self.point);
        let d = target - origin;
        let dist = d.norm();
        if dist.is_nan() || dist <= 0.0 || dist.is_infinite() {
            return None;
        }
        Some((
            crate::geometry::Ray::new(origin, d / dist),
            dist - shadow_margin(origin, target, dist),
        ))
    }
}

/// The surface points of a packet ([`crate::lanes`]) rays leave from: a
/// [`SpawnPoint`] per lane. Its rays are the ones [`SpawnPoint`] casts, bit for bit.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct SpawnLanes {
    /// The points as their objects computed them.
    pub(crate) point: V3,
    /// Their per-axis error bounds.
    pub(crate) error: V3,
    /// Their unit geometric normals.
    pub(crate) normal: V3,
}

impl SpawnLanes {
    /// Sets lane `i` to `s`.
    #[inline(always)]
    pub(crate) fn set(&mut self, i: usize, s: &SpawnPoint) {
        self.point.set(i, s.point);
        self.error.set(i, s.error);
        self.normal.set(i, s.normal);
    }

    /// [`SpawnPoint::origin_towards`] of every lane, each along its own `dir`.
    #[inline(always)]
    pub(crate) fn origin_towards(&self, dir: &V3) -> V3 {
        let facing = dir.dot(&self.normal);
        let n = V3::select(lanes::lt(&facing, 0.0), &self.normal.neg(), &self.normal);
        let d = n.abs().dot(&self.error);
        let o = self.point.add(&n.scale(&d));
        V3 {
            x: away_lanes(&o.x, &n.x),
            y: away_lanes(&o.y, &n.y),
            z: away_lanes(&o.z, &n.z),
        }
    }

    /// [`SpawnPoint::ray_to`] of every lane towards one `target`: the rays, where each must
    /// stop, and the lanes that have a ray (the others' target is their origin).
    #[inline(always)]
    pub(crate) fn ray_to(&self, target: DVec3) -> (RayLanes, Lanes, Mask) {
        let origin = self.origin_towards(&self.point.from(target));
        let d = origin.from(target);
        let dist = d.norm();
        let valid = lanes::gt(&dist, 0.0) & lanes::lt(&dist, f64::INFINITY);
        let dir = d.div(&dist);
        // shadow_margin, lane by lane.
        let far = origin.abs().max_element();
        let near = target.abs().max_element();
        let t_max =
            lanes::map(|i| dist[i] - gamma(SHADOW_ROUNDING_STEPS) * (far[i] + near + dist[i]));
        (RayLanes { origin, dir }, t_max, valid)
    }
}

/// [`away`] of every lane: the same bit steps, the rare cases (zeros, infinities, NaN) one by
/// one through [`away_rare`].
#[inline(always)]
fn away_lanes(x: &Lanes, s: &Lanes) -> Lanes {
    let mut out = [0.0; lanes::WIDTH];
    let mut rare: Mask = 0;
    for i in 0..lanes::WIDTH {
        let a = x[i].abs();
        rare |= Mask::from(!(a > 0.0 && a < f64::INFINITY)) << i;
        let bits = x[i].to_bits() as i64;
        // +1 towards +∞, −1 towards −∞, 0 to stay; negated for a negative x (whose
        // neighbour towards +∞ is one bit pattern less): `(dir ^ m) − m` with m = 0 or −1.
        let dir = i64::from(s[i] > 0.0) - i64::from(s[i] < 0.0);
        let m = -(((bits as u64) >> 63) as i64);
        out[i] = f64::from_bits(bits.wrapping_add((dir ^ m) - m) as u64);
    }
    for i in lanes::each(rare) {
        out[i] = away_rare(x[i], s[i]);
    }
    out
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
pub(crate) fn shadow_margin(origin: DVec3, target: DVec3, dist: f64) -> f64 {
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

    /// Every lane of a packet leaves its surface and aims at its target exactly as the
    /// point alone does, edge cases (zero and huge coordinates, exact points) included.
    #[test]
    fn packets_spawn_the_rays_points_spawn_alone() {
        let mut rnd = crate::geometry::testing::test_uniform(23);
        for round in 0..40 {
            let points: Vec<SpawnPoint> = (0..lanes::WIDTH)
                .map(|i| {
                    let p = DVec3::new(rnd() - 0.5, rnd() * 1e3, -rnd()) * [1.0, 1e8, 1e-9][i % 3];
                    let p = if i == 5 {
                        DVec3::new(0.0, -0.0, 1.0)
                    } else {
                        p
                    };
                    let n = (DVec3::new(rnd(), rnd(), rnd()) - 0.5).unit();
                    let n = if i == 7 { DVec3::Y } else { n };
                    at(p, [0.0, 1e-12, rnd() * 1e-6][i % 3], n)
                })
                .collect();
            let mut packet = SpawnLanes::default();
            for (i, s) in points.iter().enumerate() {
                packet.set(i, s);
            }
            let dirs: Vec<DVec3> = (0..lanes::WIDTH)
                .map(|i| (DVec3::new(rnd(), rnd(), rnd()) - 0.5) * if i == 3 { 0.0 } else { 1.0 })
                .collect();
            let dirs = V3::map(|i| dirs[i]);
            let target = match round % 3 {
                0 => DVec3::new(rnd(), rnd(), rnd()) * 1e3,
                1 => points[2].point,
                _ => DVec3::new(0.0, 1.0, -0.0),
            };
            let origins = packet.origin_towards(&dirs);
            let (rays, t_max, valid) = packet.ray_to(target);
            for (i, s) in points.iter().enumerate() {
                let o = s.origin_towards(dirs.get(i));
                assert_eq!(
                    origins.get(i).to_array().map(f64::to_bits),
                    o.to_array().map(f64::to_bits)
                );
                let want = s.ray_to(target);
                assert_eq!(valid & (1 << i) != 0, want.is_some(), "lane {i}");
                if let Some((ray, t)) = want {
                    assert_eq!(rays.origin.get(i), ray.origin);
                    assert_eq!(
                        rays.dir.get(i).to_array().map(f64::to_bits),
                        ray.dir.to_array().map(f64::to_bits)
                    );
                    assert_eq!(t_max[i].to_bits(), t.to_bits());
                }
            }
        }
    }

    #[test]
    fn away_in_lanes_steps_as_away() {
        let xs = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            1e-310,
            -1e-310,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            123.456,
            -7.0e200,
            3.0,
            -2.5,
        ];
        for s in [1.0, -2.0, 0.0, -0.0, f64::NAN, -1e-300] {
            let got = away_lanes(&xs, &[s; lanes::WIDTH]);
            for (x, g) in xs.iter().zip(got) {
                assert_eq!(g.to_bits(), away(*x, s).to_bits(), "{x:e} towards {s}");
            }
        }
    }

    #[test]
    fn a_ray_to_a_target_is_aimed_from_its_origin_and_stops_short() {
        let s = at(DVec3::new(0.0, 1.0, 0.0), 1e-12, DVec3::Y);
        let target = DVec3::new(2.0, 0.0, 1.0);
        let (ray, t_max) = s.ray_to(target).unwrap();
        let end = ray.at(t_max);
        assert!((target - end).norm() < 1e-12);
        assert!(((target - ray.origin).unit() - ray.dir).norm() < 1e-15);
        assert!(t_max < (target - ray.origin).norm());
    }
}
