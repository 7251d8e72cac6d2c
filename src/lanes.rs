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
//! same work takes about half the instructions (scene A, issue 12).
//!
//! What crosses lanes (selects by a [`Mask`], comparisons into one, folds across the lanes) runs
//! four lanes at a time in 256-bit registers through `wide`'s safe SIMD types: the compiler
//! vectorises the element-wise arithmetic well by itself, but a select by a bit mask, or a
//! minimum across the lanes, came out as a test and a jump per lane or as shuffles and spills
//! (issue 12: building a packet's culling bundle, `crate::geometry::lanes::cull::Bundle`, cost
//! 13% of scene A that way). Each of those operations is exact (blends, minima, maxima), so a
//! lane's value is the one the scalar code computes.
//!
//! A leaf beside [`crate::num`]: plain lane maths, no rays and no shapes (a packet of rays and
//! the shape-specific packet code, sphere lanes and culling, are `crate::geometry::lanes`).

use glam::DVec3;
use wide::f64x4;

/// Rays in a packet: a pixel's 4×4 camera samples.
pub(crate) const WIDTH: usize = 16;

/// One number per ray of a packet.
pub(crate) type Lanes = [f64; WIDTH];

/// One bit per ray of a packet (bit `i` for ray `i`).
pub(crate) type Mask = u32;

/// The mask of the first `n` rays.
#[inline(always)]
pub(crate) fn first(n: usize) -> Mask {
    if n >= WIDTH {
        (1u32 << WIDTH) - 1
    } else {
        (1u32 << n) - 1
    }
}

/// The rays of `mask`, in increasing order.
#[inline(always)]
pub(crate) fn each(mask: Mask) -> impl Iterator<Item = usize> {
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
pub(crate) fn map(f: impl Fn(usize) -> f64) -> Lanes {
    let mut out = [0.0; WIDTH];
    for (i, o) in out.iter_mut().enumerate() {
        *o = f(i);
    }
    out
}

/// The lanes where `f(i)` holds.
#[inline(always)]
pub(crate) fn mask_of(f: impl Fn(usize) -> bool) -> Mask {
    let mut m = 0;
    for i in 0..WIDTH {
        m |= Mask::from(f(i)) << i;
    }
    m
}

/// Groups of four lanes in a packet.
const QUADS: usize = WIDTH / 4;

/// All bits set: a true lane of a blend mask.
const TRUE: f64 = f64::from_bits(u64::MAX);

/// The blend mask of four lanes, indexed by their four bits of a [`Mask`].
const NIBBLES: [[f64; 4]; 16] = {
    let mut table = [[0.0; 4]; 16];
    let mut n = 0;
    while n < 16 {
        let mut j = 0;
        while j < 4 {
            if (n >> j) & 1 == 1 {
                table[n][j] = TRUE;
            }
            j += 1;
        }
        n += 1;
    }
    table
};

/// Lanes `4q … 4q + 3` of `v`.
#[inline(always)]
pub(crate) fn quad(v: &Lanes, q: usize) -> f64x4 {
    f64x4::new([v[4 * q], v[4 * q + 1], v[4 * q + 2], v[4 * q + 3]])
}

/// The blend mask of lanes `4q … 4q + 3` of `m`.
#[inline(always)]
fn quad_mask(m: Mask, q: usize) -> f64x4 {
    f64x4::new(NIBBLES[((m >> (4 * q)) & 15) as usize])
}

/// `a` where `m` has the lane, else `b`.
#[inline(always)]
pub(crate) fn select(m: Mask, a: &Lanes, b: &Lanes) -> Lanes {
    let mut out = [0.0; WIDTH];
    for q in 0..QUADS {
        let r = quad_mask(m, q).select(quad(a, q), quad(b, q));
        out[4 * q..4 * q + 4].copy_from_slice(&r.to_array());
    }
    out
}

/// The lanes where `test(quad of v, quad of splat(x))` holds, the quads' blend masks packed
/// into a [`Mask`].
#[inline(always)]
fn mask_where(v: &Lanes, x: f64, test: impl Fn(f64x4, f64x4) -> f64x4) -> Mask {
    let x = f64x4::splat(x);
    let mut m = 0;
    for q in 0..QUADS {
        m |= test(quad(v, q), x).to_bitmask() << (4 * q);
    }
    m
}

/// The lanes where `v > x` (false for NaN, as `>`).
#[inline(always)]
pub(crate) fn gt(v: &Lanes, x: f64) -> Mask {
    mask_where(v, x, f64x4::simd_gt)
}

/// The lanes where `v ≥ x` (false for NaN, as `>=`).
#[inline(always)]
pub(crate) fn ge(v: &Lanes, x: f64) -> Mask {
    mask_where(v, x, f64x4::simd_ge)
}

/// The lanes where `v < x` (false for NaN, as `<`).
#[inline(always)]
pub(crate) fn lt(v: &Lanes, x: f64) -> Mask {
    mask_where(v, x, f64x4::simd_lt)
}

/// `f` folded over the lanes: four quads into one, then its four lanes. `f` must be exact and
/// not care about order (a minimum, a maximum), or only its finiteness may matter.
#[inline(always)]
fn fold(v: &Lanes, f: impl Fn(f64x4, f64x4) -> f64x4, g: impl Fn(f64, f64) -> f64) -> f64 {
    let r = f(f(quad(v, 0), quad(v, 1)), f(quad(v, 2), quad(v, 3))).to_array();
    g(g(r[0], r[1]), g(r[2], r[3]))
}

/// The smallest lane (a NaN lane may or may not win: callers catch NaN apart).
#[inline(always)]
pub(crate) fn min(v: &Lanes) -> f64 {
    fold(v, f64x4::fast_min, |a, b| if b < a { b } else { a })
}

/// The largest lane (a NaN lane may or may not win: callers catch NaN apart).
#[inline(always)]
pub(crate) fn max(v: &Lanes) -> f64 {
    fold(v, f64x4::fast_max, |a, b| if b > a { b } else { a })
}

/// The sum of the lanes, in an order of its own: for finiteness tests only.
#[inline(always)]
pub(crate) fn sum(v: &Lanes) -> f64 {
    fold(v, |a, b| a + b, |a, b| a + b)
}

/// A vector per ray of a packet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct V3 {
    /// The rays' x.
    pub(crate) x: Lanes,
    /// The rays' y.
    pub(crate) y: Lanes,
    /// The rays' z.
    pub(crate) z: Lanes,
}

