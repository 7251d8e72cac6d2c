//! The path tracer: global illumination for a scene that asks for it
//! (`render { integrator: path(..) }`, docs/gi.md). A unidirectional path tracer with
//! next-event estimation towards the scene's lights and Russian roulette; the material terms
//! become a BSDF ([`bsdf`]).
//!
//! Units: a surface's emission and the environment (the sky or background) are radiances. A
//! light of colour `Lc` is a delta light that gives a surface facing it the irradiance `π·Lc`
//! (so a white Lambertian surface facing it shows `Lc`, exactly Whitted's diffuse term), fading
//! and shaped by its spot cone as under Whitted; an area light is its grid of such points.
//! Neither is seen by rays that meet it: only surfaces and the environment are.

mod bsdf;
mod emitters;
mod environment;

use std::f64::consts::PI;

use glam::DVec3;

use crate::geometry::Ray;
use crate::ir::{Color, Fog, Material, PathTracing, Sky};
use crate::opt::{Effects, Prepared};
use crate::render::context::Ctx;
use crate::render::path::Path;
use crate::render::sampler::Rng;
use crate::render::scatter::{self, Scattering, reflect};
use crate::render::shading::{self, Surface, light_sample};
use crate::render::{fog, mix, sky};
use bsdf::Bsdf;
use emitters::Emitters;
use environment::Environment;

use super::whitted::Whitted;

/// The random-number streams of one bounce (each bounce has a generator of its own).
const PICK: u32 = 1;
const DIRECTION: u32 = 2;
const ROULETTE: u32 = 3;
const EMITTER: u32 = 4;
const EMITTER_POINT: u32 = 5;
const SKY: u32 = 6;
const SKY_DIRECTION: u32 = 7;

/// The path tracer over a prepared scene.
pub(crate) struct PathTracer<'a> {
    scene: &'a Prepared,
    /// The Whitted integrator's view of a hit (its surface, colour and bump), shared so both
    /// integrators see the same surface.
    surfaces: Whitted<'a>,
    effects: Effects,
    settings: PathTracing,
    /// The glowing spheres and quads next-event estimation aims at.
    emitters: Emitters<'a>,
    /// The sky tabulated for sampling by brightness (`None` without a sky).
    environment: Option<Environment>,
    /// Whether light is tested for blockers (`render { shadows: .. }`).
    shadows: bool,
    background: Color,
    sky: Option<&'a Sky>,
    fog: Option<&'a Fog>,
    alpha: bool,
}

impl<'a> PathTracer<'a> {
    /// The path tracer for `scene` with `settings`.
    pub(crate) fn new(scene: &'a Prepared, settings: PathTracing) -> PathTracer<'a> {
        let s = scene.settings();
        PathTracer {
            scene,
            surfaces: Whitted::new(scene),
            effects: scene.effects(),
            settings,
            emitters: Emitters::new(scene.emitters()),
            environment: s
                .sky
                .as_ref()
                .and_then(|sky| Environment::new(|d| sky::color(scene, sky, d, s.background))),
            shadows: s.shadows,
            background: s.background,
            sky: s.sky.as_ref(),
            fog: s.fog.as_ref(),
            alpha: s.alpha,
        }
    }

    /// The scene it traces.
    pub(crate) fn scene(&self) -> &'a Prepared {
        self.scene
    }

    /// The radiance arriving along camera ray `ray`: the mean of `samples` paths.
    pub(crate) fn trace(&self, ray: &Ray, ctx: &mut Ctx) -> Color {
        let n = self.settings.samples.max(1);
        let mut sum = Color::ZERO;
        for j in 0..n {
            let rng = ctx.rng.path(j, n);
            sum += self.radiance(ray, &rng, ctx);
        }
        sum / f64::from(n)
    }

