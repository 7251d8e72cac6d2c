//! List functions: `len`, `sum`, `flatten`, `concat`, `reverse`, `zip`, `enumerate`, `any`,
//! `all`, `reduce` and `iterate` (the language's answer to `while`). A `Vec3` counts as a list
//! of three `Float`s everywhere a list is read, so `sum([1, 2, 3])` is 6.

use std::rc::Rc;

use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::R;
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Param, Sig, Ty};
use crate::eval::types;
use crate::eval::value::Value;
use crate::source::Span;
use crate::syntax::ast::BinOp;

/// List functions with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&LEN, len),
    (&SUM, sum),
    (&FLATTEN, flatten),
    (&CONCAT, concat),
    (&REVERSE, reverse),
    (&ZIP, zip),
    (&ENUMERATE, enumerate),
    (&ANY, any),
    (&ALL, all),
    (&REDUCE, reduce),
    (&ITERATE, iterate),
];

/// The list a list function reads.
const THE_LIST: Param = Param::new("list", Ty::List, "a list (a `Vec3` is three numbers)");
/// The parameter of the one-list functions.
const LIST: &[Param] = &[THE_LIST];
/// `any`, `all`.
const PREDICATE: &[Param] = &[
    THE_LIST,
    Param::new(
        "f",
        Ty::Fn,
        "what to ask of each element (without it, the elements are `Bool`s)",
    )
    .optional(),
];

/// The elements of a list-like value: a `List`, or a `Vec3` as three `Float`s.
pub(crate) fn items(v: &Value) -> Option<Rc<Vec<Value>>> {
    match v {
        Value::List(l) => Some(l.clone()),
        Value::Vec3(x) => Some(Rc::new(x.to_array().map(Value::Float).to_vec())),
        _ => None,
    }
}

/// The list argument `name`, or a type error that says a list was expected.
fn list_arg(it: &dyn Host, p: &mut Params, name: &str) -> R<(Rc<Vec<Value>>, Span)> {
    let (v, sp) = p.req(name)?;
    match items(&v) {
        Some(l) => Ok((l, sp)),
        None => Err(types::mismatch(it, "List", &v, sp).into()),
    }
}

/// A function argument, checked to be callable.
fn fn_arg(it: &dyn Host, p: &mut Params, name: &str) -> R<(Value, Span)> {
    let (f, sp) = p.req(name)?;
    if !matches!(f, Value::Fn(_) | Value::Builtin(_)) {
        return Err(types::mismatch(it, "Fn", &f, sp).into());
    }
    Ok((f, sp))
}

/// Calls `f` with positional arguments.
pub(crate) fn call(it: &mut dyn Host, f: &Value, args: &[Value], fs: Span, site: Span) -> R<Value> {
    let a = args
        .iter()
        .map(|v| ArgVal {
            name: None,
            value: v.clone(),
            span: fs,
        })
        .collect();
    it.call_value(f.clone(), a, site, fs)
}

fn list(it: &dyn Host, v: Vec<Value>, span: Span) -> R<Value> {
    it.new_list(v.len(), span)?;
    Ok(Value::List(Rc::new(v)))
}

/// `len(x)`.
pub(crate) static LEN: Sig = Sig::new(
    "len",
    Group::List,
    "The number of elements (of a `String`, its characters).",
    &[Param::new(
        "list",
        Ty::OneOf(&[Ty::List, Ty::Vec3, Ty::String, Ty::Range]),
        "a `List`, `Vec3`, `String` or range",
    )],
    "Int",
)
.examples(&["len(list: [1, 2, 3])"]);
fn len(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &LEN, a)?;
    let (v, sp) = p.req("list")?;
    Ok(Value::Int(match v {
        Value::List(l) => l.len() as i64,
        Value::Vec3(_) => 3,
        Value::Str(s) => s.chars().count() as i64,
        Value::Range(r) => r.len().min(i64::MAX as u64) as i64,
        other => return Err(types::mismatch(it, "List", &other, sp).into()),
    }))
}

