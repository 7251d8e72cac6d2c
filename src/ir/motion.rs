//! Motion within a frame: how an object or the camera moves while the shutter is open.

use glam::{DAffine3, DQuat, DVec3};

/// The interval of a frame during which the film is exposed, in fractions of a frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shutter {
    /// When the shutter opens (0 = the frame's start).
    pub open: f64,
    /// When it closes (≥ `open`; equal means no motion blur).
    pub close: f64,
}

impl Shutter {
    /// True when the shutter stays open for a while, so moving things blur.
    pub fn is_open(&self) -> bool {
        self.close > self.open
    }
}

/// An object's motion while the shutter is open: at shutter fraction `s` ∈ [0, 1] (0 = open,
/// 1 = close) its object-to-world transform is `frame · D(s) · frame⁻¹ · transform`, with
/// `D(s) = translate(s·translate) · rotate(slerp(1, rotate, s)) · scale(lerp(1, scale, s))`:
/// pbrt-v4's `AnimatedTransform` interpolation (translation and scale linearly, rotation by
/// quaternion slerp) from the identity to the motion. `frame` is the space the motion was given
/// in (the object's parent space when `.moving` was called, carried through later transforms).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Displacement at shutter close.
    pub translate: DVec3,
    /// Rotation at shutter close (unit quaternion; slerp takes the shorter arc, as pbrt does).
    pub rotate: DQuat,
    /// Scale factors at shutter close.
    pub scale: DVec3,
    /// The space the motion is expressed in (maps it to world space).
    pub frame: DAffine3,
}

impl Motion {
    /// A motion given in the parent space of the object it moves.
    pub fn new(translate: DVec3, rotate: DQuat, scale: DVec3) -> Motion {
        Motion {
            translate,
            rotate,
            scale,
            frame: DAffine3::IDENTITY,
        }
    }

    /// The motion's own transform `D(s)` at shutter fraction `s`.
    pub fn delta(&self, s: f64) -> DAffine3 {
        let q = slerp_from_identity(self.rotate, s);
        let scale = DVec3::ONE.lerp(self.scale, s);
        DAffine3::from_scale_rotation_translation(scale, q, self.translate * s)
    }

    /// The object-to-world transform at shutter fraction `s` of an object placed by `transform`
    /// at shutter open.
    pub fn at(&self, transform: DAffine3, s: f64) -> DAffine3 {
        if s == 0.0 {
            return transform;
        }
        self.frame * self.delta(s) * self.frame.inverse() * transform
    }

    /// The same motion after the object is transformed by `t` (applied after its placement).
    pub fn transformed(&self, t: DAffine3) -> Motion {
        Motion {
            frame: t * self.frame,
            ..*self
        }
    }

    /// True when nothing moves.
    pub fn is_still(&self) -> bool {
        self.translate == DVec3::ZERO && self.rotate == DQuat::IDENTITY && self.scale == DVec3::ONE
    }
}

/// Spherical interpolation from the identity to `q` along the shorter arc (pbrt-v4's `Slerp`),
/// with `libm` so the result is the same on every machine.
pub fn slerp_from_identity(q: DQuat, s: f64) -> DQuat {
    // The identity is (0, 0, 0, 1): its dot product with q is q.w; −q is the same rotation.
    let q = if q.w < 0.0 { -q } else { q };
    let cos_theta = q.w.clamp(-1.0, 1.0);
    if cos_theta > 0.9995 {
        return (DQuat::IDENTITY * (1.0 - s) + q * s).normalize();
    }
    let theta = libm::acos(cos_theta);
    let sin_theta = libm::sin(theta);
    let a = libm::sin((1.0 - s) * theta) / sin_theta;
    let b = libm::sin(s * theta) / sin_theta;
    (DQuat::IDENTITY * a + q * b).normalize()
}

/// The camera's motion while the shutter is open: its eye and the point it looks at at shutter
/// close; both move linearly from their positions at open.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraMotion {
    /// Eye at shutter close.
    pub eye: DVec3,
    /// Point looked at at shutter close.
    pub center: DVec3,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Norm;

    #[test]
    fn the_motion_interpolates_translation_and_scale_linearly_and_rotation_by_slerp() {
        let m = Motion::new(
            DVec3::new(2.0, 0.0, 0.0),
            DQuat::from_rotation_y(90f64.to_radians()),
            DVec3::splat(3.0),
        );
        let half = m.delta(0.5);
        let want = DAffine3::from_scale_rotation_translation(
            DVec3::splat(2.0),
            DQuat::from_rotation_y(45f64.to_radians()),
            DVec3::new(1.0, 0.0, 0.0),
        );
        assert!(half.abs_diff_eq(want, 1e-12), "{half:?}");
        let end = m.delta(1.0);
        let full = DAffine3::from_scale_rotation_translation(m.scale, m.rotate, m.translate);
        assert!(end.abs_diff_eq(full, 1e-12));
        assert_eq!(m.at(DAffine3::IDENTITY, 0.0), DAffine3::IDENTITY);
        // A motion given before a move turns about the object's own origin.
        let p = DAffine3::from_translation(DVec3::new(5.0, 0.0, 0.0));
        let moved = m.transformed(p);
        let origin = moved.at(p, 1.0).transform_point3(DVec3::ZERO);
        assert!((origin - DVec3::new(7.0, 0.0, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn slerp_takes_the_shorter_arc() {
        let q = -DQuat::from_rotation_z(60f64.to_radians());
        let mid = slerp_from_identity(q, 0.5);
        assert!(mid.abs_diff_eq(DQuat::from_rotation_z(30f64.to_radians()), 1e-12));
    }
}
