//! Real roots of polynomials up to degree 15 on an interval, in f64 (tori and blobs use
//! degree 4, surfaces of revolution 6, algebraic surfaces up to 15).
//!
//! Closed-form quartic formulas lose most of their digits on grazing rays (two nearly equal
//! roots), which shows as speckle. Instead the roots are isolated by the critical points of the
//! polynomial (the roots of its derivative, found the same way, recursively): between two
//! neighbouring critical points the polynomial is monotone, so a sign change brackets exactly one
//! root, which safeguarded Newton steps then polish to full precision.

/// Maximum degree handled. A polynomial of degree `n` has at most `n` real roots, so every
/// fixed-size list below holds them all; higher coefficients are ignored.
pub(crate) const MAX_DEGREE: usize = 15;

/// A root where the polynomial changes sign; `rising` is true when it goes from − to +.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Root {
    /// Location.
    pub(crate) t: f64,
    /// Sign of the polynomial just after the root is positive.
    pub(crate) rising: bool,
}

/// A small fixed-capacity list of roots (at most `MAX_DEGREE`).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Roots {
    items: [f64; MAX_DEGREE],
    rising: [bool; MAX_DEGREE],
    len: usize,
}

impl Roots {
    fn push(&mut self, t: f64, rising: bool) {
        if self.len < MAX_DEGREE {
            self.items[self.len] = t;
            self.rising[self.len] = rising;
            self.len += 1;
        }
    }

    /// Number of roots (the tests').
    #[cfg(test)]
    fn len(&self) -> usize {
        self.len
    }

    /// The roots in increasing order.
    pub(crate) fn iter(&self) -> impl Iterator<Item = Root> + '_ {
        (0..self.len).map(|i| Root {
            t: self.items[i],
            rising: self.rising[i],
        })
    }
}

/// Evaluates `c[0] + c[1]·x + … + c[deg]·x^deg` (Horner).
pub(crate) fn eval(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &k| acc * x + k)
}

/// Value and derivative at `x`.
fn eval_d(c: &[f64], x: f64) -> (f64, f64) {
    let mut p = 0.0;
    let mut d = 0.0;
    for &k in c.iter().rev() {
        d = d * x + p;
        p = p * x + k;
    }
    (p, d)
}

/// The sign-changing real roots of the polynomial with coefficients `c` (lowest degree first,
/// at most degree [`MAX_DEGREE`]) strictly inside `(a, b)`, in increasing order. Roots of even multiplicity
/// (a ray touching a surface) do not change the sign and are not reported.
pub(crate) fn roots_in(c: &[f64], a: f64, b: f64) -> Roots {
    let mut deg = c.len().min(MAX_DEGREE + 1);
    while deg > 0 && c[deg - 1] == 0.0 {
        deg -= 1;
    }
    let c = &c[..deg];
    let mut out = Roots::default();
    if deg < 2 || a >= b || !a.is_finite() || !b.is_finite() {
        return out;
    }
    // Most calls (a ray passing a lathe's segment, a sweep's piece) have no root at all: the
    // Bernstein hull proves that in O(n²) before the derivative chain is searched.
    if deg > 3 && one_sign_on(c, a, b) {
        return out;
    }
    // Critical points split (a, b) into monotone pieces.
    let mut d = [0.0; MAX_DEGREE];
    for i in 1..deg {
        d[i - 1] = c[i] * i as f64;
    }
    let mut knots = [0.0; MAX_DEGREE + 1];
    let mut n = 0;
    knots[n] = a;
    n += 1;
    if deg > 2 {
        for r in critical_points(&d[..deg - 1], a, b) {
            if r > knots[n - 1] && r < b && n < knots.len() - 1 {
                knots[n] = r;
                n += 1;
            }
        }
    }
    knots[n] = b;
    n += 1;
    let mut prev = eval(c, knots[0]);
    for w in 1..n {
        let (x0, x1) = (knots[w - 1], knots[w]);
        let f1 = eval(c, x1);
        if (prev < 0.0 && f1 > 0.0) || (prev > 0.0 && f1 < 0.0) {
            out.push(polish(c, x0, x1, prev), f1 > 0.0);
        } else if f1 == 0.0 && w + 1 < n {
            // An exact zero at a critical point: a root when the sign differs on both sides.
            let next = eval(c, knots[w + 1]);
            if (prev < 0.0 && next > 0.0) || (prev > 0.0 && next < 0.0) {
                out.push(x1, next > 0.0);
            }
            continue;
        }
        if f1 != 0.0 {
            prev = f1;
        }
    }
    out
}