/// `sum(list)`: the elements added with `+`, so numbers, angles, vectors and colours all sum
/// (the first element starts the sum; `sum([])` is `0`).
pub(crate) static SUM: Sig = Sig::new(
    "sum",
    Group::List,
    "The elements added with `+` (`0` for `[]`).",
    LIST,
    "their sum",
)
.examples(&["sum([1, 2, 3])"]);
fn sum(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SUM, a)?;
    let (l, sp) = list_arg(it, &mut p, "list")?;
    let mut iter = l.iter();
    let Some(first) = iter.next() else {
        return Ok(Value::Int(0));
    };
    let mut acc = first.clone();
    for x in iter {
        acc = crate::eval::ops::binary(it, BinOp::Add, acc, x.clone(), sp, sp, sp)?;
    }
    Ok(acc)
}

/// `flatten(list)`: the elements of the inner lists in order (one level; other elements stay).
pub(crate) static FLATTEN: Sig = Sig::new(
    "flatten",
    Group::List,
    "The elements of the inner lists in order (one level).",
    LIST,
    "List",
)
.examples(&["flatten([[1, 2], [3]])"]);
fn flatten(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &FLATTEN, a)?;
    let (l, sp) = list_arg(it, &mut p, "list")?;
    let mut out = Vec::new();
    for x in l.iter() {
        match x {
            Value::List(inner) => out.extend(inner.iter().cloned()),
            other => out.push(other.clone()),
        }
    }
    list(it, out, sp)
}

/// `concat(a, b, ...)`: the lists one after another.
static CONCAT: Sig = Sig::new(
    "concat",
    Group::List,
    "The lists one after another.",
    &[Param::new("lists", Ty::List, "lists")],
    "List",
)
.variadic()
.examples(&["concat([1], [2, 3])"]);
fn concat(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut out = Vec::new();
    for x in a {
        let Some(l) = items(&x.value) else {
            return Err(types::mismatch(it, "List", &x.value, x.span).into());
        };
        out.extend(l.iter().cloned());
        it.check_list_len(out.len(), s.span)?;
    }
    list(it, out, s.span)
}

/// `reverse(list)`.
pub(crate) static REVERSE: Sig = Sig::new(
    "reverse",
    Group::List,
    "The elements in reverse order.",
    LIST,
    "List",
)
.examples(&["reverse([1, 2, 3])"]);
fn reverse(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &REVERSE, a)?;
    let (l, sp) = list_arg(it, &mut p, "list")?;
    list(it, l.iter().rev().cloned().collect(), sp)
}

/// `zip(a, b)`: pairs `[a[i], b[i]]` up to the shorter length.
pub(crate) static ZIP: Sig = Sig::new(
    "zip",
    Group::List,
    "Pairs `[a[i], b[i]]` up to the shorter length.",
    &[
        Param::new("a", Ty::List, "the first list"),
        Param::new("b", Ty::List, "the second list"),
    ],
    "List",
)
.examples(&["zip(a: [1, 2], b: [3, 4])"]);
fn zip(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ZIP, a)?;
    let (x, sp) = list_arg(it, &mut p, "a")?;
    let (y, _) = list_arg(it, &mut p, "b")?;
    let pairs = x
        .iter()
        .zip(y.iter())
        .map(|(a, b)| Value::List(Rc::new(vec![a.clone(), b.clone()])))
        .collect();
    list(it, pairs, sp)
}

/// `enumerate(list)`: pairs `[i, list[i]]`.
pub(crate) static ENUMERATE: Sig = Sig::new(
    "enumerate",
    Group::List,
    "Pairs `[i, list[i]]`.",
    LIST,
    "List",
)
.examples(&["enumerate([\"a\", \"b\"])"]);
fn enumerate(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ENUMERATE, a)?;
    let (l, sp) = list_arg(it, &mut p, "list")?;
    let pairs = l
        .iter()
        .enumerate()
        .map(|(i, x)| Value::List(Rc::new(vec![Value::Int(i as i64), x.clone()])))
        .collect();
    list(it, pairs, sp)
}

