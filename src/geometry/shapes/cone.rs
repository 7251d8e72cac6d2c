//! Cones and frustums between two points, open or capped.

use crate::num::Norm;
use glam::DVec3;

use crate::geometry::shapes::cylinder::{AxisFrame, convex_crossings};
use crate::geometry::shapes::quartic::quadratic;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// A cone or frustum in object space: the radius goes linearly from `r0` at the base to `r1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cone {
    frame: AxisFrame,
    r0: f64,
    r1: f64,
    /// Radius change per unit height.
    k: f64,
    capped: bool,
}

impl Cone {
    /// A cone; `None` for coincident ends, a negative radius or both radii zero.
    pub(crate) fn new(base: DVec3, top: DVec3, r0: f64, r1: f64, capped: bool) -> Option<Cone> {
        let frame = AxisFrame::new(base, top)?;
        let ok = r0 >= 0.0 && r1 >= 0.0 && r0.max(r1) > 0.0 && r0.is_finite() && r1.is_finite();
        ok.then_some(Cone {
            frame,
            r0,
            r1,
            k: (r1 - r0) / frame.height,
            capped,
        })
    }

    /// Whether the ends are closed (a solid).
    pub(crate) fn is_closed(&self) -> bool {
        self.capped
    }

    /// Where the line of `ray` meets the infinite double cone `|radial|² = ρ(y)²`.
    ///
    /// The quadratic is formed at the point of the line closest to the middle of the axis and
    /// its roots moved back by that point's parameter: formed at a far origin, its coefficients
    /// are ~distance² and cancel away the cone's own size (from 10⁸ sizes every hit is lost).
    /// The sphere's rearrangement (the closest approach to the centre) has no counterpart: the
    /// double cone's quadratic form is indefinite, so the parabola's vertex need not lie near it.
    fn lateral_roots(&self, ray: &Ray) -> Option<(f64, f64)> {
        let f = &self.frame;
        let middle = f.base + 0.5 * f.height * f.axis;
        let s = (middle - ray.origin).dot(ray.dir) / ray.dir.length_squared();
        let w = ray.at(s) - f.base;
        let (wa, da) = (w.dot(f.axis), ray.dir.dot(f.axis));
        let wp = w - wa * f.axis;
        let dp = ray.dir - da * f.axis;
        let rho0 = self.r0 + self.k * wa;
        let a = dp.length_squared() - self.k * self.k * da * da;
        let b = 2.0 * (wp.dot(dp) - self.k * rho0 * da);
        let c = wp.length_squared() - rho0 * rho0;
        let (t0, t1) = quadratic(a, b, c)?;
        Some((s + t0, s + t1))
    }

    fn candidates(&self, ray: &Ray) -> [Option<Hit>; 4] {
        let f = &self.frame;
        let mut out = [None; 4];
        if let Some((t0, t1)) = self.lateral_roots(ray) {
            for (i, t) in [t0, t1].into_iter().enumerate() {
                let p = ray.at(t);
                let y = (p - f.base).dot(f.axis);
                if !(0.0..=f.height).contains(&y) {
                    continue;
                }
                let radial = (p - f.base) - y * f.axis;
                let rho = self.r0 + self.k * y;
                // Gradient of |radial|² − ρ(y)²; zero only at an apex.
                let normal = (radial - rho * self.k * f.axis)
                    .try_unit()
                    .unwrap_or(if self.r0 == 0.0 { -f.axis } else { f.axis });
                out[i] = Some(Hit {
                    t,
                    normal,
                    uv: f.uv(p),
                });
            }
        }
        if self.capped {
            if self.r0 > 0.0 {
                out[2] = f.cap(ray, 0.0, self.r0, -f.axis);
            }
            if self.r1 > 0.0 {
                out[3] = f.cap(ray, f.height, self.r1, f.axis);
            }
        }
        out
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        crate::geometry::ray::nearest(self.candidates(ray).into_iter().flatten(), t_min, t_max)
    }

    /// Entry and exit along the whole line (capped cones are convex).
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        convex_crossings(self.candidates(ray).into_iter().flatten(), out);
    }

    /// Error bound of a computed point `p` on the cone: the residual of the part it lies on
    /// (the side's distance in the plane through the axis, or a cap's) plus its rounding.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let f = &self.frame;
        let (y, rho, size) = f.height_and_radius(p);
        let side = (rho - (self.r0 + self.k * y)) / (1.0 + self.k * self.k).sqrt();
        let residual = f.nearest_part(
            y,
            side,
            self.capped && self.r0 > 0.0,
            self.capped && self.r1 > 0.0,
        );
        let magnitude = size + self.r0 + self.r1 + (self.k * y).abs();
        rounding::from_residual(residual, 14, magnitude)
    }

    /// True when `p` is inside or on the solid.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        let f = &self.frame;
        let w = p - f.base;
        let y = w.dot(f.axis);
        let rho = self.r0 + self.k * y;
        (0.0..=f.height).contains(&y) && (w - y * f.axis).length_squared() <= rho * rho
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        let f = &self.frame;
        f.disk_bounds(0.0, self.r0)
            .union(f.disk_bounds(f.height, self.r1))
    }
}
