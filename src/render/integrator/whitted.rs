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

use crate::num::Norm;
pub use batch::PacketScratch;

use glam::DVec3;

use super::gloss;
use crate::geometry::{Ray, SurfaceHit};
use crate::ir::limits::MAX_GLOSS_SAMPLES;
use crate::ir::{Color, Material, ShadingModel};
use crate::opt::{Effects, Prepared};
use crate::render::offset::SpawnPoint;
use crate::render::record::{Branch, NoRecord, Recorder};
use crate::render::shading::{self, Ctx, Surface};
use crate::render::{bump, texture};

/// The stack of media a ray is inside (indices of refraction, innermost last); the outside is 1.
#[derive(Clone, Copy, Debug)]
pub struct Media {
    etas: [f64; 8],
    len: usize,
}

impl PartialEq for Media {
    fn eq(&self, o: &Media) -> bool {
        self.etas[..self.len] == o.etas[..o.len]
    }
}

impl Default for Media {
    fn default() -> Media {
        Media::OUTSIDE
    }
}

impl Media {
    /// Not inside anything (index 1).
    pub const OUTSIDE: Media = Media {
        etas: [1.0; 8],
        len: 0,
    };

    /// The index of the innermost medium.
    pub fn current(&self) -> f64 {
        if self.len == 0 {
            1.0
        } else {
            self.etas[self.len - 1]
        }
    }

    /// After entering a medium of index `eta` (a full stack forgets its outermost entry).
    pub fn enter(mut self, eta: f64) -> Media {
        if self.len == self.etas.len() {
            self.etas.copy_within(1.., 0);
            self.len -= 1;
        }
        self.etas[self.len] = eta;
        self.len += 1;
        self
    }

    /// After leaving a medium of index `eta`: its innermost entry is removed (unchanged when the
    /// ray was not known to be inside it, e.g. a camera placed inside glass).
    pub fn leave(mut self, eta: f64) -> Media {
        if let Some(i) = self.etas[..self.len].iter().rposition(|e| *e == eta) {
            self.etas.copy_within(i + 1..self.len, i);
            self.len -= 1;
        }
        self
    }
}

/// Snell's law: the refracted direction of unit `d` at a surface with unit normal `n` facing the
/// incoming ray, going from index `n1` into `n2`; `None` on total internal reflection.
pub fn refract(d: DVec3, n: DVec3, n1: f64, n2: f64) -> Option<DVec3> {
    let r = n1 / n2;
    let cos_i = (-d.dot(n)).min(1.0);
    let k = 1.0 - r * r * (1.0 - cos_i * cos_i);
    if k < 0.0 {
        return None;
    }
    Some((r * d + (r * cos_i - k.sqrt()) * n).unit())
}

/// The mirror direction of unit `d` about unit `n`.
pub fn reflect(d: DVec3, n: DVec3) -> DVec3 {
    d - 2.0 * d.dot(n) * n
}

/// Where a path is: how often it has bounced, which media it is inside and how much it still
/// weighs in its pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Path {
    /// Bounces so far (0 for a camera ray).
    pub depth: u32,
    /// The media the ray travels in.
    pub media: Media,
    /// The product of the reflect/refract coefficients along the path (1 for a camera ray):
    /// what the insignificance cut-off compares.
    pub weight: f64,
}

impl Path {
    /// A camera ray's path: no bounce yet, outside everything, full weight.
    pub const CAMERA: Path = Path {
        depth: 0,
        media: Media::OUTSIDE,
        weight: 1.0,
    };

    fn bounce(self, media: Media, k: f64) -> Path {
        Path {
            depth: self.depth + 1,
            media,
            weight: self.weight * k,
        }
    }
}

/// A secondary ray about to be cast: where from, its ideal (mirror or refraction) direction, the
/// normal of the side it leaves through, and which of the two it is.
pub struct Outgoing {
    /// Origin (already offset off the surface).
    pub from: DVec3,
    /// The ideal direction (unit).
    pub dir: DVec3,
    /// Unit normal of the side the ray leaves through.
    pub side: DVec3,
    /// A refracted (not reflected) ray.
    pub refracted: bool,
    /// The time of the ray it continues (motion blur).
    pub time: f64,
}