/// `any` and `all`: over `Bool`s, or over what a predicate `f` says of each element.
fn any_all(
    it: &mut dyn Host,
    s: CallSite,
    a: Vec<ArgVal>,
    want: bool,
    sig: &'static Sig,
) -> R<Value> {
    let mut p = Params::new(s, sig, a)?;
    let (l, sp) = list_arg(it, &mut p, "list")?;
    let f = match p.get("f") {
        Some((f, fs)) if matches!(f, Value::Fn(_) | Value::Builtin(_)) => Some((f, fs)),
        Some((other, fs)) => return Err(types::mismatch(it, "Fn", &other, fs).into()),
        None => None,
    };
    for x in l.iter() {
        let (v, vs) = match &f {
            Some((f, fs)) => (call(it, f, std::slice::from_ref(x), *fs, s.span)?, *fs),
            None => (x.clone(), sp),
        };
        if types::boolean(it, &v, vs)? == want {
            return Ok(Value::Bool(want));
        }
    }
    Ok(Value::Bool(!want))
}

/// `any(list, f)`.
pub(crate) static ANY: Sig = Sig::new(
    "any",
    Group::List,
    "Whether any element is true (or satisfies `f`).",
    PREDICATE,
    "Bool",
)
.examples(&["any(list: [1, 2], f: fn(x) x > 1)"]);
fn any(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    any_all(it, s, a, true, &ANY)
}

/// `all(list, f)`.
pub(crate) static ALL: Sig = Sig::new(
    "all",
    Group::List,
    "Whether every element is true (or satisfies `f`).",
    PREDICATE,
    "Bool",
)
.examples(&["all([true, false])"]);
fn all(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    any_all(it, s, a, false, &ALL)
}

/// `reduce(list, init, f)`: `f(f(f(init, l[0]), l[1]), ...)`, the accumulation a loop with a
/// mutable variable would do.
pub(crate) static REDUCE: Sig = Sig::new(
    "reduce",
    Group::List,
    "`f(f(f(init, l[0]), l[1]), ...)`.",
    &[
        THE_LIST,
        Param::new("init", Ty::Any, "the value to start from"),
        Param::new("f", Ty::Fn, "the step: `f(accumulated, element)`"),
    ],
    "the last value of `f`",
)
.examples(&["reduce(list: [1, 2, 3], init: 0, f: fn(acc, x) acc + x)"]);
fn reduce(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &REDUCE, a)?;
    let (l, _) = list_arg(it, &mut p, "list")?;
    let (mut acc, _) = p.req("init")?;
    let (f, fs) = fn_arg(it, &mut p, "f")?;
    for x in l.iter() {
        acc = call(it, &f, &[acc, x.clone()], fs, s.span)?;
    }
    Ok(acc)
}

/// `iterate(start, next, while)`: the list `start, next(start), next(next(start)), ...` for as
/// long as `while` holds for the element: a `while` loop as a value. Every step counts against
/// the loop budget.
static ITERATE: Sig = Sig::new(
    "iterate",
    Group::List,
    "`start, next(start), next(next(start)), ...` while `while` holds.",
    &[
        Param::new("start", Ty::Any, "the first element"),
        Param::new("next", Ty::Fn, "the element after a given one"),
        Param::new("while", Ty::Fn, "whether an element belongs to the list"),
    ],
    "List",
)
.examples(&["iterate(start: 1, next: fn(x) x * 2, while: fn(x) x < 100)"]);
fn iterate(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ITERATE, a)?;
    let (mut x, _) = p.req("start")?;
    let (next, ns) = fn_arg(it, &mut p, "next")?;
    let (cond, cs) = fn_arg(it, &mut p, "while")?;
    let mut out = Vec::new();
    loop {
        let keep = call(it, &cond, std::slice::from_ref(&x), cs, s.span)?;
        if !types::boolean(it, &keep, cs)? {
            break;
        }
        it.step(s.span, crate::eval::budgets::Step::Iterate)?;
        it.check_list_len(out.len() + 1, s.span)?;
        it.charge(crate::eval::value::VALUE_BYTES, s.span, "`iterate`'s list")?;
        out.push(x.clone());
        x = call(it, &next, &[x], ns, s.span)?;
    }
    Ok(Value::List(Rc::new(out)))
}
