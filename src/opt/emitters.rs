//! The glowing objects the path tracer samples directly (next-event estimation): spheres and
//! quads of constant emission, in world space. Any other emissive surface still lights the
//! scene, found by the paths that meet it (docs/gi.md).

use glam::DVec3;

use crate::num::Norm;

use crate::ir::{Color, Material, MaterialId, Object, Shape};

/// A shape of an emitter, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EmitterShape {
    /// A sphere.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
    /// The parallelogram `corner + s·u + t·v`, s, t in [0, 1]; its front normal is `u × v`.
    Parallelogram {
        /// One corner.
        corner: DVec3,
        /// First edge.
        u: DVec3,
        /// Second edge.
        v: DVec3,
    },
}

/// An object that emits light of one radiance everywhere on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emitter {
    /// The top-level object it is (an index into the scene's objects, as the world's hits
    /// tell).
    pub object: u32,
    /// Where it is.
    pub shape: EmitterShape,
    /// The radiance it emits, `emission·C`.
    pub radiance: Color,
    /// Whether it emits on both sides (else only to the outside, or the front of a quad).
    pub both_sides: bool,
}

impl EmitterShape {
    /// Its area.
    pub fn area(&self) -> f64 {
        match *self {
            EmitterShape::Sphere { radius, .. } => 4.0 * std::f64::consts::PI * radius * radius,
            EmitterShape::Parallelogram { u, v, .. } => u.cross(v).norm(),
        }
    }
}

/// The emitter top-level object `o` (number `index`, material `fallback` when it names none)
/// is, when it is a still, fully visible sphere or quad of one constant emission under a
/// transform that keeps its kind (a sphere under a similarity, a quad under any affine map).
pub(crate) fn of(
    o: &Object,
    index: u32,
    materials: &[Material],
    fallback: MaterialId,
) -> Option<Emitter> {
    let m = materials.get(o.material.unwrap_or(fallback).0 as usize)?;
    if m.emission == Color::ZERO || m.texture.is_some() || m.mix.is_some() {
        return None;
    }
    if o.motion.as_ref().is_some_and(|m| !m.is_still()) || !o.visibility.is_all() {
        return None;
    }
    let a = o.transform.affine();
    let shape = match o.shape {
        Shape::Sphere { center, radius } => {
            let scale = similarity_scale(a.matrix3)?;
            EmitterShape::Sphere {
                center: a.transform_point3(center),
                radius: radius * scale,
            }
        }
        Shape::Quad { corner, u, v } => EmitterShape::Parallelogram {
            corner: a.transform_point3(corner),
            u: a.transform_vector3(u),
            v: a.transform_vector3(v),
        },
        _ => return None,
    };
    (shape.area() > 0.0 && shape.area().is_finite()).then_some(Emitter {
        object: index,
        shape,
        radiance: m.emission * m.color,
        both_sides: m.emits_both_sides,
    })
}

/// The scale of `m` when it is a rotation (or reflection) times a uniform scale: columns of
/// one length, at right angles (to 1e-9 relative); `None` otherwise.
fn similarity_scale(m: glam::DMat3) -> Option<f64> {
    let (x, y, z) = (m.x_axis, m.y_axis, m.z_axis);
    let s = x.norm();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * s * s;
    let ok = s > 0.0
        && close(y.length_squared(), s * s)
        && close(z.length_squared(), s * s)
        && close(x.dot(y), 0.0)
        && close(y.dot(z), 0.0)
        && close(x.dot(z), 0.0);
    ok.then_some(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DAffine3, DMat3};

    #[test]
    fn a_similarity_has_one_scale_and_a_shear_none() {
        let r = DMat3::from_rotation_y(0.7) * 2.5;
        assert!((similarity_scale(r).unwrap() - 2.5).abs() < 1e-12);
        let mirrored = DMat3::from_diagonal(DVec3::new(-3.0, 3.0, 3.0));
        assert_eq!(similarity_scale(mirrored), Some(3.0));
        let stretched = DMat3::from_diagonal(DVec3::new(1.0, 2.0, 1.0));
        assert_eq!(similarity_scale(stretched), None);
        let sheared = DAffine3::from_cols_array(&[
            1.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0,
        ]);
        assert_eq!(similarity_scale(sheared.matrix3), None);
    }
}
