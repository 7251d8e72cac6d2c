//! The ideal directions of smooth surfaces: the mirror direction and Snell's refraction, for one
//! ray and for a packet's lanes.

use crate::lanes::{self, V3};
use crate::num::Norm;
use glam::DVec3;

/// Snell's law: the refracted direction of unit `d` at a surface with unit normal `n` facing the
/// incoming ray, going from index `n1` into `n2`; `None` on total internal reflection.
pub fn refract(d: DVec3, n: DVec3, n1: f64, n2: f64) -> Option<DVec3> {
    let r = n1 / n2;
    let cos_i = (-d.dot(n)).min(1.0);
    let k = 1.0 - r * r * (1.0 - cos_i * cos_i);
    if k < 0.0 {
        return None;
    }
    Some((r * d + (r * cos_i - k.sqrt()) * n).unit())
}

/// The mirror direction of unit `d` about unit `n`.
pub(crate) fn reflect(d: DVec3, n: DVec3) -> DVec3 {
    d - 2.0 * d.dot(n) * n
}

/// [`reflect`] lane by lane, `d − (2·(d·n))·n`, the same operations in the same order.
#[inline(always)]
pub(crate) fn reflect_lanes(d: &V3, n: &V3) -> V3 {
    let d_n = d.dot(n);
    d.sub(&n.scale(&lanes::map(|i| 2.0 * d_n[i])))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn head_on_refraction_is_undeviated() {
        let d = DVec3::new(0.0, 0.0, -1.0);
        let t = refract(d, DVec3::Z, 1.0, 1.5).unwrap();
        assert!((t - d).norm() < 1e-15);
    }

    #[test]
    fn snell_holds_and_total_internal_reflection_past_the_critical_angle() {
        let n = DVec3::Y;
        for deg in [10.0f64, 30.0, 41.0, 42.0, 60.0, 89.0] {
            let a = deg.to_radians();
            let d = DVec3::new(a.sin(), -a.cos(), 0.0);
            // Into glass: always refracts, sin θt = sin θi / 1.5.
            let t = refract(d, n, 1.0, 1.5).unwrap();
            assert!((t.x - a.sin() / 1.5).abs() < 1e-12);
            // Out of glass: the critical angle is asin(1/1.5) ≈ 41.81°.
            let out = refract(d, n, 1.5, 1.0);
            assert_eq!(out.is_none(), deg > 41.82, "{deg}");
            if let Some(t) = out {
                assert!((t.x - a.sin() * 1.5).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn lanes_reflect_bit_for_bit_as_one_ray() {
        let d = V3::map(|i| DVec3::new(0.3 + i as f64 * 0.01, -0.8, 0.1 * i as f64).unit());
        let n = V3::map(|i| DVec3::new(0.05 * i as f64, 1.0, -0.2).unit());
        let r = reflect_lanes(&d, &n);
        for i in 0..lanes::WIDTH {
            assert_eq!(r.get(i), reflect(d.get(i), n.get(i)));
        }
    }
}
