//! A surface point to shade and the lights as it sees them: the light samples, their shadow
//! rays and the Phong highlight every shading model shares. The bottom of the shading folder:
//! the models and the glass-shadow tracer read it, it reads none of them.

use crate::num::Norm;
use glam::DVec3;

use crate::geometry::Ray;
use crate::ir::{Color, LightKind, Material, PARALLEL_DISTANCE, cylinder_share};
use crate::opt::{Prepared, PreparedLight};
use crate::render::deal::Weight;
use crate::render::film::Stats;
use crate::render::offset::SpawnPoint;
use crate::render::sampler::Rng;

/// A surface point to shade.
#[derive(Clone, Copy)]
pub(crate) struct Surface<'m> {
    /// The hit point.
    pub(crate) p: DVec3,
    /// Where shadow rays leave the surface (the point with its error bound).
    pub(crate) spawn: SpawnPoint,
    /// Unit normal facing the incoming ray (flipped for hits from inside).
    pub(crate) n: DVec3,
    /// Unit vector towards the viewer (−ray direction).
    pub(crate) v: DVec3,
    /// Base colour (material or texture).
    pub(crate) color: Color,
    /// Surface coefficients.
    pub(crate) mat: &'m Material,
    /// Surface coordinates (for hatching).
    pub(crate) uv: glam::DVec2,
    /// Recursion depth of the ray that hit it (decorrelates light samples between bounces).
    pub(crate) depth: u32,
    /// The shutter fraction of the ray that hit it (shadow rays see moving objects then).
    pub(crate) time: f64,
}

/// One sample of one light as seen from a surface point.
#[derive(Clone, Copy)]
pub(crate) struct LightSample {
    /// Unit vector from the surface to the sample.
    pub(crate) l: DVec3,
    /// The sample's position (shadow rays aim at it).
    pub(crate) position: DVec3,
    /// The light's colour times the sample's share (1/samples), its cone's and its fading's.
    pub(crate) color: Color,
    /// Whether objects cast shadows from it.
    pub(crate) shadows: bool,
}

/// The `k`-th sample of light `index` for a surface point (stratified and jittered on area
/// lights), weighing `weight` of the light ([`crate::render::deal::LightShare::weight`]).
pub(crate) fn light_sample(
    light: &PreparedLight,
    index: usize,
    k: u32,
    weight: Weight,
    s: &Surface<'_>,
    rng: &Rng,
) -> LightSample {
    // A cylinder light's share at the point, found with its sample position.
    let mut beam = None;
    let pos = match light.kind {
        LightKind::Point { position } => position,
        LightKind::Parallel { direction } => s.p - PARALLEL_DISTANCE * direction,
        LightKind::Cylinder {
            position,
            axis,
            radius,
            falloff,
            tightness,
            ..
        } => {
            // The beam reaching the point left the light's plane (through `position`, across
            // the axis) straight up the axis from it; shadow rays go back there. Behind the
            // plane (or on it) the beam does not reach.
            let along = (s.p - position).dot(axis);
            let start = s.p - along * axis;
            beam = Some(if along > 0.0 {
                cylinder_share(radius, falloff, tightness, (start - position).norm())
            } else {
                0.0
            });
            start
        }
        LightKind::Area {
            corner,
            u,
            v,
            samples,
            circular,
            orient,
        } => {
            let (nu, nv) = (samples[0].max(1), samples[1].max(1));
            let stream = (s.depth.wrapping_mul(0x1000_0000))
                ^ ((index as u32).wrapping_mul(0x0010_0000))
                ^ k;
            let (ju, jv) = rng.get2(stream.wrapping_add(1));
            let a = (f64::from(k % nu) + ju) / f64::from(nu);
            let b = (f64::from(k / nu) + jv) / f64::from(nv);
            if circular {
                disk_point(corner, u, v, orient, s.p, a, b)
            } else {
                corner + a * u + b * v
            }
        }
    };
    let d = pos - s.p;
    let dist = d.norm();
    let l = match light.kind {
        // Exactly the light's direction, not the rounded way to the far point.
        LightKind::Parallel { direction } => -direction,
        LightKind::Cylinder { axis, .. } => -axis,
        _ if dist > 0.0 => d / dist,
        _ => s.n,
    };
    let mut color = light.color * f64::from(weight.num) / f64::from(weight.den);
    if let Some(spot) = light.spot {
        color *= spot.share(-l);
    }
    if let Some(share) = beam {
        color *= share;
    }
    if let Some(fade) = light.fade {
        color *= fade.share(dist);
    }
    LightSample {
        l,
        position: pos,
        color,
        shadows: light.shadows,
    }
}

/// The point of a circular area light (the ellipse inscribed in `corner + s·u + t·v`) for the
/// grid point `(a, b)` of the unit square: Shirley and Chiu's concentric map, which keeps the
/// grid's strata equal in area (POV-Ray's own shell map does not). An `orient`ed disk faces
/// `p`, both its radii `|u| / 2`, its axes made as POV-Ray makes them.
pub(crate) fn disk_point(
    corner: DVec3,
    u: DVec3,
    v: DVec3,
    orient: bool,
    p: DVec3,
    a: f64,
    b: f64,
) -> DVec3 {
    let center = corner + 0.5 * (u + v);
    let (x, y) = concentric(2.0 * a - 1.0, 2.0 * b - 1.0);
    let (u, v) = if orient {
        oriented_axes(center - p, u.norm())
    } else {
        (u, v)
    };
    center + (0.5 * x) * u + (0.5 * y) * v
}

