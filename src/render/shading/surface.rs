//! A surface point to shade and the lights as it sees them: the light samples, their shadow
//! rays and the Phong highlight every shading model shares. The bottom of the shading folder:
//! the models and the glass-shadow tracer read it, it reads none of them.

use crate::num::Norm;
use glam::DVec3;

use crate::geometry::Ray;
use crate::ir::{Color, LightKind, Material, PARALLEL_DISTANCE};
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
    let pos = match light.kind {
        LightKind::Point { position } => position,
        LightKind::Parallel { direction } => s.p - PARALLEL_DISTANCE * direction,
        LightKind::Area {
            corner,
            u,
            v,
            samples,
        } => {
            let (nu, nv) = (samples[0].max(1), samples[1].max(1));
            let stream = (s.depth.wrapping_mul(0x1000_0000))
                ^ ((index as u32).wrapping_mul(0x0010_0000))
                ^ k;
            let (ju, jv) = rng.get2(stream.wrapping_add(1));
            let a = (f64::from(k % nu) + ju) / f64::from(nu);
            let b = (f64::from(k / nu) + jv) / f64::from(nv);
            corner + a * u + b * v
        }
    };
    let d = pos - s.p;
    let dist = d.norm();
    let l = match light.kind {
        // Exactly the light's direction, not the rounded way to the far point.
        LightKind::Parallel { direction } => -direction,
        _ if dist > 0.0 => d / dist,
        _ => s.n,
    };
    let mut color = light.color * f64::from(weight.num) / f64::from(weight.den);
    if let Some(spot) = light.spot {
        color *= spot.share(-l);
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
        Some((ray, t_max)) => !scene.world().occluded(&ray, 0.0, t_max),
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
