//! Unary and binary operators: arithmetic, comparison, `>>` on transforms, CSG on objects.

use std::rc::Rc;

use crate::ir::CsgOp;
use crate::source::Span;
use crate::syntax::ast::{BinOp, UnOp};

use super::error::{R, error};
use super::host::Host;
use super::operands::Operands;
use super::value::{Obj, ObjShape, Value};

/// `-x`, `!x`.
pub(crate) fn unary(op: UnOp, v: Value, span: Span) -> R<Value> {
    Ok(match (op, v) {
        (UnOp::Neg, Value::Int(i)) => Value::Int(i.checked_neg().ok_or_else(|| overflow(span))?),
        (UnOp::Neg, Value::Float(f)) => Value::Float(-f),
        (UnOp::Neg, Value::Angle(a)) => Value::Angle(-a),
        (UnOp::Neg, Value::Vec3(v)) => Value::Vec3(-v),
        (UnOp::Not, Value::Bool(b)) => Value::Bool(!b),
        (op, v) => {
            let sym = if op == UnOp::Neg { "-" } else { "!" };
            return Err(error(
                "rtc::type::operator",
                span,
                format!(
                    "cannot apply `{sym}` to {}",
                    super::value::a_type(v.type_name())
                ),
            )
            .with_label(format!("this is {}", super::value::a_type(v.type_name())))
            .with_help(if op == UnOp::Neg {
                "negate a number, angle or vector"
            } else {
                "`!` needs a `Bool`"
            })
            .into());
        }
    })
}

fn overflow(span: Span) -> crate::diag::Diagnostic {
    error("rtc::value::overflow", span, "integer overflow")
        .with_label("the result does not fit in 64 bits")
        .with_help("use floats for very large numbers, e.g. `1.0e20`")
}

/// A number in flight on the arithmetic fast paths: held in registers, not as a [`Value`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Num {
    /// An `Int`.
    Int(i64),
    /// A `Float`.
    Float(f64),
}

impl Num {
    /// The number `v` is, if it is one.
    #[inline(always)]
    pub(crate) fn of(v: &Value) -> Option<Num> {
        match *v {
            Value::Int(i) => Some(Num::Int(i)),
            Value::Float(f) => Some(Num::Float(f)),
            _ => None,
        }
    }

    /// As a float (what [`Value::as_f64`] gives for it).
    #[inline(always)]
    pub(crate) fn f64(self) -> f64 {
        match self {
            Num::Int(i) => i as f64,
            Num::Float(f) => f,
        }
    }

    /// As a value.
    #[inline(always)]
    pub(crate) fn value(self) -> Value {
        match self {
            Num::Int(i) => Value::Int(i),
            Num::Float(f) => Value::Float(f),
        }
    }
}

/// `a op b` on two numbers when the result is ordinary (no overflow, no division by zero,
/// finite): the arithmetic of loops, without the general operator's checks and messages. `None`
/// sends the operation to [`binary`], which gives the same value or the error.
#[inline(always)]
pub(crate) fn num_op(op: BinOp, l: Num, r: Num) -> Option<Num> {
    use BinOp::*;
    match (l, r) {
        (Num::Int(a), Num::Int(b)) => Some(Num::Int(match op {
            Add => a.checked_add(b)?,
            Sub => a.checked_sub(b)?,
            Mul => a.checked_mul(b)?,
            Rem => a.checked_rem_euclid(b)?,
            _ => return None,
        })),
        _ => {
            let (a, b) = (l.f64(), r.f64());
            let v = match op {
                Add => a + b,
                Sub => a - b,
                Mul => a * b,
                Div if b != 0.0 => a / b,
                _ => return None,
            };
            v.is_finite().then_some(Num::Float(v))
        }
    }
}

/// [`num_op`] on two values (`None` unless both are numbers).
#[inline]
pub(crate) fn arithmetic(op: BinOp, l: &Value, r: &Value) -> Option<Value> {
    num_op(op, Num::of(l)?, Num::of(r)?).map(Num::value)
}

