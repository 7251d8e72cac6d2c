//! Cylinders between two points, open or capped, and the axis frame cones share.

use crate::num::Norm;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::{
    aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding, shapes::circle_quadratic,
};

/// An orthonormal frame along a segment: `base`, unit `axis`, length `height`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AxisFrame {
    /// Start of the axis.
    pub(crate) base: DVec3,
    /// Unit axis direction.
    pub(crate) axis: DVec3,
    /// Length of the axis.
    pub(crate) height: f64,
    e1: DVec3,
    e2: DVec3,
}

impl AxisFrame {
    /// A frame from `base` to `top`; `None` when they coincide.
    pub(crate) fn new(base: DVec3, top: DVec3) -> Option<AxisFrame> {
        let d = top - base;
        let height = d.norm();
        let axis = d.try_unit()?;
        let e1 = axis.any_orthonormal_vector();
        Some(AxisFrame {
            base,
            axis,
            height,
            e1,
            e2: axis.cross(e1),
        })
    }

    /// (angle / 2π, height fraction) of a point.
    pub(crate) fn uv(&self, p: DVec3) -> DVec2 {
        let w = p - self.base;
        let angle = libm::atan2(w.dot(self.e2), w.dot(self.e1)).rem_euclid(TAU);
        DVec2::new(
            angle / TAU,
            (w.dot(self.axis) / self.height).clamp(0.0, 1.0),
        )
    }

    /// A point's height along the axis, its distance from the axis, and the size of the
    /// numbers that gave them (for error bounds).
    pub(crate) fn height_and_radius(&self, p: DVec3) -> (f64, f64, f64) {
        let w = p - self.base;
        let y = w.dot(self.axis);
        let rho = (w - y * self.axis).norm();
        (y, rho, w.abs().element_sum() + self.height)
    }

    /// The smallest residual of a point on the caps at heights 0 (when `base_cap`) and the top
    /// (when `top_cap`), and `side` (the lateral surface's residual).
    pub(crate) fn nearest_part(&self, y: f64, side: f64, base_cap: bool, top_cap: bool) -> f64 {
        let mut r = side.abs();
        if base_cap {
            r = r.min(y.abs());
        }
        if top_cap {
            r = r.min((y - self.height).abs());
        }
        r
    }

    /// Bounds of a disk of `radius` centred on the axis at height `y`.
    pub(crate) fn disk_bounds(&self, y: f64, radius: f64) -> Aabb {
        let c = self.base + y * self.axis;
        let ext = radius
            * (DVec3::ONE - self.axis * self.axis)
                .max(DVec3::ZERO)
                .powf(0.5);
        Aabb::new(c - ext, c + ext)
    }

    /// Hit on the cap at height `y` with radius `radius`, whose outward normal is `normal`.
    pub(crate) fn cap(&self, ray: &Ray, y: f64, radius: f64, normal: DVec3) -> Option<Hit> {
        let da = ray.dir.dot(self.axis);
        if da == 0.0 {
            return None;
        }
        let t = (y - (ray.origin - self.base).dot(self.axis)) / da;
        let w = ray.at(t) - self.base;
        let radial = w - w.dot(self.axis) * self.axis;
        (radial.length_squared() <= radius * radius && t.is_finite()).then(|| Hit {
            t,
            normal,
            uv: self.uv(ray.at(t)),
        })
    }
}

/// A cylinder in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cylinder {
    frame: AxisFrame,
    radius: f64,
    capped: bool,
}

impl Cylinder {
    /// A cylinder; `None` for coincident ends or a non-positive radius.
    pub(crate) fn new(base: DVec3, top: DVec3, radius: f64, capped: bool) -> Option<Cylinder> {
        let frame = AxisFrame::new(base, top)?;
        (radius > 0.0 && radius.is_finite()).then_some(Cylinder {
            frame,
            radius,
            capped,
        })
    }

    /// Whether the ends are closed (a solid).
    pub(crate) fn is_closed(&self) -> bool {
        self.capped
    }

    /// Every surface hit along the whole line, unsorted (at most four).
    fn candidates(&self, ray: &Ray) -> ([Option<Hit>; 4], usize) {
        let f = &self.frame;
        let mut out = [None; 4];
        let w = ray.origin - f.base;
        let wp = w - w.dot(f.axis) * f.axis;
        let dp = ray.dir - ray.dir.dot(f.axis) * f.axis;
        if let Some((t0, t1)) =
            circle_quadratic::roots(wp, dp, circle_quadratic::DirSquared::of(dp), self.radius)
        {
            for (i, t) in [t0, t1].into_iter().enumerate() {
                let p = ray.at(t);
                let y = (p - f.base).dot(f.axis);
                if (0.0..=f.height).contains(&y) {
                    let radial = (p - f.base) - y * f.axis;
                    if let Some(normal) = radial.try_unit() {
                        out[i] = Some(Hit {
                            t,
                            normal,
                            uv: f.uv(p),
                        });
                    }
                }
            }
        }
        if self.capped {
            out[2] = f.cap(ray, 0.0, self.radius, -f.axis);
            out[3] = f.cap(ray, f.height, self.radius, f.axis);
        }
        (out, 4)
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (c, n) = self.candidates(ray);
        crate::geometry::ray::nearest(c[..n].iter().flatten().copied(), t_min, t_max)
    }

    /// Entry and exit along the whole line (capped cylinders are convex).
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        let (c, n) = self.candidates(ray);
        convex_crossings(c[..n].iter().flatten().copied(), out);
    }

    /// Error bound of a computed point `p` on the cylinder: the residual of the part it lies
    /// on (side or cap) plus the rounding of evaluating it.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let f = &self.frame;
        let (y, rho, size) = f.height_and_radius(p);
        let residual = f.nearest_part(y, rho - self.radius, self.capped, self.capped);
        rounding::from_residual(residual, 10, size + self.radius)
    }

    /// True when `p` is inside or on the solid.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        let f = &self.frame;
        let w = p - f.base;
        let y = w.dot(f.axis);
        (0.0..=f.height).contains(&y)
            && (w - y * f.axis).length_squared() <= self.radius * self.radius
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        let f = &self.frame;
        f.disk_bounds(0.0, self.radius)
            .union(f.disk_bounds(f.height, self.radius))
    }
}

/// For a convex solid, the first hit enters and the last leaves, whatever duplicates a rim
/// hit produced in between.
pub(crate) fn convex_crossings(hits: impl Iterator<Item = Hit>, out: &mut Vec<Crossing>) {
    let mut first: Option<Hit> = None;
    let mut last: Option<Hit> = None;
    for h in hits {
        if first.is_none_or(|f| h.t < f.t) {
            first = Some(h);
        }
        if last.is_none_or(|l| h.t > l.t) {
            last = Some(h);
        }
    }
    if let (Some(f), Some(l)) = (first, last) {
        out.push(Crossing {
            hit: f,
            entering: true,
        });
        out.push(Crossing {
            hit: l,
            entering: false,
        });
    }
}
