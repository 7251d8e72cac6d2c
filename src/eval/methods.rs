//! Method calls: transforms, `.material(m)` and the visibility flags on objects, transform chaining, applying a
//! transform to a point or vector, RNG draws, list methods and vector methods.

use std::rc::Rc;

use crate::source::Span;
use crate::syntax::ast::Name;

use super::args::{ArgVal, CallSite, Params};
use super::builtins as b;
use super::error::R;
use super::host::Host;
use super::motion::{LOOK_AT_METHOD, MOVING};
use super::schema::{Group, Param, Sig, Ty};
use super::transform::is_method as is_transform;
use super::types;
use super::value::{Obj, Value};

/// The methods of each receiver type with their schemas, in the order messages list them. A
/// list or vector method that is also a function (`l.sum()` is `sum(l)`) has the function's
/// schema, its receiver the first parameter.
pub(crate) static RECEIVERS: &[(&str, &[&[&Sig]])] = &[
    (
        "Object",
        &[
            TRANSFORMS,
            &[&MATERIAL, &MOVING, &LOOK_AT_METHOD],
            super::visibility::METHODS,
            super::modifiers::METHODS,
        ],
    ),
    ("Transform", &[TRANSFORMS, &[&POINT, &VECTOR]]),
    ("Texture", &[TRANSFORMS, super::texture_methods::METHODS]),
    ("Rng", &[super::rng::METHODS]),
    ("List", &[&[&MAP, &FILTER], LIST_FUNCTIONS]),
    (
        "Vec3",
        &[&[&MAP, &FILTER], LIST_FUNCTIONS, VEC_FUNCTIONS, TRANSFORMS],
    ),
];

/// The transform methods of objects, transforms and vectors.
const TRANSFORMS: &[&Sig] = super::transform::METHODS;

/// List functions that are also methods of lists and vectors (`l.sum()` is `sum(l)`).
const LIST_FUNCTIONS: &[&Sig] = &[
    &b::lists::LEN,
    &b::lists::SUM,
    &b::MIN,
    &b::MAX,
    &b::lists::FLATTEN,
    &b::lists::REVERSE,
    &b::lists::ZIP,
    &b::lists::ENUMERATE,
    &b::lists::ANY,
    &b::lists::ALL,
    &b::lists::REDUCE,
];

/// The names of the methods of values of type `receiver`, in order.
fn names(receiver: &str) -> Vec<&'static str> {
    RECEIVERS
        .iter()
        .filter(|(r, _)| *r == receiver)
        .flat_map(|(_, tables)| tables.iter().flat_map(|t| t.iter().map(|m| m.name)))
        .collect()
}

/// Whether `n` is in a method table.
fn has(table: &[&Sig], n: &str) -> bool {
    table.iter().any(|m| m.name == n)
}

