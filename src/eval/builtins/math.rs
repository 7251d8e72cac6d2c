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
use crate::eval::schema::{Group, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;

/// Math functions with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&SIN, sin),
    (&COS, cos),
    (&TAN, tan),
    (&ASIN, asin),
    (&ACOS, acos),
    (&ATAN, atan),
    (&ATAN2, atan2),
    (&SQRT, sqrt),
    (&ABS, abs),
    (&FLOOR, floor),
    (&CEIL, ceil),
    (&ROUND, round),
    (&EXP, exp),
    (&LN, ln),
    (&POW, pow),
    (&MIN, min),
    (&MAX, max),
    (&DOT, dot),
    (&CROSS, cross),
    (&NORMALIZE, normalize),
    (&LENGTH, length),
    (&DISTANCE, distance),
    (&FLOAT, float),
    (&INT, int),
    (&STR, str_),
    (&PRINT, print),
    (&ASSERT, assert),
];

/// The one parameter of most number functions.
const X: Param = Param::new("x", Ty::Float, "a number");
/// The parameter of the trigonometric functions.
const ANGLE: &[Param] = &[Param::new("angle", Ty::Angle, "an angle").unit(Unit::Angle)];
/// `dot`, `cross`, `distance`.
const TWO_VECS: &[Param] = &[
    Param::new("a", Ty::Vec3, "the first vector"),
    Param::new("b", Ty::Vec3, "the second vector"),
];
/// `length`, `normalize`.
const ONE_VEC: &[Param] = &[Param::new("v", Ty::Vec3, "a vector")];
/// `min`, `max`.
const VALUES: &[Param] = &[Param::new(
    "values",
    Ty::OneOf(&[Ty::Float, Ty::Angle, Ty::List]),
    "numbers or angles, or one list (or `Vec3`) of them",
)];

/// Constants: axes and circle numbers.
pub(crate) fn constants() -> Vec<(&'static str, Value)> {
    vec![
        ("X", Value::Vec3(DVec3::X)),
        ("Y", Value::Vec3(DVec3::Y)),
        ("Z", Value::Vec3(DVec3::Z)),
        ("pi", Value::Float(std::f64::consts::PI)),
        ("tau", Value::Float(std::f64::consts::TAU)),
    ]
}

/// The number argument `x` of a one-number function, checked by its schema.
fn one(
    it: &dyn Host,
    site: CallSite,
    args: Vec<ArgVal>,
    sig: &'static Sig,
) -> R<(f64, crate::source::Span)> {
    let mut p = Params::new(site, sig, args)?;
    p.float(it, "x")
}

fn one_angle(it: &dyn Host, site: CallSite, args: Vec<ArgVal>, sig: &'static Sig) -> R<f64> {
    let mut p = Params::new(site, sig, args)?;
    Ok(p.angle(it, "angle")?.0)
}

/// `sin(angle)`.
static SIN: Sig =
    Sig::new("sin", Group::Math, "The sine of an angle.", ANGLE, "Float").examples(&["sin(30deg)"]);
fn sin(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(libm::sin(one_angle(it, s, a, &SIN)?)))
}
/// `cos(angle)`.
static COS: Sig = Sig::new(
    "cos",
    Group::Math,
    "The cosine of an angle.",
    ANGLE,
    "Float",
)
.examples(&["cos(angle: 60deg)"]);
fn cos(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(libm::cos(one_angle(it, s, a, &COS)?)))
}
/// `tan(angle)`.
static TAN: Sig = Sig::new(
    "tan",
    Group::Math,
    "The tangent of an angle.",
    ANGLE,
    "Float",
)
.examples(&["tan(45deg)"]);
fn tan(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(libm::tan(one_angle(it, s, a, &TAN)?)))
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

