//! Scale invariance (issue 10): one scene — a floor, a mirror ball, a glass ball, a drilled box
//! (coincident CSG faces), a cylinder, a torus, one shadow-casting light — scaled as a whole by
//! 10⁻⁶ … 10⁸ renders the image it renders at scale 1, but for at most 0.1 % of the pixels
//! (rays through a silhouette or shadow edge may round to the other side when every coordinate
//! is multiplied by a number that is not a power of two).
//!
//! The rule is invariance itself: scaling a scene (camera, lights and objects) changes no angle,
//! so the exact image is the same; the reference is the scale-1 render.

mod numerics_support;

use numerics_support::{assert_same_at_scales, at};

fn scene(s: f64) -> String {
    let p = |x: [f64; 3]| at(s, [0.0; 3], x);
    let r = |x: f64| format!("{:e}", x * s);
    format!(
        "rtc 1\n\
         camera {{ eye: {}, center: {}, fov: 40deg, resolution: [120, 90] }}\n\
         render {{ max_depth: 5 }}\n\
         point_light {{ position: {} }}\n\
         plane(point: {}, normal: Y).material(material {{ color: rgb(0.8, 0.8, 0.7), reflect: 0.2 }})\n\
         sphere(center: {}, radius: {}).material(material {{ color: rgb(0.9, 0.9, 0.9), reflect: 0.8 }})\n\
         sphere(center: {}, radius: {}).material(material {{ color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0.3, refract: 0.9, eta: 1.5 }})\n\
         (box(min: {}, max: {}) - box(min: {}, max: {})).material(material {{ color: rgb(0.2, 0.5, 0.9) }})\n\
         cylinder(base: {}, top: {}, radius: {}).material(material {{ color: rgb(0.3, 0.8, 0.3) }})\n\
         torus(center: {}, major_radius: {}, minor_radius: {}).material(material {{ color: rgb(0.9, 0.6, 0.1) }})\n",
        p([0.0, 2.5, 7.0]),
        p([0.0, 0.6, 0.0]),
        p([4.0, 6.0, 5.0]),
        p([0.0, 0.0, 0.0]),
        p([-1.3, 0.7, 0.0]),
        r(0.7),
        p([0.9, 0.6, 1.2]),
        r(0.6),
        p([0.8, 0.0, -1.6]),
        p([2.2, 1.4, -0.2]),
        p([1.2, 0.4, -1.6]),
        p([1.8, 1.0, -0.2]),
        p([-2.6, 0.0, -1.0]),
        p([-2.6, 1.5, -1.0]),
        r(0.3),
        p([-0.6, 0.25, 2.0]),
        r(0.5),
        r(0.25),
    )
}

#[test]
fn the_same_scene_at_every_scale_renders_the_same_image() {
    assert_same_at_scales(&[1e-6, 1e-4, 1e-2, 3.7, 1e2, 1e4, 1e6, 1e8], scene);
}
