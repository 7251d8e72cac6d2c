//! Infinite planes (half-spaces for CSG).

use glam::{DVec2, DVec3};

use crate::geometry::{ray::Hit, ray::Ray, rounding};

/// Intersection of `ray` with the plane through `point` with unit `normal`, in (t_min, t_max).
pub(crate) fn intersect(
    point: DVec3,
    normal: DVec3,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<Hit> {
    let denom = normal.dot(ray.dir);
    if denom == 0.0 {
        return None;
    }
    let t = (point - ray.origin).dot(normal) / denom;
    if !(t > t_min && t < t_max) {
        return None;
    }
    let p = ray.at(t) - point;
    // Planar coordinates in a frame on the plane, wrapped to [0, 1).
    let tangent = normal.any_orthonormal_vector();
    let bitangent = normal.cross(tangent);
    let uv = DVec2::new(p.dot(tangent), p.dot(bitangent));
    Some(Hit {
        t,
        normal,
        uv: uv - uv.floor(),
    })
}

/// Error bound of a computed point `p` on the plane through `point` with unit `normal` (also
/// every flat shape's): the residual `(p − point)·n` plus its rounding.
pub(crate) fn point_error(point: DVec3, normal: DVec3, p: DVec3) -> DVec3 {
    let w = p - point;
    rounding::from_residual(w.dot(normal), 5, w.abs().dot(normal.abs()))
}
