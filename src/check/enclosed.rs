//! The lints "a light inside an opaque object" and "the camera inside an opaque object", for
//! every closed solid (sphere, box, capped cylinder and cone, torus, blob, a mesh whose file is
//! a closed surface, CSG of those), each
//! by its own inside test (`geometry::shapes::Leaf::contains`, `geometry::shapes::csg::combine`), placed
//! by its transform. An enclosure is a mistake only when something lies outside it: a light
//! inside a solid that also holds the other objects lights them, and a sky dome around the
//! camera, the lights and the set is a backdrop. "Outside" is judged on one point per object
//! (its bounds' centre; a plane's own point): the corners of the box around those points all
//! inside the solid mean everything is.

use glam::DVec3;

use crate::diag::{Diagnostic, Diagnostics};
use crate::geometry::aabb::Aabb;
use crate::geometry::shapes::{self, csg};
use crate::ir::{Object, Scene, Shape, Visibility};
use crate::opt::objects::{inside_mesh, mesh_bounds};

/// At most this many enclosing objects are kept for the end of the pass.
const MAX_FOUND: usize = 16;

/// What the pass over the objects gathers: the opaque solids holding a light or the eye, and
/// the box around every object's representative point.
pub(super) struct Enclosures {
    found: Vec<Found>,
    points: Option<(DVec3, DVec3)>,
}

/// An opaque solid holding some lights (by index) or the eye.
struct Found {
    object: Object,
    lights: Vec<usize>,
    eye: bool,
}

impl Enclosures {
    /// Nothing seen yet.
    pub(super) fn new() -> Enclosures {
        Enclosures {
            found: Vec::new(),
            points: None,
        }
    }

    /// Takes in one top-level object.
    pub(super) fn object(&mut self, scene: &Scene, o: &Object) {
        let world = local_bounds(&o.shape).map(|b| b.transformed(&o.transform.affine()));
        if let Some(p) = representative(o, world) {
            self.points = Some(match self.points {
                None => (p, p),
                Some((lo, hi)) => (lo.min(p), hi.max(p)),
            });
        }
        if self.found.len() >= MAX_FOUND
            || matches!(o.shape, Shape::Plane { .. })
            || !opaque(scene, o)
        {
            return;
        }
        // Points outside the object's box are outside it: only what is left asks whether it is
        // a closed solid and what its inside holds (for a large mesh, both walk its faces).
        let near = |p: DVec3| world.is_none_or(|b| b.contains(p, 0.0));
        // An object that casts no shadow (a light's `looks_like` bulb) blocks no light.
        let blocks_light = !o.visibility.hides(Visibility::NO_SHADOW);
        let lights: Vec<usize> = (scene.lights.iter().enumerate())
            .filter(|(_, l)| blocks_light && near(l.kind.center()))
            .map(|(i, _)| i)
            .collect();
        let eye = near(scene.camera.eye);
        if (lights.is_empty() && !eye) || !closed(o) {
            return;
        }
        let lights: Vec<usize> = lights
            .into_iter()
            .filter(|&i| contains(o, scene.lights[i].kind.center()))
            .collect();
        let eye = eye && contains(o, scene.camera.eye);
        if eye || !lights.is_empty() {
            self.found.push(Found {
                object: o.clone(),
                lights,
                eye,
            });
        }
    }

    /// The warnings: each enclosure something lies outside of.
    pub(super) fn finish(self, scene: &Scene, out: &mut Diagnostics) {
        for f in &self.found {
            if !self.outside(&f.object) {
                continue;
            }
            let o = &f.object;
            let kind = match o.shape.kind_name() {
                "csg" => "CSG object",
                k => k,
            };
            for &i in &f.lights {
                let l = &scene.lights[i];
                let p = l.kind.center();
                out.push(
                    Diagnostic::warning(
                        "rtc::scene::light_enclosed",
                        l.span,
                        format!(
                            "the light at {p} is inside an opaque {kind}; it lights nothing outside it"
                        ),
                    )
                    .with_label("this light")
                    .with_secondary(o.span, "encloses the light")
                    .with_help(format!(
                        "move the light outside the {kind}, or make the {kind} refractive (`refract` > 0)"
                    )),
                );
            }
            if f.eye {
                out.push(
                    Diagnostic::warning(
                        "rtc::scene::camera_enclosed",
                        scene.camera.span,
                        format!(
                            "the camera is inside an opaque {kind}; the image will show only its inside"
                        ),
                    )
                    .with_label("this camera")
                    .with_secondary(o.span, "encloses the eye")
                    .with_help(format!("move `eye` outside the {kind}")),
                );
            }
        }
    }

    /// Whether some object's representative point may lie outside `o`: a corner of their box
    /// is outside it.
    fn outside(&self, o: &Object) -> bool {
        let Some((lo, hi)) = self.points else {
            return false;
        };
        (0..8).any(|k| {
            let pick = |bit: u32, a: f64, b: f64| if k & bit == 0 { a } else { b };
            let corner = DVec3::new(
                pick(1, lo.x, hi.x),
                pick(2, lo.y, hi.y),
                pick(4, lo.z, hi.z),
            );
            !contains(o, corner)
        })
    }
}

/// Whether neither `o` nor any CSG operand of it refracts (light passes through glass).
fn opaque(scene: &Scene, o: &Object) -> bool {
    let glass = o.material.is_some_and(|m| scene.material(m).refract > 0.0);
    !glass
        && match &o.shape {
            Shape::Csg { children, .. } => children.iter().all(|c| opaque(scene, c)),
            _ => true,
        }
}

/// Whether `o` encloses a volume whose inside `contains` can tell (a mesh when its file is a
/// closed surface).
fn closed(o: &Object) -> bool {
    shapes::encloses_volume(&o.shape, &|source: &crate::ir::MeshSource, smooth: bool| {
        mesh_bounds(source, smooth).is_some_and(|(_, closed)| closed)
    })
}

/// Whether world point `p` is inside object `o` (at its shutter-open placement); false for
/// surfaces, meshes, and transforms that cannot be inverted.
fn contains(o: &Object, p: DVec3) -> bool {
    let q = if o.transform.is_identity() {
        p
    } else {
        let t = o.transform.affine();
        if t.matrix3.determinant() == 0.0 {
            return false;
        }
        t.inverse().transform_point3(p)
    };
    match &o.shape {
        Shape::Csg { op, children } => csg::combine(*op, children.iter().map(|c| contains(c, q))),
        Shape::Mesh { source, smooth, .. } => inside_mesh(source, *smooth, q),
        s => shapes::leaf(s).is_ok_and(|l| l.contains(q)),
    }
}

/// One point standing for where `o` is: the centre of its world bounds `world`, or a plane's
/// own point.
fn representative(o: &Object, world: Option<Aabb>) -> Option<DVec3> {
    if let Shape::Plane { point, .. } = o.shape {
        return Some(o.transform.affine().transform_point3(point));
    }
    let b = world?;
    let c = 0.5 * (b.min + b.max);
    c.is_finite().then_some(c)
}

/// The object-space bounds of a shape, CSG included; `None` for invalid shapes and meshes that
/// do not load.
fn local_bounds(s: &Shape) -> Option<Aabb> {
    match s {
        Shape::Mesh { source, smooth, .. } => mesh_bounds(source, *smooth).map(|(b, _)| b),
        Shape::Csg { op, children } => {
            let boxes: Option<Vec<Aabb>> = children
                .iter()
                .map(|c| Some(local_bounds(&c.shape)?.transformed(&c.transform.affine())))
                .collect();
            Some(csg::bounds(*op, &boxes?))
        }
        _ => shapes::bounds(s),
    }
}
