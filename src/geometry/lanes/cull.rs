//! Which of the world's loose spheres a bundle of ray segments can meet at all: a pixel's
//! camera rays (one eye, directions inside the pixel) or the shadow rays of its hit points
//! (towards one light) lie inside a thin capsule, and a sphere clearly outside the capsule is
//! missed by every ray of the bundle, so its test can be skipped.
//!
//! Why: scene A (six spheres) tested every sphere on every camera and shadow ray, although a
//! pixel's rays can meet only the backdrop and at most one or two others (issue 12).
//!
//! Bit-identity: a skipped sphere is one whose exact test ([`crate::geometry::shapes::sphere::hit_t_with`])
//! provably finds no hit in any ray's interval, so skipping it changes no result. The exact
//! test finds a `t` only where the computed point `origin + t·dir` lies within the rounding of
//! the quadratic of the sphere's surface: a few ε·|p|² in the gap (`circle_quadratic::roots`), i.e. a
//! point off the sphere by at most ~√(20ε·|p|·r) ≤ 7·10⁻⁸ of the coordinates' magnitude (near
//! a tangent, where the square root amplifies the gap's error), much less elsewhere. A sphere
//! is skipped only when every point of every segment is farther from its surface than
//! [`MARGIN`] = 10⁻⁵ of that magnitude, 100 times more; the capsule's own rounding (a few ε)
//! is inside that margin too.

use crate::num::Norm;
use std::cmp::Ordering;

use glam::DVec3;

use crate::geometry::lanes::RayLanes;
use crate::geometry::ray::Ray;
use crate::lanes::{self, Lanes, Mask, V3, WIDTH};

/// How far outside the capsule (relative to the magnitude of the coordinates involved) a
/// sphere must lie to be skipped; see the module documentation.
const MARGIN: f64 = 1e-5;

/// Directions whose squared length is this close to 1 count as unit (world rays are unit up
/// to a few ε); a bundle with any other direction skips nothing.
const UNIT_SLACK: f64 = 1e-9;

/// The spheres a bundle of segments may meet, one bit per sphere (in the lanes' order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Among(pub(crate) u64);

impl Among {
    /// Every sphere (nothing skipped).
    pub const ALL: Among = Among(u64::MAX);

    /// The lane positions of the spheres kept, in increasing order (the lanes' test order).
    pub(crate) fn positions(self) -> impl Iterator<Item = usize> {
        let mut bits = self.0;
        std::iter::from_fn(move || {
            let k = bits.trailing_zeros() as usize;
            bits &= bits.wrapping_sub(1);
            (k < 64).then_some(k)
        })
    }
}

/// The smallest sphere around a set of spheres' bounds (centre, radius), padded: the reach of
/// infinite rays (no sphere's hit lies beyond it).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Reach {
    center: DVec3,
    radius: f64,
}

impl Reach {
    /// A sphere containing every sphere `(centre, radius)` (not minimal), padded by MARGIN.
    pub(crate) fn of(spheres: &[(DVec3, f64)]) -> Reach {
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &(c, r) in spheres {
            lo = lo.min(c - r);
            hi = hi.max(c + r);
        }
        let center = (lo + hi) * 0.5;
        let radius = spheres
            .iter()
            .map(|&(c, r)| (c - center).norm() + r)
            .fold(0.0, f64::max);
        Reach {
            center,
            radius: radius * (1.0 + MARGIN) + MARGIN * l1(center),
        }
    }
}

/// A bundle of ray segments `origin + t·dir`, `t ∈ [0, t_max]` (`t_max` may be infinite), as
/// bounds: filled ray by ray ([`Bundle::push`], a few comparisons), then asked which spheres it
/// may meet ([`crate::geometry::world::World::among`]).
#[derive(Clone, Copy, Debug)]
pub struct Bundle {
    /// Box of the origins.
    origins: (DVec3, DVec3),
    /// Box of the ends of the finite segments.
    ends: (DVec3, DVec3),
    /// Box of the directions of the infinite ones.
    dirs: (DVec3, DVec3),
    /// The smallest `|dir|²` of an infinite one.
    unit: f64,
    /// A sum of every coordinate pushed: not finite when any of them is not (the boxes'
    /// comparisons would drop a NaN silently).
    probe: f64,
    /// Segments pushed.
    count: u32,
    /// Whether any of them is infinite.
    infinite: bool,
}

impl Default for Bundle {
    fn default() -> Bundle {
        Bundle::new()
    }
}

