//! Spheres.

use crate::num::Norm;

use glam::DVec3;

use crate::geometry::ray::equirectangular_uv;
use crate::geometry::shapes::circle_quadratic::{self, DirSquared};
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// Ray parameter of the nearest intersection in (t_min, t_max), without normal or uv: the hot
/// path for candidate and shadow tests (uv costs an `acos` and an `atan2`).
///
/// Uses the cancellation-free quadratic of [`circle_quadratic::roots`], which keeps its hits from far away.
#[inline]
pub(crate) fn hit_t(center: DVec3, radius: f64, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
    hit_t_with(center, radius, DirSquared::of(ray.dir), ray, t_min, t_max)
}

/// [`hit_t`] with `|dir|²` computed once per ray by the caller (bit-identical results).
#[inline]
pub(crate) fn hit_t_with(
    center: DVec3,
    radius: f64,
    dir: DirSquared,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<f64> {
    let (t0, t1) = circle_quadratic::roots(ray.origin - center, ray.dir, dir, radius)?;
    nearer_root(t0, t1, t_min, t_max)
}

/// The nearer of the ordered roots `t0 ≤ t1` in (t_min, t_max), if either lies there.
#[inline]
pub(crate) fn nearer_root(t0: f64, t1: f64, t_min: f64, t_max: f64) -> Option<f64> {
    if t0 > t_min && t0 < t_max {
        Some(t0)
    } else if t1 > t_min && t1 < t_max {
        Some(t1)
    } else {
        None
    }
}

/// Error bound of a computed point `p` on the sphere: its residual `| |p − c| − r |` plus the
/// rounding of evaluating it (see [`crate::geometry::rounding`]).
pub(crate) fn point_error(center: DVec3, radius: f64, p: DVec3) -> DVec3 {
    let len = (p - center).norm();
    rounding::from_residual(len - radius, 6, len + radius)
}

/// Nearest intersection of `ray` with the sphere in (t_min, t_max).
pub(crate) fn intersect(
    center: DVec3,
    radius: f64,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<Hit> {
    let t = hit_t(center, radius, ray, t_min, t_max)?;
    let normal = (ray.at(t) - center).unit();
    Some(Hit {
        t,
        normal,
        uv: equirectangular_uv(normal),
    })
}

/// Object-space bounds.
pub(crate) fn bounds(center: DVec3, radius: f64) -> Aabb {
    Aabb::new(center - radius, center + radius)
}

/// Both boundary crossings along the whole line of `ray` (entering first).
pub(crate) fn crossings(center: DVec3, radius: f64, ray: &Ray, out: &mut Vec<Crossing>) {
    let Some((t0, t1)) = circle_quadratic::roots(
        ray.origin - center,
        ray.dir,
        DirSquared::of(ray.dir),
        radius,
    ) else {
        return;
    };
    for (t, entering) in [(t0, true), (t1, false)] {
        let normal = (ray.at(t) - center).unit();
        out.push(Crossing {
            hit: Hit {
                t,
                normal,
                uv: equirectangular_uv(normal),
            },
            entering,
        });
    }
}

/// True when `p` is inside or on the sphere.
pub(crate) fn contains(center: DVec3, radius: f64, p: DVec3) -> bool {
    (p - center).length_squared() <= radius * radius
}
