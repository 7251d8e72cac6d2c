//! The world the renderer queries: every object prepared for intersection in world space,
//! bounded ones under one top-level BVH, unbounded ones (planes) tested beside it.

pub(crate) mod balls;
mod packet;
pub(crate) mod primitive;
mod reach;

use std::time::Duration;

use glam::{DMat3, DVec2, DVec3};
use obvhs::BvhBuildParams;

use crate::geometry::bvh::{Bvh, BvhRay, to_f32_box};
use crate::geometry::lanes::cull::{Among, Bundle};
use crate::geometry::lanes::spheres::SphereLanes;
use crate::geometry::world::balls::{BALL, Ball, WorldParts};
use crate::geometry::world::primitive::{GeoHit, Geom, Primitive, SurfaceId};
use crate::geometry::{aabb::Aabb, ray::MappingFrame, ray::Ray};
use crate::ir::MaterialId;

mod batch;

/// A world-space hit with everything shading needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit {
    /// Ray parameter (world space; the ray direction is unit so this is a distance).
    pub t: f64,
    /// World-space hit point.
    pub point: DVec3,
    /// Unit outward normal in world space (not flipped towards the ray); on smooth meshes the
    /// interpolated shading normal.
    pub normal: DVec3,
    /// Unit outward geometric normal (the true surface's; use it for ray offsets).
    pub geometric_normal: DVec3,
    /// Surface coordinates.
    pub uv: DVec2,
    /// Hit point in the leaf object's own space (for solid textures).
    pub(crate) local_point: DVec3,
    /// The hit point as the object computed it and moved it out to world space (equal to
    /// `point` up to rounding); `error` bounds its distance from the surface per axis. Spawned
    /// rays leave from here (`render::offset`).
    pub surface_point: DVec3,
    /// Per-axis floating-point error bound of `surface_point` (see [`crate::geometry::rounding`]).
    pub error: DVec3,
    /// The material to shade with (an index into the prepared scene's material table, which
    /// holds a mesh's MTL materials after the scene's).
    pub material: MaterialId,
    /// The surface hit: [`World::object`] and [`World::frame`] tell its object and mapping
    /// frame (kept out of the hit so it stays small: hits are copied on every candidate).
    pub surface: SurfaceId,
    /// A mesh's vertex colours interpolated at the hit, when the object shows them: the
    /// surface colour in place of the material's.
    pub(crate) vertex_color: Option<glam::Vec3>,
}

/// The nearest loose sphere along a ray (its lane position and `t`), from
/// [`World::nearest_sphere`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SphereHit(Option<(usize, f64)>);

/// What the world knows about one surface.
#[derive(Clone, Copy, Debug, PartialEq)]
struct SurfaceInfo {
    /// The top-level object it belongs to (an index into the scene's objects).
    object: u32,
    /// The frame texture mappings read its hits in.
    frame: MappingFrame,
    /// Carries a gradient of its object space (where `local_point` lies) to world space: the
    /// inverse transpose of the linear part of its placement, composed down a CSG tree (at
    /// shutter open for a moving one).
    normal_matrix: DMat3,
}

/// What building the world took (for `rtc render --stats`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct WorldStats {
    /// Top-level objects.
    pub(crate) objects: usize,
    /// Objects outside the BVH (unbounded).
    pub(crate) unbounded: usize,
    /// Time spent building the top-level BVH.
    pub(crate) bvh_build_time: Duration,
    /// Approximate heap bytes of the objects and the top-level BVH (meshes not included).
    pub(crate) memory_bytes: usize,
}

/// All objects of a scene, ready for ray queries.
#[derive(Clone, Debug)]
pub struct World {
    /// Whether hits need surface coordinates (textures, bumps, hatching); see [`World::need_uv`].
    need_uv: bool,
    /// Every object but the plain spheres. Object ids index it, or `balls` when tagged [`BALL`].
    nodes: Vec<Primitive>,
    /// The unmoving spheres, untransformed or translated (compact: most objects of a large
    /// scene).
    balls: Vec<Ball>,
    /// Every leaf and mesh node by its [`SurfaceId`].
    surfaces: Vec<SurfaceInfo>,
    /// Top level over the bounded nodes (`None` when a linear scan is as fast).
    bvh: Option<Bvh>,
    /// Objects tested beside the BVH (all of them when there is no BVH), except `spheres`.
    loose: Vec<u32>,
    /// The balls among the loose objects, tested first with a t-only quadratic, several at
    /// once; only the winner computes its full hit (the course scenes are all spheres).
    spheres: SphereLanes,
    /// The object id ([`BALL`] tagged) of each of `spheres`.
    sphere_ids: Vec<u32>,
    /// The padded box of everything, `None` when something is unbounded (`World::may_meet`).
    reach: Option<Aabb>,
    stats: WorldStats,
}

