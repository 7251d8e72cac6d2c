//! A prepared object: its geometry in object space, its transform, its material, its bounds.
//! Nodes nest for CSG; every level moves rays in and hits out through its own transform.

use crate::num::Norm;
use std::borrow::Cow;
use std::sync::Arc;

use glam::{DAffine3, DMat3, DVec2, DVec3, Vec3};

use crate::geometry::bvh::packet::PACKET;
use crate::geometry::shapes::Leaf;
use crate::geometry::{
    aabb::Aabb, mesh::Mesh, ray::Hit, ray::Ray, rounding, shapes::csg, shapes::sphere,
};
use crate::ir::{CsgOp, MaterialId, Motion};

mod csg_nodes;

use csg_nodes::{csg_crossings, csg_intersect};

/// A hit with everything shading needs, in the space of the ray that was given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct GeoHit {
    /// Ray parameter.
    pub(crate) t: f64,
    /// Unit shading normal (interpolated on smooth meshes), outward.
    pub(crate) normal: DVec3,
    /// Unit geometric normal, outward.
    pub(crate) geometric_normal: DVec3,
    /// Surface coordinates.
    pub(crate) uv: DVec2,
    /// The hit point in the leaf object's own space.
    pub(crate) local_point: DVec3,
    /// The hit point in the space of the ray that was given, moved out from `local_point`
    /// through every transform on the way (so `error` bounds it).
    pub(crate) point: DVec3,
    /// Per-axis bound on how far `point` may lie from the true surface (see
    /// [`crate::geometry::rounding`]).
    pub(crate) error: DVec3,
    /// The surface hit (see [`SurfaceId`]).
    pub(crate) surface: SurfaceId,
    /// The material to shade with.
    pub(crate) material: MaterialId,
    /// A mesh's vertex colours interpolated at the hit, when the object shows them.
    pub(crate) vertex_color: Option<Vec3>,
}

/// A boundary crossing of a solid node (for CSG).
#[derive(Clone, Copy, Debug, PartialEq)]
struct PrimitiveCrossing {
    /// The hit.
    hit: GeoHit,
    /// Outside → inside.
    entering: bool,
}

/// A mesh placed by an object.
#[derive(Clone, Debug)]
pub(crate) struct MeshRef {
    /// The shared data (instanced by path and smoothing).
    pub(crate) data: Arc<Mesh>,
    /// Material id of each of the file's MTL materials, when the object uses them.
    pub(crate) mtl: Option<Vec<MaterialId>>,
    /// Whether hits carry the mesh's vertex colours (the object uses the file's own
    /// appearance, `use_mtl`, and the mesh has them).
    pub(crate) colors: bool,
}

/// Geometry of one node, in object space.
#[derive(Clone, Debug)]
pub(crate) enum Geom {
    /// A single shape (see [`Leaf`]).
    Leaf(Leaf),
    /// A triangle mesh.
    Mesh(MeshRef),
    /// A CSG node.
    Csg {
        /// The operation.
        op: CsgOp,
        /// Operands.
        children: Vec<Primitive>,
    },
}

/// Object-to-parent placement.
#[derive(Clone, Debug)]
pub(crate) struct Placement {
    /// Parent → object.
    to_object: DAffine3,
    /// Object → parent.
    to_parent: DAffine3,
    /// Normal matrix (inverse transpose of the linear part of `to_parent`).
    pub(super) normal_matrix: DMat3,
}

impl Placement {
    /// The placement by `transform` (which must be invertible).
    pub(super) fn of(transform: DAffine3) -> Placement {
        Placement {
            to_object: transform.inverse(),
            to_parent: transform,
            normal_matrix: transform.matrix3.inverse().transpose(),
        }
    }