    /// One path's estimate of the radiance along `camera`.
    fn radiance(&self, camera: &Ray, rng: &Rng, ctx: &mut Ctx) -> Color {
        let scene = self.scene;
        let mut light = Color::ZERO;
        let mut beta = Color::ONE;
        let mut ray = *camera;
        let mut path = Path::CAMERA;
        // The density of the BSDF sample that made `ray` (0 for the camera ray and after a
        // delta lobe, which no light sampling can make) and where it left from.
        let mut bsdf_pdf = 0.0;
        let mut from = ray.origin;
        for bounce in 0..=self.settings.bounces {
            let found = if self.effects.visibility_flags {
                scene.seen_hit(&ray, 0.0, f64::INFINITY, path.ray_kind())
            } else {
                scene.world().intersect(&ray, 0.0, f64::INFINITY)
            };
            let Some(hit) = found else {
                if self.alpha && bounce == 0 {
                    // Transparent black: the film's colour is premultiplied by the alpha.
                    return Color::ZERO;
                }
                let weight = match &self.environment {
                    // Sky sampling could have found this direction too: weigh the two ways.
                    Some(env) if bsdf_pdf > 0.0 => power_heuristic(bsdf_pdf, env.pdf(ray.dir)),
                    _ => 1.0,
                };
                light += beta * self.sky_seen(&ray, path) * weight;
                break;
            };
            let (add, keep) = self.fog_over(&ray, hit.t, path);
            light += beta * add;
            beta *= keep;
            let stored = scene.material(hit.material);
            let mixed;
            let mat = match stored.mix {
                Some(_) if self.effects.textures => {
                    mixed = mix::resolve(scene, &hit, scene.world().frame(&hit), stored);
                    &mixed
                }
                _ => stored,
            };
            let (s, inside, facing) = self.surfaces.surface(&ray, &hit, path, mat);
            if inside && self.effects.absorption && mat.absorption != Color::ZERO {
                beta *= scatter::beer_lambert(mat.absorption, hit.t);
            }
            if self.effects.emission && (mat.emits_both_sides || !inside) {
                let emitted = shading::finish::emitted(mat, s.color);
                let sampled = self.emitters.of_object(scene.world().object(&hit));
                let weight = match sampled {
                    // Light sampling could have found this point too: weigh the two ways.
                    Some(k) if bsdf_pdf > 0.0 => {
                        power_heuristic(bsdf_pdf, self.emitters.pdf(k, from, hit.point, hit.normal))
                    }
                    _ => 1.0,
                };
                light += beta * emitted * weight;
            }
            if bounce == self.settings.bounces {
                break;
            }
            let (bsdf, after) = self.bsdf(&ray, &s, facing, inside, path, mat);
            if !bsdf.scatters() {
                break;
            }
            let rng = rng.derive(bounce);
            if bsdf.has_density() {
                light += beta * self.direct(&s, &bsdf, &rng, ctx);
                light += beta * self.direct_emitter(&s, &bsdf, &rng, ctx);
                light += beta * self.direct_sky(&s, &bsdf, path, &rng, ctx);
            }
            let pick = rng.get2(PICK).0;
            let Some(out) = bsdf.sample(pick, rng.get2(DIRECTION)) else {
                break;
            };
            beta *= out.throughput;
            bsdf_pdf = out.pdf;
            from = s.p;
            if bounce + 1 >= self.settings.roulette {
                // Russian roulette: a path carrying little goes on with probability `q`,
                // weighed up by 1/q, so the estimate stays unbiased.
                let q = beta.max_element().min(1.0);
                if rng.get2(ROULETTE).0 >= q {
                    break;
                }
                beta /= q;
            }
            path = if out.transmits {
                path.bounce(after, 1.0)
            } else {
                path.reflect(path.media, 1.0)
            };
            ray = Ray::new(s.spawn.origin_towards(out.wi), out.wi).at_time(ray.time);
            ctx.stats.secondary_rays += 1;
        }
        light
    }

    /// The BSDF at surface `s` of `ray`'s hit, and the media beyond the surface for a ray
    /// that passes through it.
    fn bsdf(
        &self,
        ray: &Ray,
        s: &Surface<'_>,
        facing: DVec3,
        inside: bool,
        path: Path,
        mat: &Material,
    ) -> (Bsdf, crate::render::path::Media) {
        let scattering = Scattering::of(mat, &self.effects);
        let (n1, after) = path.media.cross(scattering.eta, inside);
        let (mut kr, kt) = if scattering.varies() {
            scattering.shares(-ray.dir.dot(s.n), n1, after.current())
        } else {
            (scattering.reflect, scattering.refract)
        };
        let mut refraction = None;
        if kt > 0.0 {
            let lobe = scattering.refraction(n1, after.current()).with_weight(kt);
            match lobe.axis(ray.dir, facing) {
                Some(axis) => {
                    let tint = scatter::tint(mat, s.color).unwrap_or(Color::ONE);
                    refraction = Some((lobe, axis, tint));
                }
                // Total internal reflection: the refracted share goes to the mirror.
                None => kr += kt,
            }
        }
        let mirror = (kr > 0.0).then(|| (scattering.mirror(kr), reflect(ray.dir, facing)));
        let bsdf = Bsdf::new(
            s.n,
            facing,
            s.v,
            s.color,
            (mat.kd, mat.ks, mat.n, mat.metallic),
            mirror,
            refraction,
        );
        (bsdf, after)
    }

