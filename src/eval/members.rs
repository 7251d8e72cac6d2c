//! Member access (`v.x`, `obj.bounds`, `module.item`, `record.field`) and indexing.

use std::rc::Rc;

use crate::source::Span;
use crate::syntax::ast::Name;

use super::error::{R, error, suggest};
use super::host::Host;
use super::value::Value;

/// Members each type offers (for did-you-mean).
fn members_of(v: &Value) -> Vec<&'static str> {
    match v {
        Value::Vec3(_) => vec!["x", "y", "z", "xy", "xz", "yz", "xyz", "zyx"],
        Value::Color(_) => vec!["r", "g", "b"],
        Value::Angle(_) => vec!["deg", "rad", "turn"],
        Value::Object(_) => [&["bounds"][..], &super::methods::object_methods()].concat(),
        Value::Camera(_) => vec!["eye", "center", "up"],
        Value::Material(_) => super::builtins::material_fields(),
        _ => Vec::new(),
    }
}

pub(crate) fn member(it: &mut dyn Host, v: Value, name: Name, vspan: Span) -> R<Value> {
    let n = name.sym.as_str();
    let found = match &v {
        Value::Module(m) => {
            return match m.export(name.sym) {
                Ok(b) if b.poisoned => Err(super::error::EvalError::Poisoned),
                Ok(b) => Ok(b.value),
                Err(true) => Err(error(
                    "rtc::module::private",
                    name.span,
                    format!("`{n}` is not public in module `{}`", m.name),
                )
                .with_label("private item")
                .with_help(format!("mark it `pub` in `{}`", m.name))
                .into()),
                Err(false) => {
                    let d = error(
                        "rtc::name::unknown",
                        name.span,
                        format!("no item named `{n}` in module `{}`", m.name),
                    )
                    .with_label(format!("not found in `{}`", m.name));
                    let help = suggest(n, m.export_names()).unwrap_or_else(|| {
                        format!("`{}` exports: {}", m.name, m.export_names().join(", "))
                    });
                    Err(d.with_help(help).into())
                }
            };
        }
        Value::Record(r) => {
            if let Some(x) = r.get(name.sym) {
                return Ok(x.clone());
            }
            let names: Vec<&str> = r.fields.iter().map(|f| f.name.as_str()).collect();
            let d = error(
                "rtc::field::unknown",
                name.span,
                format!("the record has no field `{n}`"),
            )
            .with_label("unknown field");
            let help = suggest(n, names.iter().copied())
                .unwrap_or_else(|| format!("its fields are: {}", names.join(", ")));
            return Err(d.with_help(help).into());
        }
        Value::Vec3(x)
            if !n.is_empty() && n.len() <= 3 && n.chars().all(|c| matches!(c, 'x' | 'y' | 'z')) =>
        {
            let comps: Vec<f64> = n
                .chars()
                .map(|c| match c {
                    'x' => x.x,
                    'y' => x.y,
                    _ => x.z,
                })
                .collect();
            Some(match comps.as_slice() {
                [a] => Value::Float(*a),
                [a, b, c] => Value::Vec3(glam::DVec3::new(*a, *b, *c)),
                _ => Value::List(Rc::new(comps.iter().map(|c| Value::Float(*c)).collect())),
            })
        }
        Value::Color(c) => match n {
            "r" => Some(Value::Float(c.x)),
            "g" => Some(Value::Float(c.y)),
            "b" => Some(Value::Float(c.z)),
            _ => None,
        },
        Value::Angle(a) => match n {
            "deg" => Some(Value::Float(a.to_degrees())),
            "rad" => Some(Value::Float(*a)),
            "turn" => Some(Value::Float(a / std::f64::consts::TAU)),
            _ => None,
        },
        Value::Object(o) => match n {
            "bounds" => Some(super::bounds::bounds_value(it, o, vspan)?),
            "material" => Some(match &o.material {
                Some(m) => Value::Material(m.clone()),
                None => {
                    return Err(error(
                        "rtc::value::no_material",
                        name.span,
                        "this object has no material yet",
                    )
                    .with_label("nothing to read")
                    .with_help("give it one with `.material(m)` first")
                    .into());
                }
            }),
            _ => None,
        },
        Value::Material(m) => material_field(m, n, name.span)?,
        Value::Camera(c) => match n {
            "eye" => Some(Value::Vec3(c.eye)),
            "center" => Some(Value::Vec3(c.center)),
            "up" => Some(Value::Vec3(c.up)),
            _ => None,
        },
        _ => None,
    };
    if let Some(x) = found {
        return Ok(x);
    }
    Err(unknown("member", &v, n, name.span, &members_of(&v)))
}