// Below this many bounded objects a linear scan beats the BVH's traversal set-up (measured on
// the five-spheres scene: the CwBvh path cost ~25% of the render).
const MIN_BVH_OBJECTS: usize = 12;

/// Above this many bounded objects the top-level BVH is built for speed rather than quality,
/// over Morton runs of [`LARGE_LEAF`] objects (`Bvh::build_clustered`, as for large meshes):
/// for a million spheres the medium build's reinsertion passes alone took longer than
/// evaluating the scene, and a render of such a scene is dominated by its time to first ray.
const LARGE_WORLD: usize = 300_000;

/// Most objects in a leaf of a large world's BVH.
const LARGE_LEAF: u32 = 4;

/// Rays a frame is expected to trace per object below which the BVH is built for speed too:
/// the medium build's reinsertion passes repay themselves only over many rays. Measured on
/// 100k spheres at 640×480 (a grid, one light, shadows: ~6 rays an object), the fast build
/// took 15% less CPU for the whole render, and still 6% less at 16 samples a pixel (~100 rays
/// an object); on 20k scattered spheres of mixed sizes with reflections (~120 rays an
/// object) the medium build was 6% faster, and on 100k of them (~24) the two tied.
const QUALITY_RAYS_PER_OBJECT: u64 = 32;

impl World {
    /// The world of the prepared top-level objects, for a frame expected to trace about
    /// `expected_rays` rays (which decides how much effort its BVH's build is worth).
    pub(crate) fn new(parts: WorldParts, expected_rays: u64) -> World {
        let WorldParts {
            mut nodes,
            object_of,
            balls,
        } = parts;
        let mut surfaces = Vec::new();
        for (n, &object) in nodes.iter_mut().zip(&object_of) {
            number_surfaces(n, object, DMat3::IDENTITY, &mut surfaces);
        }
        let mut stats = WorldStats {
            objects: nodes.len() + balls.len(),
            ..WorldStats::default()
        };
        let mut boxes = Vec::new();
        let mut ids = Vec::new();
        let mut loose = Vec::new();
        // Nodes and balls merged back into scene-object order, so the BVH is built over the
        // same boxes in the same order whichever storage holds a sphere.
        let (mut a, mut b) = (0, 0);
        while a < nodes.len() || b < balls.len() {
            let node_first =
                b == balls.len() || (a < nodes.len() && object_of[a] < balls[b].object());
            let (id, bounds) = if node_first {
                a += 1;
                ((a - 1) as u32, nodes[a - 1].bounds)
            } else {
                b += 1;
                (BALL | (b - 1) as u32, balls[b - 1].bounds())
            };
            match to_f32_box(&bounds).filter(|_| bounds.is_finite()) {
                Some(bx) => {
                    boxes.push(bx);
                    ids.push(id);
                }
                None if bounds.is_empty() => {}
                None => loose.push(id),
            }
        }
        stats.unbounded = loose.len();
        let object = |id: u32| match id & BALL {
            0 => object_of[id as usize],
            _ => balls[(id & !BALL) as usize].object(),
        };
        let bvh = if boxes.len() >= MIN_BVH_OBJECTS {
            // Large worlds, and worlds few rays will visit: a build for speed, and leaves of up
            // to LARGE_LEAF objects (the wide nodes over single objects took ~70 bytes per
            // object, more than the objects).
            let few_rays = expected_rays < QUALITY_RAYS_PER_OBJECT * boxes.len() as u64;
            // Without very_fast_build's one reinsertion pass: measured on 100k spheres at
            // 640×480 (~6 rays an object), 2.5% less wall for the whole render, on a million
            // 2-4% less CPU, on 100k scattered spheres (~24) no difference.
            let speed = BvhBuildParams {
                reinsertion_batch_ratio: 0.0,
                ..BvhBuildParams::very_fast_build()
            };
            let bvh = if boxes.len() > LARGE_WORLD {
                // Leaves of LARGE_LEAF neighbours along a Morton curve, fixed before the build:
                // it then works on a quarter of the boxes (a million spheres: peak memory
                // 284 -> 213 MiB, BVH 0.19 -> 0.07 s, same image; `bvh_cluster.rs`).
                Bvh::build_clustered(boxes.len(), |i| boxes[i], &ids, LARGE_LEAF as usize, speed)
            } else {
                let (build, group) = match few_rays {
                    false => (BvhBuildParams::medium_build(), 1),
                    true => (speed, LARGE_LEAF),
                };
                let params = BvhBuildParams {
                    max_prims_per_leaf: 1,
                    ..build
                };
                Bvh::build_grouped(&boxes, ids, params, group)
            };
            stats.bvh_build_time += bvh.build_time;
            stats.memory_bytes += bvh.memory();
            Some(bvh)
        } else {
            loose.extend(ids);
            loose.sort_unstable_by_key(|&id| object(id));
            None
        };
        drop(boxes);
        stats.memory_bytes += nodes.len() * std::mem::size_of::<Primitive>()
            + balls.len() * std::mem::size_of::<Ball>()
            + surfaces.len() * std::mem::size_of::<SurfaceInfo>();
        // Translated balls test rays in their object space, one by one: not in the lanes.
        let (spheres, loose): (Vec<u32>, Vec<u32>) = loose
            .into_iter()
            .partition(|&id| id & BALL != 0 && !balls[(id & !BALL) as usize].is_translated());
        let sphere_ids = spheres;
        let spheres = SphereLanes::new(sphere_ids.iter().map(|&id| {
            let b = &balls[(id & !BALL) as usize];
            (b.center, b.radius)
        }));
        let mut world = World {
            need_uv: true,
            spheres,
            sphere_ids,
            nodes,
            balls,
            surfaces,
            bvh,
            loose,
            reach: None,
            stats,
        };
        // Something outside the BVH's f32 boxes (a plane) means every ray may meet something.
        if world.stats.unbounded == 0 {
            world.reach = Some(reach::padded(world.bounds()));
        }
        world
    }