    /// Next-event estimation: the light of every light's samples reaching `s` unblocked,
    /// through the BSDF. Lights are deltas, so no other strategy finds them and no
    /// multiple-importance weight is needed.
    fn direct(&self, s: &Surface<'_>, bsdf: &Bsdf, rng: &Rng, ctx: &mut Ctx) -> Color {
        let mut c = Color::ZERO;
        for (i, l) in self.scene.lights().iter().enumerate() {
            let (first, count) = ctx.lights.cells(l.samples);
            for j in 0..count {
                let k = (first + j) % l.samples;
                let w = ctx.lights.weight(l.samples, k);
                let ls = light_sample(l, i, k, w, s, rng);
                let f = bsdf.f_cos(ls.l);
                if f == Color::ZERO || ls.color == Color::ZERO {
                    continue;
                }
                if let Some(pass) = shading::transmission(self.scene, s, &ls, &mut ctx.stats) {
                    c += f * ls.color * pass * PI;
                }
            }
        }
        c
    }

    /// Next-event estimation towards the glowing spheres and quads: one point on one of
    /// them, weighed against the BSDF's way of finding it (the power heuristic).
    fn direct_emitter(&self, s: &Surface<'_>, bsdf: &Bsdf, rng: &Rng, ctx: &mut Ctx) -> Color {
        if self.emitters.is_empty() {
            return Color::ZERO;
        }
        let Some(e) = self
            .emitters
            .sample(s.p, rng.get2(EMITTER).0, rng.get2(EMITTER_POINT))
        else {
            return Color::ZERO;
        };
        if e.radiance == Color::ZERO {
            return Color::ZERO;
        }
        let f = bsdf.f_cos(e.wi);
        if f == Color::ZERO {
            return Color::ZERO;
        }
        if self.shadows {
            let Some((ray, t_max)) = s.spawn.ray_to(e.point) else {
                return Color::ZERO;
            };
            ctx.stats.shadow_rays += 1;
            if self.scene.shadowed(&ray.at_time(s.time), 0.0, t_max) {
                return Color::ZERO;
            }
        }
        f * e.radiance * (power_heuristic(e.pdf, bsdf.pdf(e.wi)) / e.pdf)
    }

    /// Next-event estimation towards the sky: one direction drawn by the sky's brightness,
    /// weighed against the BSDF's way of finding it.
    fn direct_sky(
        &self,
        s: &Surface<'_>,
        bsdf: &Bsdf,
        path: Path,
        rng: &Rng,
        ctx: &mut Ctx,
    ) -> Color {
        let Some(env) = &self.environment else {
            return Color::ZERO;
        };
        let (dir, pdf) = env.sample(rng.get2(SKY).0, rng.get2(SKY_DIRECTION));
        let f = bsdf.f_cos(dir);
        if f == Color::ZERO || pdf <= 0.0 {
            return Color::ZERO;
        }
        let ray = Ray::new(s.spawn.origin_towards(dir), dir).at_time(s.time);
        if self.shadows {
            ctx.stats.shadow_rays += 1;
            if self.scene.shadowed(&ray, 0.0, f64::INFINITY) {
                return Color::ZERO;
            }
        }
        f * self.sky_seen(&ray, path) * (power_heuristic(pdf, bsdf.pdf(dir)) / pdf)
    }

    /// What `ray` of `path` sees where it meets nothing: the environment through the fog.
    fn sky_seen(&self, ray: &Ray, path: Path) -> Color {
        let (add, keep) = self.fog_over(ray, fog::MISS_DISTANCE, path);
        add + keep * self.environment(ray.dir)
    }

    /// The environment's radiance along unit `dir`: the sky, or the background colour.
    fn environment(&self, dir: DVec3) -> Color {
        match self.sky {
            None => self.background,
            Some(s) => sky::color(self.scene, s, dir, self.background),
        }
    }

    /// The fog over the segment of `ray` up to `t`: the light it adds and the share of the
    /// light behind it that it keeps, per channel (fog fills the space outside objects only).
    fn fog_over(&self, ray: &Ray, t: f64, path: Path) -> (Color, Color) {
        match self.fog {
            Some(f) if path.media.is_outside() => {
                let add = fog::apply(self.scene, f, ray, t, Color::ZERO);
                (add, fog::apply(self.scene, f, ray, t, Color::ONE) - add)
            }
            _ => (Color::ZERO, Color::ONE),
        }
    }
}

/// Veach's power heuristic: the weight of a sample drawn with density `a` where another
/// strategy would have drawn it with density `b`.
fn power_heuristic(a: f64, b: f64) -> f64 {
    let (a2, b2) = (a * a, b * b);
    if a2 + b2 > 0.0 { a2 / (a2 + b2) } else { 0.0 }
}
