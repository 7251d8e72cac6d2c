//! The world the renderer queries: every object prepared for intersection in world space.

use glam::{DAffine3, DMat3, DVec2, DVec3};

use super::{Aabb, Hit, Ray, plane, sphere};
use crate::diag::Diagnostic;
use crate::ir::{MaterialId, Object, Scene, Shape};

/// A world-space hit with everything shading needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit {
    /// Ray parameter (world space; the ray direction is unit so this is a distance).
    pub t: f64,
    /// World-space hit point.
    pub point: DVec3,
    /// Unit outward normal in world space (not flipped towards the ray).
    pub normal: DVec3,
    /// Surface coordinates.
    pub uv: DVec2,
    /// Hit point in the object's own space (for solid textures).
    pub local_point: DVec3,
    /// The material to shade with.
    pub material: MaterialId,
    /// Index of the top-level object in `Scene::objects`.
    pub object: u32,
}

/// One intersectable primitive.
#[derive(Clone, Debug)]
struct Primitive {
    shape: Shape,
    /// `None` for the identity: the ray is used as is.
    to_object: Option<DAffine3>,
    normal_to_world: DMat3,
    material: MaterialId,
    object: u32,
    bounds: Aabb,
}

/// All primitives of a scene, ready for ray queries.
#[derive(Clone, Debug)]
pub struct World {
    prims: Vec<Primitive>,
}

impl World {
    /// Prepares a scene; `fallback` is the material for objects that name none.
    pub fn build(scene: &Scene, fallback: MaterialId) -> Result<World, Diagnostic> {
        let mut prims = Vec::with_capacity(scene.objects.len());
        for (i, o) in scene.objects.iter().enumerate() {
            prims.push(prepare(o, i as u32, o.material.unwrap_or(fallback))?);
        }
        Ok(World { prims })
    }

    /// Number of primitives.
    pub fn len(&self) -> usize {
        self.prims.len()
    }

    /// True when there is nothing to hit.
    pub fn is_empty(&self) -> bool {
        self.prims.is_empty()
    }

    /// Bounds of everything finite.
    pub fn bounds(&self) -> Aabb {
        self.prims
            .iter()
            .filter(|p| p.bounds.is_finite())
            .fold(Aabb::EMPTY, |b, p| b.union(p.bounds))
    }

    /// The nearest hit in (t_min, t_max).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<SurfaceHit> {
        let mut best: Option<(Hit, &Primitive)> = None;
        let mut t_far = t_max;
        for p in &self.prims {
            if let Some(h) = p.intersect(ray, t_min, t_far) {
                t_far = h.t;
                best = Some((h, p));
            }
        }
        best.map(|(h, p)| p.surface_hit(ray, h))
    }

    /// True when anything lies in (t_min, t_max) along the ray (shadow rays: any hit ends it).
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.prims
            .iter()
            .any(|p| p.intersect(ray, t_min, t_max).is_some())
    }
}

fn prepare(o: &Object, index: u32, material: MaterialId) -> Result<Primitive, Diagnostic> {
    let local = match &o.shape {
        Shape::Sphere { center, radius } => sphere::bounds(*center, *radius),
        Shape::Plane { .. } => Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY),
        other => {
            return Err(Diagnostic::error(
                "rtc::render::unsupported_shape",
                o.span,
                format!("the renderer cannot draw a {} yet", other.kind_name()),
            )
            .with_label("this object")
            .with_help("use spheres and planes, or remove this object"));
        }
    };
    let identity = o.transform == DAffine3::IDENTITY;
    let bounds = if identity {
        local
    } else {
        local.transformed(&o.transform)
    };
    Ok(Primitive {
        shape: o.shape.clone(),
        to_object: (!identity).then(|| o.transform.inverse()),
        normal_to_world: o.transform.matrix3.inverse().transpose(),
        material,
        object: index,
        bounds,
    })
}

impl Primitive {
    fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        // Object-space rays keep an unnormalised direction, so t is the same in both spaces.
        let local = match &self.to_object {
            None => *ray,
            Some(m) => Ray::new(m.transform_point3(ray.origin), m.transform_vector3(ray.dir)),
        };
        match &self.shape {
            Shape::Sphere { center, radius } => {
                sphere::intersect(*center, *radius, &local, t_min, t_max)
            }
            Shape::Plane { point, normal } => {
                plane::intersect(*point, *normal, &local, t_min, t_max)
            }
            _ => None,
        }
    }

    fn surface_hit(&self, ray: &Ray, h: Hit) -> SurfaceHit {
        let point = ray.at(h.t);
        let (normal, local_point) = match &self.to_object {
            None => (h.normal, point),
            Some(m) => (
                (self.normal_to_world * h.normal).normalize(),
                m.transform_point3(point),
            ),
        };
        SurfaceHit {
            t: h.t,
            point,
            normal,
            uv: h.uv,
            local_point,
            material: self.material,
            object: self.object,
        }
    }
}