/// The parameter of `asin` and `acos`: a sine or cosine.
const UNIT_X: &[Param] = &[X.range(Range::SignedUnit)];
/// `asin(x)`.
static ASIN: Sig = Sig::new(
    "asin",
    Group::Math,
    "The angle whose sine is `x`.",
    UNIT_X,
    "Angle",
)
.domain()
.examples(&["asin(0.5)"]);
fn asin(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Angle(libm::asin(one(it, s, a, &ASIN)?.0)))
}
/// `acos(x)`.
static ACOS: Sig = Sig::new(
    "acos",
    Group::Math,
    "The angle whose cosine is `x`.",
    UNIT_X,
    "Angle",
)
.domain()
.examples(&["acos(x: 0.5)"]);
fn acos(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Angle(libm::acos(one(it, s, a, &ACOS)?.0)))
}
/// `atan(x)`.
static ATAN: Sig = Sig::new(
    "atan",
    Group::Math,
    "The angle whose tangent is `x`.",
    &[X],
    "Angle",
)
.examples(&["atan(1)"]);
fn atan(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Angle(libm::atan(one(it, s, a, &ATAN)?.0)))
}
/// `atan2(y, x)`.
static ATAN2: Sig = Sig::new(
    "atan2",
    Group::Math,
    "The angle of the point `(x, y)`, in (-180deg, 180deg].",
    &[
        Param::new("y", Ty::Float, "the y coordinate"),
        Param::new("x", Ty::Float, "the x coordinate"),
    ],
    "Angle",
)
.examples(&["atan2(y: 1, x: -1)"]);
fn atan2(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ATAN2, a)?;
    let (y, _) = p.float(it, "y")?;
    let (x, _) = p.float(it, "x")?;
    Ok(Value::Angle(libm::atan2(y, x)))
}
/// `sqrt(x)`.
static SQRT: Sig = Sig::new(
    "sqrt",
    Group::Math,
    "The square root.",
    &[X.range(Range::NonNegative)],
    "Float",
)
.domain()
.examples(&["sqrt(2)"]);
fn sqrt(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, _) = one(it, s, a, &SQRT)?;
    Ok(Value::Float(x.sqrt()))
}
/// `abs(x)`.
static ABS: Sig = Sig::new(
    "abs",
    Group::Math,
    "The absolute value, of the type it is given.",
    &[Param::new(
        "x",
        Ty::OneOf(&[Ty::Int, Ty::Float, Ty::Angle]),
        "a number or an angle",
    )],
    "Int, Float or Angle",
)
.examples(&["abs(-3)", "abs(-30deg)"]);
fn abs(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ABS, a)?;
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
/// `floor(x)`.
static FLOOR: Sig = Sig::new(
    "floor",
    Group::Math,
    "The largest `Int` ≤ `x`.",
    &[X],
    "Int",
)
.examples(&["floor(2.7)"]);
fn floor(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a, &FLOOR)?;
    to_int(x.floor(), sp)
}
/// `ceil(x)`.
static CEIL: Sig = Sig::new(
    "ceil",
    Group::Math,
    "The smallest `Int` ≥ `x`.",
    &[X],
    "Int",
)
.examples(&["ceil(2.2)"]);
fn ceil(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a, &CEIL)?;
    to_int(x.ceil(), sp)
}
/// `round(x)`.
static ROUND: Sig = Sig::new(
    "round",
    Group::Math,
    "The nearest `Int` (halves away from zero).",
    &[X],
    "Int",
)
.examples(&["round(2.5)"]);
fn round(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a, &ROUND)?;
    to_int(x.round(), sp)
}
/// `exp(x)`.
static EXP: Sig = Sig::new(
    "exp",
    Group::Math,
    "e to the power `x` (a finite result is required: x < 709.78).",
    &[X],
    "Float",
)
.examples(&["exp(1)"]);
fn exp(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let x = one(it, s, a, &EXP)?.0;
    finite(s, x, libm::exp(x))
}
/// `ln(x)`.
static LN: Sig = Sig::new(
    "ln",
    Group::Math,
    "The natural logarithm.",
    &[X.range(Range::Positive)],
    "Float",
)
.domain()
.examples(&["ln(10)"]);
fn ln(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, _) = one(it, s, a, &LN)?;
    Ok(Value::Float(libm::log(x)))
}
/// `pow(base, exponent)`.
static POW: Sig = Sig::new(
    "pow",
    Group::Math,
    "`base` to the power `exponent` (a finite result is required).",
    &[
        Param::new("base", Ty::Float, "the base"),
        Param::new("exponent", Ty::Float, "the exponent"),
    ],
    "Float",
)
.examples(&["pow(base: 2, exponent: 10)"]);
fn pow(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &POW, a)?;
    let (b, _) = p.float(it, "base")?;
    let (e, sp) = p.float(it, "exponent")?;
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
/// `min(a, b, ...)`.
pub(crate) static MIN: Sig = Sig::new(
    "min",
    Group::Math,
    "The smallest of the values.",
    VALUES,
    "the smallest value",
)
.variadic()
.examples(&["min(3, 1, 2)", "min([3, 1, 2])"]);
fn min(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    min_max(it, s, a, true)
}
/// `max(a, b, ...)`.
pub(crate) static MAX: Sig = Sig::new(
    "max",
    Group::Math,
    "The largest of the values.",
    VALUES,
    "the largest value",
)
.variadic()
.examples(&["max(10deg, 20deg)"]);
fn max(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    min_max(it, s, a, false)
}

