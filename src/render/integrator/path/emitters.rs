//! Sampling the scene's glowing spheres and quads from a surface point (next-event
//! estimation): one emitter chosen in proportion to its power, then a point on it — a sphere
//! by the cone it fills seen from outside (uniform in solid angle), by area from inside; a quad
//! by area. Densities are per unit solid angle at the shaded point and include the choice, so
//! multiple importance sampling weighs them against the BSDF's.

use std::f64::consts::PI;

use glam::DVec3;

use crate::ir::Color;
use crate::num::Norm;
use crate::opt::{Emitter, EmitterShape};

/// A point drawn on an emitter, as seen from the shaded point.
#[derive(Clone, Copy, Debug)]
pub(super) struct EmitterSample {
    /// The point on the emitter.
    pub(super) point: DVec3,
    /// Unit direction from the shaded point to it.
    pub(super) wi: DVec3,
    /// The radiance it sends towards the shaded point (zero from a side that does not emit).
    pub(super) radiance: Color,
    /// Its density per unit solid angle, the emitter's choice included.
    pub(super) pdf: f64,
}

/// The emitters of a scene with what sampling them needs.
pub(super) struct Emitters<'a> {
    all: &'a [Emitter],
    /// Cumulative choice probabilities (the last is 1).
    cdf: Vec<f64>,
    /// Emitter number + 1 by top-level object (0: the object is not sampled).
    by_object: Vec<u32>,
}

