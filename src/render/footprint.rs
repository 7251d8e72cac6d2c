//! The footprint of a pixel on a surface: how far the surface point and its texture
//! coordinates move between neighbouring pixels, for filtering textures (mip-mapped images)
//! and for the hatching shader's stroke spacing.
//!
//! The steps on the surface are approximated from the camera, as pbrt-v4's
//! `Approximate_dp_dxy` does: the rays through the neighbouring pixels, one pixel's angle
//! apart, meet the hit's tangent plane. That holds for hits seen through mirrors and glass too
//! (where it ignores the curvature that widens a reflected ray's cone), needs no state along
//! the path, and depends only on the camera and the hit, so a pixel's bytes do not depend on
//! how it was traced. The texture coordinates at the stepped points are read by finding the
//! surface again there (a short ray down the normal), so every shape and mapping works alike.

use glam::{DVec2, DVec3};

use crate::geometry::{Ray, SurfaceHit};
use crate::ir::{Camera, Projection};
use crate::num::Norm;
use crate::opt::Prepared;

/// The angle one pixel spans at the image centre (the distance between neighbouring pixels'
/// rays per unit of distance from the eye).
pub(crate) fn pixel_angle(cam: &Camera) -> f64 {
    let view = cam.center - cam.eye;
    match cam.projection {
        Projection::Course => cam.up.norm() / view.norm(),
        Projection::Perspective { fov_y } => {
            2.0 * libm::tan(0.5 * fov_y) / f64::from(cam.height.max(1))
        }
        // A pixel's width in world units, as an angle seen from `distance(eye, center)`.
        Projection::Orthographic { height } => height / f64::from(cam.height.max(1)) / view.norm(),
        // A panorama's pixel spans the same angle everywhere along its middle row.
        Projection::Equirectangular => std::f64::consts::PI / f64::from(cam.height.max(1)),
        Projection::Fisheye { fov } => fov / f64::from(cam.width.min(cam.height).max(1)),
        Projection::Cylindrical { fov } => fov / f64::from(cam.width.max(1)),
    }
}

/// The camera's unit right and up directions on screen.
pub(crate) fn screen_axes(cam: &Camera) -> (DVec3, DVec3) {
    let view = cam.center - cam.eye;
    let right = view.cross(cam.up).unit();
    (right, right.cross(view).unit())
}

/// The steps on the tangent plane at `p` (unit normal `n`) from the pixel seen there to its
/// right-hand and upper neighbours, each shortened by `fraction` (1 for a whole pixel);
/// `None` where the plane is seen edge-on.
pub(crate) fn surface_steps(cam: &Camera, p: DVec3, n: DVec3, fraction: f64) -> Option<[DVec3; 2]> {
    let to_p = p - cam.eye;
    let distance = to_p.norm();
    let w = to_p / distance;
    let (right, up) = screen_axes(cam);
    let angle = fraction * pixel_angle(cam);
    let step = |axis: DVec3| -> Option<DVec3> {
        // The neighbour's ray, `angle` off towards `axis` (taken square to the view ray).
        let side = (axis - axis.dot(w) * w).try_unit()?;
        let d = w + angle * side;
        let facing = n.dot(d);
        if facing.abs() < 1e-6 * d.norm() {
            return None;
        }
        let t = n.dot(to_p) / facing;
        let s = t * d - to_p;
        s.is_finite().then_some(s)
    };
    Some([step(right)?, step(up)?])
}

/// Where the surface of `hit` is at `p + step`: the hit of a short ray down the geometric
/// normal from above that point, on a surface of the same material; `None` past an edge.
pub(crate) fn surface_near(scene: &Prepared, hit: &SurfaceHit, step: DVec3) -> Option<SurfaceHit> {
    let n = hit.geometric_normal;
    let reach = step.norm() + hit.error.norm();
    if !(reach > 0.0 && reach.is_finite()) {
        return None;
    }
    let start = hit.point + step + 2.0 * reach * n;
    let found = scene
        .world()
        .intersect(&Ray::new(start, -n), 0.0, 4.0 * reach)?;
    (found.material == hit.material).then_some(found)
}

/// The change of the coordinates `coords` reads off a hit between the pixel seen at `hit` and
/// its right-hand and upper neighbours (each step tried forwards, then backwards), taken
/// modulo 1 so a seam does not count as a jump; `None` at a silhouette.
pub(crate) fn coordinate_steps(
    scene: &Prepared,
    hit: &SurfaceHit,
    steps: [DVec3; 2],
    coords: impl Fn(&SurfaceHit) -> DVec2,
) -> Option<[DVec2; 2]> {
    let here = coords(hit);
    let along = |step: DVec3| -> Option<DVec2> {
        [1.0, -1.0].into_iter().find_map(|sign| {
            let there = surface_near(scene, hit, sign * step)?;
            let d = coords(&there) - here;
            Some(sign * (d - d.round()))
        })
    };
    Some([along(steps[0])?, along(steps[1])?])
}