/// Shirley and Chiu's equal-area map of the square [−1, 1]² onto the unit disk.
fn concentric(x: f64, y: f64) -> (f64, f64) {
    if x == 0.0 && y == 0.0 {
        return (0.0, 0.0);
    }
    let quarter = std::f64::consts::FRAC_PI_4;
    let (r, theta) = if x.abs() > y.abs() {
        (x, quarter * (y / x))
    } else {
        (y, 2.0 * quarter - quarter * (x / y))
    };
    (r * libm::cos(theta), r * libm::sin(theta))
}

/// Two axes of length `length` across the direction `towards` (a light's centre seen from the
/// point it lights), chosen as POV-Ray's `orient` chooses them: the first across `towards` and a
/// fixed helper (`y` when `towards` is nearly along `z`, else `z`), the second across both.
fn oriented_axes(towards: DVec3, length: f64) -> (DVec3, DVec3) {
    let Some(dir) = towards.try_unit() else {
        return (DVec3::X * length, DVec3::Y * length);
    };
    let helper = if (dir.z.abs() - 1.0).abs() < 0.01 {
        DVec3::Y
    } else {
        DVec3::Z
    };
    let first = dir.cross(helper).unit();
    let second = dir.cross(first).unit();
    (first * length, second * length)
}

/// True when nothing blocks the way from the surface to the light sample (always true without
/// shadows). The shadow ray leaves the surface's error box towards the light and is aimed at the
/// sample from there ([`SpawnPoint::ray_to`]), so a light lying on a surface is not shadowed by it.
pub(crate) fn visible(
    scene: &Prepared,
    s: &Surface<'_>,
    ls: &LightSample,
    stats: &mut Stats,
) -> bool {
    match shadow_ray(scene, s, ls, stats) {
        Some((ray, t_max)) => !scene.shadowed(&ray, 0.0, t_max),
        None => true,
    }
}

/// The shadow ray [`visible`] casts and where it stops, counted; `None` when it casts none
/// (no shadows, or the sample is the ray's origin itself), which leaves the light visible.
/// Always inlined: called out of line, its result went through memory, where the batch's
/// wider reloads of the scalar stores stalled on store forwarding (~15% of `shade_batch`).
#[inline(always)]
fn shadow_ray(
    scene: &Prepared,
    s: &Surface<'_>,
    ls: &LightSample,
    stats: &mut Stats,
) -> Option<(Ray, f64)> {
    if !scene.effects().shadows || !ls.shadows {
        return None;
    }
    stats.shadow_rays += 1;
    let (ray, t_max) = s.spawn.ray_to(ls.position)?;
    Some((ray.at_time(s.time), t_max))
}

/// The Phong highlight `ks·max(0, R·V)^n` with `R = 2(N·L)N − L`.
pub(crate) fn highlight(s: &Surface<'_>, l: DVec3, n_dot_l: f64) -> f64 {
    if s.mat.ks == 0.0 {
        return 0.0;
    }
    let r = 2.0 * n_dot_l * s.n - l;
    let rv = r.dot(s.v);
    if rv > 0.0 {
        s.mat.ks * libm::pow(rv, s.mat.n)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_concentric_map_keeps_square_rings_as_circles() {
        // A point of the square at max-norm r lands at radius r: the map carries each square
        // ring onto the circle of the same "radius", so strata of equal area stay equal (the
        // rings' areas 4r² and πr² are in the same ratio for every r).
        for k in 0..=40 {
            for m in 0..=40 {
                let (x, y) = (f64::from(k) / 20.0 - 1.0, f64::from(m) / 20.0 - 1.0);
                let (u, v) = concentric(x, y);
                let r = x.abs().max(y.abs());
                assert!(((u * u + v * v).sqrt() - r).abs() < 1e-12, "({x}, {y})");
            }
        }
        // The four edge midpoints go to the four axis points.
        let (u, v) = concentric(1.0, 0.0);
        assert!((u - 1.0).abs() < 1e-15 && v.abs() < 1e-15);
        let (u, v) = concentric(0.0, 1.0);
        assert!(u.abs() < 1e-15 && (v - 1.0).abs() < 1e-15);
    }

    #[test]
    fn an_oriented_disk_faces_the_point_it_lights() {
        let (corner, u, v) = (
            DVec3::new(-1.0, 5.0, -1.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 0.0, 2.0),
        );
        let centre = corner + 0.5 * (u + v);
        for p in [
            DVec3::new(7.0, 0.0, 3.0),
            DVec3::new(0.0, -4.0, 0.0),
            DVec3::new(0.0, 5.0, 9.0),
        ] {
            let towards = (centre - p).unit();
            for (a, b) in [(0.1, 0.2), (0.9, 0.5), (0.5, 0.99), (0.0, 0.0)] {
                let q = disk_point(corner, u, v, true, p, a, b);
                // In the plane across the way to `p`, within the radius |u|/2 of the centre.
                assert!((q - centre).dot(towards).abs() < 1e-12, "{p} {a} {b}");
                assert!((q - centre).norm() <= 1.0 + 1e-12);
            }
        }
        // Not oriented: the disk lies in the light's own plane.
        let q = disk_point(corner, u, v, false, DVec3::ZERO, 0.9, 0.2);
        assert_eq!(q.y, 5.0);
        assert!((q - centre).norm() <= 1.0 + 1e-12);
    }
}