/// `recv.name(args)`.
pub(crate) fn call_method(
    it: &mut dyn Host,
    recv: Value,
    name: Name,
    args: Vec<ArgVal>,
    span: Span,
) -> R<Value> {
    let n = name.sym.as_str();
    let site = CallSite { span, name: n };
    // `.material(m)`, the commonest method of loops that make many objects, before the scan of
    // the transform methods' names (it is not one of them).
    let recv = match recv {
        Value::Object(o) if n == "material" => return set_material(it, o, site, args),
        other => other,
    };
    let is_t = is_transform(n);
    // The receiver is owned: a temporary object (`sphere(..).translate(..)`) is updated in
    // place, and only a shared one is copied.
    let recv = match recv {
        Value::Object(mut o) if is_t => {
            let t = super::transform::method_transform(it, n, site, args)?;
            let o2 = Rc::make_mut(&mut o);
            o2.transform = t * o2.transform;
            o2.motion = o2.motion.map(|m| m.transformed(t));
            o2.origin = it.derive(o2.origin);
            return Ok(Value::Object(o));
        }
        Value::Object(o) if n == "moving" => {
            return super::motion::moving(it, o, site, args);
        }
        Value::Object(o) if super::visibility::is_method(n) => {
            return super::visibility::hide(o, site, args);
        }
        Value::Object(o) if super::modifiers::is_method(n) => {
            return super::modifiers::modify(it, o, site, args);
        }
        Value::Object(mut o) if n == "look_at" => {
            let (to, up, ts) = super::motion::look_at_method(it, site, args)?;
            let t = super::motion::look_at_about(o.transform.translation, to, up, ts)?;
            let o2 = Rc::make_mut(&mut o);
            o2.transform = t * o2.transform;
            o2.motion = o2.motion.map(|m| m.transformed(t));
            o2.origin = it.derive(o2.origin);
            return Ok(Value::Object(o));
        }
        other => other,
    };
    match &recv {
        Value::Transform(a) if is_t => {
            let t = super::transform::method_transform(it, n, site, args)?;
            return Ok(Value::Transform(Rc::new(t * **a)));
        }
        Value::Texture(t) if is_t => {
            let m = super::transform::method_transform(it, n, site, args)?;
            return super::texture_methods::transformed(it, t, m, span);
        }
        Value::Texture(t) if super::texture_methods::is_method(n) => {
            let t = t.clone();
            return super::texture_methods::call(it, t, site, args);
        }
        Value::Rng(seed) if has(super::rng::METHODS, n) => {
            return super::rng::method(it, *seed, n, site, args);
        }
        Value::List(_) | Value::Vec3(_) if n == "map" || n == "filter" => {
            return map_filter(it, &recv, n == "map", site, args);
        }
        Value::List(_) | Value::Vec3(_) if has(LIST_FUNCTIONS, n) => {
            return with_receiver(it, recv, name, args, span);
        }
        Value::Vec3(v) if is_t => {
            // A point: `p.rotate(y: 90deg)` is where `rotate(y: 90deg)` takes the point `p`.
            let t = super::transform::method_transform(it, n, site, args)?;
            return Ok(Value::Vec3(t.transform_point3(*v)));
        }
        Value::Vec3(_) if has(VEC_FUNCTIONS, n) => {
            return with_receiver(it, recv, name, args, span);
        }
        Value::Transform(t) if n == "point" || n == "vector" => {
            let mut p = Params::new(site, if n == "point" { &POINT } else { &VECTOR }, args)?;
            let (v, _) = p.vec3(it, "v")?;
            return Ok(Value::Vec3(if n == "point" {
                t.transform_point3(v)
            } else {
                t.transform_vector3(v)
            }));
        }
        _ => {}
    }
    if n == "moving" && recv.type_name() == "Light" {
        return Err(super::error::error(
            "rtc::motion::light",
            name.span,
            "lights cannot move within a frame: there is no motion blur of lights",
        )
        .with_label("only objects and the camera have `.moving`")
        .with_help("move the light from frame to frame instead: compute its position from `time` (§28.1), e.g. `position: [2 + time, 5, 5]`")
        .into());
    }
    let known: Vec<&str> = match &recv {
        Value::Object(_)
        | Value::Transform(_)
        | Value::Texture(_)
        | Value::Rng(_)
        | Value::List(_)
        | Value::Vec3(_) => names(recv.type_name()),
        _ => Vec::new(),
    };
    Err(super::members::unknown(
        "method", &recv, n, name.span, &known,
    ))
}

/// `.material(m)`'s parameter.
static MATERIAL: Sig = Sig::new(
    "material",
    Group::Method,
    "The object with its own material (a group's members without one take it).",
    &[Param::new("material", Ty::Material, "the material")],
    "Object",
)
.examples(&["sphere().material(material { color: rgb(0.8, 0.1, 0.1) })"]);

/// `obj.material(m)`: the object with its own material.
fn set_material(it: &mut dyn Host, mut o: Rc<Obj>, site: CallSite, args: Vec<ArgVal>) -> R<Value> {
    let m = match args.as_slice() {
        // One material, positional or `material:`: what the schema below accepts, matched
        // without it (a loop of a million spheres calls this once per sphere).
        [
            ArgVal {
                name,
                value: Value::Material(m),
                ..
            },
        ] if name.is_none_or(|n| n.sym.as_str() == "material") => {
            let m = m.clone();
            super::args::recycle_args(args);
            m
        }
        _ => {
            let mut p = Params::new(site, &MATERIAL, args)?;
            let (m, ms) = p.req("material")?;
            let Value::Material(m) = m else {
                return Err(types::mismatch(it, "Material", &m, ms).into());
            };
            m
        }
    };
    let o2 = Rc::make_mut(&mut o);
    o2.material = Some(m);
    o2.origin = it.derive(o2.origin);
    Ok(Value::Object(o))
}

