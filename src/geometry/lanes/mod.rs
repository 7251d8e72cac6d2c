//! Structure-of-arrays vectors for a packet of up to [`WIDTH`] rays: the x, y and z of every
//! ray side by side, so one loop applies an operation to all of them and the compiler emits
//! packed SIMD instructions (`mulpd`, `divpd`, `sqrtpd`: on any x86-64, no `unsafe`).
//!
//! Every operation here is the elementwise twin of glam's `DVec3` operation of the same name,
//! with the same floating-point operations in the same order (`dot` is `(x·x' + y·y') + z·z'`,
//! `normalize` multiplies by `1 / length`), and square roots are `f64::sqrt`, which is correctly
//! rounded like libm's. So a lane computes bit for bit what the scalar code computes for that
//! ray, and images do not depend on whether a ray was traced alone or in a packet.
//!
//! Why: one ray at a time is a chain of dependent square roots and divisions, and scalar
//! `DVec3` code spends most of its instructions moving single numbers around; in packets the
//! same work takes about half the instructions (scene A, issue 12). What crosses lanes (selects
//! by a [`Mask`], comparisons into one, folds) goes through [`crate::geometry::lanes::simd`].

pub mod cull;
pub mod simd;
pub mod sphere_packet;
pub mod spheres;

use glam::DVec3;

/// Rays in a packet: a pixel's 4×4 camera samples.
pub const WIDTH: usize = 16;

/// One number per ray of a packet.
pub type Lanes = [f64; WIDTH];

/// One bit per ray of a packet (bit `i` for ray `i`).
pub type Mask = u32;

/// The mask of the first `n` rays.
#[inline(always)]
pub fn first(n: usize) -> Mask {
    if n >= WIDTH {
        (1u32 << WIDTH) - 1
    } else {
        (1u32 << n) - 1
    }
}

/// The rays of `mask`, in increasing order.
#[inline(always)]
pub fn each(mask: Mask) -> impl Iterator<Item = usize> {
    let mut bits = mask;
    std::iter::from_fn(move || {
        (bits != 0).then(|| {
            let i = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            i
        })
    })
}

/// `f(i)` for every lane.
#[inline(always)]
pub fn map(f: impl Fn(usize) -> f64) -> Lanes {
    let mut out = [0.0; WIDTH];
    for (i, o) in out.iter_mut().enumerate() {
        *o = f(i);
    }
    out
}

/// The lanes where `f(i)` holds.
#[inline(always)]
pub fn mask_of(f: impl Fn(usize) -> bool) -> Mask {
    let mut m = 0;
    for i in 0..WIDTH {
        m |= Mask::from(f(i)) << i;
    }
    m
}

/// `a` where `m` has the lane, else `b`.
#[inline(always)]
pub fn select(m: Mask, a: &Lanes, b: &Lanes) -> Lanes {
    crate::geometry::lanes::simd::select(m, a, b)
}

/// A vector per ray of a packet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3 {
    /// The rays' x.
    pub x: Lanes,
    /// The rays' y.
    pub y: Lanes,
    /// The rays' z.
    pub z: Lanes,
}

impl Default for V3 {
    fn default() -> V3 {
        V3::ZERO
    }
}

impl V3 {
    /// Zero in every lane.
    pub const ZERO: V3 = V3 {
        x: [0.0; WIDTH],
        y: [0.0; WIDTH],
        z: [0.0; WIDTH],
    };

    /// `f(i)`'s components for every lane.
    #[inline(always)]
    pub fn map(f: impl Fn(usize) -> DVec3) -> V3 {
        let mut v = V3::ZERO;
        for i in 0..WIDTH {
            let d = f(i);
            (v.x[i], v.y[i], v.z[i]) = (d.x, d.y, d.z);
        }
        v
    }

    /// The same vector in every lane.
    #[inline(always)]
    pub fn splat(d: DVec3) -> V3 {
        V3 {
            x: [d.x; WIDTH],
            y: [d.y; WIDTH],
            z: [d.z; WIDTH],
        }
    }

