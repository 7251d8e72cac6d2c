//! Whitted ray tracing: local shading plus mirror reflection and refraction, recursing up to the
//! scene's `max_depth` bounces.
//!
//! Combination rule: `I = local + kr·trace(reflected) + kt·trace(refracted)` with `kr = reflect`
//! and `kt = refract` of the material (course files set `reflect = ks`, so ks is the mirror weight
//! there; COURSE.md §2.5). Under total internal reflection the refracted share `kt` goes to the
//! reflected ray, so weights ≤ 1 never create energy. Inside/outside comes from the sign of
//! `dot(normal, dir)` (normals are outward); media are tracked on a small stack so nested
//! transparent objects refract by the ratio of the indices on both sides of each interface.

mod batch;

use glam::DVec3;

use crate::geometry::{Ray, SurfaceHit};
use crate::ir::limits::MAX_GLOSS_SAMPLES;
use crate::ir::{Color, Fog, Material, ShadingModel, Sky};
use crate::opt::{Effects, Prepared};
use crate::render::context::Ctx;
use crate::render::film::CUT_WEIGHT_UNIT;
use crate::render::offset::SpawnPoint;
use crate::render::path::Path;
use crate::render::record::{Branch, NoRecord, Recorder};
use crate::render::sampler::Rng;
use crate::render::scatter::{self, Lobe, Scattering, reflect};
use crate::render::shading::{self, Surface};
use crate::render::{bump, fog, normal_map, sky, texture};

/// A secondary ray about to be cast: where from, its lobe and the lobe's ideal direction, and
/// the normal facing the ray it continues.
struct Outgoing<'l> {
    /// Origin (already offset off the surface, towards the ideal direction).
    from: DVec3,
    /// The lobe's ideal (mirror or refraction) direction (unit).
    axis: DVec3,
    /// The unit normal facing the incoming ray.
    facing: DVec3,
    /// The lobe the ray is drawn from.
    lobe: &'l Lobe,
    /// The time of the ray it continues (motion blur).
    time: f64,
}

/// The random-number stream of a glossy lobe at bounce `depth`; `refracted` tells the two lobes
/// of a surface apart. Disjoint from the lens (0) and light streams' high bits.
fn lobe_stream(depth: u32, refracted: bool) -> u32 {
    0x4000_0000 ^ (depth << 20) ^ u32::from(refracted)
}

/// The `k`-th direction of the lobe of `out` at bounce `depth`, for a camera sample's `rng`: one
/// scrambled Sobol' sequence per camera sample and decision ([`Rng::point`]), so the bytes are a
/// pure function of (pixel, sample, seed).
fn lobe_direction(rng: &Rng, out: &Outgoing<'_>, depth: u32, k: u32) -> DVec3 {
    let u = rng.point(lobe_stream(depth, out.lobe.transmits()), k);
    out.lobe.direction_about(out.axis, out.facing, u)
}

/// The shaded-image integrator: Whitted recursion over the prepared scene.
pub struct Whitted<'a> {
    scene: &'a Prepared,
    effects: Effects,
    shading: ShadingModel,
    max_depth: u32,
    background: Color,
    sky: Option<&'a Sky>,
    fog: Option<&'a Fog>,
    alpha: bool,
    cutoff: f64,
}

