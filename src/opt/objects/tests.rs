//! Which spheres the preparation stage keeps as compact balls. (That a translated ball answers
//! every query as the primitive it replaces, bit for bit, is `geometry::world::balls`' test.)

use glam::{DAffine3, DQuat, DVec3};

use super::Builder;
use crate::ir::{MaterialId, Motion, Object, Shape, Transform, Visibility};
use crate::source::Span;

/// A sphere of radius 0.4 about `center`, placed by `t`.
fn sphere(center: [f64; 3], t: DAffine3) -> Object {
    Object {
        shape: Shape::Sphere {
            center: DVec3::from(center),
            radius: 0.4,
        },
        transform: Transform::from(t),
        material: None,
        motion: None,
        span: Span::default(),
        visibility: Visibility::ALL,
    }
}

/// `Some(translated)` for each object the builder keeps as a ball, `None` for a primitive.
fn balls(objects: &[Object]) -> Vec<Option<bool>> {
    let b = Builder::new(1, 0, crate::ir::limits::Memory::new(u64::MAX));
    let ball = |(i, o): (usize, &Object)| {
        b.ball(o, MaterialId(0), i as u32)
            .map(|b| b.is_translated())
    };
    objects.iter().enumerate().map(ball).collect()
}

/// Issue 42 item 4's rule: a sphere about its own origin that is only translated (however
/// the translations are written) becomes a translated ball; a sphere with no transform a plain
/// one; a scale (uniform or not), a rotation, a translated sphere whose centre is elsewhere,
/// and any motion stay primitives.
#[test]
fn only_untransformed_and_translated_spheres_become_balls() {
    let t = DAffine3::from_translation;
    let (p, none) = (DVec3::new(1.0, 2.0, 3.0), DAffine3::IDENTITY);
    let moving = Object {
        motion: Some(Box::new(Motion::new(DVec3::X, DQuat::IDENTITY, DVec3::ONE))),
        ..sphere([0.0; 3], t(p))
    };
    let kept = balls(&[
        sphere([0.0; 3], none),
        sphere([1.0, 2.0, 3.0], none),
        sphere([0.0; 3], t(p)),
        sphere([0.0; 3], t(DVec3::Y * 2.0) * t(DVec3::X)),
        sphere([0.0; 3], t(p) * DAffine3::IDENTITY),
        sphere([0.0; 3], t(DVec3::ZERO)),
        sphere([1.0, 0.0, 0.0], t(DVec3::Y)),
        sphere([0.0; 3], t(p) * DAffine3::from_scale(DVec3::splat(2.0))),
        sphere([0.0; 3], DAffine3::from_scale(DVec3::new(1.0, 2.0, 1.0))),
        sphere(
            [0.0; 3],
            t(p) * DAffine3::from_quat(DQuat::from_rotation_y(0.5)),
        ),
        moving,
        Object {
            shape: Shape::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::ONE,
            },
            ..sphere([0.0; 3], t(p))
        },
    ]);
    let want = [
        Some(false),
        Some(false),
        Some(true),
        Some(true),
        Some(true),
        Some(false),
        None,
        None,
        None,
        None,
        None,
        None,
    ];
    assert_eq!(kept, want);
}
