//! Materials made of materials: `material_map` (a pattern picks or blends whole materials) and
//! `layers` (materials over one another, seen through their colour maps' filter and transmit).

use std::rc::Rc;

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::{EvalError, R, error};
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Lit, Param, Sig, Ty};
use crate::eval::types;
use crate::eval::value::{Mat, MatMix, Tex, Value};
use crate::ir;
use crate::source::Span;

/// The mix constructors with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&MATERIAL_MAP, material_map), (&LAYERS, layers)];

/// Most parts one mix may have (a budget: each part is resolved at every hit that reads it).
pub(crate) const MAX_PARTS: usize = 256;

/// `material_map(pattern, stops, blend)`.
static MATERIAL_MAP: Sig = Sig::new(
    "material_map",
    Group::Look,
    "A material that changes with a pattern's value: the stops `[at, material]` around the value \
     are blended (every field, linearly) or, with `blend: false`, the one below holds.",
    &[
        Param::new("pattern", Ty::Texture, "a pattern (its colour map is not used)"),
        Param::new("stops", Ty::List, "`[at, material]` pairs").checked_by_builtin(),
        Param::new("blend", Ty::Bool, "interpolate between stops (else switch)")
            .or(Lit::Bool(true)),
    ],
    "Material",
)
.examples(&["material_map(pattern: gradient(axis: Y), stops: [[0, material { color: rgb(0.8, 0.1, 0.1) }], [1, material { reflect: 0.9 }]])"]);
fn material_map(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &MATERIAL_MAP, a)?;
    let (pv, ps) = p.req("pattern")?;
    let pattern = match pv {
        Value::Texture(t) if matches!(t.t, ir::Texture::Pattern(_)) => t,
        Value::Texture(t) => pattern_texture(it, &t, ps)?,
        other => return Err(types::mismatch(it, "Texture", &other, ps).into()),
    };
    let (sv, ss) = p.req("stops")?;
    let Value::List(items) = sv else {
        return Err(types::mismatch(it, "List", &sv, ss).into());
    };
    parts_budget(items.len(), ss)?;
    let mut stops = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let stop = match item {
            Value::List(pair) => match pair.as_slice() {
                [at, Value::Material(m)] => at
                    .as_f64()
                    .filter(|x| x.is_finite())
                    .map(|at| (at, m.clone())),
                _ => None,
            },
            _ => None,
        };
        let Some(stop) = stop else {
            return Err(error(
                "rtc::material::stop",
                ss,
                format!("entry {} of the material map is not `[at, material]`", i + 1),
            )
            .with_label("in this list")
            .with_help("write stops as `[position, material]`, e.g. `[[0, material { color: rgb(1, 0, 0) }], [1, material { reflect: 0.9 }]]`")
            .into());
        };
        stops.push(stop);
    }
    stops.sort_by(|a, b| a.0.total_cmp(&b.0));
    let blend = p.bool(it, "blend")?;
    Ok(mixed(
        it,
        s.span,
        MatMix::Map {
            pattern,
            stops,
            blend,
        },
    ))
}

/// A checker or stripes texture as the pattern it is (an image has no pattern value).
fn pattern_texture(it: &mut dyn Host, t: &Tex, span: Span) -> R<Rc<Tex>> {
    if matches!(t.t, ir::Texture::Image { .. }) {
        return Err(error(
            "rtc::material::pattern",
            span,
            "an image has no pattern value to pick materials by",
        )
        .with_label("an image texture")
        .with_help("use a pattern such as `gradient(axis: Y)` or `checker()`")
        .into());
    }
    match crate::eval::texture_methods::transformed(it, t, glam::DAffine3::IDENTITY, span)? {
        Value::Texture(t) => Ok(t),
        _ => unreachable!("a texture's transform is a texture"),
    }
}

/// Refuses more than [`MAX_PARTS`] parts and fewer than one.
fn parts_budget(n: usize, span: Span) -> R<()> {
    if (1..=MAX_PARTS).contains(&n) {
        return Ok(());
    }
    let e: EvalError = error(
        "rtc::material::parts",
        span,
        format!("a mixed material needs 1 to {MAX_PARTS} materials, not {n}"),
    )
    .with_label("this list")
    .with_help("give at least one material; nest mixes for more than the budget")
    .into();
    Err(e)
}

/// `layers(materials)`.
static LAYERS: Sig = Sig::new(
    "layers",
    Group::Look,
    "Materials over one another, top first: each shows its colour where its colour map covers \
     and lets the layers below show through its filter and transmit.",
    &[Param::new("materials", Ty::ListOf(&Ty::Material), "the layers, top first")],
    "Material",
)
.examples(&["layers([material { texture: bozo().colors([{ at: 0, color: rgb(1, 1, 1), transmit: 1 }, [1, rgb(0.3, 0.2, 0.1)]]) }, material { color: rgb(0.2, 0.5, 0.2) }])"]);
fn layers(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &LAYERS, a)?;
    let (v, span) = p.req("materials")?;
    let Value::List(items) = v else {
        return Err(types::mismatch(it, "List", &v, span).into());
    };
    parts_budget(items.len(), span)?;
    let mut mats = Vec::with_capacity(items.len());
    for item in items.iter() {
        match item {
            Value::Material(m) => mats.push(m.clone()),
            other => return Err(types::mismatch(it, "Material", other, span).into()),
        }
    }
    Ok(mixed(it, s.span, MatMix::Layers(mats)))
}

/// The material value of `mix`: its fields are its first part's (what code that reads a
/// material without a hit, such as shadow rays through glass, sees).
fn mixed(it: &mut dyn Host, span: Span, mix: MatMix) -> Value {
    let first = match &mix {
        MatMix::Map { stops, .. } => stops[0].1.clone(),
        MatMix::Layers(layers) => layers[0].clone(),
    };
    Value::Material(Rc::new(Mat {
        m: ir::Material {
            span,
            ..first.m.clone()
        },
        texture: first.texture.clone(),
        bump: first.bump.clone(),
        mix: Some(Rc::new(mix)),
        made: it.next_made(),
    }))
}