    /// Nearest hit of object `id` (a node, or a ball when tagged [`BALL`]) in (t_min, t_max).
    #[inline]
    fn hit(&self, id: u32, ray: &Ray, t_min: f64, t_max: f64) -> Option<GeoHit> {
        match id & BALL {
            0 => self.nodes[id as usize].intersect(ray, t_min, t_max),
            _ => self.balls[(id & !BALL) as usize].intersect(id & !BALL, ray, t_min, t_max),
        }
    }

    /// Whether object `id` lies in (t_min, t_max) along the ray.
    #[inline]
    fn blocks(&self, id: u32, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match id & BALL {
            0 => self.nodes[id as usize].occluded(ray, t_min, t_max),
            _ => self.balls[(id & !BALL) as usize].occluded(ray, t_min, t_max),
        }
    }

    /// Build counters.
    pub(crate) fn stats(&self) -> WorldStats {
        self.stats
    }

    /// Tells the world whether hits must carry uv; renderers that use no textures, bump maps or
    /// hatching switch it off, which saves an `acos` and an `atan2` per sphere hit.
    pub(crate) fn need_uv(&mut self, needed: bool) {
        self.need_uv = needed;
    }

    /// Bounds of everything finite.
    pub fn bounds(&self) -> Aabb {
        let nodes = self
            .nodes
            .iter()
            .filter(|n| n.bounds.is_finite())
            .fold(Aabb::EMPTY, |b, n| b.union(n.bounds));
        self.balls
            .iter()
            .map(Ball::bounds)
            .filter(Aabb::is_finite)
            .fold(nodes, Aabb::union)
    }

    /// The nearest hit in (t_min, t_max). Inlined: a caller reading the 176-byte hit back
    /// from memory right after this function stored it field by field stalled on store
    /// forwarding (~10% of the Whitted recursion's time on scene A).
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<SurfaceHit> {
        let sphere = if self.spheres.is_empty() {
            None
        } else {
            self.spheres.nearest(ray, t_min, t_max)
        };
        self.intersect_past(ray, t_min, t_max, sphere)
    }

    /// The loose spheres a bundle of ray segments may meet at all, for
    /// [`World::nearest_sphere`] and [`World::occluded_among`] (`geometry::lanes::cull`).
    pub fn among(&self, bundle: &Bundle) -> Among {
        if self.spheres.is_empty() {
            return Among::ALL;
        }
        self.spheres.among(bundle)
    }

