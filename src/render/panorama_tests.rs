//! Tests of the panoramic projections (`panorama`) through the camera that makes their rays.

use glam::DVec3;

use super::panorama::*;
use crate::ir::{self, Projection};
use crate::num::Norm;
use crate::render::camera::Camera;
use crate::source::Span;

/// A camera at the origin looking down −z, `up` = Y (right = +x).
fn camera(projection: Projection, w: u32, h: u32) -> Camera {
    Camera::new(&ir::Camera {
        eye: DVec3::ZERO,
        center: DVec3::NEG_Z,
        up: DVec3::Y,
        width: w,
        height: h,
        projection,
        aperture: 0.0,
        focus_distance: 0.0,
        shutter: None,
        motion: None,
        span: Span::default(),
    })
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).norm() < 1e-12
}

#[test]
fn equirectangular_maps_columns_to_longitude_and_rows_to_latitude() {
    let cam = camera(Projection::Equirectangular, 360, 180);
    // The image centre looks at `center`; a quarter across to the right looks right.
    assert!(close(
        cam.ray(180, 90, 0.0, 1.0, (0.5, 0.5)).dir,
        DVec3::NEG_Z
    ));
    assert!(close(cam.ray(270, 90, 0.0, 1.0, (0.5, 0.5)).dir, DVec3::X));
    assert!(close(
        cam.ray(90, 90, 0.0, 1.0, (0.5, 0.5)).dir,
        DVec3::NEG_X
    ));
    assert!(close(cam.ray(0, 90, 0.0, 1.0, (0.5, 0.5)).dir, DVec3::Z));
    // The top edge is the zenith; 45° up at a quarter of the height.
    assert!(close(
        cam.ray(17, 0, 0.0, 0.0 + 1.0, (0.5, 0.5)).dir,
        DVec3::Y
    ));
    let d = cam.ray(180, 45, 0.0, 1.0, (0.5, 0.5)).dir;
    assert!(close(d, DVec3::new(0.0, 1.0, -1.0).unit()));
}

#[test]
fn fisheye_angle_grows_with_the_distance_from_the_centre() {
    let fov = 200f64.to_radians();
    let (w, h) = (300, 200);
    let cam = camera(Projection::Fisheye { fov }, w, h);
    // The image centre (150, 100) looks along the axis.
    assert!(close(
        cam.ray(150, 99, 0.0, 0.0, (0.5, 0.5)).dir,
        DVec3::NEG_Z
    ));
    let radius = 100.0;
    for (x, y) in [
        (150, 30),
        (200, 100),
        (99, 150),
        (220, 160),
        (150, 1),
        (1, 100),
    ] {
        let (sx, sy) = (0.5, 0.5);
        let dx = f64::from(x) + sx - 150.0;
        let dy = 100.0 - (f64::from(y) + 1.0 - sy);
        let r = libm::hypot(dx, dy);
        let d = cam.ray(x, y, sx, sy, (0.5, 0.5)).dir;
        if r > radius {
            assert_eq!(d, BLIND, "({x}, {y})");
            continue;
        }
        let want = (r / radius) * fov / 2.0;
        assert!(
            (d.angle_between(DVec3::NEG_Z) - want).abs() < 1e-9,
            "({x}, {y})"
        );
        // Towards the pixel: right is +x, up is +y.
        assert!(d.x * dx >= 0.0 && d.y * dy >= 0.0, "({x}, {y}): {d:?}");
    }
    // A corner is outside the circle: black, not traced.
    assert_eq!(cam.ray(0, 0, 0.5, 0.5, (0.5, 0.5)).dir, BLIND);
    assert!(cam.has_blind_pixels());
}

#[test]
fn cylinder_turns_across_and_rises_along_its_axis() {
    let fov = 270f64.to_radians();
    let cam = camera(Projection::Cylindrical { fov }, 270, 90);
    assert!(close(
        cam.ray(135, 45, 0.0, 1.0, (0.5, 0.5)).dir,
        DVec3::NEG_Z
    ));
    // 90° to the right at a third across from the centre.
    assert!(close(cam.ray(225, 45, 0.0, 1.0, (0.5, 0.5)).dir, DVec3::X));
    // Square pixels on the horizon: a pixel up is 1° of arc on the unit cylinder.
    let d = cam.ray(135, 0, 0.0, 1.0, (0.5, 0.5)).dir;
    let rise = 45f64.to_radians();
    assert!(close(d, DVec3::new(0.0, rise, -1.0).unit()));
}
