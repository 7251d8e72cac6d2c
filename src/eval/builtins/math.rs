//! Math built-ins: trig on `Angle`, scalar functions, vector helpers, conversions, `print`, `assert`.

use crate::num::Norm;
use std::rc::Rc;

use glam::DVec3;

use crate::diag::{Diagnostic, Severity};
use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::{R, error};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::types;
use crate::eval::value::Value;

/// Math functions by name.
pub const FNS: &[(&str, BuiltinFn)] = &[
    ("sin", sin),
    ("cos", cos),
    ("tan", tan),
    ("asin", asin),
    ("acos", acos),
    ("atan", atan),
    ("atan2", atan2),
    ("sqrt", sqrt),
    ("abs", abs),
    ("floor", floor),
    ("ceil", ceil),
    ("round", round),
    ("exp", exp),
    ("ln", ln),
    ("pow", pow),
    ("min", min),
    ("max", max),
    ("dot", dot),
    ("cross", cross),
    ("normalize", normalize),
    ("length", length),
    ("distance", distance),
    ("float", float),
    ("int", int),
    ("str", str_),
    ("print", print),
    ("assert", assert),
];

/// Constants: axes and circle numbers.
pub fn constants() -> Vec<(&'static str, Value)> {
    vec![
        ("X", Value::Vec3(DVec3::X)),
        ("Y", Value::Vec3(DVec3::Y)),
        ("Z", Value::Vec3(DVec3::Z)),
        ("pi", Value::Float(std::f64::consts::PI)),
        ("tau", Value::Float(std::f64::consts::TAU)),
    ]
}

fn one(it: &dyn Host, site: CallSite, args: Vec<ArgVal>) -> R<(f64, crate::source::Span)> {
    let mut p = Params::new(site, &["x"], args)?;
    p.num(it, "x")
}

fn one_angle(it: &dyn Host, site: CallSite, args: Vec<ArgVal>) -> R<f64> {
    let mut p = Params::new(site, &["angle"], args)?;
    let (v, s) = p.req("angle")?;
    types::angle(it, &v, s)
}

fn sin(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(libm::sin(one_angle(it, s, a)?)))
}
fn cos(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(libm::cos(one_angle(it, s, a)?)))
}
fn tan(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(libm::tan(one_angle(it, s, a)?)))
}

/// A domain check that names the function: "`sqrt(x)` needs `x` >= 0, but `x` is -1".
fn domain(s: CallSite, ok: bool, rule: &str, x: f64, sp: crate::source::Span) -> R<()> {
    if ok {
        return Ok(());
    }
    let shown = crate::eval::value::fmt_f(x);
    Err(error(
        "rtc::param::out_of_range",
        sp,
        format!("`{}(x)` needs `x` {rule}, but `x` is {shown}", s.name),
    )
    .with_label(format!("evaluates to {shown}"))
    .with_help(format!("pass `{}` a value that is {rule}", s.name))
    .into())
}

/// A result that overflowed to infinity (or is NaN): stopped at the call, not in geometry.
fn finite(s: CallSite, x: f64, v: f64) -> R<Value> {
    if v.is_finite() {
        return Ok(Value::Float(v));
    }
    Err(error(
        "rtc::value::nan",
        s.span,
        format!("`{}` has no finite result here", s.name),
    )
    .with_label(format!(
        "{}({}) is too large for a number",
        s.name,
        crate::eval::value::fmt_f(x)
    ))
    .with_help("keep results below about 1.8e308, e.g. `exp(x)` needs x < 709")
    .into())
}

fn unit_arg(it: &dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<f64> {
    let (x, sp) = one(it, s, a)?;
    domain(s, (-1.0..=1.0).contains(&x), "in [-1, 1]", x, sp)?;
    Ok(x)
}
fn asin(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Angle(libm::asin(unit_arg(it, s, a)?)))
}
fn acos(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Angle(libm::acos(unit_arg(it, s, a)?)))
}
fn atan(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Angle(libm::atan(one(it, s, a)?.0)))
}
fn atan2(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["y", "x"], a)?;
    let (y, _) = p.num(it, "y")?;
    let (x, _) = p.num(it, "x")?;
    Ok(Value::Angle(libm::atan2(y, x)))
}
fn sqrt(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a)?;
    domain(s, x >= 0.0, ">= 0", x, sp)?;
    Ok(Value::Float(x.sqrt()))
}
fn abs(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["x"], a)?;
    let (v, sp) = p.req("x")?;
    Ok(match v {
        Value::Int(i) => Value::Int(i.saturating_abs()),
        Value::Angle(x) => Value::Angle(x.abs()),
        other => Value::Float(types::num(it, &other, sp)?.abs()),
    })
}
fn to_int(x: f64, sp: crate::source::Span) -> R<Value> {
    if !x.is_finite() || x.abs() > 9.0e18 {
        return Err(error(
            "rtc::value::overflow",
            sp,
            "number does not fit in an `Int`",
        )
        .with_label(format!("evaluates to {x}"))
        .with_help("keep integers below 9e18")
        .into());
    }
    Ok(Value::Int(x as i64))
}
fn floor(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a)?;
    to_int(x.floor(), sp)
}
fn ceil(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a)?;
    to_int(x.ceil(), sp)
}
fn round(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a)?;
    to_int(x.round(), sp)
}
fn exp(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let x = one(it, s, a)?.0;
    finite(s, x, libm::exp(x))
}
fn ln(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a)?;
    domain(s, x > 0.0, "> 0", x, sp)?;
    Ok(Value::Float(libm::log(x)))
}
fn pow(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["base", "exponent"], a)?;
    let (b, _) = p.num(it, "base")?;
    let (e, sp) = p.num(it, "exponent")?;
    let v = libm::pow(b, e);
    if !v.is_finite() {
        return Err(
            error("rtc::value::nan", sp, "`pow` has no finite result here")
                .with_label(format!("{b} to the power {e}"))
                .with_help("use a non-negative base for fractional exponents")
                .into(),
        );
    }
    Ok(Value::Float(v))
}