    /// Lane `i` as a `DVec3`.
    #[inline(always)]
    pub fn get(&self, i: usize) -> DVec3 {
        DVec3::new(self.x[i], self.y[i], self.z[i])
    }

    /// Sets lane `i`.
    #[inline(always)]
    pub fn set(&mut self, i: usize, d: DVec3) {
        (self.x[i], self.y[i], self.z[i]) = (d.x, d.y, d.z);
    }

    /// `f` of each component's lanes.
    #[inline(always)]
    fn zip(&self, o: &V3, f: impl Fn(f64, f64) -> f64) -> V3 {
        V3 {
            x: map(|i| f(self.x[i], o.x[i])),
            y: map(|i| f(self.y[i], o.y[i])),
            z: map(|i| f(self.z[i], o.z[i])),
        }
    }

    /// `self + o`.
    #[inline(always)]
    pub fn add(&self, o: &V3) -> V3 {
        self.zip(o, |a, b| a + b)
    }

    /// `self − o`.
    #[inline(always)]
    pub fn sub(&self, o: &V3) -> V3 {
        self.zip(o, |a, b| a - b)
    }

    /// `self · o` componentwise (glam's `DVec3 * DVec3`).
    #[inline(always)]
    pub fn mul(&self, o: &V3) -> V3 {
        self.zip(o, |a, b| a * b)
    }

    /// `d − self` for one vector `d` (a light's position minus the points).
    #[inline(always)]
    pub fn from(&self, d: DVec3) -> V3 {
        V3 {
            x: map(|i| d.x - self.x[i]),
            y: map(|i| d.y - self.y[i]),
            z: map(|i| d.z - self.z[i]),
        }
    }

    /// `s · self` per lane (glam's `f64 * DVec3`; the same as `self * s`).
    #[inline(always)]
    pub fn scale(&self, s: &Lanes) -> V3 {
        V3 {
            x: map(|i| s[i] * self.x[i]),
            y: map(|i| s[i] * self.y[i]),
            z: map(|i| s[i] * self.z[i]),
        }
    }

    /// `self / s` per lane (glam's `DVec3 / f64`: three divisions).
    #[inline(always)]
    pub fn div(&self, s: &Lanes) -> V3 {
        V3 {
            x: map(|i| self.x[i] / s[i]),
            y: map(|i| self.y[i] / s[i]),
            z: map(|i| self.z[i] / s[i]),
        }
    }

    /// `−self`.
    #[inline(always)]
    pub fn neg(&self) -> V3 {
        V3 {
            x: map(|i| -self.x[i]),
            y: map(|i| -self.y[i]),
            z: map(|i| -self.z[i]),
        }
    }

    /// `|self|` componentwise.
    #[inline(always)]
    pub fn abs(&self) -> V3 {
        V3 {
            x: map(|i| self.x[i].abs()),
            y: map(|i| self.y[i].abs()),
            z: map(|i| self.z[i].abs()),
        }
    }

    /// `self · o`, as glam's `dot`: `(x·x' + y·y') + z·z'`.
    #[inline(always)]
    pub fn dot(&self, o: &V3) -> Lanes {
        map(|i| (self.x[i] * o.x[i]) + (self.y[i] * o.y[i]) + (self.z[i] * o.z[i]))
    }

    /// `|self|`, as glam's `length`.
    #[inline(always)]
    pub fn norm(&self) -> Lanes {
        let d = self.dot(self);
        map(|i| d[i].sqrt())
    }

    /// `self / |self|`, as glam's `normalize`: times `1 / |self|`.
    #[inline(always)]
    pub fn unit(&self) -> V3 {
        let len = self.norm();
        self.scale(&map(|i| 1.0 / len[i]))
    }

