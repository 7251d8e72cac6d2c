//! Runtime values. Big values sit behind `Rc` so copying a value is cheap.

use std::fmt;
use std::rc::Rc;

use glam::{DAffine3, DVec3};

use crate::ir;
use crate::source::Span;
use crate::syntax::ast::FnDef;
use crate::syntax::intern::Sym;

/// A value of the language.
#[derive(Clone, Debug)]
pub(crate) enum Value {
    /// The result of `print` and `assert`; discarded silently.
    Unit,
    /// 64-bit integer.
    Int(i64),
    /// Float.
    Float(f64),
    /// Boolean.
    Bool(bool),
    /// String.
    Str(Rc<str>),
    /// An angle in radians.
    Angle(f64),
    /// A 3-vector.
    Vec3(DVec3),
    /// A linear RGB colour.
    Color(DVec3),
    /// An affine transform.
    Transform(Rc<DAffine3>),
    /// A list.
    List(Rc<Vec<Value>>),
    /// `a..b step s`.
    Range(Range),
    /// `{ name: value }`.
    Record(Rc<Record>),
    /// A user function or closure.
    Fn(Rc<Closure>),
    /// A built-in function.
    Builtin(Builtin),
    /// An object.
    Object(Rc<Obj>),
    /// A material.
    Material(Rc<Mat>),
    /// A texture.
    Texture(Rc<Tex>),
    /// A light, with the object that shows it.
    Light(Rc<LightVal>),
    /// A camera.
    Camera(Rc<ir::Camera>),
    /// Render settings.
    Render(Rc<RenderVal>),
    /// A shading model (`phong`, `gooch {..}`, `hatching`).
    Shading(ir::ShadingModel),
    /// An image mode (`shaded`, `normal`, `depth`).
    Mode(ir::RenderMode),
    /// A sampling strategy (`adaptive(..)`).
    Sampling(ir::Sampling),
    /// A texture mapping (`uv`, `planar`, ...).
    Mapping(ir::Mapping),
    /// An ambient convention (`per_light`, `once`).
    Ambient(ir::AmbientConvention),
    /// An output encoding (`linear`; `srgb` is the colour function, accepted by name).
    Encoding(ir::Encoding),
    /// Lens flare parameters (`flare { ... }`).
    Flare(ir::Flare),
    /// An integrator (`whitted`, `path(..)`).
    Integrator(ir::Integrator),
    /// Fog parameters (`fog { ... }`).
    Fog(Rc<FogVal>),
    /// A keyed random stream.
    Rng(u64),
    /// An imported module.
    Module(Rc<crate::eval::modules::Module>),
}

/// A built-in function: its name and which it is (its implementation is looked up by `id` in
/// the built-ins' table, so values need not know the interpreter's signature).
#[derive(Clone, Copy)]
pub(crate) struct Builtin {
    /// Name used in messages.
    pub(crate) name: &'static str,
    /// Its index in the built-ins' table (`builtins::function`).
    pub(crate) id: u16,
}

impl fmt::Debug for Builtin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "builtin {}", self.name)
    }
}

/// A numeric range.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Range {
    /// Start (inclusive).
    pub(crate) start: f64,
    /// End.
    pub(crate) end: f64,
    /// Step (non-zero).
    pub(crate) step: f64,
    /// End included.
    pub(crate) inclusive: bool,
    /// All of start, end and step were Int.
    pub(crate) ints: bool,
}

impl Range {
    /// Number of elements (saturating; the caller checks budgets).
    pub(crate) fn len(&self) -> u64 {
        let span = (self.end - self.start) / self.step;
        if !span.is_finite() || span < 0.0 {
            return 0;
        }
        // A tolerance so that 0..=1 step 0.1 includes 1 despite rounding.
        let eps = 1e-9;
        let n = if self.inclusive {
            (span + eps).floor() + 1.0
        } else {
            (span - eps).ceil().max(0.0)
        };
        if n > u64::MAX as f64 {
            u64::MAX
        } else {
            n as u64
        }
    }

    /// The `i`th element.
    pub(crate) fn get(&self, i: u64) -> Value {
        if self.ints {
            Value::Int((self.start as i64).wrapping_add((i as i64).wrapping_mul(self.step as i64)))
        } else {
            Value::Float(self.start + i as f64 * self.step)
        }
    }
}

