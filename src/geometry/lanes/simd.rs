//! A packet's lanes ([`crate::geometry::lanes`]) four at a time in 256-bit registers through `wide`'s safe
//! SIMD types: selects by a lane mask, comparisons into one, and folds across the lanes.
//!
//! Why: the compiler vectorises the lanes' element-wise arithmetic well by itself, but a select
//! by a bit mask, or a minimum across the lanes, came out as a test and a jump per lane or as
//! shuffles and spills (issue 12: building a packet's [`crate::geometry::lanes::cull::Bundle`] cost 13%
//! of scene A that way). Each operation here is exact (blends, minima, maxima), so a lane's
//! value is the one the scalar code computes.

use wide::f64x4;

use crate::geometry::lanes::{Lanes, Mask, WIDTH};

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
pub fn quad(v: &Lanes, q: usize) -> f64x4 {
    f64x4::new([v[4 * q], v[4 * q + 1], v[4 * q + 2], v[4 * q + 3]])
}

/// The blend mask of lanes `4q … 4q + 3` of `m`.
#[inline(always)]
fn mask(m: Mask, q: usize) -> f64x4 {
    f64x4::new(NIBBLES[((m >> (4 * q)) & 15) as usize])
}

/// `a` where `m` has the lane, else `b`.
#[inline(always)]
pub fn select(m: Mask, a: &Lanes, b: &Lanes) -> Lanes {
    let mut out = [0.0; WIDTH];
    for q in 0..QUADS {
        let r = mask(m, q).select(quad(a, q), quad(b, q));
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
pub fn gt(v: &Lanes, x: f64) -> Mask {
    mask_where(v, x, f64x4::simd_gt)
}

/// The lanes where `v ≥ x` (false for NaN, as `>=`).
#[inline(always)]
pub fn ge(v: &Lanes, x: f64) -> Mask {
    mask_where(v, x, f64x4::simd_ge)
}

/// The lanes where `v < x` (false for NaN, as `<`).
#[inline(always)]
pub fn lt(v: &Lanes, x: f64) -> Mask {
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
pub fn min(v: &Lanes) -> f64 {
    fold(v, f64x4::fast_min, |a, b| if b < a { b } else { a })
}

/// The largest lane (a NaN lane may or may not win: callers catch NaN apart).
#[inline(always)]
pub fn max(v: &Lanes) -> f64 {
    fold(v, f64x4::fast_max, |a, b| if b > a { b } else { a })
}

/// The sum of the lanes, in an order of its own: for finiteness tests only.
#[inline(always)]
pub fn sum(v: &Lanes) -> f64 {
    fold(v, |a, b| a + b, |a, b| a + b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::lanes;

    /// Selects pick lane by lane as the mask says, and folds find the extremes, on random
    /// lanes and masks.
    #[test]
    fn quads_select_and_fold_like_lane_by_lane_code() {
        let mut rnd = crate::geometry::testing::test_uniform(5);
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
                assert_eq!(got, lanes::mask_of(|i| test(v[i])), "{v:?}");
            }
        }
        let mut odd = [1.0; WIDTH];
        odd[13] = f64::INFINITY;
        assert!(!sum(&odd).is_finite());
        odd[13] = f64::NAN;
        assert!(sum(&odd).is_nan());
    }
}