    /// The largest component, as glam's `max_element` (`max(x, max(y, z))` with
    /// `max(a, b) = if a > b { a } else { b }`, NaN included).
    #[inline(always)]
    pub fn max_element(&self) -> Lanes {
        let max = |a: f64, b: f64| if a > b { a } else { b };
        map(|i| max(self.x[i], max(self.y[i], self.z[i])))
    }

    /// `a` in the lanes of `m`, else `b`.
    #[inline(always)]
    pub fn select(m: Mask, a: &V3, b: &V3) -> V3 {
        V3 {
            x: select(m, &a.x, &b.x),
            y: select(m, &a.y, &b.y),
            z: select(m, &a.z, &b.z),
        }
    }
}

/// A packet of rays: origins and directions (world space; the directions unit).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RayLanes {
    /// Origins.
    pub origin: V3,
    /// Directions.
    pub dir: V3,
}

impl RayLanes {
    /// The packet of `rays` (lanes past them hold zeros).
    #[inline(always)]
    pub fn of(rays: &[crate::geometry::ray::Ray]) -> RayLanes {
        let mut p = RayLanes::default();
        for (i, r) in rays.iter().enumerate().take(WIDTH) {
            p.origin.set(i, r.origin);
            p.dir.set(i, r.dir);
        }
        p
    }

    /// The points at `t` (`Ray::at`: `origin + t·dir`).
    #[inline(always)]
    pub fn at(&self, t: &Lanes) -> V3 {
        self.origin.add(&self.dir.scale(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Norm;

    fn random_v3(rnd: &mut impl FnMut() -> f64) -> (V3, Vec<DVec3>) {
        let ds: Vec<DVec3> = (0..WIDTH)
            .map(|_| DVec3::new(rnd() - 0.5, rnd() * 1e3, -rnd() * 1e-3))
            .collect();
        (V3::map(|i| ds[i]), ds)
    }

    /// Each lane operation gives glam's result bit for bit.
    #[test]
    fn lanes_compute_what_glam_computes() {
        let mut rnd = crate::geometry::testing::test_uniform(3);
        for _ in 0..50 {
            let (a, av) = random_v3(&mut rnd);
            let (b, bv) = random_v3(&mut rnd);
            let s: Lanes = std::array::from_fn(|_| rnd() * 7.0 - 3.0);
            let (dot, len, norm, max) = (a.dot(&b), a.norm(), a.unit(), a.max_element());
            let (sum, diff, prod) = (a.add(&b), a.sub(&b), a.mul(&b));
            let (scaled, divided) = (a.scale(&s), a.div(&s));
            let from = a.from(bv[3]);
            for i in 0..WIDTH {
                let same = |x: f64, y: f64| assert_eq!(x.to_bits(), y.to_bits(), "lane {i}");
                let same3 = |x: DVec3, y: DVec3| {
                    same(x.x, y.x);
                    same(x.y, y.y);
                    same(x.z, y.z);
                };
                same(dot[i], av[i].dot(bv[i]));
                same(len[i], av[i].norm());
                same3(norm.get(i), av[i].unit());
                same(max[i], av[i].max_element());
                same3(sum.get(i), av[i] + bv[i]);
                same3(diff.get(i), av[i] - bv[i]);
                same3(prod.get(i), av[i] * bv[i]);
                same3(scaled.get(i), s[i] * av[i]);
                same3(divided.get(i), av[i] / s[i]);
                same3(from.get(i), bv[3] - av[i]);
            }
        }
    }

    #[test]
    fn masks_name_their_lanes_in_order() {
        assert_eq!(first(3), 0b111);
        assert_eq!(first(WIDTH), 0xffff);
        assert_eq!(each(0b1010_0001).collect::<Vec<_>>(), vec![0, 5, 7]);
        assert_eq!(mask_of(|i| i % 4 == 1), 0x2222);
        let a = map(|i| i as f64);
        let b = map(|i| -(i as f64));
        assert_eq!(select(0b10, &a, &b)[..3], [-0.0, 1.0, -2.0]);
    }
}