/// One field of a record value.
#[derive(Clone, Debug)]
pub(crate) struct FieldVal {
    /// Its name.
    pub(crate) name: Sym,
    /// Its value.
    pub(crate) value: Value,
    /// Span of the value.
    pub(crate) span: Span,
    /// Span of the name.
    pub(crate) name_span: Span,
}

/// A record: ordered fields.
#[derive(Clone, Debug, Default)]
pub(crate) struct Record {
    /// The fields in written order.
    pub(crate) fields: Vec<FieldVal>,
}

impl Record {
    /// Looks a field up.
    pub(crate) fn get(&self, name: Sym) -> Option<&Value> {
        self.fields
            .iter()
            .find(|f| f.name == name)
            .map(|f| &f.value)
    }
}

/// A user function with the local bindings it captured.
#[derive(Debug)]
pub(crate) struct Closure {
    /// The definition.
    pub(crate) def: Rc<FnDef>,
    /// Locals visible where it was defined (module items are found through `module`).
    pub(crate) captured: Vec<(Sym, Value)>,
    /// The module whose items it sees.
    pub(crate) module: Rc<crate::eval::modules::Scope>,
}

/// An object value.
#[derive(Clone, Debug)]
pub(crate) struct Obj {
    /// The geometry.
    pub(crate) shape: ObjShape,
    /// Object to world.
    pub(crate) transform: DAffine3,
    /// Own material.
    pub(crate) material: Option<Rc<Mat>>,
    /// How it moves while the shutter is open (in the space `transform` maps into).
    pub(crate) motion: Option<ir::Motion>,
    /// Where it was made.
    pub(crate) span: Span,
    /// Its origin in the provenance record (0 when none is kept: `eval::provenance`).
    pub(crate) origin: u32,
    /// The rays that see it (`.no_shadow()`, `.no_image()`, `.no_reflection()`).
    pub(crate) visibility: ir::Visibility,
}

/// A light value: the light and the object drawn where it is (POV-Ray's `looks_like`).
#[derive(Clone, Debug)]
pub(crate) struct LightVal {
    /// The light.
    pub(crate) light: ir::Light,
    /// The object that shows it, in the light's own space (moved to its centre when emitted;
    /// it casts no shadow), if any.
    pub(crate) looks_like: Option<Obj>,
}

/// Bytes one list element is charged to the memory budget: the size of a value (what the
/// element holds besides is charged when it is made).
pub(crate) const VALUE_BYTES: u64 = std::mem::size_of::<Value>() as u64;

/// Geometry of an object value.
#[derive(Clone, Debug)]
pub(crate) enum ObjShape {
    /// A primitive (never `Shape::Csg`).
    Prim(ir::Shape),
    /// CSG over children.
    Csg(ir::CsgOp, super::operands::Operands<Obj>),
    /// A group, flattened into its children in the IR.
    Group(Rc<Vec<Obj>>),
}

/// A material value.
#[derive(Clone, Debug)]
pub(crate) struct Mat {
    /// The scalar parameters (texture ids are filled when lowering).
    pub(crate) m: ir::Material,
    /// Colour texture.
    pub(crate) texture: Option<Rc<Tex>>,
    /// Bump texture and its strength.
    pub(crate) bump: Option<(Rc<Tex>, f64)>,
    /// The materials it is made of, for a material map or layers (`m` is then its first part's).
    pub(crate) mix: Option<Rc<MatMix>>,
    /// Which material value this is ([`Interp::next_made`](super::interp::Interp::next_made)):
    /// the lowering shares one IR material per value by it.
    pub(crate) made: u64,
}

/// The parts of a mixed material value (lowered to `ir::Mix`).
#[derive(Clone, Debug)]
pub(crate) enum MatMix {
    /// `material_map(..)`: a pattern's value picks or blends the stops' materials.
    Map {
        /// The pattern (its colour map unused).
        pattern: Rc<Tex>,
        /// (position, material), sorted by position.
        stops: Vec<(f64, Rc<Mat>)>,
        /// Blend between stops (else switch).
        blend: bool,
    },
    /// `layers([..])`: top first.
    Layers(Vec<Rc<Mat>>),
}