/// Fixed-point units per unit of weight in [`crate::render::Stats::cut_weight`] (integers keep
/// the sum the same for any thread count).
pub const CUT_WEIGHT_UNIT: f64 = (1u64 << 32) as f64;

/// The shaded-image integrator: Whitted recursion over the prepared scene.
pub struct Whitted<'a> {
    scene: &'a Prepared,
    effects: Effects,
    shading: ShadingModel,
    max_depth: u32,
    background: Color,
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
            cutoff: s.cutoff,
        }
    }

    /// The colour seen along `ray` by a path in state `path`.
    pub fn trace(&self, ray: &Ray, path: Path, ctx: &mut Ctx) -> Color {
        self.trace_with(ray, path, ctx, &mut NoRecord)
    }

    /// [`Whitted::trace`], telling `rec` what the ray meets (`rtc why`).
    pub fn trace_with<R: Recorder>(
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
        let found = scene.world().intersect(ray, 0.0, f64::INFINITY);
        let Some(hit) = &found else {
            return self.background;
        };
        self.shade_at(ray, hit, path, ctx, rec)
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
        let mat = scene.material(hit.material);
        let (s, inside, facing) = self.surface(ray, hit, path, mat);
        let spawn = s.spawn;
        let mut c = match mat.shading.unwrap_or(self.shading) {
            ShadingModel::Phong => shading::phong::shade(scene, &s, ctx, rec),
            ShadingModel::Gooch(g) => shading::gooch::shade(scene, &s, &g, ctx, rec),
            ShadingModel::Hatching => shading::hatching::shade(scene, &s, ctx, rec),
        };
        if R::ON {
            rec.local(c);
        }
        if path.depth >= self.max_depth {
            return c;
        }
        let mut kr = self.reflectance(mat);
        let kt = if self.effects.refraction {
            mat.refract
        } else {
            0.0
        };
        let media = path.media;
        if kt > 0.0 {
            let (n1, after) = if inside {
                (mat.eta, media.leave(mat.eta))
            } else {
                (media.current(), media.enter(mat.eta))
            };
            match refract(ray.dir, facing, n1, after.current()) {
                Some(dir) if self.significant(path.bounce(after, kt), ctx) => {
                    let out = Outgoing {
                        from: spawn.origin_towards(dir),
                        dir,
                        side: -facing,
                        refracted: true,
                        time: ray.time,
                    };
                    if R::ON {
                        rec.branch(Branch::Refracted, kt, self.lobe_rays(mat, path), false);
                    }
                    c += kt * self.bounce(&out, mat, path.bounce(after, kt), ctx, rec);
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
            if self.significant(path.bounce(media, kr), ctx) {
                let dir = reflect(ray.dir, facing);
                let out = Outgoing {
                    from: spawn.origin_towards(dir),
                    dir,
                    side: facing,
                    refracted: false,
                    time: ray.time,
                };
                if R::ON {
                    rec.branch(Branch::Reflected, kr, self.lobe_rays(mat, path), false);
                }
                c += kr * self.bounce(&out, mat, path.bounce(media, kr), ctx, rec);
            } else if R::ON {
                rec.branch(Branch::Reflected, kr, 0, true);
            }
        }
        c
    }

    /// How much of the light `mat` reflects, when the scene reflects at all.
    #[inline(always)]
    fn reflectance(&self, mat: &Material) -> f64 {
        if self.effects.reflection {
            mat.reflect
        } else {
            0.0
        }
    }

    /// The surface point `hit` of `ray` to shade, whether the ray arrives from inside, and the
    /// unit normal facing the ray (before any bump map). Always inlined: returned from a call,
    /// the 208-byte surface was copied twice more (`memcpy`) on its way into a batch.
    #[inline(always)]
    fn surface<'m>(
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

    /// The light arriving along a secondary ray `out` for a path now in state `next`: one ray,
    /// or the mean of a glossy material's lobe around it ([`gloss`]), `gloss_samples` rays at a
    /// camera ray's hit and one after that (so rays per pixel grow linearly with depth, not
    /// exponentially).
    fn bounce<R: Recorder>(
        &self,
        out: &Outgoing,
        mat: &Material,
        next: Path,
        ctx: &mut Ctx,
        rec: &mut R,
    ) -> Color {
        if !self.effects.glossy || mat.gloss <= 0.0 {
            ctx.stats.secondary_rays += 1;
            return self.trace_with(
                &Ray::new(out.from, out.dir).at_time(out.time),
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
            let d = gloss::sample(&ctx.rng, out, mat.gloss, depth, k);
            ctx.stats.secondary_rays += 1;
            sum += self.trace_with(&Ray::new(out.from, d).at_time(out.time), next, ctx, rec);
        }
        sum / f64::from(n)
    }

    /// How many rays [`Whitted::bounce`] traces for a secondary ray leaving a hit of `path`
    /// (for the recorder; `bounce` decides the same way).
    fn lobe_rays(&self, mat: &Material, path: Path) -> u32 {
        if !self.effects.glossy || mat.gloss <= 0.0 {
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

    /// Material colour, or the texture's where the material has one. The texture is read
    /// from a copy of the hit: a hit whose address is taken lives in memory, and reloading it
    /// stalled the batch on store forwarding.
    #[inline(always)]
    pub(crate) fn base_color(&self, hit: &SurfaceHit, mat: &Material) -> Color {
        match mat.texture {
            Some(t) if self.effects.textures => self.textured(*hit, t),
            _ => mat.color,
        }
    }

    /// The colour of texture `t` at `hit`.
    fn textured(&self, hit: SurfaceHit, t: crate::ir::TextureId) -> Color {
        let frame = self.scene.world().frame(&hit);
        texture::color(&self.scene.textures()[t.0 as usize], &hit, frame)
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
        bump::perturb(
            &self.scene.textures()[b.texture.0 as usize],
            b.scale,
            &hit,
            self.scene.world().frame(&hit),
            facing,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn head_on_refraction_is_undeviated() {
        let d = DVec3::new(0.0, 0.0, -1.0);
        let t = refract(d, DVec3::Z, 1.0, 1.5).unwrap();
        assert!((t - d).norm() < 1e-15);
    }

    #[test]
    fn snell_holds_and_total_internal_reflection_past_the_critical_angle() {
        let n = DVec3::Y;
        for deg in [10.0f64, 30.0, 41.0, 42.0, 60.0, 89.0] {
            let a = deg.to_radians();
            let d = DVec3::new(a.sin(), -a.cos(), 0.0);
            // Into glass: always refracts, sin θt = sin θi / 1.5.
            let t = refract(d, n, 1.0, 1.5).unwrap();
            assert!((t.x - a.sin() / 1.5).abs() < 1e-12);
            // Out of glass: the critical angle is asin(1/1.5) ≈ 41.81°.
            let out = refract(d, n, 1.5, 1.0);
            assert_eq!(out.is_none(), deg > 41.82, "{deg}");
            if let Some(t) = out {
                assert!((t.x - a.sin() * 1.5).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn media_stack_tracks_nesting() {
        let m = Media::OUTSIDE.enter(1.5).enter(1.33);
        assert_eq!(m.current(), 1.33);
        assert_eq!(m.leave(1.33).current(), 1.5);
        assert_eq!(m.leave(1.5).current(), 1.33);
        assert_eq!(m.leave(1.5).leave(1.33), Media::OUTSIDE);
        assert_eq!(Media::OUTSIDE.leave(2.0), Media::OUTSIDE);
        let mut deep = Media::OUTSIDE;
        for i in 0..20 {
            deep = deep.enter(f64::from(i));
        }
        assert_eq!(deep.current(), 19.0);
    }
}
