//! The world's loose spheres against a packet of rays: each sphere is tested on every ray of
//! the packet at once ([`crate::lanes`]), with the operations of the one-ray test
//! ([`crate::geometry::shapes::sphere::hit_t_with`]: [`crate::geometry::shapes::circle_quadratic::roots`], then the nearer root in the
//! interval) in the same order, so every lane's `t` is the one-ray test's to the bit.
//!
//! Why: a pixel's camera rays, and its shadow rays towards one light, meet the same one or two
//! spheres; tested together, their square roots and divisions run two (or four) to an
//! instruction, where ray by ray each waited on the last.

use crate::geometry::lanes::RayLanes;
use crate::geometry::lanes::cull::Among;
use crate::geometry::lanes::spheres::SphereLanes;
use crate::lanes::{self, Lanes, Mask, WIDTH};

/// For every ray of a packet, the nearest loose sphere found: its position in the lanes'
/// order ([`NO_SPHERE`] when none) and its `t`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PacketHits {
    /// The sphere's position, or [`NO_SPHERE`].
    pub(crate) sphere: [u32; WIDTH],
    /// Its `t` (the interval's end where there is none).
    pub(crate) t: Lanes,
}

impl PacketHits {
    /// No sphere on any ray, whose intervals end at `t_max`.
    pub(crate) fn none(t_max: f64) -> PacketHits {
        PacketHits {
            sphere: [NO_SPHERE; WIDTH],
            t: [t_max; WIDTH],
        }
    }
}

/// No sphere in [`PacketHits::sphere`].
pub(crate) const NO_SPHERE: u32 = u32::MAX;

/// `|dir|²` of every ray and its reciprocal (`circle_quadratic::DirSquared` per lane).
#[inline(always)]
fn dir_squared(rays: &RayLanes) -> (Lanes, Lanes) {
    let a = rays.dir.dot(&rays.dir);
    (a, lanes::map(|i| 1.0 / a[i]))
}

impl SphereLanes {
    /// The `t` of sphere `k` on every ray of the packet in (t_min, t_max) (`t_max` per ray),
    /// and the rays that find one: `sphere::hit_t_with` lane by lane.
    #[inline(always)]
    fn packet_t(
        &self,
        k: usize,
        rays: &RayLanes,
        (a, inv): (&Lanes, &Lanes),
        t_min: f64,
        t_max: &Lanes,
    ) -> (Lanes, Mask) {
        let (c, r) = self.each[k];
        let rr = r * r;
        let p = rays.origin.sub(&crate::geometry::lanes::V3::splat(c));
        let v = &rays.dir;
        // circle_quadratic::roots: half_b = p·v, closest = p − (half_b·inv)·v, gap = r² − |closest|².
        let half_b = p.dot(v);
        let closest = p.sub(&v.scale(&lanes::map(|i| half_b[i] * inv[i])));
        let cc = closest.dot(&closest);
        let gap = lanes::map(|i| rr - cc[i]);
        // `gap ≥ 0` is false for NaN, as `roots`' `gap < 0 || gap.is_nan()` miss test.
        let meets = lanes::ge(&gap, 0.0);
        // roots_past_gap: q = −half_b − √(a·gap)·sign(half_b); t0 = q·inv, t1 = (|p|² − r²)/q.
        let root = lanes::map(|i| (a[i] * gap[i]).sqrt());
        let q = lanes::map(|i| -half_b[i] - root[i].copysign(half_b[i]));
        let pp = p.dot(&p);
        let t0 = lanes::map(|i| q[i] * inv[i]);
        let t1 = lanes::map(|i| (pp[i] - rr) / q[i]);
        let mut t = [0.0; WIDTH];
        let mut found = 0;
        for i in 0..WIDTH {
            // A tangent touching at t = 0 gives the double root 0; otherwise the roots in order.
            let (lo, hi) = if q[i] == 0.0 {
                (0.0, 0.0)
            } else if t0[i] <= t1[i] {
                (t0[i], t1[i])
            } else {
                (t1[i], t0[i])
            };
            // sphere::nearer_root.
            let (near, far) = (lo > t_min && lo < t_max[i], hi > t_min && hi < t_max[i]);
            t[i] = if near { lo } else { hi };
            found |= Mask::from(near || far) << i;
        }
        (t, found & meets)
    }