impl<'a> Emitters<'a> {
    /// The sampler over `all`.
    pub(super) fn new(all: &'a [Emitter]) -> Emitters<'a> {
        let power: Vec<f64> = all
            .iter()
            .map(|e| {
                let sides = if e.both_sides { 2.0 } else { 1.0 };
                e.radiance.max_element() * e.shape.area() * sides
            })
            .collect();
        let total: f64 = power.iter().sum();
        let mut acc = 0.0;
        let cdf = power
            .iter()
            .map(|p| {
                acc += p / total;
                acc
            })
            .collect();
        let mut by_object = Vec::new();
        for (k, e) in all.iter().enumerate() {
            let i = e.object as usize;
            if by_object.len() <= i {
                by_object.resize(i + 1, 0);
            }
            by_object[i] = k as u32 + 1;
        }
        Emitters {
            all,
            cdf,
            by_object,
        }
    }

    /// Whether there is nothing to sample.
    pub(super) fn is_empty(&self) -> bool {
        self.all.is_empty()
    }

    /// The emitter that top-level object `object` is, if it is sampled.
    pub(super) fn of_object(&self, object: u32) -> Option<usize> {
        match self.by_object.get(object as usize) {
            Some(&k) if k > 0 => Some(k as usize - 1),
            _ => None,
        }
    }

    /// The probability of choosing emitter `k`.
    fn choice(&self, k: usize) -> f64 {
        self.cdf[k] - if k == 0 { 0.0 } else { self.cdf[k - 1] }
    }

    /// A point on an emitter for the shaded point `p`, for the random numbers `pick` (which
    /// emitter) and `(a, b)` (where on it); `None` when it has no density there.
    pub(super) fn sample(&self, p: DVec3, pick: f64, (a, b): (f64, f64)) -> Option<EmitterSample> {
        let k = self
            .cdf
            .partition_point(|c| *c <= pick)
            .min(self.all.len() - 1);
        let e = &self.all[k];
        let choice = self.choice(k);
        if choice <= 0.0 {
            return None;
        }
        let (point, normal, pdf) = match e.shape {
            EmitterShape::Sphere { center, radius } => {
                let to = center - p;
                let d2 = to.length_squared();
                if sees_cone(d2, radius) {
                    // Outside: directions uniform over the cone the sphere fills.
                    let d = d2.sqrt();
                    let sin2_max = radius * radius / d2;
                    let cos_max = (1.0 - sin2_max).max(0.0).sqrt();
                    // 1 − cos θmax without cancellation for a small, far sphere.
                    let spread = sin2_max / (1.0 + cos_max);
                    let cos = 1.0 - a * spread;
                    let sin = (1.0 - cos * cos).max(0.0).sqrt();
                    let axis = to / d;
                    let (t, bt) = axis.any_orthonormal_pair();
                    let phi = 2.0 * PI * b;
                    let wi = (cos * axis + sin * (libm::cos(phi) * t + libm::sin(phi) * bt)).unit();
                    // The near crossing of the sphere along wi.
                    let along = to.dot(wi);
                    let across = (radius * radius - (d2 - along * along)).max(0.0);
                    let dist = (along - across.sqrt()).max(0.0);
                    let point = p + dist * wi;
                    let normal = (point - center).unit();
                    (point, normal, 1.0 / (2.0 * PI * spread))
                } else {
                    // Inside (an enclosure): by area.
                    let z = 1.0 - 2.0 * a;
                    let r = (1.0 - z * z).max(0.0).sqrt();
                    let phi = 2.0 * PI * b;
                    let normal = DVec3::new(r * libm::cos(phi), r * libm::sin(phi), z);
                    let point = center + radius * normal;
                    (
                        point,
                        normal,
                        area_to_solid(p, point, normal, e.shape.area())?,
                    )
                }
            }
            EmitterShape::Parallelogram { corner, u, v } => {
                let point = corner + a * u + b * v;
                let normal = u.cross(v).unit();
                (
                    point,
                    normal,
                    area_to_solid(p, point, normal, e.shape.area())?,
                )
            }
        };
        let wi = (point - p).unit();
        if !wi.is_finite() || !pdf.is_finite() || pdf <= 0.0 {
            return None;
        }
        Some(EmitterSample {
            point,
            wi,
            radiance: radiance_towards(e, normal, wi),
            pdf: choice * pdf,
        })
    }

    /// The density (per unit solid angle at `p`, choice included) with which [`Emitters::sample`]
    /// draws `point` with unit normal `normal` on emitter `k`: what multiple importance
    /// sampling weighs a path that met the emitter against.
    pub(super) fn pdf(&self, k: usize, p: DVec3, point: DVec3, normal: DVec3) -> f64 {
        let e = &self.all[k];
        let density = match e.shape {
            EmitterShape::Sphere { center, radius } => {
                let d2 = (center - p).length_squared();
                if sees_cone(d2, radius) {
                    let sin2_max = radius * radius / d2;
                    let cos_max = (1.0 - sin2_max).max(0.0).sqrt();
                    Some(1.0 / (2.0 * PI * (sin2_max / (1.0 + cos_max))))
                } else {
                    area_to_solid(p, point, normal, e.shape.area())
                }
            }
            EmitterShape::Parallelogram { .. } => area_to_solid(p, point, normal, e.shape.area()),
        };
        density.map_or(0.0, |d| self.choice(k) * d)
    }
}

/// Whether a point at squared distance `d2` from a sphere's centre samples the cone the
/// sphere fills. A point on the sphere itself (to rounding: its own hits) or inside it samples
/// by area: from its surface the cone degenerates to a half-space.
fn sees_cone(d2: f64, radius: f64) -> bool {
    d2 > radius * radius * (1.0 + 1e-6)
}

/// The density per unit solid angle at `p` of a point drawn uniformly by area (`1/area`) at
/// `point` with unit normal `normal`; `None` where it is edge-on or at `p`.
fn area_to_solid(p: DVec3, point: DVec3, normal: DVec3, area: f64) -> Option<f64> {
    let d = point - p;
    let d2 = d.length_squared();
    let cos = (normal.dot(d) / d2.sqrt()).abs();
    (cos > 0.0 && d2 > 0.0).then(|| d2 / (area * cos))
}

/// The radiance emitter `e` sends along unit `wi` (travelling from the shaded point towards
/// the emitter) from its point of unit outward normal `normal`: all of it on an emitting side.
fn radiance_towards(e: &Emitter, normal: DVec3, wi: DVec3) -> Color {
    if e.both_sides || normal.dot(wi) < 0.0 {
        e.radiance
    } else {
        Color::ZERO
    }
}