/// Vector functions that are also methods of vectors (`v.dot(w)` is `dot(v, w)`).
const VEC_FUNCTIONS: &[&Sig] = &[&b::LENGTH, &b::NORMALIZE, &b::DOT, &b::CROSS, &b::DISTANCE];

/// `t.point(p)`.
static POINT: Sig = Sig::new(
    "point",
    Group::Method,
    "Where the transform takes the point `v`.",
    &[Param::new("v", Ty::Vec3, "a point")],
    "Vec3",
)
.examples(&["rotate(y: 90deg).point(v: [1, 0, 0])"]);

/// `t.vector(v)`.
static VECTOR: Sig = Sig::new(
    "vector",
    Group::Method,
    "The direction `v` mapped by the transform (without its translation).",
    &[Param::new("v", Ty::Vec3, "a direction")],
    "Vec3",
)
.examples(&["translate([1, 2, 3]).vector(v: [1, 0, 0])"]);

/// `recv.f(args)` as the built-in `f(recv, args)`.
fn with_receiver(
    it: &mut dyn Host,
    recv: Value,
    name: Name,
    mut args: Vec<ArgVal>,
    span: Span,
) -> R<Value> {
    let f = super::builtins::global(name.sym).expect("list and vector methods are built-ins");
    args.insert(
        0,
        ArgVal {
            name: None,
            value: recv,
            span,
        },
    );
    it.call_value(f, args, span, name.span)
}

/// `l.map(f)` and `l.filter(f)` on a list or a vector. Mapping a vector to numbers gives a
/// vector again; otherwise the result is a list.
fn map_filter(
    it: &mut dyn Host,
    recv: &Value,
    map: bool,
    site: CallSite,
    args: Vec<ArgVal>,
) -> R<Value> {
    let mut p = Params::new(site, if map { &MAP } else { &FILTER }, args)?;
    let (f, fs) = p.req("f")?;
    if !matches!(f, Value::Fn(_) | Value::Builtin(_)) {
        return Err(types::mismatch(it, "Fn", &f, fs).into());
    }
    let items = super::builtins::lists::items(recv).expect("a list or a vector");
    let mut out = Vec::with_capacity(items.len());
    for x in items.iter() {
        let r = super::builtins::lists::call(it, &f, std::slice::from_ref(x), fs, site.span)?;
        if map {
            out.push(r);
        } else if types::boolean(it, &r, fs)? {
            out.push(x.clone());
        }
    }
    if let (true, Value::Vec3(_), [a, b, c]) = (map, recv, out.as_slice())
        && let (Some(x), Some(y), Some(z)) = (a.as_f64(), b.as_f64(), c.as_f64())
    {
        return Ok(Value::Vec3(glam::DVec3::new(x, y, z)));
    }
    Ok(Value::List(Rc::new(out)))
}

/// `l.map(f)`.
static MAP: Sig = Sig::new(
    "map",
    Group::Method,
    "`f` of each element (of a vector mapped to numbers, a vector).",
    &[Param::new("f", Ty::Fn, "what to make of an element")],
    "List or Vec3",
)
.examples(&["[1, 2, 3].map(f: fn(x) x * 2)"]);

/// `l.filter(f)`.
static FILTER: Sig = Sig::new(
    "filter",
    Group::Method,
    "The elements for which `f` is true.",
    &[Param::new("f", Ty::Fn, "whether to keep an element")],
    "List",
)
.examples(&["[1, 2, 3].filter(f: fn(x) x > 1)"]);

/// Methods of objects: every transform method, plus `material`, `moving` and `look_at`.
pub(crate) fn object_methods() -> Vec<&'static str> {
    names("Object")
}