/// `m.color`, `m.ka`, ...: a material's fields read back (`None` for an unknown name).
fn material_field(m: &super::value::Mat, n: &str, span: Span) -> R<Option<Value>> {
    let absent = |what: &str| -> R<Option<Value>> {
        Err(error(
            "rtc::value::no_material",
            span,
            format!("this material has no {what}"),
        )
        .with_label("nothing to read")
        .with_help(format!("set one with `m with {{ {n}: ... }}` first"))
        .into())
    };
    Ok(Some(match n {
        "color" => Value::Color(m.m.color),
        "ka" => Value::Float(m.m.ka),
        "kd" => Value::Float(m.m.kd),
        "ks" => Value::Float(m.m.ks),
        "n" => Value::Float(m.m.n),
        "reflect" => Value::Float(m.m.reflect),
        "refract" => Value::Float(m.m.refract),
        "eta" => Value::Float(m.m.eta),
        "gloss" => Value::Float(m.m.gloss),
        "gloss_samples" => Value::Int(i64::from(m.m.gloss_samples)),
        "filter" => Value::Float(m.m.filter),
        "absorption" => Value::Color(m.m.absorption),
        "fresnel" => Value::Bool(m.m.fresnel),
        "conserve_energy" => Value::Bool(m.m.conserve_energy),
        "metallic" => Value::Float(m.m.metallic),
        "brilliance" => Value::Float(m.m.brilliance),
        "emission" => Value::Color(m.m.emission),
        "emission_sides" => Value::Int(if m.m.emits_both_sides { 2 } else { 1 }),
        "texture" => match &m.texture {
            Some(t) => Value::Texture(t.clone()),
            None => return absent("texture"),
        },
        "bump" => match &m.bump {
            Some((t, _)) => Value::Texture(t.clone()),
            None => return absent("bump texture"),
        },
        "bump_scale" => Value::Float(m.bump.as_ref().map_or(1.0, |b| b.1)),
        "shading" => match m.m.shading {
            Some(s) => Value::Shading(s),
            None => return absent("shading model of its own"),
        },
        _ => return Ok(None),
    }))
}

/// The error for `v.n` when `v` has no member (or method, by `what`) called `n`: did-you-mean,
/// else the list of what it does have.
pub(crate) fn unknown(
    what: &str,
    v: &Value,
    n: &str,
    span: Span,
    known: &[&str],
) -> super::error::EvalError {
    let a_type = super::value::a_type(v.type_name());
    let d = error(
        "rtc::field::unknown",
        span,
        format!("{a_type} has no {what} `{n}`"),
    )
    .with_label(format!("unknown {what}"));
    let help = suggest(n, known.iter().copied()).unwrap_or_else(|| {
        if known.is_empty() {
            format!("{a_type} has no {what}s")
        } else {
            format!("its {what}s are: {}", known.join(", "))
        }
    });
    d.with_help(help).into()
}

/// `v[i]`; `from_vec3`: the index is the variable of a `for` over a `Vec3` (for the help).
pub(crate) fn index(v: Value, i: Value, (ispan, from_vec3): (Span, bool)) -> R<Value> {
    let Value::Int(k) = i else {
        let help = match i {
            // `for i in [0, 2, 4]`: three plain numbers are a `Vec3`, whose elements are Floats.
            Value::Float(f) if f == f.trunc() && from_vec3 => {
                "three numbers in brackets (`[0, 2, 4]`) make a `Vec3`, whose elements are Floats; write `[0, 2, 4,]` (with a trailing comma) for a `List` of Ints, or use `int(...)`"
            }
            // `0..n / 2` gives Float elements: `/` always divides exactly.
            Value::Float(f) if f == f.trunc() => {
                "`/` always gives a `Float`; divide with `div` for an `Int` (`n div 2`), or use `int(...)`"
            }
            _ => "use `round(...)` or `floor(...)` to get an `Int`",
        };
        return Err(error(
            "rtc::type::mismatch",
            ispan,
            format!("expected `Int`, found `{}`", i.type_name()),
        )
        .with_label("an index must be an integer")
        .with_help(help)
        .into());
    };
    let len = match &v {
        Value::List(l) => l.len(),
        Value::Vec3(_) => 3,
        other => {
            return Err(error(
                "rtc::type::mismatch",
                ispan,
                format!(
                    "{} cannot be indexed",
                    super::value::a_type(other.type_name())
                ),
            )
            .with_label("indexed here")
            .with_help("only lists and vectors can be indexed")
            .into());
        }
    };
    if k < 0 || k as usize >= len {
        return Err(error(
            "rtc::value::index",
            ispan,
            format!("index {k} is out of range for {len} elements"),
        )
        .with_label(format!("evaluates to {k}"))
        .with_help(if len == 0 {
            "the list is empty".to_owned()
        } else {
            format!("use an index from 0 to {}", len - 1)
        })
        .into());
    }
    Ok(match v {
        Value::List(l) => l[k as usize].clone(),
        Value::Vec3(x) => Value::Float(x[k as usize]),
        _ => unreachable!("checked above"),
    })
}
