//! Motion within a frame: how an object or the camera moves while the shutter is open.

use glam::{DAffine3, DQuat, DVec3};

use crate::num::Norm;

/// The interval of a frame during which the film is exposed, in fractions of a frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shutter {
    /// When the shutter opens (0 = the frame's start).
    pub(crate) open: f64,
    /// When it closes (≥ `open`; equal means no motion blur).
    pub(crate) close: f64,
}

impl Shutter {
    /// True when the shutter stays open for a while, so moving things blur.
    pub(crate) fn is_open(&self) -> bool {
        self.close > self.open
    }
}

/// An object's motion while the shutter is open: at shutter fraction `s` ∈ [0, 1] (0 = open,
/// 1 = close) its object-to-world transform is `frame · D(s) · frame⁻¹ · transform`, with
/// `D(s) = translate(s·translate) · rotate(slerp(1, rotate, s)) · spin(s) · scale(lerp(1, scale, s))`
/// (`spin(s)`: a turn by `s·|spin|` about `spin`'s direction, any number of turns):
/// pbrt-v4's `AnimatedTransform` interpolation (translation and scale linearly, rotation by
/// quaternion slerp) from the identity to the motion. `frame` is the space the motion was given
/// in (the object's parent space when `.moving` was called, carried through later transforms).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Displacement at shutter close.
    pub(crate) translate: DVec3,
    /// Rotation at shutter close (unit quaternion; slerp takes the shorter arc, as pbrt does).
    pub(crate) rotate: DQuat,
    /// Scale factors at shutter close.
    pub(crate) scale: DVec3,
    /// A spin about an axis through the origin: its direction, its length the angle in
    /// radians turned by shutter close (any size: `2π·n` is n whole turns; zero: none).
    pub(crate) spin: DVec3,
    /// The space the motion is expressed in (maps it to world space).
    pub(crate) frame: DAffine3,
}

impl Motion {
    /// A motion given in the parent space of the object it moves.
    pub(crate) fn new(translate: DVec3, rotate: DQuat, scale: DVec3) -> Motion {
        Motion {
            translate,
            rotate,
            scale,
            spin: DVec3::ZERO,
            frame: DAffine3::IDENTITY,
        }
    }

    /// The same motion with a spin of `angle` radians about `axis` (not zero) by shutter close.
    pub(crate) fn with_spin(self, axis: DVec3, angle: f64) -> Motion {
        let length = axis.norm();
        Motion {
            spin: if length > 0.0 && angle != 0.0 {
                axis / length * angle
            } else {
                DVec3::ZERO
            },
            ..self
        }
    }

    /// The angle the spin has turned at shutter fraction `s`, as a rotation.
    fn spin_at(&self, s: f64) -> DQuat {
        let angle = self.spin.norm();
        if angle == 0.0 {
            return DQuat::IDENTITY;
        }
        // From libm's sin and cos, as slerp does, so every machine turns alike.
        let (axis, half) = (self.spin / angle, 0.5 * s * angle);
        let (sin, cos) = (libm::sin(half), libm::cos(half));
        DQuat::from_xyzw(axis.x * sin, axis.y * sin, axis.z * sin, cos)
    }

    /// The whole angle the motion turns through, in radians: the slerp's arc, or the spin.
    pub(crate) fn turned(&self) -> f64 {
        let q = if self.rotate.w < 0.0 {
            -self.rotate
        } else {
            self.rotate
        };
        2.0 * libm::acos(q.w.clamp(-1.0, 1.0)) + self.spin.norm()
    }

    /// The motion's own transform `D(s)` at shutter fraction `s`.
    fn delta(&self, s: f64) -> DAffine3 {
        let q = slerp_from_identity(self.rotate, s) * self.spin_at(s);
        let scale = DVec3::ONE.lerp(self.scale, s);
        DAffine3::from_scale_rotation_translation(scale, q, self.translate * s)
    }

    /// The object-to-world transform at shutter fraction `s` of an object placed by `transform`
    /// at shutter open.
    pub(crate) fn at(&self, transform: DAffine3, s: f64) -> DAffine3 {
        if s == 0.0 {
            return transform;
        }
        self.frame * self.delta(s) * self.frame.inverse() * transform
    }

    /// The same motion after the object is transformed by `t` (applied after its placement).
    pub(crate) fn transformed(&self, t: DAffine3) -> Motion {
        Motion {
            frame: t * self.frame,
            ..*self
        }
    }

    /// True when nothing moves.
    pub(crate) fn is_still(&self) -> bool {
        self.translate == DVec3::ZERO
            && self.rotate == DQuat::IDENTITY
            && self.scale == DVec3::ONE
            && self.spin == DVec3::ZERO
    }
}

/// Spherical interpolation from the identity to `q` along the shorter arc (pbrt-v4's `Slerp`),
/// with `libm` so the result is the same on every machine.
fn slerp_from_identity(q: DQuat, s: f64) -> DQuat {
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
    pub(crate) eye: DVec3,
    /// Point looked at at shutter close.
    pub(crate) center: DVec3,
}

#[cfg(test)]
mod tests {
    use super::*;

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

    /// A spin turns the whole angle, past half a turn and past whole turns, linearly in time,
    /// about its axis; a still motion with a zero spin stays still.
    #[test]
    fn a_spin_turns_any_angle_about_its_axis() {
        let m = Motion::new(DVec3::ZERO, DQuat::IDENTITY, DVec3::ONE)
            .with_spin(DVec3::new(0.0, 0.0, 2.0), 630f64.to_radians());
        assert!(!m.is_still());
        assert!((m.turned() - 630f64.to_radians()).abs() < 1e-12);
        for (s, degrees) in [(0.0, 0.0), (0.25, 157.5), (0.5, 315.0), (1.0, 630.0)] {
            let p = m.delta(s).transform_point3(DVec3::X);
            let a = f64::to_radians(degrees);
            let want = DVec3::new(libm::cos(a), libm::sin(a), 0.0);
            assert!((p - want).norm() < 1e-12, "s = {s}: {p:?}");
        }
        let none = Motion::new(DVec3::ZERO, DQuat::IDENTITY, DVec3::ONE).with_spin(DVec3::Z, 0.0);
        assert!(none.is_still());
    }

    #[test]
    fn slerp_takes_the_shorter_arc() {
        let q = -DQuat::from_rotation_z(60f64.to_radians());
        let mid = slerp_from_identity(q, 0.5);
        assert!(mid.abs_diff_eq(DQuat::from_rotation_z(30f64.to_radians()), 1e-12));
    }
}