/// True when `c` (at least two coefficients) is provably nonzero with one sign on all of
/// `[a, b]`: every coefficient of its Bernstein form on the interval is strictly of one sign by
/// more than the conversion's rounding error (the hull property puts the curve between the
/// smallest and largest of them). False means only "not proven": the caller searches.
fn one_sign_on(c: &[f64], a: f64, b: f64) -> bool {
    let n = c.len() - 1;
    let mut k = [0.0; MAX_DEGREE + 1];
    let mut m = [0.0; MAX_DEGREE + 1];
    k[..=n].copy_from_slice(c);
    for (mi, ci) in m.iter_mut().zip(c) {
        *mi = ci.abs();
    }
    // Taylor shift to `a` (repeated synthetic division), the magnitudes alongside for the
    // error bound, then scaling to u ∈ [0, 1].
    for i in 0..n {
        for j in (i..n).rev() {
            k[j] += a * k[j + 1];
            m[j] += a.abs() * m[j + 1];
        }
    }
    let w = b - a;
    let mut wk = 1.0;
    for j in 0..=n {
        k[j] *= wk;
        m[j] *= wk;
        wk *= w;
    }
    // b_j = Σ_{i ≤ j} C(j, i) / C(n, i) · k_i, each checked as soon as it is known.
    let mut sign = 0.0;
    for j in 0..=n {
        let (mut sum, mut mag, mut ratio) = (0.0, 0.0, 1.0);
        for i in 0..=j {
            sum += ratio * k[i];
            mag += ratio * m[i];
            // C(j, i+1)/C(n, i+1) = C(j, i)/C(n, i) · (j − i)/(n − i).
            if i < j {
                ratio *= (j - i) as f64 / (n - i) as f64;
            }
        }
        // About (4n + 4)·ε of `mag` can be rounding; 1e-13 is over ten times that for n ≤ 15.
        let margin = 1e-13 * mag;
        let s = if sum > margin {
            1.0
        } else if sum < -margin {
            -1.0
        } else {
            return false;
        };
        if (sign != 0.0 && s != sign) || !sum.is_finite() {
            return false;
        }
        sign = s;
    }
    true
}

/// All critical points of a polynomial given its derivative coefficients `d`: the points
/// where the derivative changes sign, plus its double roots (exact zeros of both).
fn critical_points(d: &[f64], a: f64, b: f64) -> impl Iterator<Item = f64> {
    let mut pts = [0.0; MAX_DEGREE];
    let mut n = 0;
    for r in roots_in(d, a, b).iter() {
        pts[n] = r.t;
        n += 1;
    }
    // Where the derivative only touches zero (an inflection with a flat tangent), the
    // polynomial is still monotone, so those points need no split.
    pts.into_iter().take(n)
}

