//! Lowering of emitted values to the IR: objects (groups flattened, CSG kept), materials and
//! textures (shared by identity, so one material used by a million objects is stored once),
//! lights, the camera and render settings.

use std::rc::Rc;

use glam::DAffine3;

use crate::diag::Diagnostic;
use crate::ir;
use crate::source::Span;
use crate::syntax::ast::{Expr, ExprKind, Generator};

use super::value::{Mat, MatMix, Obj, ObjShape, RenderVal, Tex, Value};

/// Collects what a scene file emits.
#[derive(Default)]
pub(crate) struct Lowerer {
    /// Objects so far.
    pub(crate) objects: Vec<ir::Object>,
    /// Lights so far.
    pub(crate) lights: Vec<ir::Light>,
    /// Cameras emitted (one is required).
    pub(crate) cameras: Vec<Rc<ir::Camera>>,
    /// Render blocks emitted (at most one).
    pub(crate) renders: Vec<Rc<RenderVal>>,
    /// With provenance: per object, its origin and those of the groups placing it (innermost
    /// first).
    pub(crate) origins: Option<Vec<Vec<u32>>>,
    /// The origins of the groups being lowered (outermost first), with provenance.
    placing: Vec<u32>,
    /// The IR materials, one per material value lowered, in the order of first use.
    pub(super) materials: Vec<ir::Material>,
    /// The [`Mat::made`] of each of `materials`.
    pub(super) material_keys: Vec<u64>,
    /// The IR textures, one per texture value lowered.
    pub(super) textures: Vec<ir::Texture>,
    /// The [`Tex::made`] of each of `textures`.
    pub(super) texture_keys: Vec<u64>,
    /// Material ids by [`Mat::made`].
    mat_ids: super::fxhash::FxHashMap<u64, ir::MaterialId>,
    /// Texture ids by [`Tex::made`].
    tex_ids: super::fxhash::FxHashMap<u64, ir::TextureId>,
}

/// What an object inherits from the group or scene around it while it is lowered.
#[derive(Clone, Copy)]
struct Enclosing {
    /// The placement of the enclosing group.
    placement: DAffine3,
    /// The material its members take when they name none.
    material: Option<ir::MaterialId>,
    /// The motion of the enclosing group.
    motion: Option<ir::Motion>,
    /// The rays the enclosing group hides from.
    visibility: ir::Visibility,
}

impl Enclosing {
    /// A CSG operand inherits nothing: its placement, material, motion and flags are the CSG
    /// node's, applied to the node.
    const OPERAND: Enclosing = Enclosing {
        placement: DAffine3::IDENTITY,
        material: None,
        motion: None,
        visibility: ir::Visibility::ALL,
    };
}