impl Default for V3 {
    fn default() -> V3 {
        V3::ZERO
    }
}

impl V3 {
    /// Zero in every lane.
    pub(crate) const ZERO: V3 = V3 {
        x: [0.0; WIDTH],
        y: [0.0; WIDTH],
        z: [0.0; WIDTH],
    };

    /// `f(i)`'s components for every lane.
    #[inline(always)]
    pub(crate) fn map(f: impl Fn(usize) -> DVec3) -> V3 {
        let mut v = V3::ZERO;
        for i in 0..WIDTH {
            let d = f(i);
            (v.x[i], v.y[i], v.z[i]) = (d.x, d.y, d.z);
        }
        v
    }

    /// The same vector in every lane.
    #[inline(always)]
    pub(crate) fn splat(d: DVec3) -> V3 {
        V3 {
            x: [d.x; WIDTH],
            y: [d.y; WIDTH],
            z: [d.z; WIDTH],
        }
    }

    /// Lane `i` as a `DVec3`.
    #[inline(always)]
    pub(crate) fn get(&self, i: usize) -> DVec3 {
        DVec3::new(self.x[i], self.y[i], self.z[i])
    }

    /// Sets lane `i`.
    #[inline(always)]
    pub(crate) fn set(&mut self, i: usize, d: DVec3) {
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
    pub(crate) fn add(&self, o: &V3) -> V3 {
        self.zip(o, |a, b| a + b)
    }

    /// `self − o`.
    #[inline(always)]
    pub(crate) fn sub(&self, o: &V3) -> V3 {
        self.zip(o, |a, b| a - b)
    }

    /// `self · o` componentwise (glam's `DVec3 * DVec3`).
    #[inline(always)]
    pub(crate) fn mul(&self, o: &V3) -> V3 {
        self.zip(o, |a, b| a * b)
    }

    /// `d − self` for one vector `d` (a light's position minus the points).
    #[inline(always)]
    pub(crate) fn from(&self, d: DVec3) -> V3 {
        V3 {
            x: map(|i| d.x - self.x[i]),
            y: map(|i| d.y - self.y[i]),
            z: map(|i| d.z - self.z[i]),
        }
    }

    /// `s · self` per lane (glam's `f64 * DVec3`; the same as `self * s`).
    #[inline(always)]
    pub(crate) fn scale(&self, s: &Lanes) -> V3 {
        V3 {
            x: map(|i| s[i] * self.x[i]),
            y: map(|i| s[i] * self.y[i]),
            z: map(|i| s[i] * self.z[i]),
        }
    }

    /// `self / s` per lane (glam's `DVec3 / f64`: three divisions).
    #[inline(always)]
    pub(crate) fn div(&self, s: &Lanes) -> V3 {
        V3 {
            x: map(|i| self.x[i] / s[i]),
            y: map(|i| self.y[i] / s[i]),
            z: map(|i| self.z[i] / s[i]),
        }
    }

    /// `−self`.
    #[inline(always)]
    pub(crate) fn neg(&self) -> V3 {
        V3 {
            x: map(|i| -self.x[i]),
            y: map(|i| -self.y[i]),
            z: map(|i| -self.z[i]),
        }
    }

    /// `|self|` componentwise.
    #[inline(always)]
    pub(crate) fn abs(&self) -> V3 {
        V3 {
            x: map(|i| self.x[i].abs()),
            y: map(|i| self.y[i].abs()),
            z: map(|i| self.z[i].abs()),
        }
    }

    /// `self · o`, as glam's `dot`: `(x·x' + y·y') + z·z'`.
    #[inline(always)]
    pub(crate) fn dot(&self, o: &V3) -> Lanes {
        map(|i| (self.x[i] * o.x[i]) + (self.y[i] * o.y[i]) + (self.z[i] * o.z[i]))
    }

    /// `|self|`, as glam's `length`.
    #[inline(always)]
    pub(crate) fn norm(&self) -> Lanes {
        let d = self.dot(self);
        map(|i| d[i].sqrt())
    }

    /// `self / |self|`, as glam's `normalize`: times `1 / |self|` (the tests': the renderer
    /// divides by the lengths it already has).
    #[cfg(test)]
    fn unit(&self) -> V3 {
        let len = self.norm();
        self.scale(&map(|i| 1.0 / len[i]))
    }

    /// The largest component, as glam's `max_element` (`max(x, max(y, z))` with
    /// `max(a, b) = if a > b { a } else { b }`, NaN included).
    #[inline(always)]
    pub(crate) fn max_element(&self) -> Lanes {
        let max = |a: f64, b: f64| if a > b { a } else { b };
        map(|i| max(self.x[i], max(self.y[i], self.z[i])))
    }

    /// `a` in the lanes of `m`, else `b`.
    #[inline(always)]
    pub(crate) fn select(m: Mask, a: &V3, b: &V3) -> V3 {
        V3 {
            x: select(m, &a.x, &b.x),
            y: select(m, &a.y, &b.y),
            z: select(m, &a.z, &b.z),
        }
    }
}

/// Uniform numbers in [0, 1) from a seeded 64-bit LCG (Knuth's MMIX constants, top 53 bits), as
/// `geometry::testing::test_uniform`: reproducible lanes for unit tests.
#[cfg(test)]
fn test_uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut seed = seed;
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64) / (1u64 << 53) as f64
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
        let mut rnd = test_uniform(3);
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

    /// Selects pick lane by lane as the mask says, and folds find the extremes, on random
    /// lanes and masks.
    #[test]
    fn quads_select_and_fold_like_lane_by_lane_code() {
        let mut rnd = test_uniform(5);
        for round in 0..200 {
            let a: Lanes = std::array::from_fn(|_| rnd() * 200.0 - 100.0);
            let b: Lanes = std::array::from_fn(|_| rnd() * 200.0 - 100.0);
            let m = ((rnd() * 65536.0) as Mask) | if round == 0 { 0xffff } else { 0 };
            let got = select(m, &a, &b);
            for i in 0..WIDTH {
                let want = if m & (1 << i) != 0 { a[i] } else { b[i] };
                assert_eq!(got[i].to_bits(), want.to_bits(), "lane {i} of {m:#x}");
            }
            assert_eq!(min(&a), a.iter().copied().fold(f64::INFINITY, f64::min));
            assert_eq!(max(&a), a.iter().copied().fold(f64::NEG_INFINITY, f64::max));
            assert!(sum(&a).is_finite());
            let mut v = a;
            v[round % WIDTH] = [f64::NAN, 0.0, -0.0, f64::INFINITY][round % 4];
            for (got, test) in [
                (gt(&v, 0.0), (|x: f64| x > 0.0) as fn(f64) -> bool),
                (ge(&v, 0.0), |x| x >= 0.0),
                (lt(&v, 0.0), |x| x < 0.0),
                (lt(&v, f64::INFINITY), |x| x < f64::INFINITY),
            ] {
                assert_eq!(got, mask_of(|i| test(v[i])), "{v:?}");
            }
        }
        let mut odd = [1.0; WIDTH];
        odd[13] = f64::INFINITY;
        assert!(!sum(&odd).is_finite());
        odd[13] = f64::NAN;
        assert!(sum(&odd).is_nan());
    }
}