/// A texture value (lowered to `ir::Texture`).
#[derive(Clone, Debug)]
pub(crate) struct Tex {
    /// The texture.
    pub(crate) t: ir::Texture,
    /// Which texture value this is (as [`Mat::made`]).
    pub(crate) made: u64,
}

/// Fog as a value: its IR with the modulating pattern not yet lowered (boxed: a fog is far
/// larger than most values).
#[derive(Clone, Debug)]
pub(crate) struct FogVal {
    /// The fog (its `pattern` filled when lowered).
    pub(crate) fog: ir::Fog,
    /// The modulating pattern and its depth.
    pub(crate) pattern: Option<(Rc<Tex>, f64)>,
}

/// Render settings as a value.
#[derive(Clone, Debug)]
pub(crate) struct RenderVal {
    /// The settings (material id filled later).
    pub(crate) s: ir::RenderSettings,
    /// The default material for objects without one.
    pub(crate) material: Option<Rc<Mat>>,
    /// The sky's texture with its rotation and strength (lowered to `ir::Sky`).
    pub(crate) sky: Option<(Rc<Tex>, f64, f64)>,
    /// The fog's modulating pattern and its depth (lowered into `s.fog`).
    pub(crate) fog_pattern: Option<(Rc<Tex>, f64)>,
    /// Where it was made.
    pub(crate) span: Span,
}

impl Value {
    /// The type name used in messages.
    pub(crate) fn type_name(&self) -> &'static str {
        match self {
            Value::Unit => "Unit",
            Value::Int(_) => "Int",
            Value::Float(_) => "Float",
            Value::Bool(_) => "Bool",
            Value::Str(_) => "String",
            Value::Angle(_) => "Angle",
            Value::Vec3(_) => "Vec3",
            Value::Color(_) => "Color",
            Value::Transform(_) => "Transform",
            Value::List(_) => "List",
            Value::Range(_) => "Range",
            Value::Record(_) => "Record",
            Value::Fn(_) | Value::Builtin(_) => "Fn",
            Value::Object(_) => "Object",
            Value::Material(_) => "Material",
            Value::Texture(_) => "Texture",
            Value::Light(_) => "Light",
            Value::Camera(_) => "Camera",
            Value::Render(_) => "Render",
            Value::Shading(_) => "Shading",
            Value::Mode(_) => "Mode",
            Value::Sampling(_) => "Sampling",
            Value::Mapping(_) => "Mapping",
            Value::Ambient(_) => "Ambient",
            Value::Encoding(_) => "Encoding",
            Value::Flare(_) => "Flare",
            Value::Integrator(_) => "Integrator",
            Value::Fog(_) => "Fog",
            Value::Rng(_) => "Rng",
            Value::Module(_) => "Module",
        }
    }

    /// The value as a float, if it is a number.
    pub(crate) fn as_f64(&self) -> Option<f64> {
        match *self {
            Value::Int(i) => Some(i as f64),
            Value::Float(f) => Some(f),
            _ => None,
        }
    }

    /// A short rendering for messages and `print`: lists show their first 8 items, and the
    /// whole text stops after [`SHOW_LIMIT`] bytes with `...` (lists that share their items
    /// describe exponentially large trees in a few steps; their text must stay small).
    pub(crate) fn show(&self) -> String {
        let mut out = String::new();
        self.show_into(&mut out);
        if out.len() > SHOW_LIMIT {
            let mut end = SHOW_LIMIT;
            while !out.is_char_boundary(end) {
                end -= 1;
            }
            out.truncate(end);
            out.push_str("...");
        }
        out
    }

    /// Appends the rendering to `out`, stopping early once `out` is past [`SHOW_LIMIT`].
    fn show_into(&self, out: &mut String) {
        if out.len() > SHOW_LIMIT {
            return;
        }
        match self {
            Value::Unit => out.push_str("()"),
            Value::Int(i) => out.push_str(&i.to_string()),
            Value::Float(f) => out.push_str(&fmt_f(*f)),
            Value::Bool(b) => out.push_str(&b.to_string()),
            Value::Str(s) => {
                let mut end = s.len().min(SHOW_LIMIT + 1);
                while !s.is_char_boundary(end) {
                    end -= 1;
                }
                out.push_str(&s[..end]);
            }
            Value::Angle(a) => out.push_str(&format!("{}deg", fmt_f(a.to_degrees()))),
            Value::Vec3(v) => {
                out.push_str(&format!("[{}, {}, {}]", fmt_f(v.x), fmt_f(v.y), fmt_f(v.z)));
            }
            Value::Color(c) => {
                out.push_str(&format!(
                    "rgb({}, {}, {})",
                    fmt_f(c.x),
                    fmt_f(c.y),
                    fmt_f(c.z)
                ));
            }
            Value::List(l) => {
                out.push('[');
                for (i, v) in l.iter().take(8).enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    v.show_into(out);
                }
                out.push_str(if l.len() > 8 { ", ...]" } else { "]" });
            }
            Value::Range(r) => out.push_str(&format!("{}..{}", fmt_f(r.start), fmt_f(r.end))),
            Value::Record(r) => {
                out.push_str("{ ");
                for (i, f) in r.fields.iter().enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    out.push_str(&format!("{}: ", f.name));
                    f.value.show_into(out);
                }
                out.push_str(" }");
            }
            Value::Object(o) => out.push_str(&format!("<{}>", obj_kind(o))),
            Value::Material(m) => out.push_str(&show_material(m)),
            Value::Transform(t) => {
                out.push_str("matrix([");
                for r in 0..3 {
                    let row = t.matrix3.row(r);
                    if r > 0 {
                        out.push_str(", ");
                    }
                    out.push_str(&format!(
                        "[{}, {}, {}, {}]",
                        fmt_f(row.x),
                        fmt_f(row.y),
                        fmt_f(row.z),
                        fmt_f(t.translation[r])
                    ));
                }
                out.push_str("])");
            }
            other => out.push_str(&format!("<{}>", other.type_name())),
        }
    }
}