    /// The offset of a placement that only translates (its matrix part has the identity's
    /// bits): [`Placement::of`] that translation rebuilds this placement bit for bit.
    pub(super) fn translation(&self) -> Option<DVec3> {
        let bits = |m: DMat3| m.to_cols_array().map(f64::to_bits);
        (bits(self.to_parent.matrix3) == bits(DMat3::IDENTITY))
            .then_some(self.to_parent.translation)
    }
}

/// A node that moves while the shutter is open: its placement at shutter open and its motion.
#[derive(Clone, Debug)]
pub(crate) struct Moving {
    /// Object → parent at shutter open.
    transform: DAffine3,
    /// How that placement changes up to shutter close.
    motion: Motion,
}

/// A prepared object.
#[derive(Clone, Debug)]
pub(crate) struct Primitive {
    /// Geometry in object space.
    pub(crate) geom: Geom,
    /// `None` for the identity (boxed: most objects of a large scene are untransformed, and
    /// the placement's three matrices would triple an untransformed sphere's size).
    pub(crate) placement: Option<Box<Placement>>,
    /// Material of this node (inherited by CSG children that name none).
    pub(crate) material: MaterialId,
    /// Bounds in the parent's space (infinite for unbounded geometry).
    pub(crate) bounds: Aabb,
    /// The surface a leaf or mesh node is, once the world has numbered them.
    pub(crate) surface: SurfaceId,
    /// `None` for a node that stands still; `placement` is then its placement at every time.
    pub(crate) moving: Option<Box<Moving>>,
}

/// A surface of the world: one leaf shape or mesh, wherever it sits (a top-level object or an
/// operand deep inside CSG). Hits carry it; the world tells its object and mapping frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SurfaceId(pub u32);

impl Primitive {
    /// The inverse transpose of its placement's linear part (at shutter open when it moves).
    pub(crate) fn normal_matrix(&self) -> DMat3 {
        self.placement
            .as_ref()
            .map_or(DMat3::IDENTITY, |p| p.normal_matrix)
    }

    /// Wraps geometry with a transform (which must be invertible) and a material.
    pub(crate) fn new(geom: Geom, transform: DAffine3, material: MaterialId) -> Primitive {
        let local = geom.bounds();
        let placement =
            (transform != DAffine3::IDENTITY).then(|| Box::new(Placement::of(transform)));
        let bounds = match &placement {
            None => local,
            Some(p) => local.transformed(&p.to_parent),
        };
        Primitive {
            geom,
            placement,
            material,
            bounds,
            surface: SurfaceId::default(),
            moving: None,
        }
    }

    /// Like [`Primitive::new`] for a node placed by `transform` at shutter open that moves by
    /// `motion` until shutter close; its bounds cover the whole motion.
    pub(crate) fn moving(
        geom: Geom,
        transform: DAffine3,
        motion: Motion,
        material: MaterialId,
    ) -> Primitive {
        let mut p = Primitive::new(geom, transform, material);
        if motion.is_still() {
            return p;
        }
        p.bounds = crate::geometry::motion::swept_bounds(p.geom.bounds(), transform, &motion);
        p.moving = Some(Box::new(Moving { transform, motion }));
        p
    }

