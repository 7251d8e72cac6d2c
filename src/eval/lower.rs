//! Lowering of emitted values to the IR: objects (groups flattened, CSG kept), materials and
//! textures (shared by identity, so one material used by a million objects is stored once),
//! lights, the camera and render settings.

use std::rc::Rc;

use glam::DAffine3;

use crate::diag::Diagnostic;
use crate::ir;
use crate::source::Span;
use crate::syntax::ast::{Expr, ExprKind, Generator};

use super::value::{Mat, Obj, ObjShape, RenderVal, Tex, Value};

/// Collects what a scene file emits.
#[derive(Default)]
pub struct Lowerer {
    /// Objects so far.
    pub objects: Vec<ir::Object>,
    /// Lights so far.
    pub lights: Vec<ir::Light>,
    /// Cameras emitted (one is required).
    pub cameras: Vec<Rc<ir::Camera>>,
    /// Render blocks emitted (at most one).
    pub renders: Vec<Rc<RenderVal>>,
    /// With provenance: per object, its origin and those of the groups placing it (innermost
    /// first).
    pub origins: Option<Vec<Vec<u32>>>,
    /// The origins of the groups being lowered (outermost first), with provenance.
    placing: Vec<u32>,
    materials: Vec<ir::Material>,
    textures: Vec<ir::Texture>,
    mat_ids: super::fxhash::FxHashMap<*const Mat, ir::MaterialId>,
    tex_ids: super::fxhash::FxHashMap<*const Tex, ir::TextureId>,
    /// Keeps every lowered material alive so its address is never reused by another.
    keep: Vec<Rc<Mat>>,
    keep_tex: Vec<Rc<Tex>>,
}

/// Whether a value is something a scene file may emit.
pub fn emittable(v: &Value) -> bool {
    match v {
        Value::Object(_) | Value::Light(_) | Value::Camera(_) | Value::Render(_) => true,
        Value::List(l) => {
            !l.is_empty()
                && l.iter()
                    .all(|x| emittable(x) || matches!(x, Value::List(_)))
        }
        _ => false,
    }
}

impl Lowerer {
    /// Adds an emitted value; `Err` carries the type of a value that cannot be emitted.
    pub fn emit(&mut self, v: &Value, max_objects: u64, span: Span) -> Result<(), Diagnostic> {
        match v {
            Value::Object(o) => {
                self.object(o, DAffine3::IDENTITY, None);
                if self.objects.len() as u64 > max_objects {
                    return Err(Diagnostic::error(
                        "rtc::budget::objects",
                        span,
                        "too many objects",
                    )
                    .with_label(format!("the scene passes {max_objects} objects here"))
                    .with_help("emit fewer objects, e.g. with a coarser loop `step`"));
                }
            }
            Value::Light(l) => self.lights.push((**l).clone()),
            Value::Camera(c) => self.cameras.push(c.clone()),
            Value::Render(r) => self.renders.push(r.clone()),
            Value::List(l) => {
                for x in l.iter() {
                    self.emit(x, max_objects, span)?;
                }
            }
            Value::Unit => {}
            other => {
                return Err(Diagnostic::error(
                    "rtc::value::discarded",
                    span,
                    format!(
                        "{} cannot be part of the scene",
                        super::value::a_type(other.type_name())
                    ),
                )
                .with_label("this value goes nowhere")
                .with_help("bind it with `let name = ...`, or remove it"));
            }
        }
        Ok(())
    }

    /// Makes room at once for the objects of a top-level `for` whose generators are all
    /// integer-literal ranges (`for i in 0..100, j in 0..100`) and that has no filter: it
    /// makes one element per iteration, usually one object. Without it the object vector grows
    /// by doubling on the way to a million objects, copying itself and touching its pages
    /// twice. At most `limit` (the object budget) are reserved; a body that emits no object
    /// leaves the room untouched (address space, never paged in).
    pub fn reserve_for(&mut self, gens: &[Generator], filter: Option<&Expr>, limit: u64) {
        let int = |e: &Expr| match e.kind {
            ExprKind::Int(i) => Some(i),
            _ => None,
        };
        let count = |g: &Generator| match &g.iter.kind {
            ExprKind::Range {
                start,
                end,
                inclusive,
                step: None,
            } => {
                let (a, b) = (int(start)?, int(end)?);
                let n = b.checked_sub(a)?.checked_add(i64::from(*inclusive))?;
                u64::try_from(n.max(0)).ok()
            }
            _ => None,
        };
        if filter.is_some() {
            return;
        }
        let total = gens
            .iter()
            .try_fold(1u64, |acc, g| acc.checked_mul(count(g)?));
        if let Some(n) = total.map(|n| n.min(limit)) {
            // Only a hint: where the room cannot be had, the vector grows as it would have.
            let _ = self.objects.try_reserve(usize::try_from(n).unwrap_or(0));
        }
    }

    fn texture(&mut self, t: &Rc<Tex>) -> ir::TextureId {
        if let Some(id) = self.tex_ids.get(&Rc::as_ptr(t)) {
            return *id;
        }
        self.textures.push(t.t.clone());
        let id = ir::TextureId((self.textures.len() - 1) as u32);
        self.tex_ids.insert(Rc::as_ptr(t), id);
        self.keep_tex.push(t.clone());
        id
    }

