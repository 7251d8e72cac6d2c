//! Method calls: transforms and `.material(m)` on objects, transform chaining, RNG draws and
//! list helpers.

use std::rc::Rc;

use crate::source::Span;
use crate::syntax::ast::Name;

use super::call::{ArgVal, CallSite};
use super::error::R;
use super::interp::Interp;
use super::types;
use super::value::Value;

/// `recv.name(args)`.
pub fn call_method(
    it: &mut Interp,
    recv: Value,
    name: Name,
    args: Vec<ArgVal>,
    span: Span,
) -> R<Value> {
    let n = name.sym.as_str();
    let site = CallSite { span, name: n };
    let is_t = super::transform::METHODS.contains(&n);
    // The receiver is owned: a temporary object (`sphere(..).translate(..)`) is updated in
    // place, and only a shared one is copied.
    let recv = match recv {
        Value::Object(mut o) if is_t => {
            let t = super::transform::method_transform(it, n, site, args)?;
            let o2 = Rc::make_mut(&mut o);
            o2.transform = t * o2.transform;
            return Ok(Value::Object(o));
        }
        Value::Object(mut o) if n == "material" => {
            let mut p = super::builtins::Params::new(site, &["material"], args)?;
            let (m, ms) = p.req("material")?;
            let Value::Material(m) = m else {
                return Err(types::mismatch(it, "Material", &m, ms).into());
            };
            Rc::make_mut(&mut o).material = Some(m);
            return Ok(Value::Object(o));
        }
        other => other,
    };
    match &recv {
        Value::Transform(a) if is_t => {
            let t = super::transform::method_transform(it, n, site, args)?;
            return Ok(Value::Transform(Rc::new(t * **a)));
        }
        Value::Rng(seed) if super::rng::METHODS.contains(&n) => {
            return super::rng::method(it, *seed, n, site, args);
        }
        Value::List(l) if n == "map" || n == "filter" => {
            let mut p = super::builtins::Params::new(site, &["f"], args)?;
            let (f, fs) = p.req("f")?;
            if !matches!(f, Value::Fn(_) | Value::Builtin(_)) {
                return Err(types::mismatch(it, "Fn", &f, fs).into());
            }
            let mut out = Vec::with_capacity(l.len());
            for x in l.iter() {
                let a = vec![ArgVal {
                    name: None,
                    value: x.clone(),
                    span: fs,
                }];
                let r = it.call_value(f.clone(), a, span, fs)?;
                if n == "map" {
                    out.push(r);
                } else if types::boolean(it, &r, fs)? {
                    out.push(x.clone());
                }
            }
            return Ok(Value::List(Rc::new(out)));
        }
        _ => {}
    }
    let known: Vec<&str> = match &recv {
        Value::Object(_) => object_methods(),
        Value::Transform(_) => super::transform::METHODS.to_vec(),
        Value::Rng(_) => super::rng::METHODS.to_vec(),
        Value::List(_) => vec!["map", "filter"],
        _ => Vec::new(),
    };
    Err(super::members::unknown(
        "method", &recv, n, name.span, &known,
    ))
}

/// Methods of objects: every transform method, plus `material`.
pub fn object_methods() -> Vec<&'static str> {
    [super::transform::METHODS, &["material"]].concat()
}
