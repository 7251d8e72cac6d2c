//! Axis-aligned boxes (closed solids).

use crate::num::Norm;
use glam::{DVec2, DVec3};

use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// An axis-aligned box in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cuboid {
    /// Minimum corner.
    min: DVec3,
    /// Maximum corner.
    max: DVec3,
}

/// Where a ray enters and leaves the box: parameters and outward normals.
struct Span2 {
    t0: f64,
    n0: DVec3,
    t1: f64,
    n1: DVec3,
}

impl Cuboid {
    /// A box from any two opposite corners.
    pub(crate) fn new(a: DVec3, b: DVec3) -> Cuboid {
        Cuboid {
            min: a.min(b),
            max: a.max(b),
        }
    }

    /// Slab test over the whole line, tracking which face gives each end.
    fn slabs(&self, ray: &Ray) -> Option<Span2> {
        let mut s = Span2 {
            t0: f64::NEG_INFINITY,
            n0: DVec3::ZERO,
            t1: f64::INFINITY,
            n1: DVec3::ZERO,
        };
        for axis in 0..3 {
            let (o, d) = (ray.origin[axis], ray.dir[axis]);
            let (lo, hi) = (self.min[axis], self.max[axis]);
            if d == 0.0 {
                if o < lo || o > hi {
                    return None;
                }
                continue;
            }
            let (ta, tb) = ((lo - o) / d, (hi - o) / d);
            let (near, far) = if ta <= tb { (ta, tb) } else { (tb, ta) };
            let mut e = DVec3::ZERO;
            e[axis] = 1.0;
            if near > s.t0 {
                s.t0 = near;
                s.n0 = -e * d.signum();
            }
            if far < s.t1 {
                s.t1 = far;
                s.n1 = e * d.signum();
            }
        }
        (s.t0 <= s.t1 && s.t0.is_finite() && s.t1.is_finite()).then_some(s)
    }

    fn hit(&self, ray: &Ray, t: f64, normal: DVec3) -> Hit {
        let p = ray.at(t);
        let size = (self.max - self.min).max(DVec3::splat(f64::MIN_POSITIVE));
        let q = ((p - self.min) / size).clamp(DVec3::ZERO, DVec3::ONE);
        let uv = match normal.abs().max_position() {
            0 => DVec2::new(q.z, q.y),
            1 => DVec2::new(q.x, q.z),
            _ => DVec2::new(q.x, q.y),
        };
        Hit { t, normal, uv }
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let s = self.slabs(ray)?;
        if s.t0 > t_min && s.t0 < t_max {
            Some(self.hit(ray, s.t0, s.n0))
        } else if s.t1 > t_min && s.t1 < t_max {
            Some(self.hit(ray, s.t1, s.n1))
        } else {
            None
        }
    }

    /// Entry and exit along the whole line.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        if let Some(s) = self.slabs(ray) {
            out.push(Crossing {
                hit: self.hit(ray, s.t0, s.n0),
                entering: true,
            });
            out.push(Crossing {
                hit: self.hit(ray, s.t1, s.n1),
                entering: false,
            });
        }
    }

    /// Error bound of a computed point `p` on the box: its signed distance to the box (exact
    /// up to the rounding of a few operations on the distances themselves).
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let q = (self.min - p).max(p - self.max);
        let outside = q.max(DVec3::ZERO).norm();
        let inside = q.max_element().min(0.0);
        let distance = outside + inside;
        rounding::from_residual(distance, 5, q.abs().max_element())
    }

    /// True when `p` is inside or on the box.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        Aabb::new(self.min, self.max)
    }
}