/// Whether a value is something a scene file may emit.
pub(crate) fn emittable(v: &Value) -> bool {
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
    pub(crate) fn emit(
        &mut self,
        v: &Value,
        budget: &super::budgets::ObjectBudget,
        span: Span,
    ) -> Result<(), Diagnostic> {
        let max_objects = budget.max_objects;
        match v {
            Value::Object(o) => {
                self.object(o, DAffine3::IDENTITY, None);
                budget.check_memory(self.objects.len(), span)?;
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
            Value::Light(l) => {
                self.lights.push(l.light.clone());
                if let Some(look) = &l.looks_like {
                    // At the light's centre, and never in the way of any light (POV-Ray's rule:
                    // the light shines from inside it).
                    let at = DAffine3::from_translation(l.light.kind.center());
                    let mut shown = look.clone();
                    shown.transform = at * shown.transform;
                    shown.motion = shown.motion.map(|m| m.transformed(at));
                    shown.visibility = shown.visibility.with(ir::Visibility::NO_SHADOW);
                    self.emit(&Value::Object(Rc::new(shown)), budget, span)?;
                }
            }
            Value::Camera(c) => self.cameras.push(c.clone()),
            Value::Render(r) => self.renders.push(r.clone()),
            Value::List(l) => {
                for x in l.iter() {
                    self.emit(x, budget, span)?;
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
    pub(crate) fn reserve_for(&mut self, gens: &[Generator], filter: Option<&Expr>, limit: u64) {
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

    fn texture(&mut self, t: &Tex) -> ir::TextureId {
        if let Some(id) = self.tex_ids.get(&t.made) {
            return *id;
        }
        let id = self.add_texture(t.made, t.t.clone());
        self.tex_ids.insert(t.made, id);
        id
    }

    /// Appends a texture (`made` is its value's [`Tex::made`]).
    fn add_texture(&mut self, made: u64, t: ir::Texture) -> ir::TextureId {
        self.textures.push(t);
        self.texture_keys.push(made);
        ir::TextureId((self.textures.len() - 1) as u32)
    }

    /// Appends a material (`made` is its value's [`Mat::made`]).
    fn add_material(&mut self, made: u64, m: ir::Material) -> ir::MaterialId {
        self.materials.push(m);
        self.material_keys.push(made);
        ir::MaterialId((self.materials.len() - 1) as u32)
    }

    /// The id of a material, adding it on first use.
    fn material(&mut self, m: &Mat) -> ir::MaterialId {
        if let Some(id) = self.mat_ids.get(&m.made) {
            return *id;
        }
        let mut im = m.m.clone();
        im.mix = m.mix.as_ref().map(|mix| Box::new(self.mix(mix)));
        im.texture = m.texture.as_ref().map(|t| self.texture(t));
        im.bump = m.bump.as_ref().map(|(t, s)| ir::Bump {
            texture: self.texture(t),
            scale: *s,
        });
        let id = self.add_material(m.made, im);
        self.mat_ids.insert(m.made, id);
        id
    }

    /// A mixed material's parts, lowered (before the material itself, so a loop part's
    /// renumbering meets them first).
    fn mix(&mut self, mix: &MatMix) -> ir::Mix {
        match mix {
            MatMix::Map {
                pattern,
                stops,
                blend,
            } => ir::Mix::Map {
                texture: self.texture(pattern),
                stops: stops
                    .iter()
                    .map(|(at, m)| (*at, self.material(m)))
                    .collect(),
                blend: *blend,
            },
            MatMix::Layers(layers) => {
                ir::Mix::Layers(layers.iter().map(|m| self.material(m)).collect())
            }
        }
    }

    fn object(&mut self, o: &Obj, parent: DAffine3, inherited: Option<ir::MaterialId>) {
        let mut out = std::mem::take(&mut self.objects);
        self.lower_into(
            o,
            Enclosing {
                placement: parent,
                material: inherited,
                motion: None,
                visibility: ir::Visibility::ALL,
            },
            &mut out,
            true,
        );
        self.objects = out;
    }

    fn lower_into(
        &mut self,
        o: &Obj,
        from: Enclosing,
        out: &mut Vec<ir::Object>,
        scene_level: bool,
    ) {
        let Enclosing {
            placement: parent,
            material: inherited,
            motion: moving,
            visibility: hidden,
        } = from;
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
        // A group's flags hold for its members.
        let visibility = hidden.with(o.visibility);
        match &o.shape {
            ObjShape::Prim(s) => out.push(ir::Object {
                shape: s.clone(),
                transform: t.into(),
                material: mat,
                motion: motion.map(Box::new),
                span: o.span,
                visibility,
            }),
            ObjShape::Group(ch) => {
                let placing = self.origins.is_some();
                if placing {
                    self.placing.push(o.origin);
                }
                for c in ch.iter() {
                    self.lower_into(
                        c,
                        Enclosing {
                            placement: t,
                            material: mat,
                            motion,
                            visibility,
                        },
                        out,
                        scene_level,
                    );
                }
                if placing {
                    self.placing.pop();
                }
            }
            ObjShape::Csg(op, ch) => {
                let mut kids = Vec::with_capacity(ch.len());
                for c in ch.items().iter() {
                    match &c.shape {
                        // A group inside CSG acts as the union of its children.
                        ObjShape::Group(g) => {
                            let mut sub = Vec::new();
                            let cm = c.material.as_ref().map(|m| self.material(m));
                            for x in g.iter() {
                                self.lower_into(x, Enclosing::OPERAND, &mut sub, false);
                            }
                            kids.push(ir::Object {
                                shape: ir::Shape::Csg {
                                    op: ir::CsgOp::Union,
                                    children: sub,
                                },
                                transform: c.transform.into(),
                                material: cm,
                                motion: c.motion.map(Box::new),
                                span: c.span,
                                visibility: c.visibility,
                            });
                        }
                        _ => self.lower_into(c, Enclosing::OPERAND, &mut kids, false),
                    }
                }
                // The renderer hides whole top-level objects: an operand's flags hide the
                // whole CSG object (documented, docs/language.md "Visibility").
                let visibility = kids.iter().fold(visibility, |v, k| v.with(flags_within(k)));
                out.push(ir::Object {
                    shape: ir::Shape::Csg {
                        op: *op,
                        children: kids,
                    },
                    transform: t.into(),
                    material: mat,
                    motion: motion.map(Box::new),
                    span: o.span,
                    visibility,
                });
            }
        }
    }

    /// Appends what another thread's replay emitted in a part of a loop (`split`). The
    /// part's first `materials` materials and `textures` textures are this lowerer's own (the
    /// replay lowered the same values before the loop); its new ones are renumbered after
    /// this lowerer's. A new one whose value was made before the loop (number ≤ `made`) is the
    /// value this thread knows by that number, shared if this thread lowered it already.
    pub(super) fn absorb(
        &mut self,
        part: super::parts::ScenePart,
        made: u64,
        materials: usize,
        textures: usize,
    ) {
        let super::parts::ScenePart {
            objects,
            lights,
            cameras,
            materials: new_materials,
            textures: new_textures,
        } = part;
        let tex: Vec<ir::TextureId> = new_textures
            .into_iter()
            .map(|(key, t)| self.shared(key, made, |l| l.add_texture(key, t), |l| &mut l.tex_ids))
            .collect();
        let retex = |id: ir::TextureId| match (id.0 as usize).checked_sub(textures) {
            Some(i) => tex[i],
            None => id,
        };
        // A mixed material's parts come before it, so they are renumbered when it is.
        let mut mat: Vec<ir::MaterialId> = Vec::with_capacity(new_materials.len());
        for (key, mut m) in new_materials {
            m.texture = m.texture.map(retex);
            if let Some(b) = &mut m.bump {
                b.texture = retex(b.texture);
            }
            if let Some(mix) = &mut m.mix {
                let remat = |id: ir::MaterialId| match (id.0 as usize).checked_sub(materials) {
                    Some(i) => mat[i],
                    None => id,
                };
                match &mut **mix {
                    ir::Mix::Map { texture, stops, .. } => {
                        *texture = retex(*texture);
                        for (_, id) in stops {
                            *id = remat(*id);
                        }
                    }
                    ir::Mix::Layers(layers) => {
                        for id in layers {
                            *id = remat(*id);
                        }
                    }
                }
            }
            let id = self.shared(key, made, |l| l.add_material(key, m), |l| &mut l.mat_ids);
            mat.push(id);
        }
        let remat = |id: ir::MaterialId| match (id.0 as usize).checked_sub(materials) {
            Some(i) => mat[i],
            None => id,
        };
        self.objects.extend(objects.into_iter().map(|mut o| {
            renumber(&mut o, &remat);
            o
        }));
        self.lights.extend(lights);
        self.cameras.extend(cameras.into_iter().map(Rc::new));
    }

    /// The id of value `key` absorbed from another thread: `add` makes it, and `ids` shares it
    /// when the value was made before the split loop (`key <= made`).
    fn shared<I: Copy>(
        &mut self,
        key: u64,
        made: u64,
        add: impl FnOnce(&mut Self) -> I,
        ids: impl Fn(&mut Self) -> &mut super::fxhash::FxHashMap<u64, I>,
    ) -> I {
        if key > made {
            // Made inside the loop, on the other thread: no value here has its number.
            return add(self);
        }
        if let Some(id) = ids(self).get(&key) {
            return *id;
        }
        let id = add(self);
        ids(self).insert(key, id);
        id
    }

    /// Builds the scene, which carries on the load's `memory` charged so far; `Err` lists what
    /// is missing or duplicated.
    pub(crate) fn finish(
        mut self,
        memory: ir::limits::Memory,
    ) -> Result<ir::Scene, Vec<Diagnostic>> {
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
                if let (Some(f), Some((t, depth))) = (s.fog.as_mut(), r.fog_pattern.as_ref()) {
                    f.pattern = Some(ir::FogPattern {
                        texture: self.texture(t),
                        depth: *depth,
                    });
                }
                s.sky = r.sky.as_ref().map(|(t, rotation, strength)| ir::Sky {
                    texture: self.texture(t),
                    rotation: *rotation,
                    strength: *strength,
                });
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
            memory,
        })
    }
}

/// Renames the material ids of an object and its CSG operands.
fn renumber(o: &mut ir::Object, remat: &impl Fn(ir::MaterialId) -> ir::MaterialId) {
    o.material = o.material.map(remat);
    if let ir::Shape::Csg { children, .. } = &mut o.shape {
        for c in children {
            renumber(c, remat);
        }
    }
}

/// Where the elements of a `for` go.
pub(crate) enum Sink<'a> {
    /// Collected into a list value.
    List(&'a mut Vec<Value>),
    /// Emitted straight into the scene (top-level loops), with the statement's span.
    Emit(&'a mut Lowerer, Span),
}

/// The visibility flags of `o` and of everything inside it (CSG operands, at any depth).
fn flags_within(o: &ir::Object) -> ir::Visibility {
    match &o.shape {
        ir::Shape::Csg { children, .. } => children
            .iter()
            .fold(o.visibility, |v, k| v.with(flags_within(k))),
        _ => o.visibility,
    }
}
