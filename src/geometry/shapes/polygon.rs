//! Planar polygons, convex or concave (even-odd rule), closed implicitly.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use crate::geometry::{aabb::Aabb, ray::Hit, ray::Ray};

/// A planar polygon in object space; its front normal follows the winding (Newell's method).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Polygon {
    origin: DVec3,
    normal: DVec3,
    e1: DVec3,
    e2: DVec3,
    /// Vertices in the plane's 2-D frame.
    pts: Vec<DVec2>,
    lo: DVec2,
    size: DVec2,
    bounds: Aabb,
}

/// Why a polygon cannot be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PolygonError {
    /// Fewer than three vertices.
    TooFew,
    /// The vertices enclose no area.
    Degenerate,
    /// A vertex lies off the plane of the others.
    NotPlanar,
}

impl Polygon {
    /// Builds a polygon, checking it has area and is planar (to 1e-9 of its size).
    pub(crate) fn new(points: &[DVec3]) -> Result<Polygon, PolygonError> {
        if points.len() < 3 {
            return Err(PolygonError::TooFew);
        }
        let mut n = DVec3::ZERO;
        for (i, p) in points.iter().enumerate() {
            let q = points[(i + 1) % points.len()];
            n += DVec3::new(
                (p.y - q.y) * (p.z + q.z),
                (p.z - q.z) * (p.x + q.x),
                (p.x - q.x) * (p.y + q.y),
            );
        }
        let normal = n.try_unit().ok_or(PolygonError::Degenerate)?;
        let origin = points[0];
        let bounds = points
            .iter()
            .fold(Aabb::EMPTY, |b, &p| b.union(Aabb::new(p, p)));
        let scale = (bounds.max - bounds.min)
            .max_element()
            .max(f64::MIN_POSITIVE);
        if points
            .iter()
            .any(|p| (*p - origin).dot(normal).abs() > 1e-9 * scale)
        {
            return Err(PolygonError::NotPlanar);
        }
        let e1 = (points[1] - origin)
            .reject_from(normal)
            .try_unit()
            .unwrap_or_else(|| normal.any_orthonormal_vector());
        let e2 = normal.cross(e1);
        let pts: Vec<DVec2> = points
            .iter()
            .map(|p| DVec2::new((*p - origin).dot(e1), (*p - origin).dot(e2)))
            .collect();
        let lo = pts.iter().fold(DVec2::INFINITY, |a, p| a.min(*p));
        let hi = pts.iter().fold(DVec2::NEG_INFINITY, |a, p| a.max(*p));
        Ok(Polygon {
            origin,
            normal,
            e1,
            e2,
            pts,
            lo,
            size: (hi - lo).max(DVec2::splat(f64::MIN_POSITIVE)),
            bounds,
        })
    }

    /// Even-odd point-in-polygon test in the plane's frame.
    fn inside(&self, q: DVec2) -> bool {
        let mut inside = false;
        let n = self.pts.len();
        let mut j = n - 1;
        for i in 0..n {
            let (a, b) = (self.pts[i], self.pts[j]);
            if (a.y > q.y) != (b.y > q.y) {
                let x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if q.x < x {
                    inside = !inside;
                }
            }
            j = i;
        }
        inside
    }

    /// Nearest hit in (t_min, t_max); uv spans the polygon's extent in its plane.
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let denom = self.normal.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = (self.origin - ray.origin).dot(self.normal) / denom;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let w = ray.at(t) - self.origin;
        let q = DVec2::new(w.dot(self.e1), w.dot(self.e2));
        self.inside(q).then(|| Hit {
            t,
            normal: self.normal,
            uv: ((q - self.lo) / self.size).clamp(DVec2::ZERO, DVec2::ONE),
        })
    }

    /// Error bound of a computed point `p` on it: its residual off its plane.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        crate::geometry::shapes::plane::point_error(self.origin, self.normal, p)
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        self.bounds
    }
}