/// Longest text `Value::show` produces before it ends in `...`.
pub const SHOW_LIMIT: usize = 10_000;

/// A material as the `material { .. }` call that makes it (textures shown by kind).
fn show_material(m: &Mat) -> String {
    let c = m.m.color;
    let mut fields = vec![
        format!("color: rgb({}, {}, {})", fmt_f(c.x), fmt_f(c.y), fmt_f(c.z)),
        format!("ka: {}", fmt_f(m.m.ka)),
        format!("kd: {}", fmt_f(m.m.kd)),
        format!("ks: {}", fmt_f(m.m.ks)),
        format!("n: {}", fmt_f(m.m.n)),
        format!("reflect: {}", fmt_f(m.m.reflect)),
        format!("refract: {}", fmt_f(m.m.refract)),
        format!("eta: {}", fmt_f(m.m.eta)),
    ];
    if m.texture.is_some() {
        fields.push("texture: <Texture>".into());
    }
    if let Some((_, s)) = &m.bump {
        fields.push(format!("bump: <Texture>, bump_scale: {}", fmt_f(*s)));
    }
    format!("material {{ {} }}", fields.join(", "))
}

/// Kind name of an object value.
pub(crate) fn obj_kind(o: &Obj) -> &'static str {
    match &o.shape {
        ObjShape::Prim(s) => s.kind_name(),
        ObjShape::Csg(ir::CsgOp::Clip, _) => "clipped surface",
        ObjShape::Csg(..) => "csg",
        ObjShape::Group(_) => "group",
    }
}

/// Formats a float without noise: integers without a fraction, otherwise up to 6 digits.
pub(crate) fn fmt_f(f: f64) -> String {
    crate::diag::number(f)
}

/// "an `Int`", "a `Float`": a type name with its article, for messages.
pub(crate) fn a_type(t: &str) -> String {
    let vowel = t.starts_with(['A', 'E', 'I', 'O', 'U']);
    format!("{} `{t}`", if vowel { "an" } else { "a" })
}

/// Builds a record value from (name, value) pairs with `span` for every field.
pub(crate) fn record_of(fields: &[(&str, Value)], span: Span) -> Value {
    Value::Record(Rc::new(Record {
        fields: fields
            .iter()
            .map(|(k, v)| FieldVal {
                name: Sym::new(k),
                value: v.clone(),
                span,
                name_span: span,
            })
            .collect(),
    }))
}
