//! Floating-point error bounds of hit points (after pbrt-v4's `gamma` and `Point3fi`).
//!
//! Every hit carries a per-axis bound on how far its point may lie from the true surface. A
//! shape computes it in its own space from the point's residual (how far the computed point is
//! from the surface, by the shape's distance-like function) plus the rounding of evaluating that
//! residual; each transform on the way out adds the rounding of its own arithmetic. Spawned rays
//! start just outside that box (`render::offset`), and CSG treats crossings whose boxes touch as
//! one event ([`same_event`]).

use glam::{DAffine3, DVec3};

/// Unit roundoff of f64 (half the machine epsilon).
const UNIT_ROUNDOFF: f64 = f64::EPSILON * 0.5;

/// `γ(n) = nu / (1 − nu)`: the relative error bound of `n` rounded operations (Higham).
pub const fn gamma(n: u32) -> f64 {
    let nu = n as f64 * UNIT_ROUNDOFF;
    nu / (1.0 - nu)
}

/// A surface point's bound from its residual: `|residual|` (the distance from the computed
/// point to the surface, as evaluated) plus `γ(ops)·magnitude` (what that evaluation may be off
/// by, `magnitude` being the largest size that entered it). The same on every axis.
pub(crate) fn from_residual(residual: f64, ops: u32, magnitude: f64) -> DVec3 {
    DVec3::splat(residual.abs() + gamma(ops) * magnitude)
}

/// The point `p` (error bound `err`) moved by `m`, and the bound of the result: the rounding of
/// `m·p + translation` plus the error carried through the matrix (pbrt-v4 `Transform` of a
/// `Point3fi`).
pub(crate) fn transform_point(m: &DAffine3, p: DVec3, err: DVec3) -> (DVec3, DVec3) {
    let q = m.transform_point3(p);
    let a = m.matrix3.transpose();
    let (ax, ay, az) = (a.x_axis.abs(), a.y_axis.abs(), a.z_axis.abs());
    let pa = p.abs();
    let t = m.translation.abs();
    let rounding = DVec3::new(ax.dot(pa), ay.dot(pa), az.dot(pa)) + t;
    let carried = DVec3::new(ax.dot(err), ay.dot(err), az.dot(err));
    (q, gamma(3) * rounding + (1.0 + gamma(3)) * carried)
}

/// Whether two crossings of one ray (points `pa`, `pb` with bounds `ea`, `eb` and unit normals
/// `na`, `nb`) may be the same place: along each normal the points are no farther apart than
/// their bounds allow. Crossings this close cannot be ordered by their computed `t`.
pub(crate) fn same_event(pa: DVec3, ea: DVec3, na: DVec3, pb: DVec3, eb: DVec3, nb: DVec3) -> bool {
    let d = pb - pa;
    let slack = 1.0 + gamma(4);
    let within = |n: DVec3| {
        d.dot(n).abs() <= slack * ((ea + eb).dot(n.abs()) + gamma(3) * d.abs().dot(n.abs()))
    };
    within(na) && within(nb)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_grows_with_the_operation_count() {
        assert!(gamma(1) > UNIT_ROUNDOFF && gamma(1) < 1.1 * UNIT_ROUNDOFF);
        assert!(gamma(5) > 5.0 * UNIT_ROUNDOFF);
    }

    #[test]
    fn a_transformed_point_stays_within_its_bound() {
        let m = DAffine3::from_scale_rotation_translation(
            DVec3::new(1e6, 3e5, 2e6),
            glam::DQuat::from_rotation_y(0.7),
            DVec3::new(1e7, -3.0, 5e6),
        );
        let p = DVec3::new(0.3, -0.7, 0.11);
        let (q, e) = transform_point(&m, p, DVec3::ZERO);
        // The same point computed another way differs by less than the bound.
        let alt = m.matrix3 * p + m.translation;
        assert!(((q - alt).abs() - e).max_element() <= 0.0, "{q} {alt} {e}");
        assert!(e.max_element() < 1e-7 * q.abs().max_element());
    }

    #[test]
    fn crossings_on_one_plane_are_one_event_and_apart_are_not() {
        let n = DVec3::Z;
        let e = DVec3::splat(1e-15);
        let p = DVec3::new(0.1, 0.2, 1.0);
        assert!(same_event(p, e, n, p + DVec3::new(1e-3, 0.0, 5e-16), e, n));
        assert!(!same_event(p, e, n, p + DVec3::new(0.0, 0.0, 1e-9), e, n));
    }
}