    /// The id of a material, adding it on first use.
    pub fn material(&mut self, m: &Rc<Mat>) -> ir::MaterialId {
        if let Some(id) = self.mat_ids.get(&Rc::as_ptr(m)) {
            return *id;
        }
        let mut im = m.m.clone();
        im.texture = m.texture.as_ref().map(|t| self.texture(t));
        im.bump = m.bump.as_ref().map(|(t, s)| ir::Bump {
            texture: self.texture(t),
            scale: *s,
        });
        self.materials.push(im);
        let id = ir::MaterialId((self.materials.len() - 1) as u32);
        self.mat_ids.insert(Rc::as_ptr(m), id);
        self.keep.push(m.clone());
        id
    }

    fn object(&mut self, o: &Obj, parent: DAffine3, inherited: Option<ir::MaterialId>) {
        let mut out = std::mem::take(&mut self.objects);
        self.lower_into(o, parent, inherited, None, &mut out, true);
        self.objects = out;
    }

    fn lower_into(
        &mut self,
        o: &Obj,
        parent: DAffine3,
        inherited: Option<ir::MaterialId>,
        moving: Option<ir::Motion>,
        out: &mut Vec<ir::Object>,
        scene_level: bool,
    ) {
        // A scene-level object (not a CSG operand) gets its provenance entry.
        if scene_level
            && !matches!(o.shape, ObjShape::Group(_))
            && let Some(origins) = &mut self.origins
        {
            let mut own = vec![o.origin];
            own.extend(self.placing.iter().rev());
            origins.push(own);
        }
        let t = parent * o.transform;
        // A group's motion moves all its members (`.moving` refuses motion nested in a group).
        let motion = o.motion.map(|m| m.transformed(parent)).or(moving);
        let mat = match &o.material {
            Some(m) => Some(self.material(m)),
            None => inherited,
        };
        match &o.shape {
            ObjShape::Prim(s) => out.push(ir::Object {
                shape: s.clone(),
                transform: t,
                material: mat,
                motion: motion.map(Box::new),
                span: o.span,
            }),
            ObjShape::Group(ch) => {
                let placing = self.origins.is_some();
                if placing {
                    self.placing.push(o.origin);
                }
                for c in ch.iter() {
                    self.lower_into(c, t, mat, motion, out, scene_level);
                }
                if placing {
                    self.placing.pop();
                }
            }
            ObjShape::Csg(op, ch) => {
                let mut kids = Vec::with_capacity(ch.len());
                for c in ch.iter() {
                    match &c.shape {
                        // A group inside CSG acts as the union of its children.
                        ObjShape::Group(g) => {
                            let mut sub = Vec::new();
                            let cm = c.material.as_ref().map(|m| self.material(m));
                            for x in g.iter() {
                                self.lower_into(x, DAffine3::IDENTITY, None, None, &mut sub, false);
                            }
                            kids.push(ir::Object {
                                shape: ir::Shape::Csg {
                                    op: ir::CsgOp::Union,
                                    children: sub,
                                },
                                transform: c.transform,
                                material: cm,
                                motion: c.motion.map(Box::new),
                                span: c.span,
                            });
                        }
                        _ => self.lower_into(c, DAffine3::IDENTITY, None, None, &mut kids, false),
                    }
                }
                out.push(ir::Object {
                    shape: ir::Shape::Csg {
                        op: *op,
                        children: kids,
                    },
                    transform: t,
                    material: mat,
                    motion: motion.map(Box::new),
                    span: o.span,
                });
            }
        }
    }

    /// Builds the scene; `Err` lists what is missing or duplicated.
    pub fn finish(mut self) -> Result<ir::Scene, Vec<Diagnostic>> {
        let mut errs = Vec::new();
        if self.cameras.len() > 1 {
            errs.push(
                Diagnostic::error(
                    "rtc::camera::duplicate",
                    self.cameras[1].span,
                    "the scene has two cameras",
                )
                .with_label("second camera")
                .with_secondary(self.cameras[0].span, "first camera")
                .with_help("remove one of them, or bind the spare one with `let`"),
            );
        }
        if self.renders.len() > 1 {
            errs.push(
                Diagnostic::error(
                    "rtc::render::duplicate",
                    self.renders[1].span,
                    "the scene has two `render` blocks",
                )
                .with_label("second `render`")
                .with_secondary(self.renders[0].span, "first `render`")
                .with_help("merge them into one `render { ... }`"),
            );
        }
        let Some(camera) = self.cameras.first().map(|c| (**c).clone()) else {
            errs.push(
                Diagnostic::new(
                    crate::diag::Severity::Error,
                    "rtc::camera::missing",
                    None,
                    "the scene has no camera",
                )
                .with_help("add one, e.g. `camera { eye: [0, 2, 8], center: [0, 0, 0] }`"),
            );
            return Err(errs);
        };
        if !errs.is_empty() {
            return Err(errs);
        }
        let settings = match self.renders.first().cloned() {
            Some(r) => {
                let mut s = r.s.clone();
                s.default_material = r.material.as_ref().map(|m| self.material(m));
                s
            }
            None => ir::RenderSettings::language_defaults(),
        };
        Ok(ir::Scene {
            camera,
            lights: self.lights,
            materials: self.materials,
            textures: self.textures,
            objects: self.objects,
            settings,
        })
    }
}