impl Bundle {
    /// No segment yet.
    pub fn new() -> Bundle {
        let empty = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        Bundle {
            origins: empty,
            ends: empty,
            dirs: empty,
            unit: f64::INFINITY,
            probe: 0.0,
            count: 0,
            infinite: false,
        }
    }

    /// Adds the segment of `ray` from `t = 0` to `t_max`.
    #[inline(always)]
    pub fn push(&mut self, ray: &Ray, t_max: f64) {
        let (o, d) = (ray.origin, ray.dir);
        grow(&mut self.origins, o);
        self.probe += (o.x + o.y + o.z) + (d.x + d.y + d.z);
        if t_max < f64::INFINITY {
            let e = ray.at(t_max);
            grow(&mut self.ends, e);
            self.probe += e.x + e.y + e.z;
        } else {
            grow(&mut self.dirs, d);
            let aa = d.length_squared();
            self.unit = if aa < self.unit { aa } else { self.unit };
            self.infinite = true;
        }
        self.count += 1;
    }

    /// The segments of the rays of `live` in a packet, ray `i` from `t = 0` to `t_max[i]`:
    /// the bundle [`Bundle::push`] builds ray by ray, but with each bound reduced across the
    /// lanes at once (ray by ray, every comparison waited on the one before).
    #[inline(never)]
    pub(crate) fn of_packet(rays: &RayLanes, t_max: &Lanes, live: Mask) -> Bundle {
        if live == 0 {
            return Bundle::new();
        }
        // The other lanes become copies of a live one, which leave every bound as it is, so
        // the reductions need no masks.
        let f = live.trailing_zeros() as usize;
        let fill = |v: &Lanes| lanes::select(live, v, &[v[f]; WIDTH]);
        let fill3 = |v: &V3| V3 {
            x: fill(&v.x),
            y: fill(&v.y),
            z: fill(&v.z),
        };
        let (o, d, t) = (fill3(&rays.origin), fill3(&rays.dir), fill(t_max));
        let ended = lanes::lt(&t, f64::INFINITY);
        if ended != 0 && ended != lanes::first(WIDTH) {
            // Finite and infinite segments mixed (no packet the renderer casts): ray by ray.
            let mut b = Bundle::new();
            for i in lanes::each(live) {
                b.push(&Ray::new(rays.origin.get(i), rays.dir.get(i)), t_max[i]);
            }
            return b;
        }
        let sum = |v: &V3| lanes::map(|i| v.x[i] + v.y[i] + v.z[i]);
        let (so, sd) = (sum(&o), sum(&d));
        let mut b = Bundle {
            origins: bounds(&o),
            count: live.count_ones(),
            ..Bundle::new()
        };
        // Only the finiteness of `probe` matters, so the order of its sum is free.
        if ended != 0 {
            let e = o.add(&d.scale(&t));
            let se = sum(&e);
            b.ends = bounds(&e);
            b.probe = lanes::sum(&lanes::map(|i| (so[i] + sd[i]) + se[i]));
        } else {
            b.dirs = bounds(&d);
            b.unit = lanes::min(&d.dot(&d));
            b.probe = lanes::sum(&lanes::map(|i| so[i] + sd[i]));
            b.infinite = true;
        }
        b
    }
}

/// The box of the points of `v`.
#[inline(always)]
fn bounds(v: &V3) -> (DVec3, DVec3) {
    (
        DVec3::new(lanes::min(&v.x), lanes::min(&v.y), lanes::min(&v.z)),
        DVec3::new(lanes::max(&v.x), lanes::max(&v.y), lanes::max(&v.z)),
    )
}

/// `b` grown to hold `p` (plain comparisons: NaN is caught by [`Bundle::probe`]).
#[inline(always)]
fn grow(b: &mut (DVec3, DVec3), p: DVec3) {
    let lo = |a: f64, x: f64| if x < a { x } else { a };
    let hi = |a: f64, x: f64| if x > a { x } else { a };
    b.0 = DVec3::new(lo(b.0.x, p.x), lo(b.0.y, p.y), lo(b.0.z, p.z));
    b.1 = DVec3::new(hi(b.1.x, p.x), hi(b.1.y, p.y), hi(b.1.z, p.z));
}

