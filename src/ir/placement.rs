//! An object's placement in the world, stored in as few bytes as its kind needs: most objects a
//! loop makes are placed by their own parameters (identity) or only moved (a translation), and a
//! million of them would otherwise carry a million 96-byte matrices.

use glam::{DAffine3, DMat3, DVec3};

/// An object-to-world affine transform in a compact form (16–32 bytes instead of 96).
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Transform {
    /// The identity.
    #[default]
    Identity,
    /// A pure translation.
    Translation(DVec3),
    /// Any other affine map.
    Affine(Box<DAffine3>),
}

impl Transform {
    /// The identity.
    pub const IDENTITY: Transform = Transform::Identity;

    /// The compact form of `t`; [`Transform::affine`] gives back exactly `t`, bit for bit (a
    /// matrix part is dropped only when its bits are the identity's, so `-0.0` stays).
    fn new(t: DAffine3) -> Transform {
        let bits = |m: DMat3| m.to_cols_array().map(f64::to_bits);
        if bits(t.matrix3) != bits(DMat3::IDENTITY) {
            return Transform::Affine(Box::new(t));
        }
        if t.translation.to_array().map(f64::to_bits) == [0; 3] {
            Transform::Identity
        } else {
            Transform::Translation(t.translation)
        }
    }

    /// The transform as a matrix.
    #[inline]
    pub fn affine(&self) -> DAffine3 {
        match self {
            Transform::Identity => DAffine3::IDENTITY,
            Transform::Translation(v) => DAffine3::from_translation(*v),
            Transform::Affine(t) => **t,
        }
    }

    /// Whether it equals the identity (by value, as `affine() == DAffine3::IDENTITY`).
    pub fn is_identity(&self) -> bool {
        match self {
            Transform::Identity => true,
            Transform::Translation(v) => *v == DVec3::ZERO,
            Transform::Affine(t) => **t == DAffine3::IDENTITY,
        }
    }
}

impl From<DAffine3> for Transform {
    fn from(t: DAffine3) -> Transform {
        Transform::new(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_form_gives_back_its_matrix_bit_for_bit() {
        let cases = [
            DAffine3::IDENTITY,
            DAffine3::from_translation(DVec3::new(1.5, -0.0, 3.0)),
            DAffine3::from_translation(DVec3::new(-0.0, 0.0, 0.0)),
            DAffine3::from_scale(DVec3::new(2.0, 1.0, 1.0)),
            DAffine3::from_cols(DVec3::X, DVec3::new(-0.0, 1.0, 0.0), DVec3::Z, DVec3::ONE),
            DAffine3::from_rotation_y(0.3) * DAffine3::from_translation(DVec3::ONE),
        ];
        let bits = |t: DAffine3| t.to_cols_array().map(f64::to_bits);
        for t in cases {
            let c = Transform::new(t);
            assert_eq!(bits(c.affine()), bits(t), "{t:?} as {c:?}");
            assert_eq!(c.is_identity(), t == DAffine3::IDENTITY, "{t:?}");
        }
        assert_eq!(Transform::new(DAffine3::IDENTITY), Transform::Identity);
        assert!(matches!(
            Transform::new(DAffine3::from_translation(DVec3::X)),
            Transform::Translation(_)
        ));
        assert!(std::mem::size_of::<Transform>() <= 32);
    }
}