    /// The first half of [`World::intersect`] for a ray of the bundle `among` was made of, in a
    /// sub-interval of its segment: the nearest loose sphere's `t` only, without testing the
    /// loose spheres the bundle cannot meet ([`Among::ALL`]: all of them, in lanes), so a batch
    /// of rays can find theirs before any of them builds its hit (their chains of square roots
    /// and divisions overlap).
    #[inline(always)]
    pub fn nearest_sphere(&self, ray: &Ray, t_min: f64, t_max: f64, among: Among) -> SphereHit {
        SphereHit(if among == Among::ALL {
            self.spheres.nearest(ray, t_min, t_max)
        } else {
            self.spheres.nearest_among(ray, t_min, t_max, among)
        })
    }

    /// The second half, after [`World::nearest_sphere`]: everything else, and the same hit as
    /// [`World::intersect`]. Always
    /// inlined: returned through memory, the 176-byte hit was reloaded in wider pieces than it
    /// was stored in, which stalled on store forwarding (~5% of scene A's time).
    #[inline(always)]
    pub fn intersect_after(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        first: SphereHit,
    ) -> Option<SurfaceHit> {
        self.intersect_past(ray, t_min, t_max, first.0)
    }

    /// The rest of [`World::intersect`] once the nearest loose sphere `sphere` (its lane
    /// position and `t`) is known.
    #[inline(always)]
    fn intersect_past(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        sphere: Option<(usize, f64)>,
    ) -> Option<SurfaceHit> {
        let mut best: Option<(GeoHit, u32)> = None;
        let mut far = t_max;
        let mut best_sphere = None;
        if let Some((k, t)) = sphere {
            far = t;
            best_sphere = Some((self.sphere_ids[k], t));
        }
        for &i in &self.loose {
            if let Some(h) = self.hit(i, ray, t_min, far) {
                far = h.t;
                best = Some((h, i));
            }
        }
        self.nearest_in_bvh(ray, t_min, far, &mut best);
        self.nearest_hit(ray, best, best_sphere)
    }

    /// The nearest hit on the objects under the top-level BVH nearer than `far` (and than
    /// `best`, which it replaces).
    #[inline(always)]
    fn nearest_in_bvh(
        &self,
        ray: &Ray,
        t_min: f64,
        mut far: f64,
        best: &mut Option<(GeoHit, u32)>,
    ) {
        if let Some(bvh) = &self.bvh {
            match BvhRay::new(ray.origin, ray.dir, t_min, far) {
                Some(r) => bvh.closest(&r, |slot, _| {
                    let i = bvh.order[slot];
                    match self.hit(i, ray, t_min, far) {
                        Some(h) => {
                            far = h.t;
                            *best = Some((h, i));
                            (h.t as f32).next_up()
                        }
                        None => f32::INFINITY,
                    }
                }),
                None => {
                    for &i in &bvh.order {
                        if let Some(h) = self.hit(i, ray, t_min, far) {
                            far = h.t;
                            *best = Some((h, i));
                        }
                    }
                }
            }
        }
    }

    /// The world-space hit of the nearest object hit `best`, or else of the nearest
    /// fast-path sphere `best_sphere` (its id and `t`).
    #[inline(always)]
    fn nearest_hit(
        &self,
        ray: &Ray,
        best: Option<(GeoHit, u32)>,
        best_sphere: Option<(u32, f64)>,
    ) -> Option<SurfaceHit> {
        match best {
            Some((h, i)) => Some(self.surface_hit(ray, h, i)),
            // The nearest hit is a fast-path sphere: now compute its normal and the rest at the
            // t found above (the lanes compute `sphere::hit_t` bit for bit). Built straight
            // into the result: moved through `best` it was a 152-byte `memcpy` per hit.
            // (Not a closure: LLVM kept it out of line, and the hit went through memory.)
            None => match best_sphere {
                Some((i, t)) => {
                    let h = self.balls[(i & !BALL) as usize].hit_at(i & !BALL, ray, t);
                    Some(self.surface_hit(ray, h, i))
                }
                None => None,
            },
        }
    }

    /// The world-space hit of `ray` from object `i`'s hit `h`, with uv when needed.
    #[inline(always)]
    fn surface_hit(&self, ray: &Ray, h: GeoHit, i: u32) -> SurfaceHit {
        // The uv from a copy: `h` itself never has its address taken, so it can stay in
        // registers (stored and reloaded, it stalled on store forwarding).
        let uv = if self.need_uv { self.uv(h, i) } else { h.uv };
        SurfaceHit {
            t: h.t,
            point: ray.at(h.t),
            normal: h.normal,
            geometric_normal: h.geometric_normal,
            uv,
            local_point: h.local_point,
            surface_point: h.point,
            error: h.error,
            material: h.material,
            surface: h.surface,
            vertex_color: h.vertex_color,
        }
    }

