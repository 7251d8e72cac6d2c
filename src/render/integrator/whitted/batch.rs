//! The camera samples of a pixel traced side by side: each stage of the Whitted recursion (the
//! nearest hits and their surfaces, the shading with its shadow rays, the reflected rays) runs
//! over up to [`BATCH`] rays before the next stage starts.
//!
//! Why: every ray is a chain of dependent square roots and divisions (camera direction, root,
//! normal, error bound, light direction, re-aimed shadow ray, its root), so a ray traced alone
//! keeps the CPU waiting on one `sqrtsd`/`divsd` after another (scene A, issue 12). Rays of one
//! stage are independent, and the CPU overlaps their chains. Each ray gets exactly the
//! operations, in the same order, that [`Whitted::trace`] gives it, so its colour is the same
//! to the bit; only the order of the (integer) counters' increments changes.

use glam::DVec3;

use super::{Path, Whitted, reflect};
use crate::geometry::Ray;
use crate::geometry::sphere_cull::Bundle;
use crate::geometry::world::SphereHit;
use crate::ir::{Color, LightSampling, Material, ShadingModel};
use crate::render::record::NoRecord;
use crate::render::shading::{BATCH, Ctx, Surface, phong};

impl Whitted<'_> {
    /// Whether [`Whitted::trace_batch`] can trace this scene's camera samples: nothing draws
    /// random numbers per sample (no lens, area light, open shutter or glossy lobe), every
    /// sample takes every light cell, and shadows are not tinted by glass.
    pub fn batches(&self) -> bool {
        !self.scene.random()
            && !self.effects.glass_shadows
            && self.scene.settings().light_samples != LightSampling::Spread
    }

    /// Whether a hit on `mat` is shaded in the batch (Phong, no refracted ray); others take
    /// [`Whitted::trace`]'s own path from their hit on.
    fn batched(&self, mat: &Material) -> bool {
        mat.shading.unwrap_or(self.shading) == ShadingModel::Phong
            && !(self.effects.refraction && mat.refract > 0.0)
    }

    /// The colours of up to [`BATCH`] rays with their paths into `out`, each bit for bit what
    /// [`Whitted::trace`] gives it. Only for scenes where [`Whitted::batches`] holds.
    pub fn trace_batch(&self, rays: &[Ray], paths: &[Path], ctx: &mut Ctx, out: &mut [Color]) {
        let scene = self.scene;
        let world = scene.world();
        // The hits are read where `intersect` returned them: stored in an array they were
        // copied there (a `memcpy` per ray, 8% of scene A's profile).
        let mut live: [Option<Surface<'_>>; BATCH] = [None; BATCH];
        let mut facing = [DVec3::ZERO; BATCH];
        // The spheres the batch's rays can meet at all: a pixel's camera rays, the few in the
        // pixel; its reflected rays, those in the narrow fan a small patch of surface casts.
        let mut bundle = Bundle::new();
        for r in rays {
            bundle.push(r, f64::INFINITY);
        }
        let among = world.among(&bundle);
        // The spheres' `t`s first, then the hits: two short loops overlap more rays' chains.
        let mut first = [SphereHit::default(); BATCH];
        for (f, r) in first.iter_mut().zip(rays) {
            *f = world.nearest_sphere(r, 0.0, f64::INFINITY, among);
        }
        for i in 0..rays.len() {
            // By value, and lent out only as a copy: a hit whose address is taken lives in
            // memory, and reading it back in wider pieces than it was stored in stalled on
            // store forwarding.
            let Some(hit) = world.intersect_after(&rays[i], 0.0, f64::INFINITY, first[i]) else {
                out[i] = self.background;
                continue;
            };
            let mat = scene.material(hit.material);
            if !self.batched(mat) {
                let lent = hit;
                out[i] = self.shade_at(&rays[i], &lent, paths[i], ctx, &mut NoRecord);
                continue;
            }
            let (s, _, f) = self.surface(&rays[i], &hit, paths[i], mat);
            (live[i], facing[i]) = (Some(s), f);
        }
        let n = rays.len();
        phong::shade_batch(scene, &live[..n], ctx, &mut out[..n]);
        // The reflected rays of the batch, as `shade_at` casts them (no refraction here, and
        // no gloss: `batches` excludes it).
        let mut next = [Ray::new(DVec3::ZERO, DVec3::ZERO); BATCH];
        let mut next_paths = [Path::CAMERA; BATCH];
        let mut back = [(0usize, 0.0f64); BATCH];
        let mut m = 0;
        for i in 0..n {
            let (Some(s), path) = (&live[i], paths[i]) else {
                continue;
            };
            if path.depth >= self.max_depth {
                continue;
            }
            let kr = self.reflectance(s.mat);
            if kr > 0.0 && self.significant(path.bounce(path.media, kr), ctx) {
                let dir = reflect(rays[i].dir, facing[i]);
                ctx.stats.secondary_rays += 1;
                next[m] = Ray::new(s.spawn.origin_towards(dir), dir).at_time(rays[i].time);
                next_paths[m] = path.bounce(path.media, kr);
                back[m] = (i, kr);
                m += 1;
            }
        }
        if m == 0 {
            return;
        }
        let mut light = [Color::ZERO; BATCH];
        self.trace_batch(&next[..m], &next_paths[..m], ctx, &mut light[..m]);
        for (&(i, kr), l) in back[..m].iter().zip(&light) {
            out[i] += kr * *l;
        }
    }
}
