//! Written values that the language turns into exactly the IR's numbers where it normalises
//! what it reads: a direction it makes a unit vector, a rotation it makes a quaternion, a spin
//! it splits into axis and angle. Each is found among the IR value's neighbours a few units of
//! the last place away, checked with the language's own arithmetic.

use glam::{DMat3, DQuat, DVec3};

use crate::ir::Motion;
use crate::num::Norm;

/// Units of the last place tried on each side of a number.
const REACH: i64 = 2;

/// A vector whose unit vector (`v · (1 / |v|)`, as the language normalises a `normal:`) is
/// exactly `n`; `n` itself when none is found near it.
pub(crate) fn unit_preimage(n: DVec3) -> DVec3 {
    if n.unit() == n {
        return n;
    }
    for scale in [1.0, 3.0, 5.0, 7.0, 10.0] {
        let base = (n * scale).to_array();
        let found = around(&base, |c| {
            let v = DVec3::from_array([c[0], c[1], c[2]]);
            (v.unit() == n).then_some(v)
        });
        if let Some(v) = found {
            return v;
        }
    }
    n
}

/// A rotation matrix the language turns into exactly `q` (`from_mat3(m).normalize()`); `q`'s
/// own matrix when none is found near it.
pub(crate) fn rotation_preimage(q: DQuat) -> DMat3 {
    let base = DMat3::from_quat(q);
    around(&base.to_cols_array(), |c| {
        let m = DMat3::from_cols_array(&[c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]]);
        (DQuat::from_mat3(&m).normalize() == q).then_some(m)
    })
    .unwrap_or(base)
}

/// `spin:` and `axis:` that give back the spin vector `s` (the language keeps
/// `axis / |axis| · angle`).
pub(crate) fn spin_preimage(s: DVec3) -> (DVec3, f64) {
    let angle = s.norm();
    let rebuilt = |axis: DVec3, a: f64| {
        Motion::new(DVec3::ZERO, DQuat::IDENTITY, DVec3::ONE)
            .with_spin(axis, a)
            .spin
    };
    for axis in [s, s / angle] {
        let found = around(&[angle, axis.x, axis.y, axis.z], |c| {
            let axis = DVec3::new(c[1], c[2], c[3]);
            (rebuilt(axis, c[0]) == s).then_some((axis, c[0]))
        });
        if let Some(f) = found {
            return f;
        }
    }
    (s, angle)
}

/// The first `f(cells)` that is `Some`, over `base` and its neighbours: every non-zero cell
/// moved by up to [`REACH`] units of the last place (zeros stay zeros), nearest first.
fn around<T>(base: &[f64], f: impl Fn(&[f64]) -> Option<T>) -> Option<T> {
    let free: Vec<usize> = (0..base.len()).filter(|&i| base[i] != 0.0).collect();
    for reach in 0..=REACH {
        let side = 2 * reach + 1;
        let count = side.pow(free.len() as u32);
        for k in 0..count {
            let mut cells = base.to_vec();
            let mut rest = k;
            let mut outer = false;
            for &i in &free {
                let step = rest % side - reach;
                rest /= side;
                outer |= step.abs() == reach;
                cells[i] = next(base[i], step);
            }
            // Each ring tries only what the smaller rings did not.
            if reach > 0 && !outer {
                continue;
            }
            if let Some(t) = f(&cells) {
                return Some(t);
            }
        }
    }
    None
}

/// The float `steps` units of the last place above `x` (below for negative steps), for `x`
/// not zero.
fn next(x: f64, steps: i64) -> f64 {
    let bits = x.to_bits() as i64;
    let signed = if x > 0.0 { steps } else { -steps };
    f64::from_bits((bits + signed) as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn preimages_give_back_their_values() {
        let n = DVec3::new(0.0, 0.4, 1.0).unit();
        assert_eq!(unit_preimage(n).unit(), n);
        let q = DQuat::from_rotation_z(230f64.to_radians());
        let q = DQuat::from_mat3(&DMat3::from_quat(q)).normalize();
        assert_eq!(DQuat::from_mat3(&rotation_preimage(q)).normalize(), q);
        assert_eq!(next(1.0, 1), 1.0 + f64::EPSILON);
        assert_eq!(next(-1.0, 1), -1.0 + f64::EPSILON / 2.0);
    }
}