/// The spheres of `spheres` that any segment of `bundle` may meet; [`Among::ALL`] when the
/// bundle is empty, holds a non-finite value or an infinite segment whose direction is not
/// unit, or there are more than 64 spheres. Queries using the result must ask for `t` in a
/// sub-interval of their segment's `[0, t_max]`.
pub(crate) fn among(spheres: &[(DVec3, f64)], reach: Reach, bundle: &Bundle) -> Among {
    if spheres.len() > 64 || bundle.count == 0 || !bundle.probe.is_finite() {
        return Among::ALL;
    }
    let (m0, rho0) = center_and_radius(bundle.origins);
    let mut ends = bundle.ends;
    if bundle.infinite {
        if bundle.unit < 1.0 - UNIT_SLACK || bundle.unit.is_nan() {
            return Among::ALL;
        }
        // No hit of any sphere lies farther along a unit ray than the reach's far side, so
        // an infinite segment may stop there: its end lies in origins + far·directions.
        let far = ((m0 - reach.center).norm() + rho0 + reach.radius) * (1.0 + MARGIN);
        let (o, d) = (bundle.origins, bundle.dirs);
        grow(&mut ends, o.0 + far * d.0);
        grow(&mut ends, o.1 + far * d.1);
    }
    let (m1, rho1) = center_and_radius(ends);
    // Every segment lies within `rho` of the axis segment m0 → m1: its point at fraction s is
    // (1−s)·origin + s·end, at most (1−s)·ρ0 + s·ρ1 from the axis's.
    let rho = rho0.max(rho1);
    let axis = m1 - m0;
    let axis2 = axis.length_squared();
    let mut mask = 0u64;
    for (k, &(c, r)) in spheres.iter().enumerate() {
        let w = c - m0;
        let along = w.dot(axis);
        // The squared distance from c to the axis segment, without a division: to its start,
        // its end, or (between them) to its line, times |axis|² (Lagrange's identity).
        let (gap2, unit2) = if along <= 0.0 || axis2 == 0.0 {
            (w.length_squared(), 1.0)
        } else if along >= axis2 {
            ((c - m1).length_squared(), 1.0)
        } else {
            (w.length_squared() * axis2 - along * along, axis2)
        };
        let scale = l1(m0) + l1(m1) + l1(c) + r + rho;
        let reach = r + rho + MARGIN * scale;
        // Anything but "clearly farther" (NaN included) keeps the sphere.
        if gap2.partial_cmp(&(reach * reach * unit2)) != Some(Ordering::Greater) {
            mask |= 1 << k;
        }
    }
    Among(mask)
}

/// The centre of the box `lo..hi` and the distance from it to the box's corners.
fn center_and_radius((lo, hi): (DVec3, DVec3)) -> (DVec3, f64) {
    ((lo + hi) * 0.5, (hi - lo).norm() * 0.5)
}

