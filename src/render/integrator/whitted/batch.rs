//! The camera samples of a pixel traced as a packet ([`crate::geometry::lanes`]): each stage
//! of the Whitted recursion (the nearest hits and their surfaces, the shading with its shadow
//! rays, the reflected rays) runs over up to [`BATCH`] rays at once before the next starts.
//! A reflected ray stays in the lane of the ray it continues, so nothing is shuffled between
//! bounces.
//!
//! Why: every ray is a chain of dependent square roots and divisions (camera direction, root,
//! normal, error bound, light direction, re-aimed shadow ray, its root), and scalar `DVec3`
//! code spends most of its instructions moving single numbers. Rays of one stage are
//! independent: in lanes the compiler pairs their arithmetic and the CPU overlaps their
//! chains (scene A, issue 12). Each ray gets exactly the operations, in the same order, that
//! [`Whitted::trace`] gives it, so its colour is the same to the bit; only the order of the
//! (integer) counters' increments changes.

use glam::DVec3;

use super::Whitted;
use crate::geometry::Ray;
use crate::geometry::lanes::RayLanes;
use crate::geometry::lanes::cull::Bundle;
use crate::geometry::lanes::sphere_packet::{NO_SPHERE, PacketHits};
use crate::geometry::rounding::gamma;
use crate::geometry::world::SphereHit;
use crate::ir::{Color, LightSampling, Material, ShadingModel};
use crate::lanes::{self, Lanes, Mask, V3};
use crate::render::context::{BATCH, Ctx};
use crate::render::offset::SpawnLanes;
use crate::render::path::{Media, Path};
use crate::render::record::NoRecord;
use crate::render::scatter::{Scattering, reflect_lanes};
use crate::render::shading::Surface;
use crate::render::shading::phong_packet::{self, SurfaceLanes};

/// Where the rays of a packet are: they have bounced equally often in the same media (camera
/// rays, then the mirror rays of those), and each weighs its own share of its pixel.
#[derive(Clone, Copy)]
struct PacketPath {
    depth: u32,
    media: Media,
    weight: Lanes,
}

impl PacketPath {
    /// Camera rays.
    const CAMERA: PacketPath = PacketPath {
        depth: 0,
        media: Media::OUTSIDE,
        weight: [1.0; BATCH],
    };

    /// The path of lane `i` alone.
    fn lane(&self, i: usize) -> Path {
        Path {
            depth: self.depth,
            media: self.media,
            weight: self.weight[i],
            // Every bounce of a packet is a mirror reflection.
            reflected: self.depth > 0,
        }
    }
}

/// A packet's surfaces being shaded, with what its reflected rays need. Reused from packet to
/// packet through the tile's [`crate::render::context::Scratch`], one per recursion depth in
/// use: built afresh it was a 3.8 kB `memset` (Rust initialises it), and moved out of a call a
/// `memcpy`.
struct Shading {
    /// The points, as Phong reads them.
    s: SurfaceLanes,
    /// The normals facing the incoming rays before any bump map (mirrors reflect about them).
    facing: V3,
    /// The mirror weights.
    kr: Lanes,
}

impl Default for Shading {
    fn default() -> Shading {
        Shading {
            s: SurfaceLanes::default(),
            facing: V3::ZERO,
            kr: [0.0; BATCH],
        }
    }
}