    /// The placement at the ray's time: the fixed one, or a moving node's at that instant.
    #[inline]
    fn placement_at(&self, ray: &Ray) -> Option<Cow<'_, Placement>> {
        match &self.moving {
            None => self.placement.as_deref().map(Cow::Borrowed),
            Some(m) => Some(Cow::Owned(Placement::of(
                m.motion.at(m.transform, ray.time),
            ))),
        }
    }

    /// The ray in object space (same `t` and time).
    #[inline]
    fn local(place: Option<&Placement>, ray: &Ray) -> Ray {
        match place {
            None => *ray,
            Some(p) => Ray {
                origin: p.to_object.transform_point3(ray.origin),
                dir: p.to_object.transform_vector3(ray.dir),
                time: ray.time,
            },
        }
    }

    /// The ray in object space (same `t` and time), and `t_min` raised past the rounding of
    /// moving its origin there (pbrt-v4 moves the origin to the edge of that error along the
    /// ray): a ray spawned just outside a surface must not meet it again because the transform
    /// moved its origin by more than the spawn offset.
    #[inline]
    pub(super) fn local_after(place: Option<&Placement>, ray: &Ray, t_min: f64) -> (Ray, f64) {
        match place {
            None => (*ray, t_min),
            Some(p) => {
                let (origin, err) =
                    rounding::transform_point(&p.to_object, ray.origin, DVec3::ZERO);
                let dir = p.to_object.transform_vector3(ray.dir);
                let lift = dir.abs().dot(err) / dir.length_squared();
                let local = Ray {
                    origin,
                    dir,
                    time: ray.time,
                };
                (local, t_min + lift)
            }
        }
    }

    /// Moves a hit from object space to the parent's space.
    #[inline]
    pub(super) fn out(place: Option<&Placement>, mut h: GeoHit) -> GeoHit {
        if let Some(p) = place {
            (h.point, h.error) = rounding::transform_point(&p.to_parent, h.point, h.error);
            h.normal = (p.normal_matrix * h.normal).unit_or(h.normal);
            h.geometric_normal = (p.normal_matrix * h.geometric_normal).unit_or(h.geometric_normal);
        }
        h
    }

    fn leaf(&self, l: &Leaf, ray: &Ray, h: Hit) -> GeoHit {
        let local_point = ray.at(h.t);
        GeoHit {
            t: h.t,
            normal: h.normal,
            geometric_normal: h.normal,
            uv: h.uv,
            local_point,
            point: local_point,
            error: l.point_error(local_point),
            surface: self.surface,
            material: self.material,
            vertex_color: None,
        }
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<GeoHit> {
        // Spheres: the quadratic is cheaper than a slab test, and uv waits for `finish`.
        if let Geom::Leaf(Leaf::Sphere { center, radius }) = &self.geom {
            let place = self.placement_at(ray);
            let place = place.as_deref();
            let (r, t_min) = Self::local_after(place, ray, t_min);
            return plain_sphere_hit(
                *center,
                *radius,
                &r,
                t_min,
                t_max,
                self.surface,
                self.material,
            )
            .map(|h| Self::out(place, h));
        }
        // Meshes clip against their bounds themselves (and need the entry point anyway).
        if self.bounds.is_empty()
            || (!matches!(self.geom, Geom::Mesh(_))
                && self.bounds.is_finite()
                && self.bounds.hit_interval(ray, t_min, t_max).is_none())
        {
            return None;
        }
        let place = self.placement_at(ray);
        let place = place.as_deref();
        let (r, t_min) = Self::local_after(place, ray, t_min);
        match &self.geom {
            Geom::Leaf(l) => l
                .intersect(&r, t_min, t_max)
                .map(|h| Self::out(place, self.leaf(l, &r, h))),
            Geom::Mesh(m) => m
                .data
                .intersect(&r, t_min, t_max)
                .map(|h| Self::out(place, self.mesh_hit(&r, m, h))),
            Geom::Csg { op, children } => {
                csg_intersect(*op, children, &r, t_min, t_max).map(|h| Self::out(place, h))
            }
        }
    }

    /// Completes what `intersect` leaves out for speed (a sphere's uv) on the hit that wins.
    pub(crate) fn finish(&self, h: &mut GeoHit) {
        if let Geom::Leaf(l @ Leaf::Sphere { .. }) = &self.geom {
            h.uv = l.frame().spherical_uv(h.local_point);
        }
    }

    /// True when anything of this node lies in (t_min, t_max).
    pub(crate) fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match &self.geom {
            Geom::Leaf(Leaf::Sphere { center, radius }) => {
                let place = self.placement_at(ray);
                let (r, t_min) = Self::local_after(place.as_deref(), ray, t_min);
                sphere::hit_t(*center, *radius, &r, t_min, t_max).is_some()
            }
            Geom::Mesh(m) => {
                if self.bounds.hit_interval(ray, t_min, t_max).is_none() {
                    return false;
                }
                let place = self.placement_at(ray);
                let (r, t_min) = Self::local_after(place.as_deref(), ray, t_min);
                m.data.occluded(&r, t_min, t_max)
            }
            _ => self.intersect(ray, t_min, t_max).is_some(),
        }
    }

    /// Whether [`Primitive::intersect_packet`] and [`Primitive::occluded_packet`] trace rays
    /// together here (a mesh fixed in place) rather than one by one.
    pub(crate) fn packets(&self) -> bool {
        matches!(self.geom, Geom::Mesh(_)) && self.moving.is_none()
    }

    /// [`Primitive::intersect`] of up to [`PACKET`] rays with their own `t_max`: `hit(i, h)`
    /// for each ray `i` that has a hit, `h` bit for bit `intersect(&rays[i], t_min, t_max[i])`.
    /// A mesh traces them as a packet.
    pub(crate) fn intersect_packet(
        &self,
        rays: &[Ray],
        t_min: f64,
        t_max: &[f64],
        mut hit: impl FnMut(usize, GeoHit),
    ) {
        let n = rays.len();
        let (Geom::Mesh(m), true) = (&self.geom, self.packets()) else {
            for i in 0..n {
                if let Some(h) = self.intersect(&rays[i], t_min, t_max[i]) {
                    hit(i, h);
                }
            }
            return;
        };
        if self.bounds.is_empty() {
            return;
        }
        let place = self.placement.as_deref();
        let mut local = [Ray::new(DVec3::ZERO, DVec3::ZERO); PACKET];
        let mut lo = [0.0; PACKET];
        for i in 0..n {
            (local[i], lo[i]) = Self::local_after(place, &rays[i], t_min);
        }
        m.data
            .intersect_packet(&local[..n], &lo[..n], &t_max[..n], |i, h| {
                hit(i, Self::out(place, self.mesh_hit(&local[i], m, h)))
            });
    }

    /// [`Primitive::occluded`] of the rays of `active` (bits) with their own `t_max`: the
    /// rays it holds for. A mesh traces them as a packet.
    pub(crate) fn occluded_packet(
        &self,
        rays: &[Ray],
        t_min: f64,
        t_max: &[f64],
        active: u32,
    ) -> u32 {
        let n = rays.len();
        let each = |i: usize| active >> i & 1 == 1;
        let (Geom::Mesh(m), true) = (&self.geom, self.packets()) else {
            return (0..n)
                .filter(|&i| each(i) && self.occluded(&rays[i], t_min, t_max[i]))
                .fold(0, |m, i| m | 1 << i);
        };
        let place = self.placement.as_deref();
        let mut local = [Ray::new(DVec3::ZERO, DVec3::ZERO); PACKET];
        let mut lo = [0.0; PACKET];
        let mut inside = 0u32;
        for i in (0..n).filter(|&i| each(i)) {
            if self
                .bounds
                .hit_interval(&rays[i], t_min, t_max[i])
                .is_some()
            {
                (local[i], lo[i]) = Self::local_after(place, &rays[i], t_min);
                inside |= 1 << i;
            }
        }
        m.data
            .occluded_packet(&local[..n], &lo[..n], &t_max[..n], inside)
    }

    fn mesh_hit(&self, r: &Ray, m: &MeshRef, h: crate::geometry::mesh::MeshHit) -> GeoHit {
        let material = match (&m.mtl, h.material) {
            (Some(ids), Some(i)) => ids.get(i as usize).copied().unwrap_or(self.material),
            _ => self.material,
        };
        let local_point = r.at(h.t);
        GeoHit {
            t: h.t,
            normal: h.shading,
            geometric_normal: h.geometric,
            uv: h.uv,
            local_point,
            point: local_point,
            error: h.error,
            surface: self.surface,
            material,
            vertex_color: if m.colors { h.color } else { None },
        }
    }

    /// Whether the ray's line starts (at t → −∞) inside this solid.
    fn inside_at_start(&self, ray: &Ray) -> bool {
        let place = self.placement_at(ray);
        let r = Self::local(place.as_deref(), ray);
        match &self.geom {
            Geom::Leaf(l) => l.inside_at_start(&r),
            Geom::Csg { op, children } => {
                csg::combine(*op, children.iter().map(|c| c.inside_at_start(&r)))
            }
            Geom::Mesh(_) => false,
        }
    }

    /// Every boundary crossing along the whole line of `ray`, sorted by `t` (solids only).
    fn crossings(&self, ray: &Ray, out: &mut Vec<PrimitiveCrossing>) {
        if self.bounds.is_empty()
            || (self.bounds.is_finite()
                && self
                    .bounds
                    .hit_interval(ray, f64::NEG_INFINITY, f64::INFINITY)
                    .is_none())
        {
            return;
        }
        let place = self.placement_at(ray);
        let place = place.as_deref();
        let r = Self::local(place, ray);
        let start = out.len();
        match &self.geom {
            Geom::Leaf(l) => {
                let mut tmp = Vec::new();
                l.crossings(&r, &mut tmp);
                for c in tmp {
                    out.push(PrimitiveCrossing {
                        hit: Self::out(place, self.leaf(l, &r, c.hit)),
                        entering: c.entering,
                    });
                }
            }
            Geom::Mesh(m) => {
                let mut hits = Vec::new();
                m.data.all_hits(&r, &mut hits);
                for (h, entering) in hits {
                    out.push(PrimitiveCrossing {
                        hit: Self::out(place, self.mesh_hit(&r, m, h)),
                        entering,
                    });
                }
            }
            Geom::Csg { op, children } => {
                let mut tmp = Vec::new();
                csg_crossings(*op, children, &r, &mut tmp);
                out.extend(tmp.into_iter().map(|c| PrimitiveCrossing {
                    hit: Self::out(place, c.hit),
                    entering: c.entering,
                }));
            }
        }
        out[start..].sort_by(|a, b| a.hit.t.total_cmp(&b.hit.t));
    }
}

