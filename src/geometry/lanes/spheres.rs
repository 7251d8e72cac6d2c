//! The world's loose spheres tested four at a time: centres and squared radii in
//! structure-of-arrays lanes. The miss test (the sign of [`crate::geometry::shapes::circle_quadratic::roots`]' gap) runs on
//! all lanes at once, in plain `[f64; LANES]` loops the compiler turns into SIMD instructions
//! (SSE2 on any x86-64; no `unsafe`, no fused multiply-add, no approximate square root), and
//! only the lanes whose line meets their sphere finish the quadratic, one by one, through the
//! scalar code itself ([`crate::geometry::shapes::circle_quadratic::roots_past_gap`], [`crate::geometry::shapes::sphere::nearer_root`]). Every
//! lane computes the scalar test's operations in the same order, so a `t` is bit-identical to
//! `sphere::hit_t_with`'s and images do not depend on the lane width or the CPU.
//!
//! Why: scene A (six spheres) spent ~45% of its instructions in one-sphere-at-a-time tests
//! whose hit/miss branches the CPU cannot predict; most of them are misses, decided here
//! without a branch per sphere.

use glam::DVec3;

use crate::geometry::lanes::cull::{self, Among, Bundle, Reach};
use crate::geometry::ray::Ray;
use crate::geometry::shapes::circle_quadratic::{DirSquared, roots_past_gap};
use crate::geometry::shapes::sphere::{hit_t_with, nearer_root};

/// Spheres per lane group.
const LANES: usize = 4;

type Lane = [f64; LANES];

/// Loose spheres in lane groups of [`LANES`], padded with spheres no ray hits.
#[derive(Clone, Debug, Default)]
pub(crate) struct SphereLanes {
    x: Vec<Lane>,
    y: Vec<Lane>,
    z: Vec<Lane>,
    /// `r·r` as the scalar test computes it; padding lanes hold −∞ (a gap below zero: a miss).
    rr: Vec<Lane>,
    len: usize,
    /// The spheres one by one, for bundles that test only a few of them ([`Among`]).
    pub(crate) each: Vec<(DVec3, f64)>,
    /// Where every sphere lies (how far infinite rays of a bundle reach).
    reach: Reach,
}

/// One group's intermediate values of `circle_quadratic::roots` for one ray.
struct Gaps {
    px: Lane,
    py: Lane,
    pz: Lane,
    half_b: Lane,
    gap: Lane,
    /// Lanes whose line meets their sphere (`gap ≥ 0`), one bit each.
    meets: u32,
}

impl SphereLanes {
    /// The lanes of spheres `(centre, radius)`, in order (an index below is a position here).
    pub(crate) fn new(spheres: impl IntoIterator<Item = (DVec3, f64)>) -> SphereLanes {
        let mut s = SphereLanes::default();
        for (c, r) in spheres {
            let (g, l) = (s.len / LANES, s.len % LANES);
            if l == 0 {
                s.x.push([0.0; LANES]);
                s.y.push([0.0; LANES]);
                s.z.push([0.0; LANES]);
                s.rr.push([f64::NEG_INFINITY; LANES]);
            }
            (s.x[g][l], s.y[g][l], s.z[g][l]) = (c.x, c.y, c.z);
            s.rr[g][l] = r * r;
            s.len += 1;
            s.each.push((c, r));
        }
        s.reach = Reach::of(&s.each);
        s
    }

    /// The spheres any segment of `bundle` may meet ([`sphere_cull`]); queries with it ask
    /// for sub-intervals of those segments.
    pub(crate) fn among(&self, bundle: &Bundle) -> Among {
        cull::among(&self.each, self.reach, bundle)
    }

    /// [`SphereLanes::nearest`] when only the spheres of `among` can be hit: the others are
    /// not tested. The spheres are tested one by one in order, with the scalar test the lanes
    /// compute bit for bit, so the result is the same.
    #[inline]
    pub(crate) fn nearest_among(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        among: Among,
    ) -> Option<(usize, f64)> {
        let d = DirSquared::of(ray.dir);
        let mut best = None;
        let mut far = t_max;
        for k in among.positions() {
            let Some(&(c, r)) = self.each.get(k) else {
                break;
            };
            if let Some(t) = hit_t_with(c, r, d, ray, t_min, far) {
                far = t;
                best = Some((k, t));
            }
        }
        best
    }

    /// [`SphereLanes::any`] when only the spheres of `among` can be hit.
    #[inline]
    pub(crate) fn any_among(&self, ray: &Ray, t_min: f64, t_max: f64, among: Among) -> bool {
        let d = DirSquared::of(ray.dir);
        for k in among.positions() {
            let Some(&(c, r)) = self.each.get(k) else {
                break;
            };
            if hit_t_with(c, r, d, ray, t_min, t_max).is_some() {
                return true;
            }
        }
        false
    }

    /// Number of spheres (the tests').
    #[cfg(test)]
    fn len(&self) -> usize {
        self.len
    }