    /// The nearest sphere of `among` for each ray of `live` in (t_min, t_max): what
    /// [`SphereLanes::nearest_among`] finds for that ray, bit for bit (the spheres in the same
    /// order, each against the nearest hit so far).
    pub(crate) fn nearest_packet(
        &self,
        rays: &RayLanes,
        live: Mask,
        t_min: f64,
        t_max: f64,
        among: Among,
    ) -> PacketHits {
        let d = dir_squared(rays);
        let mut best = PacketHits::none(t_max);
        if live == 0 {
            return best;
        }
        for k in among.positions() {
            if k >= self.each.len() {
                break;
            }
            let (t, found) = self.packet_t(k, rays, (&d.0, &d.1), t_min, &best.t);
            let found = found & live;
            best.t = lanes::select(found, &t, &best.t);
            for (i, b) in best.sphere.iter_mut().enumerate() {
                *b = if found & (1 << i) != 0 { k as u32 } else { *b };
            }
        }
        best
    }

    /// The rays of `live` that meet a sphere of `among` in (t_min, t_max[i]): what
    /// [`SphereLanes::any_among`] answers for each.
    pub(crate) fn any_packet(
        &self,
        rays: &RayLanes,
        live: Mask,
        t_min: f64,
        t_max: &Lanes,
        among: Among,
    ) -> Mask {
        let d = dir_squared(rays);
        let mut hit = 0;
        for k in among.positions() {
            if k >= self.each.len() || hit & live == live {
                break;
            }
            hit |= self.packet_t(k, rays, (&d.0, &d.1), t_min, t_max).1;
        }
        hit & live
    }
}

#[cfg(test)]
mod tests {
    use crate::num::Norm;
    use glam::DVec3;

    use super::*;
    use crate::geometry::ray::Ray;

    /// Every lane agrees bit for bit with the one-ray tests, on random packets and on the
    /// cases the scalar code singles out (tangents at the origin, rays from inside,
    /// degenerate and NaN directions), with partial packets and partial `among` sets.
    #[test]
    fn packets_find_what_one_ray_finds() {
        let mut rnd = crate::geometry::testing::test_uniform(17);
        for round in 0..60 {
            let count = 1 + round % 9;
            let spheres: Vec<(DVec3, f64)> = (0..count)
                .map(|_| (DVec3::new(rnd(), rnd(), rnd()) * 8.0 - 4.0, 0.3 + rnd()))
                .collect();
            let l = SphereLanes::new(spheres.iter().copied());
            let mut rays: Vec<Ray> = (0..WIDTH)
                .map(|_| {
                    let origin = DVec3::new(rnd(), rnd(), rnd()) * 16.0 - 8.0;
                    Ray::new(origin, (DVec3::new(rnd(), rnd(), rnd()) - 0.5).unit())
                })
                .collect();
            if round % 3 == 0 {
                let (c, r) = spheres[0];
                rays[1] = Ray::new(c + DVec3::new(r, 0.0, 0.0), DVec3::Y);
                rays[2] = Ray::new(c, DVec3::Z);
                rays[3] = Ray::new(DVec3::ONE, DVec3::ZERO);
                rays[4] = Ray::new(DVec3::ONE, DVec3::splat(f64::NAN));
            }
            let n = [WIDTH, 9, 1, 13][round % 4];
            let packet = RayLanes::of(&rays[..n]);
            let among = [Among::ALL, Among(0b1011_0101)][round % 2];
            for (t_min, t_max) in [(0.0, f64::INFINITY), (-1.0, 3.0), (1e-9, 5.0)] {
                let got = l.nearest_packet(&packet, lanes::first(n), t_min, t_max, among);
                let ends = lanes::map(|i| [t_max, 2.0, 0.5, 7.0][i % 4]);
                let any = l.any_packet(&packet, lanes::first(n), t_min, &ends, among);
                for (i, ray) in rays[..n].iter().enumerate() {
                    let want = l.nearest_among(ray, t_min, t_max, among);
                    let have = (got.sphere[i] != NO_SPHERE)
                        .then(|| (got.sphere[i] as usize, got.t[i].to_bits()));
                    assert_eq!(have, want.map(|(k, t)| (k, t.to_bits())), "{ray:?}");
                    let blocked = l.any_among(ray, t_min, ends[i], among);
                    assert_eq!(any & (1 << i) != 0, blocked, "{ray:?} to {}", ends[i]);
                }
                assert_eq!(any >> n, 0);
            }
        }
    }
}