/// `a op b` for every operator except the short-circuit `&&` and `||`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn binary(
    it: &mut dyn Host,
    op: BinOp,
    l: Value,
    r: Value,
    ls: Span,
    rs: Span,
    span: Span,
) -> R<Value> {
    use BinOp::*;
    use Value::*;
    let v = match (op, &l, &r) {
        (Add, Int(a), Int(b)) => Int(a.checked_add(*b).ok_or_else(|| overflow(span))?),
        (Sub, Int(a), Int(b)) => Int(a.checked_sub(*b).ok_or_else(|| overflow(span))?),
        (Mul, Int(a), Int(b)) => Int(a.checked_mul(*b).ok_or_else(|| overflow(span))?),
        (Rem, Int(a), Int(b)) => {
            if *b == 0 {
                return Err(div_zero(rs));
            }
            Int(a.checked_rem_euclid(*b).ok_or_else(|| overflow(span))?)
        }
        (IntDiv, Int(a), Int(b)) => {
            if *b == 0 {
                return Err(div_zero(rs));
            }
            Int(a.checked_div_euclid(*b).ok_or_else(|| overflow(span))?)
        }
        (Pow, Int(a), Int(b)) if *b >= 0 => {
            let e = u32::try_from(*b).map_err(|_| overflow(span))?;
            Int(a.checked_pow(e).ok_or_else(|| overflow(span))?)
        }
        (Add | Sub | Mul | Div | Rem | Pow, Int(_) | Float(_), Int(_) | Float(_)) => {
            let (a, b) = (l.as_f64().unwrap_or(0.0), r.as_f64().unwrap_or(0.0));
            let v = match op {
                Add => a + b,
                Sub => a - b,
                Mul => a * b,
                Div if b == 0.0 => return Err(div_zero(rs)),
                Div => a / b,
                Rem if b == 0.0 => return Err(div_zero(rs)),
                Rem => a.rem_euclid(b),
                _ => libm::pow(a, b),
            };
            Float(v)
        }
        (Add, Angle(a), Angle(b)) => Angle(a + b),
        (Sub, Angle(a), Angle(b)) => Angle(a - b),
        (Mul, Angle(a), Int(_) | Float(_)) => Angle(a * r.as_f64().unwrap_or(0.0)),
        (Mul, Int(_) | Float(_), Angle(b)) => Angle(l.as_f64().unwrap_or(0.0) * b),
        (Div, Angle(a), Int(_) | Float(_)) => Angle(a / nonzero(r.as_f64(), rs)?),
        (Div, Angle(a), Angle(b)) => Float(a / nonzero(Some(*b), rs)?),
        (Add, Vec3(a), Vec3(b)) => Vec3(*a + *b),
        (Sub, Vec3(a), Vec3(b)) => Vec3(*a - *b),
        (Mul, Vec3(a), Vec3(b)) => Vec3(*a * *b),
        (Mul, Vec3(a), Int(_) | Float(_)) => Vec3(*a * r.as_f64().unwrap_or(0.0)),
        (Mul, Int(_) | Float(_), Vec3(b)) => Vec3(l.as_f64().unwrap_or(0.0) * *b),
        (Div, Vec3(a), Int(_) | Float(_)) => Vec3(*a / nonzero(r.as_f64(), rs)?),
        (Add, Color(a), Color(b)) => Color(*a + *b),
        (Sub, Color(a), Color(b)) => Color(*a - *b),
        (Mul, Color(a), Color(b)) => Color(*a * *b),
        (Mul, Color(a), Int(_) | Float(_)) => Color(*a * r.as_f64().unwrap_or(0.0)),
        (Mul, Int(_) | Float(_), Color(b)) => Color(l.as_f64().unwrap_or(0.0) * *b),
        (Div, Color(a), Int(_) | Float(_)) => Color(*a / nonzero(r.as_f64(), rs)?),
        (Add, Str(a), Str(b)) => {
            it.new_string(a.len() + b.len(), span)?;
            Str(format!("{a}{b}").into())
        }
        (Add, List(a), List(b)) => {
            it.new_list(a.len() + b.len(), span)?;
            List(Rc::new(a.iter().chain(b.iter()).cloned().collect()))
        }
        (Then, Transform(a), Transform(b)) => Transform(Rc::new(**b * **a)),
        (Union, Object(_), Object(_)) => csg(it, CsgOp::Union, &l, &r, ls, rs, span)?,
        (Inter, Object(_), Object(_)) => csg(it, CsgOp::Intersection, &l, &r, ls, rs, span)?,
        (Sub, Object(_), Object(_)) => csg(it, CsgOp::Difference, &l, &r, ls, rs, span)?,
        (Eq | Ne, _, _) => {
            let eq = equal(&l, &r).ok_or_else(|| op_error(it, op, &l, &r, ls, rs))?;
            Bool(eq == (op == Eq))
        }
        (Lt | Le | Gt | Ge, _, _) => {
            let (a, b) = match (&l, &r) {
                (Angle(a), Angle(b)) => (*a, *b),
                _ => match (l.as_f64(), r.as_f64()) {
                    (Some(a), Some(b)) => (a, b),
                    _ => return Err(op_error(it, op, &l, &r, ls, rs).into()),
                },
            };
            Bool(match op {
                Lt => a < b,
                Le => a <= b,
                Gt => a > b,
                _ => a >= b,
            })
        }
        _ => return Err(op_error(it, op, &l, &r, ls, rs).into()),
    };
    let finite = match &v {
        Float(x) | Angle(x) => x.is_finite(),
        Vec3(x) | Color(x) => x.is_finite(),
        _ => true,
    };
    if !finite {
        return Err(not_finite(it, op, &l, &r, span));
    }
    Ok(v)
}