    /// True when there are no spheres.
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// `circle_quadratic::roots` up to its miss test, for every sphere of group `g` at once (the same
    /// operations in the same order: `p = origin − centre`, `half_b = p·v`,
    /// `gap = r² − |p − (half_b/|v|²)·v|²`).
    #[inline(always)]
    fn gaps(&self, g: usize, ray: &Ray, d: DirSquared) -> Gaps {
        let (o, v) = (ray.origin, ray.dir);
        let (cx, cy, cz, rr) = (&self.x[g], &self.y[g], &self.z[g], &self.rr[g]);
        let mut l = Gaps {
            px: [0.0; LANES],
            py: [0.0; LANES],
            pz: [0.0; LANES],
            half_b: [0.0; LANES],
            gap: [0.0; LANES],
            meets: 0,
        };
        for i in 0..LANES {
            l.px[i] = o.x - cx[i];
            l.py[i] = o.y - cy[i];
            l.pz[i] = o.z - cz[i];
            l.half_b[i] = l.px[i] * v.x + l.py[i] * v.y + l.pz[i] * v.z;
            let k = l.half_b[i] * d.inv;
            let (qx, qy, qz) = (l.px[i] - k * v.x, l.py[i] - k * v.y, l.pz[i] - k * v.z);
            l.gap[i] = rr[i] - (qx * qx + qy * qy + qz * qz);
        }
        // `gap ≥ 0` is false for NaN (a zero or non-finite direction): roots' miss test.
        for i in 0..LANES {
            l.meets |= u32::from(l.gap[i] >= 0.0) << i;
        }
        l
    }

    /// `sphere::hit_t_with` of lane `i` of group `g`, whose line meets its sphere.
    #[inline(always)]
    fn finish(
        &self,
        g: usize,
        i: usize,
        l: &Gaps,
        d: DirSquared,
        t_min: f64,
        t_max: f64,
    ) -> Option<f64> {
        let p = DVec3::new(l.px[i], l.py[i], l.pz[i]);
        let (t0, t1) = roots_past_gap(p, l.half_b[i], l.gap[i], d, self.rr[g][i]);
        nearer_root(t0, t1, t_min, t_max)
    }

    /// The nearest sphere in (t_min, t_max) and its `t`: exactly what testing the spheres one
    /// by one with `sphere::hit_t_with`, each against the nearest hit so far, finds.
    #[inline]
    pub(crate) fn nearest(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(usize, f64)> {
        let d = DirSquared::of(ray.dir);
        let mut best = None;
        let mut far = t_max;
        for g in 0..self.x.len() {
            let l = self.gaps(g, ray, d);
            let mut meets = l.meets;
            while meets != 0 {
                let i = meets.trailing_zeros() as usize;
                meets &= meets - 1;
                if let Some(t) = self.finish(g, i, &l, d, t_min, far) {
                    far = t;
                    best = Some((g * LANES + i, t));
                }
            }
        }
        best
    }

    /// True when any sphere lies in (t_min, t_max) along the ray.
    #[inline]
    pub(crate) fn any(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let d = DirSquared::of(ray.dir);
        (0..self.x.len()).any(|g| {
            let l = self.gaps(g, ray, d);
            let mut meets = l.meets;
            while meets != 0 {
                let i = meets.trailing_zeros() as usize;
                meets &= meets - 1;
                if self.finish(g, i, &l, d, t_min, t_max).is_some() {
                    return true;
                }
            }
            false
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::shapes::sphere;
    use crate::num::Norm;

    /// Every lane agrees bit for bit with the scalar test, on random rays and on the cases the
    /// scalar code singles out (tangents at the origin, rays from inside, degenerate rays).
    #[test]
    fn lanes_find_what_the_scalar_test_finds() {
        let mut rnd = crate::geometry::testing::test_uniform(5);
        for count in [1usize, 3, 4, 6, 9] {
            let spheres: Vec<(DVec3, f64)> = (0..count)
                .map(|_| (DVec3::new(rnd(), rnd(), rnd()) * 8.0 - 4.0, 0.3 + rnd()))
                .collect();
            let l = SphereLanes::new(spheres.iter().copied());
            assert_eq!(l.len(), count);
            let mut rays = vec![
                // Tangent to the first sphere at the origin: the double root 0.
                Ray::new(
                    spheres[0].0 + DVec3::new(spheres[0].1, 0.0, 0.0),
                    DVec3::new(0.0, 1.0, 0.0),
                ),
                // From the centre of the first sphere (inside).
                Ray::new(spheres[0].0, DVec3::new(0.0, 0.0, 1.0)),
                Ray::new(DVec3::ONE, DVec3::ZERO),
                Ray::new(DVec3::ONE, DVec3::splat(f64::NAN)),
            ];
            for _ in 0..2000 {
                let origin = DVec3::new(rnd(), rnd(), rnd()) * 16.0 - 8.0;
                let dir = (DVec3::new(rnd(), rnd(), rnd()) - 0.5).unit();
                rays.push(Ray::new(origin, dir));
            }
            for ray in &rays {
                for (t_min, t_max) in [(0.0, f64::INFINITY), (-1.0, 3.0), (1e-9, 5.0)] {
                    let d = DirSquared::of(ray.dir);
                    let mut want = None;
                    let mut far = t_max;
                    for (i, (c, r)) in spheres.iter().enumerate() {
                        if let Some(t) = sphere::hit_t_with(*c, *r, d, ray, t_min, far) {
                            far = t;
                            want = Some((i, t));
                        }
                    }
                    let got = l.nearest(ray, t_min, t_max);
                    assert_eq!(
                        got.map(|(i, t)| (i, t.to_bits())),
                        want.map(|(i, t)| (i, t.to_bits())),
                        "{ray:?} in ({t_min}, {t_max})"
                    );
                    assert_eq!(l.any(ray, t_min, t_max), want.is_some());
                }
            }
        }
    }
}