/// The nearest hit in (t_min, t_max) of the sphere (`center`, `radius`) in the ray's space,
/// without uv (added by `finish` on the hit that wins): the one sphere hit of primitives and of
/// the world's compact spheres.
#[inline]
pub(crate) fn plain_sphere_hit(
    center: DVec3,
    radius: f64,
    r: &Ray,
    t_min: f64,
    t_max: f64,
    surface: SurfaceId,
    material: MaterialId,
) -> Option<GeoHit> {
    sphere::hit_t(center, radius, r, t_min, t_max)
        .map(|t| plain_sphere_hit_at(center, radius, r, t, surface, material))
}

/// [`plain_sphere_hit`] at a `t` already found by the same test (`sphere::hit_t` or its lanes).
#[inline]
pub(crate) fn plain_sphere_hit_at(
    center: DVec3,
    radius: f64,
    r: &Ray,
    t: f64,
    surface: SurfaceId,
    material: MaterialId,
) -> GeoHit {
    let local_point = r.at(t);
    let normal = (local_point - center).unit();
    GeoHit {
        t,
        normal,
        geometric_normal: normal,
        uv: DVec2::ZERO,
        local_point,
        point: local_point,
        error: sphere::point_error(center, radius, local_point),
        surface,
        material,
        vertex_color: None,
    }
}

impl Geom {
    /// Object-space bounds (infinite for planes; CSG per its operation).
    fn bounds(&self) -> Aabb {
        match self {
            Geom::Leaf(l) => l.bounds(),
            Geom::Mesh(m) => m.data.bounds(),
            Geom::Csg { op, children } => {
                let b: Vec<Aabb> = children.iter().map(|c| c.bounds).collect();
                csg::bounds(*op, &b)
            }
        }
    }
}
