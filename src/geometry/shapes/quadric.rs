//! General quadric surfaces (POV-Ray's `quadric`): the points where
//! `A·x² + B·y² + C·z² + D·xy + E·xz + F·yz + G·x + H·y + I·z + J = 0`, inside where the
//! polynomial is negative. Ellipsoids, paraboloids, hyperboloids, cones and cylinders of any
//! orientation are all one shape; most of them are unbounded (bound them with CSG).
//!
//! Along a ray `o + t·d` the polynomial is the quadratic `a·t² + b·t + c`, solved in the form
//! whose two terms never cancel (the larger root from `−b − sign(b)·√disc`, the other from the
//! product `c/a`), and linear when `a` vanishes (a ray parallel to a paraboloid's axis meets it
//! once).

use crate::num::Norm;

use glam::DVec3;

use crate::geometry::ray::equirectangular_uv;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// A quadric `f(p) = pᵀ·Q·p + L·p + J = 0`, stored as POV-Ray writes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Quadric {
    /// `A, B, C`: the coefficients of `x², y², z²`.
    pub(crate) squares: DVec3,
    /// `D, E, F`: the coefficients of `xy, xz, yz`.
    pub(crate) mixed: DVec3,
    /// `G, H, I`: the coefficients of `x, y, z`.
    pub(crate) linear: DVec3,
    /// `J`: the constant.
    pub(crate) constant: f64,
}

impl Quadric {
    /// The polynomial at `p` (negative inside).
    pub(crate) fn value(&self, p: DVec3) -> f64 {
        let (s, m, l) = (self.squares, self.mixed, self.linear);
        s.x * p.x * p.x
            + s.y * p.y * p.y
            + s.z * p.z * p.z
            + m.x * p.x * p.y
            + m.y * p.x * p.z
            + m.z * p.y * p.z
            + l.dot(p)
            + self.constant
    }

    /// The polynomial's gradient at `p` (points outside; zero at a cone's apex).
    pub(crate) fn gradient(&self, p: DVec3) -> DVec3 {
        let (s, m, l) = (self.squares, self.mixed, self.linear);
        DVec3::new(
            2.0 * s.x * p.x + m.x * p.y + m.y * p.z + l.x,
            2.0 * s.y * p.y + m.x * p.x + m.z * p.z + l.y,
            2.0 * s.z * p.z + m.y * p.x + m.z * p.y + l.z,
        )
    }

    /// The quadratic form alone at `d` (the `t²` coefficient along a ray of direction `d`).
    fn form(&self, d: DVec3) -> f64 {
        let (s, m) = (self.squares, self.mixed);
        s.x * d.x * d.x
            + s.y * d.y * d.y
            + s.z * d.z * d.z
            + m.x * d.x * d.y
            + m.y * d.x * d.z
            + m.z * d.y * d.z
    }

    /// `(a, b, c)` of `f(o + t·d) = a·t² + b·t + c`.
    fn along(&self, ray: &Ray) -> (f64, f64, f64) {
        let (o, d) = (ray.origin, ray.dir);
        // b = ∇f(o)·d: the gradient at the origin already holds every cross term once.
        (self.form(d), self.gradient(o).dot(d), self.value(o))
    }

    /// The parameters where the whole line of `ray` meets the surface, in increasing order
    /// (none, one for a line crossing a degenerate direction once, or two).
    fn roots(&self, ray: &Ray) -> ([f64; 2], usize) {
        let (a, b, c) = self.along(ray);
        // Relative to the other terms, a vanishing `a` is a line the quadratic meets once.
        let scale = b.abs().max(c.abs()).max(f64::MIN_POSITIVE);
        if a.abs() <= 1e-12 * scale {
            if b == 0.0 {
                return ([0.0; 2], 0);
            }
            return ([-c / b, 0.0], 1);
        }
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 || disc.is_nan() {
            return ([0.0; 2], 0);
        }
        let q = -0.5 * (b + disc.sqrt().copysign(b));
        let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
        ([t0.min(t1), t0.max(t1)], 2)
    }

    /// The hit at parameter `t`: the unit gradient as normal, uv its direction's longitude and
    /// latitude (as on a sphere: an ellipsoid maps like one).
    fn hit(&self, ray: &Ray, t: f64) -> Hit {
        let g = self.gradient(ray.at(t));
        // At a cone's apex the gradient vanishes: face the ray.
        let normal = if g == DVec3::ZERO {
            -ray.dir.unit_or(DVec3::Y)
        } else {
            g.unit()
        };
        Hit {
            t,
            normal,
            uv: equirectangular_uv(normal),
        }
    }