impl<'a> Whitted<'a> {
    /// The integrator for `scene`'s settings.
    pub fn new(scene: &'a Prepared) -> Whitted<'a> {
        let s = scene.settings();
        Whitted {
            scene,
            effects: scene.effects(),
            shading: s.shading,
            max_depth: s.max_depth,
            background: s.background,
            sky: s.sky.as_ref(),
            fog: s.fog.as_ref(),
            alpha: s.alpha,
            cutoff: s.cutoff,
        }
    }

    /// The colour seen along `ray` by a path in state `path`.
    pub fn trace(&self, ray: &Ray, path: Path, ctx: &mut Ctx) -> Color {
        self.trace_with(ray, path, ctx, &mut NoRecord)
    }

    /// [`Whitted::trace`], telling `rec` what the ray meets (`rtc why`).
    pub(crate) fn trace_with<R: Recorder>(
        &self,
        ray: &Ray,
        path: Path,
        ctx: &mut Ctx,
        rec: &mut R,
    ) -> Color {
        if R::ON {
            rec.ray(ray, &path);
        }
        let c = self.shade_hit(ray, path, ctx, rec);
        if R::ON {
            rec.done(c);
        }
        c
    }

    fn shade_hit<R: Recorder>(&self, ray: &Ray, path: Path, ctx: &mut Ctx, rec: &mut R) -> Color {
        let scene = self.scene;
        // Borrowed where the world wrote it: moving the 176-byte hit out of its `Option` was a
        // `memcpy` per camera ray (5% of scene A's time).
        let found = if self.effects.visibility_flags {
            scene.seen_hit(ray, 0.0, f64::INFINITY, path.ray_kind())
        } else {
            scene.world().intersect(ray, 0.0, f64::INFINITY)
        };
        let Some(hit) = &found else {
            return self.missed(ray, path);
        };
        let c = self.shade_at(ray, hit, path, ctx, rec);
        self.fogged(ray, hit.t, path, c)
    }

    /// What `ray` of `path` sees where it meets nothing: the background, or the sky, through
    /// the fog.
    fn missed(&self, ray: &Ray, path: Path) -> Color {
        if self.alpha && path.depth == 0 {
            // Transparent black: the film's colour is premultiplied by the alpha channel.
            return Color::ZERO;
        }
        let c = match self.sky {
            None => self.background,
            Some(s) => sky::color(self.scene, s, ray.dir, self.background),
        };
        self.fogged(ray, fog::MISS_DISTANCE, path, c)
    }

    /// `c`, seen at distance `t` along `ray`, as it arrives through the scene's fog (which fills
    /// the space outside objects only, as POV-Ray's fills what is not inside a solid).
    #[inline(always)]
    fn fogged(&self, ray: &Ray, t: f64, path: Path, c: Color) -> Color {
        match self.fog {
            Some(f) if path.media.is_outside() => fog::apply(self.scene, f, ray, t, c),
            _ => c,
        }
    }

    /// The colour of `ray`'s nearest hit `hit` (everything [`Whitted::trace_with`] does after
    /// the intersection).
    #[inline]
    fn shade_at<R: Recorder>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        path: Path,
        ctx: &mut Ctx,
        rec: &mut R,
    ) -> Color {
        let scene = self.scene;
        if R::ON {
            rec.hit(hit);
        }
        let stored = scene.material(hit.material);
        let mixed;
        let mat = match stored.mix {
            Some(_) if self.effects.textures => {
                mixed = super::super::mix::resolve(scene, hit, scene.world().frame(hit), stored);
                &mixed
            }
            _ => stored,
        };
        let (s, inside, facing) = self.surface(ray, hit, path, mat);
        let spawn = s.spawn;
        let mut c = match mat.shading.unwrap_or(self.shading) {
            ShadingModel::Phong => shading::phong::shade(scene, &s, ctx, rec),
            ShadingModel::Gooch(g) => shading::gooch::shade(scene, &s, &g, ctx, rec),
            ShadingModel::Hatching => shading::hatching::shade(scene, &s, ctx, rec),
        };
        if self.effects.emission {
            c += shading::finish::emitted(mat, s.color);
        }
        if R::ON {
            rec.local(c);
        }
        if path.depth >= self.max_depth {
            return self.absorbed(c, mat, hit, inside);
        }
        let scattering = Scattering::of(mat, &self.effects);
        let media = path.media;
        let (mut kr, kt) = if scattering.varies() {
            let (n1, after) = media.cross(scattering.eta, inside);
            scattering.shares(-ray.dir.dot(s.n), n1, after.current())
        } else {
            (scattering.reflect, scattering.refract)
        };
        if kt > 0.0 {
            let (n1, after) = media.cross(scattering.eta, inside);
            let lobe = scattering.refraction(n1, after.current());
            match lobe.axis(ray.dir, facing) {
                Some(axis) if self.significant(path.bounce(after, kt), ctx) => {
                    let out = Outgoing {
                        from: spawn.origin_towards(axis),
                        axis,
                        facing,
                        lobe: &lobe,
                        time: ray.time,
                    };
                    if R::ON {
                        rec.branch(
                            Branch::of(&lobe),
                            kt,
                            self.lobe_rays(&lobe, mat, path),
                            false,
                        );
                    }
                    let through = kt * self.bounce(&out, mat, path.bounce(after, kt), ctx, rec);
                    // The colour tints what is seen through the surface as it tints its
                    // shadow (one rule: `scatter::tint`).
                    c += match scatter::tint(mat, s.color) {
                        Some(t) => t * through,
                        None => through,
                    };
                }
                Some(_) => {
                    if R::ON {
                        rec.branch(Branch::Refracted, kt, 0, true);
                    }
                }
                None => {
                    if R::ON {
                        rec.total_internal_reflection();
                    }
                    kr += kt
                }
            }
        }
        if kr > 0.0 {
            if self.significant(path.reflect(media, kr), ctx) {
                let lobe = scattering.mirror(kr);
                let axis = reflect(ray.dir, facing);
                let out = Outgoing {
                    from: spawn.origin_towards(axis),
                    axis,
                    facing,
                    lobe: &lobe,
                    time: ray.time,
                };
                if R::ON {
                    rec.branch(
                        Branch::of(&lobe),
                        kr,
                        self.lobe_rays(&lobe, mat, path),
                        false,
                    );
                }
                c += kr * self.bounce(&out, mat, path.reflect(media, kr), ctx, rec);
            } else if R::ON {
                rec.branch(Branch::Reflected, kr, 0, true);
            }
        }
        self.absorbed(c, mat, hit, inside)
    }