/// An operation whose result is infinite or NaN: stopped here, before it reaches geometry.
fn not_finite(
    it: &dyn Host,
    op: BinOp,
    l: &Value,
    r: &Value,
    span: Span,
) -> super::error::EvalError {
    let help = if op == BinOp::Pow {
        "a negative base needs a whole exponent; keep results below about 1.8e308"
    } else {
        "keep results below about 1.8e308"
    };
    let shown = |v: &Value| match v.show() {
        s if s.starts_with('-') => format!("({s})"),
        s => s,
    };
    error(
        "rtc::value::nan",
        span,
        format!("`{}` has no finite result", it.snippet(span).trim()),
    )
    .with_label(format!(
        "{} {} {} is not a finite number",
        shown(l),
        op.as_str(),
        shown(r)
    ))
    .with_help(help)
    .into()
}

fn nonzero(v: Option<f64>, span: Span) -> R<f64> {
    match v {
        Some(x) if x != 0.0 => Ok(x),
        _ => Err(div_zero(span)),
    }
}

fn div_zero(span: Span) -> super::error::EvalError {
    error("rtc::value::division_by_zero", span, "division by zero")
        .with_label("this is zero")
        .with_help("guard the division with an `if`, or divide by a non-zero value")
        .into()
}

fn equal(a: &Value, b: &Value) -> Option<bool> {
    use Value::*;
    Some(match (a, b) {
        (Int(_) | Float(_), Int(_) | Float(_)) => a.as_f64() == b.as_f64(),
        (Bool(x), Bool(y)) => x == y,
        (Str(x), Str(y)) => x == y,
        (Angle(x), Angle(y)) => x == y,
        (Vec3(x), Vec3(y)) => x == y,
        (Color(x), Color(y)) => x == y,
        // Lists compare element by element; a `Vec3` counts as a list of three numbers.
        (List(_) | Vec3(_), List(_) | Vec3(_)) => {
            let (x, y) = (
                super::builtins::lists::items(a)?,
                super::builtins::lists::items(b)?,
            );
            if x.len() != y.len() {
                return Some(false);
            }
            for (p, q) in x.iter().zip(y.iter()) {
                if !equal(p, q)? {
                    return Some(false);
                }
            }
            true
        }
        _ => return None,
    })
}