    /// The uv of object `i`'s hit `h`, which `intersect` leaves out for speed.
    fn uv(&self, mut h: GeoHit, i: u32) -> DVec2 {
        match i & BALL {
            0 => self.nodes[i as usize].finish(&mut h),
            _ => self.balls[(i & !BALL) as usize].finish(&mut h),
        }
        h.uv
    }

    /// True when anything lies in (t_min, t_max) along the ray (shadow rays: any hit ends it).
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.spheres.any(ray, t_min, t_max) || self.occluded_past(ray, t_min, t_max)
    }

    /// [`World::occluded`] of a ray of the bundle `among` was made of, in a sub-interval of its
    /// segment, without testing the loose spheres the bundle cannot meet.
    pub fn occluded_among(&self, ray: &Ray, t_min: f64, t_max: f64, among: Among) -> bool {
        self.spheres.any_among(ray, t_min, t_max, among) || self.occluded_past(ray, t_min, t_max)
    }

    /// Whether anything but the loose spheres lies in (t_min, t_max) along the ray.
    #[inline(always)]
    fn occluded_past(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        if self
            .loose
            .iter()
            .any(|&i| self.blocks(i, ray, t_min, t_max))
        {
            return true;
        }
        self.occluded_in_bvh(ray, t_min, t_max)
    }

    /// Whether anything under the top-level BVH lies in (t_min, t_max) along the ray.
    #[inline(always)]
    fn occluded_in_bvh(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let Some(bvh) = &self.bvh else {
            return false;
        };
        match BvhRay::new(ray.origin, ray.dir, t_min, t_max) {
            Some(r) => bvh.any(&r, |slot| self.blocks(bvh.order[slot], ray, t_min, t_max)),
            None => bvh.order.iter().any(|&i| self.blocks(i, ray, t_min, t_max)),
        }
    }

    /// The top-level object (an index into the scene's objects) a hit belongs to.
    pub fn object(&self, hit: &SurfaceHit) -> u32 {
        if let Some(b) = self.ball(hit) {
            return b.object();
        }
        self.surfaces
            .get(hit.surface.0 as usize)
            .map_or(0, |s| s.object)
    }

    /// The frame texture mappings read a hit's `local_point` in: its leaf shape's (a sphere's
    /// own centre, even inside CSG), else the object-space origin.
    pub(crate) fn frame(&self, hit: &SurfaceHit) -> MappingFrame {
        if let Some(b) = self.ball(hit) {
            return b.frame();
        }
        self.surfaces
            .get(hit.surface.0 as usize)
            .map_or(MappingFrame::Object, |s| s.frame)
    }

    /// The matrix that carries a gradient at `hit` from its object space (where `local_point`
    /// lies) to world space (for a ball, the identity or its translation's).
    pub(crate) fn normal_matrix(&self, hit: &SurfaceHit) -> DMat3 {
        if let Some(b) = self.ball(hit) {
            return b.normal_matrix();
        }
        self.surfaces
            .get(hit.surface.0 as usize)
            .map_or(DMat3::IDENTITY, |s| s.normal_matrix)
    }

    /// The ball a hit is on, if it is on one.
    fn ball(&self, hit: &SurfaceHit) -> Option<&Ball> {
        let id = hit.surface.0;
        (id & BALL != 0)
            .then(|| self.balls.get((id & !BALL) as usize))
            .flatten()
    }
}

/// Numbers the leaf and mesh nodes of `n` (a node of top-level object `object`) from
/// `surfaces.len()` on, recording each one's object and mapping frame.
fn number_surfaces(n: &mut Primitive, object: u32, parent: DMat3, surfaces: &mut Vec<SurfaceInfo>) {
    let normal_matrix = parent * n.normal_matrix();
    let frame = match &mut n.geom {
        Geom::Leaf(l) => l.frame(),
        Geom::Mesh(_) => MappingFrame::Object,
        Geom::Csg { children, .. } => {
            for c in children {
                number_surfaces(c, object, normal_matrix, surfaces);
            }
            return;
        }
    };
    n.surface = SurfaceId(surfaces.len() as u32);
    surfaces.push(SurfaceInfo {
        object,
        frame,
        normal_matrix,
    });
}

/// Triangles a prepared object places, counting every instance.
pub(crate) fn instanced_triangles(n: &Primitive) -> usize {
    match &n.geom {
        Geom::Mesh(m) => m.data.triangle_count(),
        Geom::Csg { children, .. } => children.iter().map(instanced_triangles).sum(),
        _ => 0,
    }
}