fn two_vecs(it: &dyn Host, s: CallSite, a: Vec<ArgVal>, sig: &'static Sig) -> R<(DVec3, DVec3)> {
    let mut p = Params::new(s, sig, a)?;
    Ok((p.vec3(it, "a")?.0, p.vec3(it, "b")?.0))
}
/// `dot(a, b)`.
pub(crate) static DOT: Sig = Sig::new("dot", Group::Math, "The dot product.", TWO_VECS, "Float")
    .examples(&["dot(a: X, b: Y)"]);
fn dot(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, y) = two_vecs(it, s, a, &DOT)?;
    Ok(Value::Float(x.dot(y)))
}
/// `cross(a, b)`.
pub(crate) static CROSS: Sig =
    Sig::new("cross", Group::Math, "The cross product.", TWO_VECS, "Vec3")
        .examples(&["cross(X, Y)"]);
fn cross(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, y) = two_vecs(it, s, a, &CROSS)?;
    Ok(Value::Vec3(x.cross(y)))
}
/// `distance(a, b)`.
pub(crate) static DISTANCE: Sig = Sig::new(
    "distance",
    Group::Math,
    "The distance between two points.",
    TWO_VECS,
    "Float",
)
.examples(&["distance([0, 0, 0], [3, 4, 0])"]);
fn distance(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, y) = two_vecs(it, s, a, &DISTANCE)?;
    Ok(Value::Float(x.distance_to(y)))
}
/// `length(v)`.
pub(crate) static LENGTH: Sig = Sig::new(
    "length",
    Group::Math,
    "The length of a vector.",
    ONE_VEC,
    "Float",
)
.examples(&["length(v: [3, 4, 0])"]);
fn length(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &LENGTH, a)?;
    Ok(Value::Float(p.vec3(it, "v")?.0.norm()))
}
/// `normalize(v)`.
pub(crate) static NORMALIZE: Sig = Sig::new(
    "normalize",
    Group::Math,
    "The unit vector along a non-zero vector (zero is `rtc::value::nan`).",
    ONE_VEC,
    "Vec3",
)
.examples(&["normalize([3, 4, 0])"]);
fn normalize(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &NORMALIZE, a)?;
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
/// `float(x)`.
static FLOAT: Sig = Sig::new(
    "float",
    Group::Misc,
    "The number as a `Float`.",
    &[X],
    "Float",
)
.examples(&["float(3)"]);
fn float(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Float(one(it, s, a, &FLOAT)?.0))
}
/// `int(x)`.
static INT: Sig = Sig::new(
    "int",
    Group::Misc,
    "The number truncated toward zero.",
    &[X],
    "Int",
)
.examples(&["int(-2.7)"]);
fn int(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (x, sp) = one(it, s, a, &INT)?;
    to_int(x.trunc(), sp)
}
/// `str(value)`.
static STR: Sig = Sig::new(
    "str",
    Group::Misc,
    "The value as text (as `print` shows it).",
    &[Param::new("value", Ty::Any, "any value")],
    "String",
)
.examples(&["str(value: 42)"]);
fn str_(_: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &STR, a)?;
    let (v, _) = p.req("value")?;
    Ok(match v {
        Value::Str(_) => v,
        _ => Value::Str(Rc::from(v.show())),
    })
}

/// `print(values...)`.
static PRINT: Sig = Sig::new(
    "print",
    Group::Misc,
    "Reports the values as a note (`rtc::print`).",
    &[Param::new("values", Ty::Any, "any values")],
    "()",
)
.variadic()
.examples(&["print(\"radius\", 2)"]);
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

/// `assert(condition, message)`.
static ASSERT: Sig = Sig::new(
    "assert",
    Group::Misc,
    "Stops with `rtc::assert::failed` when the condition is false.",
    &[
        Param::new("condition", Ty::Bool, "what must hold"),
        Param::new("message", Ty::String, "what the error says").optional(),
    ],
    "()",
)
.examples(&["assert(condition: 1 < 2, message: \"one is less than two\")"]);
fn assert(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ASSERT, a)?;
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