/// `|x| + |y| + |z|`, at least the Euclidean length.
fn l1(v: DVec3) -> f64 {
    v.abs().element_sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::shapes::circle_quadratic::DirSquared;
    use crate::geometry::shapes::sphere;

    fn bundle(rays: &[(Ray, f64)]) -> Bundle {
        let mut b = Bundle::new();
        for (r, t) in rays {
            b.push(r, *t);
        }
        b
    }

    /// A skipped sphere is never hit: random bundles (pixels of a pinhole camera, shadow rays
    /// of nearby points towards one light, and scattered rays) against random spheres, and
    /// the bundle skips spheres when it is thin.
    #[test]
    fn skipped_spheres_are_never_hit() {
        let mut rnd = crate::geometry::testing::test_uniform(11);
        let mut skipped = 0;
        for round in 0..300 {
            let spheres: Vec<(DVec3, f64)> = (0..7)
                .map(|_| {
                    (
                        DVec3::new(rnd(), rnd(), rnd()) * 40.0 - 20.0,
                        0.5 + 4.0 * rnd(),
                    )
                })
                .collect();
            let reach = Reach::of(&spheres);
            let spread = [1e-3, 0.05, 3.0][round % 3];
            let base = DVec3::new(rnd(), rnd(), rnd()) * 60.0 - 30.0;
            let aim = (DVec3::new(rnd(), rnd(), rnd()) - 0.5).unit();
            let light = DVec3::new(rnd(), rnd(), rnd()) * 60.0 - 30.0;
            let rays: Vec<(Ray, f64)> = (0..16)
                .map(|_| {
                    let jitter = (DVec3::new(rnd(), rnd(), rnd()) - 0.5) * spread;
                    if round % 2 == 0 {
                        // A camera pixel: one eye, nearby directions, no end.
                        (Ray::new(base, (aim + jitter).unit()), f64::INFINITY)
                    } else {
                        // Shadow rays from nearby points to one light.
                        let o = base + jitter;
                        let d = light - o;
                        let dist = d.norm();
                        (Ray::new(o, d / dist), dist)
                    }
                })
                .collect();
            let got = among(&spheres, reach, &bundle(&rays));
            for (k, &(c, r)) in spheres.iter().enumerate() {
                if got.0 & (1 << k) != 0 {
                    continue;
                }
                skipped += 1;
                for (ray, t_max) in &rays {
                    let d = DirSquared::of(ray.dir);
                    assert_eq!(
                        sphere::hit_t_with(c, r, d, ray, 0.0, *t_max),
                        None,
                        "sphere {k} skipped but hit by {ray:?}"
                    );
                }
            }
        }
        assert!(skipped > 300, "{skipped}");
    }

    /// A packet's bundle is the one its live rays pushed one by one give: camera-like,
    /// shadow-like and mixed packets, partial masks; a NaN or an infinite coordinate makes
    /// both non-finite.
    #[test]
    fn a_packets_bundle_is_its_rays_pushed_one_by_one() {
        let mut rnd = crate::geometry::testing::test_uniform(23);
        for round in 0..400 {
            let rays: Vec<Ray> = (0..WIDTH)
                .map(|_| {
                    let o = DVec3::new(rnd(), rnd(), rnd()) * 50.0 - 25.0;
                    Ray::new(o, (DVec3::new(rnd(), rnd(), rnd()) - 0.5).unit())
                })
                .collect();
            let mut packet = RayLanes::of(&rays);
            let t_max: Lanes = std::array::from_fn(|i| match round % 3 {
                0 => f64::INFINITY,
                1 => 1.0 + i as f64,
                _ => [f64::INFINITY, 3.0][i % 2],
            });
            let live = (rnd() * 65536.0) as Mask | (u32::from(round % 5 == 0) * 0xffff);
            if round % 7 == 3 {
                packet.origin.y[round % WIDTH] = [f64::NAN, f64::INFINITY][round % 2];
            }
            let got = Bundle::of_packet(&packet, &t_max, live);
            let mut want = Bundle::new();
            for i in lanes::each(live) {
                want.push(&Ray::new(packet.origin.get(i), packet.dir.get(i)), t_max[i]);
            }
            let key = |b: &Bundle| {
                (
                    b.origins,
                    b.ends,
                    b.dirs,
                    b.unit,
                    b.count,
                    b.infinite,
                    b.probe.is_finite(),
                )
            };
            if want.probe.is_finite() {
                assert_eq!(key(&got), key(&want), "round {round}, live {live:#x}");
            } else {
                // `among` keeps every sphere then, whatever the boxes hold.
                assert!(!got.probe.is_finite(), "round {round}, live {live:#x}");
            }
        }
    }

    /// Grazing rays: a sphere touched by one ray of the bundle, or missed by less than the
    /// margin, is kept.
    #[test]
    fn a_sphere_grazed_by_one_ray_is_kept() {
        let spheres = [(DVec3::new(0.0, 1.0, -10.0), 1.0)];
        let reach = Reach::of(&spheres);
        let graze = Ray::new(DVec3::ZERO, DVec3::new(0.0, 0.0, -1.0));
        let away = Ray::new(DVec3::ZERO, DVec3::new(0.0, -0.6, -0.8));
        let both = [(graze, f64::INFINITY), (away, f64::INFINITY)];
        assert_eq!(among(&spheres, reach, &bundle(&both)).0, 1);
        assert_eq!(among(&spheres, reach, &bundle(&both[1..])).0, 0);
        // A segment stopping short of the sphere skips it; a NaN, an infinity or a long
        // direction keeps everything.
        assert_eq!(among(&spheres, reach, &bundle(&[(graze, 5.0)])).0, 0);
        for odd in [
            (Ray::new(DVec3::splat(f64::NAN), graze.dir), 5.0),
            (
                Ray::new(DVec3::new(0.0, f64::INFINITY, 0.0), graze.dir),
                5.0,
            ),
            (
                Ray::new(DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 1.0)),
                f64::INFINITY,
            ),
            (
                Ray::new(DVec3::ZERO, DVec3::new(0.0, -0.3, -0.4)),
                f64::INFINITY,
            ),
        ] {
            assert_eq!(
                among(&spheres, reach, &bundle(&[odd])),
                Among::ALL,
                "{odd:?}"
            );
        }
    }
}