    /// The colour `c` found at `hit` as it arrives back at the ray's origin: dimmed by the
    /// absorption of the object the ray travelled through when it hit the object from inside
    /// (Beer–Lambert over the hit distance).
    #[inline(always)]
    fn absorbed(&self, c: Color, mat: &Material, hit: &SurfaceHit, inside: bool) -> Color {
        if self.effects.absorption && inside && mat.absorption != Color::ZERO {
            c * scatter::beer_lambert(mat.absorption, hit.t)
        } else {
            c
        }
    }

    /// How much of the light `mat` reflects, when the scene reflects at all.
    #[inline(always)]
    fn reflectance(&self, mat: &Material) -> f64 {
        Scattering::of(mat, &self.effects).reflect
    }

    /// The surface point `hit` of `ray` to shade, whether the ray arrives from inside, and the
    /// unit normal facing the ray (before any bump map). Always inlined: returned from a call,
    /// the 208-byte surface was copied twice more (`memcpy`) on its way into a batch.
    #[inline(always)]
    pub(crate) fn surface<'m>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        path: Path,
        mat: &'m Material,
    ) -> (Surface<'m>, bool, DVec3) {
        let inside = hit.normal.dot(ray.dir) > 0.0;
        let facing = if inside { -hit.normal } else { hit.normal };
        let s = Surface {
            p: hit.point,
            spawn: SpawnPoint::of(hit),
            n: self.bumped(hit, facing, mat),
            v: -ray.dir,
            color: self.base_color(hit, mat),
            mat,
            uv: hit.uv,
            depth: path.depth,
            time: ray.time,
        };
        (s, inside, facing)
    }

    /// The light arriving along a secondary ray `out` for a path now in state `next`: one ray
    /// for a delta lobe, or the mean over a glossy lobe's directions, `gloss_samples` rays at a
    /// camera ray's hit and one after that (so rays per pixel grow linearly with depth, not
    /// exponentially). The lobe's constant weight is applied by the caller, outside the mean.
    fn bounce<R: Recorder>(
        &self,
        out: &Outgoing<'_>,
        mat: &Material,
        next: Path,
        ctx: &mut Ctx,
        rec: &mut R,
    ) -> Color {
        if out.lobe.is_delta() {
            ctx.stats.secondary_rays += 1;
            return self.trace_with(
                &Ray::new(out.from, out.axis).at_time(out.time),
                next,
                ctx,
                rec,
            );
        }
        let depth = next.depth - 1;
        let n = if depth == 0 {
            mat.gloss_samples.clamp(1, MAX_GLOSS_SAMPLES)
        } else {
            1
        };
        let mut sum = Color::ZERO;
        for k in 0..n {
            let d = lobe_direction(&ctx.rng, out, depth, k);
            ctx.stats.secondary_rays += 1;
            sum += self.trace_with(&Ray::new(out.from, d).at_time(out.time), next, ctx, rec);
        }
        sum / f64::from(n)
    }

    /// How many rays [`Whitted::bounce`] traces for `lobe` leaving a hit of `path` (for the
    /// recorder; `bounce` decides the same way).
    fn lobe_rays(&self, lobe: &Lobe, mat: &Material, path: Path) -> u32 {
        if lobe.is_delta() {
            1
        } else if path.depth == 0 {
            mat.gloss_samples.clamp(1, MAX_GLOSS_SAMPLES)
        } else {
            1
        }
    }

    /// Whether a secondary ray with this path is worth tracing: its weight is at least the
    /// cut-off (always with cut-off 0, since weights are positive). A ray cut is counted with
    /// its weight, which bounds the radiance it would have added for a scene lit at ≤ 1.
    fn significant(&self, next: Path, ctx: &mut Ctx) -> bool {
        if next.weight >= self.cutoff {
            return true;
        }
        ctx.stats.cut_rays += 1;
        ctx.stats.cut_weight += (next.weight * CUT_WEIGHT_UNIT) as u64;
        false
    }

    /// Material colour, or the texture's where the material has one; on a mesh showing its
    /// vertex colours, the interpolated vertex colour in place of the material colour (times
    /// the texture's, as glTF multiplies `COLOR_0` into its base colour). The texture is read
    /// from a copy of the hit: a hit whose address is taken lives in memory, and reloading it
    /// stalled the batch on store forwarding.
    #[inline(always)]
    pub(crate) fn base_color(&self, hit: &SurfaceHit, mat: &Material) -> Color {
        match (mat.texture, hit.vertex_color) {
            (Some(t), None) if self.effects.textures => self.textured(*hit, t),
            (_, None) => mat.color,
            (Some(t), Some(v)) if self.effects.textures => v.as_dvec3() * self.textured(*hit, t),
            (_, Some(v)) => v.as_dvec3(),
        }
    }

    /// The colour of texture `t` at `hit`.
    fn textured(&self, hit: SurfaceHit, t: crate::ir::TextureId) -> Color {
        let frame = self.scene.world().frame(&hit);
        match &self.scene.textures()[t.0 as usize] {
            crate::opt::TextureMap::Mipmap(chain, mapping) => {
                texture::mipmapped(self.scene, chain, *mapping, &hit, frame)
            }
            tex => texture::color(tex, &hit, frame),
        }
    }

    /// The shading normal: `facing`, tilted by the material's bump map where it has one (read
    /// from a copy of the hit, as in [`Whitted::base_color`]).
    #[inline(always)]
    pub(crate) fn bumped(&self, hit: &SurfaceHit, facing: DVec3, mat: &Material) -> DVec3 {
        match mat.bump {
            Some(b) if self.effects.bump => self.bump_tilt(*hit, facing, b),
            _ => facing,
        }
    }

    /// `facing` tilted by bump map `b` at `hit`.
    fn bump_tilt(&self, hit: SurfaceHit, facing: DVec3, b: crate::ir::Bump) -> DVec3 {
        let world = self.scene.world();
        let tex = &self.scene.textures()[b.texture.0 as usize];
        if let crate::opt::TextureMap::NormalMap(pic, mapping) = tex {
            let tangents = normal_map::measured_tangents(self.scene, &hit, *mapping)
                .unwrap_or_else(|| normal_map::fallback_tangents(facing));
            let frame = world.frame(&hit);
            return normal_map::tilt(pic, *mapping, b.scale, &hit, frame, facing, tangents);
        }
        bump::perturb(
            tex,
            b.scale,
            &hit,
            world.frame(&hit),
            world.normal_matrix(&hit),
            facing,
        )
    }
}