impl Whitted<'_> {
    /// Whether [`Whitted::trace_batch`] can trace this scene's camera samples: nothing draws
    /// random numbers per sample (no lens, area light, open shutter or glossy lobe), every
    /// sample takes every light cell, shadows are not tinted by glass, every light is a
    /// point light, and no object is hidden from some rays. A scene with a sky or fog traces
    /// one ray at a time: the packet's misses and hits know neither, and one test here keeps
    /// them out of every packet.
    pub fn batches(&self) -> bool {
        self.sky.is_none()
            && self.fog.is_none()
            && !self.alpha
            && !self.scene.random()
            && !self.effects.glass_shadows
            && self.scene.settings().light_samples != LightSampling::Spread
            && phong_packet::applies(self.scene)
            && !self.effects.visibility_flags
    }

    /// Whether a hit on `mat` is shaded in the packet (Phong, no refracted ray, not mixed, no finish
    /// term beyond Phong's: [`Material::plain_finish`]); others take
    /// [`Whitted::trace`]'s own path from their hit on.
    fn batched(&self, mat: &Material) -> bool {
        mat.mix.is_none()
            && mat.shading.unwrap_or(self.shading) == ShadingModel::Phong
            && !Scattering::of(mat, &self.effects).transmits()
            && mat.plain_finish()
    }

    /// Whether a surface of `mat` needs its whole hit record (a texture or a bump map to
    /// read), which the packet's own sphere hits do not carry.
    fn needs_hit(&self, mat: &Material) -> bool {
        (self.effects.textures && mat.texture.is_some())
            || (self.effects.bump && mat.bump.is_some())
    }

    /// The colours of up to [`BATCH`] camera rays into `out`, each bit for bit what
    /// [`Whitted::trace`] gives it. Only for scenes where [`Whitted::batches`] holds.
    pub fn trace_batch(&self, rays: &[Ray], ctx: &mut Ctx, out: &mut [Color]) {
        let n = rays.len().min(BATCH);
        let time = lanes::map(|i| if i < n { rays[i].time } else { 0.0 });
        self.trace_camera_packet(&RayLanes::of(&rays[..n]), &time, n, ctx, out);
    }

    /// [`Whitted::trace_batch`] of the first `n` rays of a packet of camera rays at shutter
    /// time 0 (a pinhole camera's).
    pub(crate) fn trace_lanes(
        &self,
        packet: &RayLanes,
        n: usize,
        ctx: &mut Ctx,
        out: &mut [Color],
    ) {
        self.trace_camera_packet(packet, &[0.0; BATCH], n, ctx, out);
    }

    /// The colours of the first `n` camera rays of a packet, at shutter times `time`, into
    /// `out`.
    #[inline(always)]
    fn trace_camera_packet(
        &self,
        packet: &RayLanes,
        time: &Lanes,
        n: usize,
        ctx: &mut Ctx,
        out: &mut [Color],
    ) {
        let n = n.min(BATCH);
        let c = self.trace_packet(packet, time, lanes::first(n), &PacketPath::CAMERA, ctx);
        for (i, o) in out.iter_mut().enumerate().take(n) {
            *o = c.get(i);
        }
    }

    /// The colours of the rays of `live` (other lanes hold anything).
    fn trace_packet(
        &self,
        rays: &RayLanes,
        time: &Lanes,
        live: Mask,
        path: &PacketPath,
        ctx: &mut Ctx,
    ) -> V3 {
        let world = self.scene.world();
        // Camera rays that meet nothing are background and go no further (mirror rays start
        // inside the world's box: the test would keep them all). A world of balls finds its
        // misses as cheaply by itself (the capsule cull below): there the test only cost (4%
        // more instructions on scene A, whose floor ball fills the view).
        let live = if path.depth == 0 && !world.balls_only() {
            world.may_meet(rays, live)
        } else {
            live
        };
        if live == 0 {
            return V3::splat(self.background);
        }
        // The spheres the packet's rays can meet at all: a pixel's camera rays, the few in the
        // pixel; its reflected rays, those in the narrow fan a small patch of surface casts.
        let first = if world.has_loose_spheres() {
            let bundle = Bundle::of_packet(rays, &[f64::INFINITY; BATCH], live);
            let among = world.among(&bundle);
            world.nearest_packet(rays, live, 0.0, f64::INFINITY, among)
        } else {
            PacketHits::none(f64::INFINITY)
        };
        // The surfaces go into a reused buffer (see [`Shading`]).
        let mut sh: Box<Shading> = ctx.scratch.take();
        let mut out = V3::splat(self.background);
        if world.balls_only() {
            let hit = live & lanes::mask_of(|i| first.sphere[i] != NO_SPHERE);
            if hit == 0 {
                ctx.scratch.give(sh);
                return out;
            }
            self.ball_surfaces(rays, time, &first, hit, &mut sh);
            self.ball_exceptions(rays, time, &first, path, ctx, &mut sh, &mut out);
        } else {
            self.surfaces(rays, time, &first, live, path, ctx, &mut sh, &mut out);
        }
        let out = self.finish(rays, time, path, &sh, out, ctx);
        ctx.scratch.give(sh);
        out
    }

    /// The colours of a packet from its surfaces on: `out` (the lanes already done) with the
    /// shaded lanes' Phong colours and their mirror rays' light.
    #[inline(always)]
    fn finish(
        &self,
        rays: &RayLanes,
        time: &Lanes,
        path: &PacketPath,
        sh: &Shading,
        out: V3,
        ctx: &mut Ctx,
    ) -> V3 {
        if sh.s.live == 0 {
            // Nothing to shade and no mirror to follow.
            return out;
        }
        let c = phong_packet::shade(self.scene, &sh.s, ctx);
        let mut out = V3::select(sh.s.live, &c, &out);
        self.reflect_packet(rays, time, path, sh, ctx, &mut out);
        out
    }

    /// The surfaces of the hits `hit` of a packet in a world of loose spheres only, built in
    /// lanes from the spheres' `t`s: `plain_sphere_hit_at`, `World::surface_hit` and
    /// [`Whitted::surface`] lane by lane (lanes whose material needs more are redone by
    /// [`Whitted::ball_exceptions`]).
    #[inline(always)]
    fn ball_surfaces(
        &self,
        rays: &RayLanes,
        time: &Lanes,
        first: &PacketHits,
        hit: Mask,
        sh: &mut Shading,
    ) {
        let scene = self.scene;
        let world = scene.world();
        let ball = |i: usize| {
            // Lanes without a hit read any ball: their values are never used.
            let k = if hit & (1 << i) != 0 {
                first.sphere[i]
            } else {
                0
            };
            world.loose_ball(k)
        };
        let center = V3::map(|i| ball(i).center);
        let radius = lanes::map(|i| ball(i).radius);
        let mats: [&Material; BATCH] = std::array::from_fn(|i| scene.material(ball(i).material));
        // plain_sphere_hit_at: the point, its normal and its error bound.
        let point = rays.at(&first.t);
        let w = point.sub(&center);
        let len = w.norm();
        let normal = w.scale(&lanes::map(|i| 1.0 / len[i]));
        let e = lanes::map(|i| (len[i] - radius[i]).abs() + gamma(6) * (len[i] + radius[i]));
        // Whitted::surface: the normal facing the ray, the viewer, the material.
        let cos = normal.dot(&rays.dir);
        let facing = V3::select(lanes::gt(&cos, 0.0), &normal.neg(), &normal);
        let s = &mut sh.s;
        s.live = hit;
        s.p = point;
        s.spawn = SpawnLanes {
            point,
            error: V3 { x: e, y: e, z: e },
            normal,
        };
        s.n = facing;
        s.v = rays.dir.neg();
        s.color = V3::map(|i| mats[i].color);
        s.ka = lanes::map(|i| mats[i].ka);
        s.kd = lanes::map(|i| mats[i].kd);
        s.ks = lanes::map(|i| mats[i].ks);
        s.shininess = lanes::map(|i| mats[i].n);
        s.time = *time;
        sh.facing = facing;
        sh.kr = lanes::map(|i| self.reflectance(mats[i]));
    }

    /// The lanes of [`Whitted::ball_surfaces`] whose material needs more than the packet's
    /// sphere hits carry (textures, bump maps, another shading model): redone by the one-ray
    /// path, into the packet or straight into `out`.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn ball_exceptions(
        &self,
        rays: &RayLanes,
        time: &Lanes,
        first: &PacketHits,
        path: &PacketPath,
        ctx: &mut Ctx,
        sh: &mut Shading,
        out: &mut V3,
    ) {
        let world = self.scene.world();
        for i in lanes::each(sh.s.live) {
            let mat = self
                .scene
                .material(world.loose_ball(first.sphere[i]).material);
            if !self.batched(mat) || self.needs_hit(mat) {
                sh.s.live &= !(1 << i);
                let one = SphereHit::of_lane(first, i);
                let ray = lane_ray(rays, time, i);
                let hit = world.intersect_after(&ray, 0.0, f64::INFINITY, one);
                if let Some((s, f, kr)) =
                    self.surface_or_color(&ray, hit, path.lane(i), ctx, i, out)
                {
                    sh.s.set(i, &s);
                    sh.facing.set(i, f);
                    sh.kr[i] = kr;
                }
            }
        }
    }

    /// The surfaces of a packet's hits in any world, ray by ray from each ray's nearest loose
    /// sphere on ([`Whitted::surface_or_color`]); lanes shaded one by one go into `out`.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn surfaces(
        &self,
        rays: &RayLanes,
        time: &Lanes,
        first: &PacketHits,
        live: Mask,
        path: &PacketPath,
        ctx: &mut Ctx,
        sh: &mut Shading,
        out: &mut V3,
    ) {
        sh.s.live = 0;
        // The live rays side by side for the world's packet query (a mesh's BVH tested once
        // per node for all of them), each hit what `intersect_after` finds for it alone.
        let mut lane = [0usize; BATCH];
        let mut one = [Ray::new(DVec3::ZERO, DVec3::ZERO); BATCH];
        let mut firsts = [SphereHit::default(); BATCH];
        let mut m = 0;
        for i in lanes::each(live) {
            (lane[m], one[m], firsts[m]) =
                (i, lane_ray(rays, time, i), SphereHit::of_lane(first, i));
            m += 1;
        }
        let mut hits = [None; BATCH];
        let world = self.scene.world();
        world.intersect_batch_after(&one[..m], 0.0, f64::INFINITY, &firsts[..m], &mut hits[..m]);
        for j in 0..m {
            let i = lane[j];
            if let Some((s, f, kr)) =
                self.surface_or_color(&one[j], hits[j], path.lane(i), ctx, i, out)
            {
                sh.s.set(i, &s);
                sh.facing.set(i, f);
                sh.kr[i] = kr;
            }
        }
    }

    /// The one-ray path of lane `i` from its nearest hit `hit` on: its surface (with the
    /// normal facing the ray and the mirror weight) when the packet shades it, else `None`
    /// and its colour straight into `out`.
    #[inline(always)]
    fn surface_or_color(
        &self,
        ray: &Ray,
        hit: Option<crate::geometry::SurfaceHit>,
        path: Path,
        ctx: &mut Ctx,
        i: usize,
        out: &mut V3,
    ) -> Option<(Surface<'_>, DVec3, f64)> {
        let scene = self.scene;
        // By value, and lent out only as a copy: a hit whose address is taken lives in
        // memory, and reading it back in wider pieces than it was stored in stalled on store
        // forwarding.
        let Some(hit) = hit else {
            out.set(i, self.background);
            return None;
        };
        let mat = scene.material(hit.material);
        if !self.batched(mat) {
            let lent = hit;
            out.set(i, self.shade_at(ray, &lent, path, ctx, &mut NoRecord));
            return None;
        }
        let (s, _, f) = self.surface(ray, &hit, path, mat);
        Some((s, f, self.reflectance(mat)))
    }

    /// The mirror rays of a shaded packet, as `shade_at` casts them (no refraction here, and
    /// no gloss: `batches` excludes it), traced as a packet of their own in the same lanes and
    /// added to `out`.
    #[inline(always)]
    fn reflect_packet(
        &self,
        rays: &RayLanes,
        time: &Lanes,
        path: &PacketPath,
        sh: &Shading,
        ctx: &mut Ctx,
        out: &mut V3,
    ) {
        if path.depth >= self.max_depth {
            return;
        }
        let mut bounce: Mask = 0;
        for i in lanes::each(sh.s.live) {
            if sh.kr[i] > 0.0 && self.significant(path.lane(i).reflect(path.media, sh.kr[i]), ctx) {
                bounce |= 1 << i;
            }
        }
        if bounce == 0 {
            return;
        }
        ctx.stats.secondary_rays += u64::from(bounce.count_ones());
        // The mirror lobe's ideal direction, leaving from the spawn point along it.
        let dir = reflect_lanes(&rays.dir, &sh.facing);
        let next = RayLanes {
            origin: sh.s.spawn.origin_towards(&dir),
            dir,
        };
        let next_path = PacketPath {
            depth: path.depth + 1,
            media: path.media,
            weight: lanes::map(|i| path.weight[i] * sh.kr[i]),
        };
        let light = self.trace_packet(&next, time, bounce, &next_path, ctx);
        for i in lanes::each(bounce) {
            out.set(i, out.get(i) + sh.kr[i] * light.get(i));
        }
    }
}

/// Lane `i` of a packet as a ray.
#[inline(always)]
fn lane_ray(rays: &RayLanes, time: &Lanes, i: usize) -> Ray {
    Ray::new(rays.origin.get(i), rays.dir.get(i)).at_time(time[i])
}