fn min_max(it: &dyn Host, s: CallSite, a: Vec<ArgVal>, want_min: bool) -> R<Value> {
    // `max(xs)` of an empty list: say so, at the list.
    if let [one] = a.as_slice()
        && super::lists::items(&one.value).is_some_and(|l| l.is_empty())
    {
        return Err(error(
            "rtc::value::empty",
            one.span,
            format!("`{}` of an empty list has no value", s.name),
        )
        .with_label("this list is empty")
        .with_help(format!(
            "give `{}` a list with at least one element, or check `len(...) > 0` first (`if len(xs) > 0 {{ {}(xs) }} else {{ 0 }}`)",
            s.name, s.name
        ))
        .into());
    }
    let items: Vec<(Value, crate::source::Span)> = match a.as_slice() {
        [one] => match super::lists::items(&one.value) {
            Some(l) => l.iter().map(|v| (v.clone(), one.span)).collect(),
            None => vec![(one.value.clone(), one.span)],
        },
        _ => a.into_iter().map(|x| (x.value, x.span)).collect(),
    };
    let mut best: Option<Value> = None;
    for (v, sp) in items {
        let key = match &v {
            Value::Angle(x) => *x,
            other => types::num(it, other, sp)?,
        };
        let better = match &best {
            None => true,
            Some(b) => {
                let bk = match b {
                    Value::Angle(x) => *x,
                    o => o.as_f64().unwrap_or(0.0),
                };
                if want_min { key < bk } else { key > bk }
            }
        };
        if better {
            best = Some(v);
        }
    }
    best.ok_or_else(|| {
        error(
            "rtc::arg::missing",
            s.span,
            format!("`{}` needs at least one value", s.name),
        )
        .with_label("nothing to compare")
        .with_help(format!("write `{}(a, b)`", s.name))
        .into()
    })
}
fn min(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    min_max(it, s, a, true)
}
fn max(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    min_max(it, s, a, false)
}

fn two_vecs(it: &dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<(DVec3, DVec3)> {
    let mut p = Params::new(s, &["a", "b"], a)?;
    Ok((p.vec3(it, "a")?.0, p.vec3(it, "b")?.0))
}
fn dot(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, y) = two_vecs(it, s, a)?;
    Ok(Value::Float(x.dot(y)))
}
fn cross(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, y) = two_vecs(it, s, a)?;
    Ok(Value::Vec3(x.cross(y)))
}
fn distance(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, y) = two_vecs(it, s, a)?;
    Ok(Value::Float(x.distance_to(y)))
}
fn length(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["v"], a)?;
    Ok(Value::Float(p.vec3(it, "v")?.0.norm()))
}
fn normalize(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["v"], a)?;
    let (v, sp) = p.vec3(it, "v")?;
    if v.length_squared() == 0.0 || !v.is_finite() {
        return Err(
            error("rtc::value::nan", sp, "cannot normalize a zero vector")
                .with_label("this vector has length 0")
                .with_help("check the vector is not `[0, 0, 0]` before normalizing")
                .into(),
        );
    }
    Ok(Value::Vec3(v.unit()))
}
fn float(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(one(it, s, a)?.0))
}
fn int(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a)?;
    to_int(x.trunc(), sp)
}
fn str_(_: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["value"], a)?;
    let (v, _) = p.req("value")?;
    Ok(match v {
        Value::Str(_) => v,
        _ => Value::Str(Rc::from(v.show())),
    })
}

fn print(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let text: Vec<String> = a.iter().map(|x| x.value.show()).collect();
    it.report(Diagnostic::new(
        Severity::Note,
        "rtc::print",
        Some(s.span),
        text.join(" "),
    ));
    Ok(Value::Unit)
}

fn assert(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["condition", "message"], a)?;
    let (c, sp) = p.req("condition")?;
    let ok = types::boolean(it, &c, sp)?;
    if ok {
        return Ok(Value::Unit);
    }
    let msg = match p.get("message") {
        Some((m, ms)) => types::string(it, &m, ms)?.to_string(),
        None => format!("`{}` is false", it.snippet(sp).trim()),
    };
    Err(error(
        "rtc::assert::failed",
        sp,
        format!("assertion failed: {msg}"),
    )
    .with_label("this condition is false")
    .with_help("fix the values it checks, or the assertion")
    .into())
}