    /// Nearest intersection of `ray` in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (ts, n) = self.roots(ray);
        let t = ts[..n].iter().copied().find(|t| *t > t_min && *t < t_max)?;
        Some(self.hit(ray, t))
    }

    /// Every crossing along the whole line of `ray`: entering where the polynomial falls
    /// through zero (the gradient against the ray).
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        let (ts, n) = self.roots(ray);
        for &t in &ts[..n] {
            let hit = self.hit(ray, t);
            let slope = self.gradient(ray.at(t)).dot(ray.dir);
            // A tangent (slope 0) touches without entering; it is reported as a pair by the
            // quadratic and cancels out.
            out.push(Crossing {
                hit,
                entering: slope < 0.0,
            });
        }
    }

    /// Whether the line of `ray` starts inside (at t → −∞): the sign of the polynomial there,
    /// from its leading term.
    pub(crate) fn inside_at_start(&self, ray: &Ray) -> bool {
        let (a, b, c) = self.along(ray);
        let scale = b.abs().max(c.abs()).max(f64::MIN_POSITIVE);
        if a.abs() > 1e-12 * scale {
            a < 0.0
        } else if b != 0.0 {
            b > 0.0
        } else {
            c < 0.0
        }
    }

    /// True when `p` is inside or on the surface.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        self.value(p) <= 0.0
    }

    /// Object-space bounds: unbounded (a quadric is bounded only when it is an ellipsoid, and
    /// scenes bound theirs with CSG, as POV-Ray's do).
    pub(crate) fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY)
    }

    /// Error bound of a computed point `p` on the surface: the residual `f(p)/|∇f(p)|` (a
    /// first-order distance) plus the rounding of evaluating the polynomial.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let g = self.gradient(p).norm().max(f64::MIN_POSITIVE);
        let size = self.squares.abs().max_element() * p.length_squared()
            + self.mixed.abs().max_element() * p.length_squared()
            + self.linear.abs().dot(p.abs())
            + self.constant.abs();
        rounding::from_residual(self.value(p) / g, 12, size / g)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit sphere as a quadric: x² + y² + z² − 1.
    fn unit_sphere() -> Quadric {
        Quadric {
            squares: DVec3::ONE,
            mixed: DVec3::ZERO,
            linear: DVec3::ZERO,
            constant: -1.0,
        }
    }

    #[test]
    fn the_sphere_quadric_meets_a_ray_where_the_sphere_does() {
        let q = unit_sphere();
        let r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let h = q.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert_eq!(h.t, 4.0);
        assert_eq!(h.normal, -DVec3::Z);
        let mut out = Vec::new();
        q.crossings(&r, &mut out);
        assert_eq!(out.len(), 2);
        assert!(out[0].entering && !out[1].entering);
        assert_eq!(out[1].hit.t, 6.0);
        assert!(q.contains(DVec3::ZERO) && !q.contains(DVec3::splat(1.0)));
    }

    #[test]
    fn a_paraboloid_is_met_once_along_its_axis() {
        // y = x² + z²: x² + z² − y = 0, inside above the bowl.
        let q = Quadric {
            squares: DVec3::new(1.0, 0.0, 1.0),
            mixed: DVec3::ZERO,
            linear: DVec3::new(0.0, -1.0, 0.0),
            constant: 0.0,
        };
        let down = Ray::new(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y);
        let h = q.intersect(&down, 0.0, f64::INFINITY).unwrap();
        assert_eq!(h.t, 5.0);
        assert_eq!(h.normal, -DVec3::Y);
        // Going down the axis the line starts inside (above the bowl) and leaves once.
        assert!(q.inside_at_start(&down));
        let mut out = Vec::new();
        q.crossings(&down, &mut out);
        assert_eq!(out.len(), 1);
        assert!(!out[0].entering);
    }

    #[test]
    fn a_cylinder_quadric_contains_its_whole_axis() {
        // x² + z² − 1: an infinite cylinder along y.
        let q = Quadric {
            squares: DVec3::new(1.0, 0.0, 1.0),
            mixed: DVec3::ZERO,
            linear: DVec3::ZERO,
            constant: -1.0,
        };
        let along = Ray::new(DVec3::ZERO, DVec3::Y);
        assert!(q.intersect(&along, 0.0, f64::INFINITY).is_none());
        assert!(q.inside_at_start(&along));
        let across = Ray::new(DVec3::new(-3.0, 7.0, 0.0), DVec3::X);
        assert_eq!(q.intersect(&across, 0.0, f64::INFINITY).unwrap().t, 2.0);
        assert!(!q.inside_at_start(&across));
    }

    #[test]
    fn far_hits_keep_a_small_residual() {
        let q = unit_sphere();
        let r = Ray::new(DVec3::new(0.3, 0.2, -1e6), DVec3::Z);
        let h = q.intersect(&r, 0.0, f64::INFINITY).unwrap();
        let p = r.at(h.t);
        let err = q.point_error(p);
        assert!((p.norm() - 1.0).abs() <= err.x, "{p} {err}");
    }
}
