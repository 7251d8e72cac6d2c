//! Bounds of moving nodes: a box that holds a node wherever it is while the shutter is open, so
//! a BVH built over such boxes never misses it.

use crate::num::Norm;
use glam::{DAffine3, DVec3};

use crate::geometry::aabb::Aabb;
use crate::ir::Motion;

/// Times sampled across the shutter; the padding below covers the path between them.
const STEPS: u32 = 32;

/// A box holding `local` (object-space bounds) placed by `motion.at(transform, s)` for every
/// s ∈ [0, 1]: the union of the placed boxes at `STEPS + 1` times, grown by half of the
/// longest distance any corner can travel between two neighbouring times. A point whose path
/// between two samples has length L is never farther than L/2 from one of them, so the box is
/// conservative for rotation as well as for straight motion.
pub(crate) fn swept_bounds(local: Aabb, transform: DAffine3, motion: &Motion) -> Aabb {
    if local.is_empty() || !local.is_finite() {
        return local.transformed(&transform);
    }
    let mut b = Aabb::EMPTY;
    for i in 0..=STEPS {
        let s = f64::from(i) / f64::from(STEPS);
        b = b.union(local.transformed(&motion.at(transform, s)));
    }
    // A corner p moves as x(s) = F·q(s) with q(s) = D(s)·r, r = F⁻¹·T·p (F: the motion's frame).
    // |q'(s)| ≤ |translate| + θ·|S(s)·r| + |scale − 1|·|r| (θ: the whole angle turned, the
    // slerp's arc or the spin).
    let to_motion = motion.frame.inverse() * transform;
    let r_max = corners(&local)
        .iter()
        .map(|c| to_motion.transform_point3(*c).norm())
        .fold(0.0, f64::max);
    let theta = motion.turned();
    let s_max = motion.scale.abs().max_element().max(1.0);
    let ds = (motion.scale - DVec3::ONE).abs().max_element();
    let speed = motion.translate.norm() + (theta * s_max + ds) * r_max;
    let m = motion.frame.matrix3;
    let frame_norm =
        (m.x_axis.length_squared() + m.y_axis.length_squared() + m.z_axis.length_squared()).sqrt();
    let pad = 0.5 * frame_norm * speed / f64::from(STEPS);
    Aabb::new(b.min - DVec3::splat(pad), b.max + DVec3::splat(pad))
}

fn corners(b: &Aabb) -> [DVec3; 8] {
    let (lo, hi) = (b.min, b.max);
    std::array::from_fn(|i| {
        DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    #[test]
    fn a_spinning_box_stays_inside_its_swept_bounds() {
        let local = Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
        let transform = DAffine3::from_translation(DVec3::new(3.0, 0.0, 0.0));
        let motion = Motion::new(
            DVec3::new(0.0, 2.0, 0.0),
            DQuat::from_rotation_y(170f64.to_radians()),
            DVec3::splat(1.5),
        );
        let b = swept_bounds(local, transform, &motion);
        for i in 0..=1000 {
            let s = f64::from(i) / 1000.0;
            let placed = local.transformed(&motion.at(transform, s));
            assert!(
                b.contains(placed.min, 0.0) && b.contains(placed.max, 0.0),
                "s = {s}"
            );
        }
    }

    /// A spin of three quarters of a turn and more sweeps the whole circle it turns through,
    /// not the shorter arc between its ends.
    #[test]
    fn a_long_spin_is_covered() {
        let local = Aabb::new(DVec3::new(2.0, -0.1, -0.1), DVec3::new(2.2, 0.1, 0.1));
        let motion = Motion::new(DVec3::ZERO, DQuat::IDENTITY, DVec3::ONE)
            .with_spin(DVec3::Z, 450f64.to_radians());
        let b = swept_bounds(local, DAffine3::IDENTITY, &motion);
        for i in 0..=1000 {
            let s = f64::from(i) / 1000.0;
            let placed = local.transformed(&motion.at(DAffine3::IDENTITY, s));
            assert!(
                b.contains(placed.min, 0.0) && b.contains(placed.max, 0.0),
                "s = {s}"
            );
        }
        assert!(
            b.min.x < -2.0 && b.min.y < -2.0,
            "the far side of the circle: {b:?}"
        );
    }
}