/// The unique root of a polynomial monotone on `[lo, hi]` with a sign change, to full precision.
fn polish(c: &[f64], mut lo: f64, mut hi: f64, f_lo: f64) -> f64 {
    let lo_negative = f_lo < 0.0;
    let mut x = 0.5 * (lo + hi);
    for _ in 0..200 {
        let (f, df) = eval_d(c, x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == lo_negative {
            lo = x;
        } else {
            hi = x;
        }
        let newton = x - f / df;
        let next = if newton > lo && newton < hi && newton.is_finite() {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if next == x || hi - lo <= f64::EPSILON * lo.abs().max(hi.abs()) {
            return next;
        }
        x = next;
    }
    x
}

/// A bound on the magnitude of every root (Cauchy's: `1 + max |c_i / c_deg|`), so the whole real
/// line's roots are those in `(−bound, bound)`; `None` for a constant or non-finite polynomial.
pub(crate) fn root_bound(c: &[f64]) -> Option<f64> {
    let deg = c.iter().rposition(|&k| k != 0.0)?;
    if deg == 0 {
        return None;
    }
    let lead = c[deg].abs();
    let m = c[..deg].iter().fold(0.0f64, |m, &k| m.max(k.abs() / lead));
    let b = 1.0 + m;
    // Doubling keeps the roots strictly inside, away from the open interval's ends.
    (b.is_finite()).then_some(2.0 * b)
}

/// Both real roots of `a·t² + b·t + c` in increasing order (equal for a double root), using the
/// cancellation-free form; a linear equation gives its one root twice.
pub(crate) fn quadratic(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    if a == 0.0 {
        if b == 0.0 {
            return None;
        }
        let t = -c / b;
        return Some((t, t));
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 || !disc.is_finite() {
        return None;
    }
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
    Some(if t0 <= t1 { (t0, t1) } else { (t1, t0) })
}

/// The smallest root in (t_min, t_max) among those `roots` reports (torus and blob hits).
pub(crate) fn nearest_root(
    t_min: f64,
    t_max: f64,
    roots: impl FnOnce(&mut dyn FnMut(f64, bool)),
) -> Option<f64> {
    let mut best: Option<f64> = None;
    roots(&mut |t, _| {
        if t > t_min && t < t_max && best.is_none_or(|b| t < b) {
            best = Some(t);
        }
    });
    best
}

#[cfg(test)]
mod tests {
    #[test]
    fn quadratic_is_stable_for_tiny_roots() {
        let (t0, t1) = super::quadratic(1.0, -1e8, 1.0).unwrap();
        assert!((t0 - 1e-8).abs() < 1e-20 && (t1 - 1e8).abs() < 1e-6);
    }

    use super::*;

    fn from_roots(r: &[f64]) -> Vec<f64> {
        // Multiply out (x − r_i).
        let mut c = vec![1.0];
        for &ri in r {
            let mut next = vec![0.0; c.len() + 1];
            for (i, &k) in c.iter().enumerate() {
                next[i + 1] += k;
                next[i] -= ri * k;
            }
            c = next;
        }
        c
    }

    #[test]
    fn finds_all_four_distinct_roots_in_order() {
        let c = from_roots(&[-3.0, -0.5, 1.25, 7.0]);
        let r: Vec<_> = roots_in(&c, -10.0, 10.0).iter().map(|r| r.t).collect();
        assert_eq!(r.len(), 4);
        for (got, want) in r.iter().zip([-3.0, -0.5, 1.25, 7.0]) {
            assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        }
        // x⁴ leading coefficient positive: the last root rises.
        assert!(
            roots_in(&c, -10.0, 10.0)
                .iter()
                .last()
                .is_some_and(|r| r.rising)
        );
    }

    #[test]
    fn separates_nearly_equal_roots() {
        let c = from_roots(&[1.0, 1.0 + 1e-7, 2.0, 5.0]);
        let r: Vec<_> = roots_in(&c, 0.0, 10.0).iter().map(|r| r.t).collect();
        assert_eq!(r.len(), 4, "{r:?}");
        // Conditioning limits these two to ~ε·|c|/|p'| ≈ 1e-8; what matters is that both exist.
        assert!(r[0] < r[1], "{r:?}");
        assert!(
            (r[0] - 1.0).abs() < 5e-8 && (r[1] - 1.0 - 1e-7).abs() < 5e-8,
            "{r:?}"
        );
        assert!(
            (r[2] - 2.0).abs() < 1e-12 && (r[3] - 5.0).abs() < 1e-12,
            "{r:?}"
        );
    }

    #[test]
    fn double_root_is_not_a_crossing_and_interval_is_respected() {
        let c = from_roots(&[2.0, 2.0, 3.0, 4.0]);
        let r: Vec<_> = roots_in(&c, 0.0, 3.5).iter().map(|r| r.t).collect();
        assert_eq!(r.len(), 1, "{r:?}");
        assert!((r[0] - 3.0).abs() < 1e-12);
    }

    fn found(c: &[f64], a: f64, b: f64) -> Vec<f64> {
        roots_in(c, a, b).iter().map(|r| r.t).collect()
    }

    #[test]
    fn degree_fifteen_with_integer_roots() {
        let want: Vec<f64> = (-7..=7).map(f64::from).collect();
        let c = from_roots(&want);
        assert_eq!(c.len(), 16);
        let r = found(&c, -20.0, 20.0);
        assert_eq!(r.len(), 15, "{r:?}");
        for (got, w) in r.iter().zip(&want) {
            assert!((got - w).abs() < 1e-9, "{got} vs {w}");
        }
        // Signs alternate, the last one rising (positive leading coefficient, odd degree).
        let rs: Vec<bool> = roots_in(&c, -20.0, 20.0).iter().map(|r| r.rising).collect();
        assert!(rs.windows(2).all(|w| w[0] != w[1]) && rs[14]);
    }

    #[test]
    fn clustered_roots_of_a_high_degree_polynomial() {
        // Five roots within 0.04 of each other, plus far ones. (Closer clusters fall below
        // what f64 coefficients can resolve: between roots 1e-3 apart the polynomial is ~1e-14,
        // under the ~1e-13 rounding of evaluating it.)
        let want = [0.99, 0.995, 1.0, 1.01, 1.03, -2.0, 4.0, 9.0];
        let c = from_roots(&want);
        let r = found(&c, -10.0, 10.0);
        assert_eq!(r.len(), 8, "{r:?}");
        let mut sorted = want;
        sorted.sort_by(f64::total_cmp);
        for (got, w) in r.iter().zip(sorted) {
            // The cluster's roots are conditioned by p' ~ 3e-9 against ~1e-13 of rounding.
            let tol = if (w - 1.0).abs() < 0.05 { 1e-6 } else { 1e-9 };
            assert!((got - w).abs() < tol, "{got} vs {w}");
        }
    }

    #[test]
    fn roots_spanning_twelve_orders_of_magnitude() {
        let want = [1e-6, 1e-3, 1.0, 1e3, 1e6, -1e-6, -5e5];
        let c = from_roots(&want);
        let bound = root_bound(&c).unwrap();
        let r = found(&c, -bound, bound);
        assert_eq!(r.len(), 7, "{r:?}");
        let mut sorted = want;
        sorted.sort_by(f64::total_cmp);
        for (got, w) in r.iter().zip(sorted) {
            assert!((got - w).abs() <= 1e-9 * w.abs(), "{got} vs {w}");
        }
    }

    #[test]
    fn the_root_bound_holds_and_even_roots_are_skipped() {
        // (x² + 1)·(x − 3)²·(x + 0.5): one sign-changing root, the double one touches.
        let c = from_roots(&[3.0, 3.0, -0.5]);
        let c: Vec<f64> = {
            let mut out = vec![0.0; c.len() + 2];
            for (i, &k) in c.iter().enumerate() {
                out[i] += k;
                out[i + 2] += k;
            }
            out
        };
        let b = root_bound(&c).unwrap();
        assert!(b > 3.0);
        assert_eq!(found(&c, -b, b), vec![-0.5]);
        assert_eq!(root_bound(&[2.0, 0.0]), None);
    }

    #[test]
    fn the_hull_proves_one_sign_only_where_there_is_one() {
        // Roots outside [0, 1]: proven; a root inside, or a touch at 0.5: never.
        assert!(one_sign_on(&from_roots(&[2.0, 3.0, -5.0, 1.5]), 0.0, 1.0));
        assert!(one_sign_on(
            &from_roots(&[1.0 + 1e-3, -1e-3, 4.0, 9.0, -2.0]),
            0.0,
            1.0
        ));
        assert!(!one_sign_on(&from_roots(&[0.3, 3.0, -5.0, 1.5]), 0.0, 1.0));
        assert!(!one_sign_on(&from_roots(&[0.5, 0.5, 4.0, 7.0]), 0.0, 1.0));
        // Random polynomials: whenever the hull says one sign, dense samples agree and the
        // search finds no root (the hull never hides a root the search would report).
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let mut proven = 0;
        for case in 0..2000 {
            let n = 4 + case % 8;
            let c: Vec<f64> = (0..=n).map(|_| next() * 10f64.powf(3.0 * next())).collect();
            let (a, b) = (next() * 3.0, 3.0 + next() * 3.0);
            if one_sign_on(&c, a, b) {
                proven += 1;
                let s0 = eval(&c, a).signum();
                for i in 0..=400 {
                    let x = a + (b - a) * f64::from(i) / 400.0;
                    assert_eq!(eval(&c, x).signum(), s0, "{c:?} on [{a}, {b}] at {x}");
                }
            }
        }
        assert!(proven > 50, "the hull proved only {proven} of 2000");
    }

    #[test]
    fn quadratic_and_cubic() {
        let r: Vec<_> = roots_in(&from_roots(&[-1.0, 2.0]), -5.0, 5.0)
            .iter()
            .map(|r| r.t)
            .collect();
        assert_eq!(r, vec![-1.0, 2.0]);
        let r = roots_in(&from_roots(&[0.1, 0.2, 0.3]), 0.0, 1.0);
        assert_eq!(r.len(), 3);
    }
}
