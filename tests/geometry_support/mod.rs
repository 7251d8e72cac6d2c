//! Shared helpers for the geometry tests: scenes of one object, a deterministic RNG, rays.
#![allow(dead_code)]

use glam::{DAffine3, DQuat, DVec3};
use rtc::assets::MeshAsset;
use rtc::geometry::mesh::{Mesh, MeshParts};
use rtc::geometry::{Ray, World};
use rtc::ir::{Camera, Material, Object, Projection, RenderSettings, Scene, Shape};
use rtc::num::Norm;
use rtc::source::Span;

/// SplitMix64: tiny, deterministic, good enough for test rays.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn f(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }

    /// Uniform on the unit sphere.
    pub fn dir(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            let l = v.length_squared();
            if l > 1e-6 && l <= 1.0 {
                return v / l.sqrt();
            }
        }
    }

    /// Uniform in a box.
    pub fn point_in(&mut self, lo: DVec3, hi: DVec3) -> DVec3 {
        DVec3::new(
            self.range(lo.x, hi.x),
            self.range(lo.y, hi.y),
            self.range(lo.z, hi.z),
        )
    }
}

pub fn object(shape: Shape, transform: DAffine3) -> Object {
    Object {
        motion: None,
        shape,
        transform: transform.into(),
        material: None,
        span: Span::default(),
        visibility: Default::default(),
    }
}

pub fn scene(objects: Vec<Object>) -> Scene {
    Scene {
        camera: Camera {
            eye: DVec3::new(0.0, 0.0, 10.0),
            center: DVec3::ZERO,
            up: DVec3::Y,
            width: 8,
            height: 8,
            projection: Projection::Perspective { fov_y: 0.7 },
            aperture: 0.0,
            focus_distance: 1.0,
            shutter: None,
            motion: None,
            span: Span::default(),
        },
        lights: Vec::new(),
        materials: vec![
            Material::default(),
            Material::default(),
            Material::default(),
        ],
        textures: Vec::new(),
        objects,
        settings: RenderSettings::default(),
        memory: Default::default(),
    }
}

/// The prepared world of a scene holding `objects`.
pub fn world(objects: Vec<Object>) -> World {
    let prepared = rtc::opt::prepare(&scene(objects)).expect("world builds");
    prepared.world().clone()
}

/// The mesh (with its BVH) the preparation stage builds from a loaded OBJ file.
pub fn mesh_of(asset: &MeshAsset) -> Mesh {
    Mesh::build(MeshParts {
        vertices: &asset.vertices,
        triangles: &asset.triangles,
        normals: &asset.normals,
        uvs: &asset.uvs,
        colors: &[],
        material_of: &asset.material_of,
    })
}

/// A skewed, mirrored (negative determinant) placement.
pub fn mirrored_transform() -> DAffine3 {
    DAffine3::from_scale_rotation_translation(
        DVec3::new(1.5, -0.7, 2.0),
        DQuat::from_euler(glam::EulerRot::XYZ, 0.3, -0.8, 1.1),
        DVec3::new(0.4, -1.2, 2.5),
    )
}

/// A ray from far outside the box through a random point inside it (unit direction).
pub fn ray_at_box(rng: &mut Rng, lo: DVec3, hi: DVec3) -> Ray {
    let c = 0.5 * (lo + hi);
    let r = (hi - lo).norm().max(1e-9);
    let target = rng.point_in(lo, hi);
    let origin = c + rng.dir() * (2.0 * r);
    Ray::new(origin, (target - origin).unit())
}

/// A direction in the hemisphere around `n`.
pub fn hemisphere(rng: &mut Rng, n: DVec3) -> DVec3 {
    let d = rng.dir();
    if d.dot(n) < 0.0 { -d } else { d }
}

/// The largest length of `xf`'s axes: how much it scales at most.
pub fn axis_scale(xf: &DAffine3) -> f64 {
    xf.matrix3
        .x_axis
        .norm()
        .max(xf.matrix3.y_axis.norm())
        .max(xf.matrix3.z_axis.norm())
}

/// What the random-ray invariants need to know of a shape placed by `xf` (object space is
/// the shape's own, before `xf`).
pub struct Probe<'a> {
    /// Names the case in messages.
    pub name: &'a str,
    /// Object to world.
    pub xf: DAffine3,
    /// The object's size in the world (tolerances and offsets scale with it).
    pub world_scale: f64,
    /// Object-space box the rays aim at.
    pub aim: (DVec3, DVec3),
    /// How many rays.
    pub rays: usize,
    /// Rays from outside must hit at least this share of the time (untransformed; 40 % of it
    /// under a transform, whose aim box is looser).
    pub min_hit_share: f64,
    /// Distance of an object-space point from the surface, found independently of rtc.
    pub dist: &'a dyn Fn(DVec3) -> f64,
    /// The largest `dist` a hit may have.
    pub tolerance: f64,
    /// Signed, object space: positive outside (or on the front side of a surface).
    pub side: &'a dyn Fn(DVec3) -> f64,
}

/// The invariants every shape keeps under random rays at `w` (which holds the probed shape):
/// no NaN, hits on the surface within the tolerance, unit normals facing out, hits within the
/// world's bounds, no re-hit of its own surface by a ray leaving it as the renderer spawns
/// rays, and enough hits.
pub fn random_ray_invariants(w: &World, p: &Probe, seed: u64) {
    let inv = p.xf.inverse();
    let aim = rtc::geometry::Aabb::new(p.aim.0, p.aim.1).transformed(&p.xf);
    let bounds = w.bounds();
    let mut rng = Rng(seed);
    let mut hits = 0;
    for i in 0..p.rays {
        let ray = ray_at_box(&mut rng, aim.min, aim.max);
        let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        let ctx = format!("{} ray {i}: {ray:?} hit t = {}", p.name, h.t);
        assert!(h.point.is_finite() && h.normal.is_finite(), "{ctx}: NaN");
        let q = inv.transform_point3(h.point);
        let d = (p.dist)(q);
        assert!(d < p.tolerance, "{ctx}: off the surface by {d:e} at {q}");
        assert!((h.normal.norm() - 1.0).abs() < 1e-12, "{ctx}: |n| ≠ 1");
        let eps = 1e-6 * p.world_scale;
        let out = (p.side)(inv.transform_point3(h.point + eps * h.normal));
        let inside = (p.side)(inv.transform_point3(h.point - eps * h.normal));
        // Where the surface is sharper than eps (a 0.05 box's edge) both sides can be out;
        // the outward side is never the inside one.
        assert!(
            out > 0.0 || inside > out,
            "{ctx}: the normal points inward ({out:e})"
        );
        if bounds.is_finite() {
            assert!(
                bounds.contains(h.point, 1e-9 * p.world_scale),
                "{ctx}: outside the bounds {bounds:?}"
            );
        }
        // A ray leaving the surface (~12° or more above its tangent plane) from the point
        // spawned as the renderer spawns it does not meet the surface again nearby.
        let dir = loop {
            let d = hemisphere(&mut rng, h.normal);
            if d.dot(h.normal) > 0.2 {
                break d;
            }
        };
        let again = Ray::new(h.point + 1e-7 * p.world_scale * h.normal, dir);
        if let Some(h2) = w.intersect(&again, 0.0, 1e-4 * p.world_scale) {
            panic!("{ctx}: re-hit its own surface at t = {:e}", h2.t);
        }
    }
    let share = hits as f64 / p.rays as f64;
    let want = p.min_hit_share * if p.xf == DAffine3::IDENTITY { 1.0 } else { 0.4 };
    assert!(share >= want, "{}: only {share} of rays hit", p.name);
}