fn op_error(
    it: &dyn Host,
    op: BinOp,
    l: &Value,
    r: &Value,
    ls: Span,
    rs: Span,
) -> crate::diag::Diagnostic {
    let (lt, rt) = (l.type_name(), r.type_name());
    let d = error(
        "rtc::type::operator",
        rs,
        format!("cannot apply `{}` to `{lt}` and `{rt}`", op.as_str()),
    )
    .with_label(format!("this is {}", super::value::a_type(rt)))
    .with_secondary(ls, format!("this is {}", super::value::a_type(lt)));
    let snippet = it.snippet(rs).trim().to_owned();
    let lsnip = it.snippet(ls).trim().to_owned();
    match (l, r) {
        (Value::Angle(_), Value::Int(_) | Value::Float(_))
            if matches!(op, BinOp::Add | BinOp::Sub) =>
        {
            d.with_help(format!("give the number a unit: `{snippet}deg`"))
        }
        (Value::Int(_) | Value::Float(_), Value::Angle(_))
            if matches!(op, BinOp::Add | BinOp::Sub) =>
        {
            d.with_help(format!("give the number a unit: `{lsnip}deg`"))
        }
        (Value::Vec3(_), Value::Int(_) | Value::Float(_))
            if matches!(op, BinOp::Add | BinOp::Sub) =>
        {
            d.with_help(format!("add a vector: `[{snippet}, {snippet}, {snippet}]`"))
        }
        (Value::Str(_), _) | (_, Value::Str(_)) if op == BinOp::Add => {
            d.with_help("use interpolation: `\"text {value}\"`")
        }
        (Value::Transform(_), Value::Transform(_)) => {
            d.with_help("compose transforms with `>>` (\"then\")")
        }
        (Value::Object(_), _) | (_, Value::Object(_)) => {
            d.with_help("CSG operators `|`, `&` and `-` need an object on both sides")
        }
        _ => d.with_help(format!(
            "convert one side so both are the same type, e.g. `{lt}`"
        )),
    }
}

/// Builds a CSG node; nested nodes of the same operation (without their own transform or
/// material) are flattened so `a | b | c` is one union of three.
fn csg(
    it: &mut dyn Host,
    op: CsgOp,
    l: &Value,
    r: &Value,
    ls: Span,
    rs: Span,
    span: Span,
) -> R<Value> {
    let (Value::Object(a), Value::Object(b)) = (l, r) else {
        unreachable!("csg on objects")
    };
    for (o, s) in [(a, ls), (b, rs)] {
        super::shapes::require_closed(it, o, s)?;
    }
    // An operand that is already this operation, plain (no material, motion or transform),
    // lends its operands: `a | b | c` is one union of three. Only a difference's base may
    // lend (`(a - b) - c` is `a - b - c`; `a - (b - c)` is not).
    let operands_of = |o: &'_ Rc<Obj>, first: bool| -> Option<Operands<Obj>> {
        match &o.shape {
            ObjShape::Csg(k, ch)
                if *k == op
                    && o.material.is_none()
                    && o.motion.is_none()
                    && o.transform == glam::DAffine3::IDENTITY
                    && (first || op != CsgOp::Difference) =>
            {
                Some(ch.clone())
            }
            _ => None,
        }
    };
    let right = match operands_of(b, false) {
        Some(ch) => ch.items().to_vec(),
        None => vec![(**b).clone()],
    };
    // Extending the left operand's list is amortised O(1), so a union grown one object at a
    // time (`reduce(l, start, fn(u, x) u | x)`) is linear, not quadratic (`eval::operands`).
    let children = match operands_of(a, true) {
        Some(ch) => ch.extended(right),
        None => Operands::new(std::iter::once((**a).clone()).chain(right).collect()),
    };
    Ok(Value::Object(Rc::new(Obj {
        shape: ObjShape::Csg(op, children),
        transform: glam::DAffine3::IDENTITY,
        material: None,
        motion: None,
        span,
        origin: it.origin(),
        visibility: crate::ir::Visibility::ALL,
    })))
}
