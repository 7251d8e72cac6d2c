//! Spheres.

use std::f64::consts::PI;

use glam::{DVec2, DVec3};

use super::{Aabb, Crossing, Hit, Ray};

/// Ray parameter of the nearest intersection in (t_min, t_max), without normal or uv: the hot
/// path for candidate and shadow tests (uv costs an `acos` and an `atan2`).
///
/// Uses the numerically stable quadratic (no cancellation between −b and √disc).
#[inline]
pub fn hit_t(center: DVec3, radius: f64, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
    hit_t_with(center, radius, ray.dir.length_squared(), ray, t_min, t_max)
}

/// [`hit_t`] with `a = |dir|²` computed once per ray by the caller (bit-identical results).
#[inline]
pub fn hit_t_with(
    center: DVec3,
    radius: f64,
    a: f64,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<f64> {
    let oc = ray.origin - center;
    let half_b = oc.dot(ray.dir);
    let c = oc.length_squared() - radius * radius;
    let disc = half_b * half_b - a * c;
    if disc < 0.0 {
        return None;
    }
    let q = -half_b - disc.sqrt().copysign(half_b);
    let (t0, t1) = (q / a, c / q);
    let (t0, t1) = if t0 > t1 { (t1, t0) } else { (t0, t1) };
    if t0 > t_min && t0 < t_max {
        Some(t0)
    } else if t1 > t_min && t1 < t_max {
        Some(t1)
    } else {
        None
    }
}

/// Nearest intersection of `ray` with the sphere in (t_min, t_max).
///
/// Uses the numerically stable quadratic (no cancellation between −b and √disc).
pub fn intersect(center: DVec3, radius: f64, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
    let oc = ray.origin - center;
    let a = ray.dir.length_squared();
    let half_b = oc.dot(ray.dir);
    let c = oc.length_squared() - radius * radius;
    let disc = half_b * half_b - a * c;
    if disc < 0.0 {
        return None;
    }
    let sq = disc.sqrt();
    let q = -half_b - sq.copysign(half_b);
    let (mut t0, mut t1) = (q / a, c / q);
    if t0 > t1 {
        std::mem::swap(&mut t0, &mut t1);
    }
    let t = if t0 > t_min && t0 < t_max {
        t0
    } else if t1 > t_min && t1 < t_max {
        t1
    } else {
        return None;
    };
    let normal = (ray.at(t) - center).normalize();
    Some(Hit {
        t,
        normal,
        uv: uv(normal),
    })
}

/// Equirectangular coordinates of a unit direction from the centre: +Y is the north pole (v = 0),
/// u = φ/2π with φ measured from +X towards −Z (counter-clockwise seen from above).
pub fn uv(n: DVec3) -> DVec2 {
    let theta = libm::acos(n.y.clamp(-1.0, 1.0));
    let mut phi = libm::atan2(-n.z, n.x);
    if phi < 0.0 {
        phi += 2.0 * PI;
    }
    DVec2::new(phi / (2.0 * PI), theta / PI)
}

/// Object-space bounds.
pub fn bounds(center: DVec3, radius: f64) -> Aabb {
    Aabb::new(center - radius, center + radius)
}

/// Both boundary crossings along the whole line of `ray` (entering first).
pub fn crossings(center: DVec3, radius: f64, ray: &Ray, out: &mut Vec<Crossing>) {
    let oc = ray.origin - center;
    let a = ray.dir.length_squared();
    let Some((t0, t1)) = super::quartic::quadratic(
        a,
        2.0 * oc.dot(ray.dir),
        oc.length_squared() - radius * radius,
    ) else {
        return;
    };
    for (t, entering) in [(t0, true), (t1, false)] {
        let normal = (ray.at(t) - center).normalize();
        out.push(Crossing {
            hit: Hit {
                t,
                normal,
                uv: uv(normal),
            },
            entering,
        });
    }
}

/// True when `p` is inside or on the sphere.
pub fn contains(center: DVec3, radius: f64, p: DVec3) -> bool {
    (p - center).length_squared() <= radius * radius
}
