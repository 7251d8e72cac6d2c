//! The arguments of a call: evaluated arguments ([`ArgVal`]), what a built-in learns of its
//! call site ([`CallSite`]), and [`Params`], the schema-checked argument reader every built-in
//! uses (unknown names with did-you-mean, arity, missing values, types and ranges).

use std::cell::RefCell;
use std::rc::Rc;

use glam::DVec3;

use crate::source::Span;
use crate::syntax::ast::Name;
use crate::syntax::intern::Sym;

use super::error::{Quote, R, error, suggest};
use super::value::Value;

/// An evaluated argument.
#[derive(Clone, Debug)]
pub struct ArgVal {
    /// `name:` of a named argument.
    pub name: Option<Name>,
    /// The value.
    pub value: Value,
    /// Span of the value expression.
    pub span: Span,
}

/// What a built-in learns about its call site.
#[derive(Clone, Copy, Debug)]
pub struct CallSite {
    /// The whole call.
    pub span: Span,
    /// The function's name as called (for messages).
    pub name: &'static str,
}

thread_local! {
    /// Emptied argument vectors of finished built-in calls (`Params` gives each back), for the
    /// next calls: a loop making a million spheres otherwise allocates and frees two per sphere.
    static SPARE_ARGS: RefCell<Vec<Vec<ArgVal>>> = const { RefCell::new(Vec::new()) };
}

/// Most spare argument vectors kept, and the largest kept (in arguments).
const SPARE_VECS: usize = 8;
const SPARE_CAPACITY: usize = 16;

/// Gives an argument vector back for reuse (its remaining values are dropped now).
pub fn recycle_args(mut args: Vec<ArgVal>) {
    if args.capacity() == 0 || args.capacity() > SPARE_CAPACITY {
        return;
    }
    args.clear();
    SPARE_ARGS.with(|s| {
        let mut s = s.borrow_mut();
        if s.len() < SPARE_VECS {
            s.push(args);
        }
    });
}

/// An empty argument vector with room for `n`, reused when one is spare.
pub(super) fn args_vec(n: usize) -> Vec<ArgVal> {
    match SPARE_ARGS.with(|s| s.borrow_mut().pop()) {
        Some(mut v) => {
            v.reserve(n);
            v
        }
        None => Vec::with_capacity(n),
    }
}

/// Schema-checked arguments of one built-in call. It keeps the call's argument vector and
/// records which argument fills each parameter, so matching allocates nothing.
pub struct Params {
    site: CallSite,
    names: &'static [&'static str],
    args: Vec<ArgVal>,
    /// `filled_by[i]`: the index in `args` of parameter `i`'s value, or [`UNFILLED`].
    filled_by: [u8; MAX_PARAMS],
}

/// Most parameters a built-in's schema may list.
const MAX_PARAMS: usize = 32;

/// A parameter without a value (yet, or any more).
const UNFILLED: u8 = u8::MAX;

/// The parameter slot named `sym` (its text is fetched once, not once per parameter).
fn slot_of(names: &[&str], sym: Sym) -> Option<usize> {
    let text = sym.as_str();
    names.iter().position(|x| *x == text)
}

impl Drop for Params {
    /// The argument vector is kept for the next call's arguments.
    fn drop(&mut self) {
        recycle_args(std::mem::take(&mut self.args));
    }
}

impl Params {
    /// Matches `args` to the parameter `names`: positional first, then named; a single record
    /// argument (`f { a: 1 }`) supplies named arguments.
    pub fn new(site: CallSite, names: &'static [&'static str], mut args: Vec<ArgVal>) -> R<Params> {
        assert!(
            names.len() <= MAX_PARAMS,
            "schema of `{}` is too long",
            site.name
        );
        let mut from_record = false;
        if args.len() == 1
            && args[0].name.is_none()
            && matches!(args[0].value, Value::Record(_))
            && let Some(ArgVal {
                value: Value::Record(r),
                ..
            }) = args.pop()
        {
            from_record = true;
            let field = |f: super::value::FieldVal| ArgVal {
                name: Some(crate::syntax::ast::Name {
                    sym: f.name,
                    span: f.name_span,
                }),
                value: f.value,
                span: f.span,
            };
            // An unshared record gives its fields up without cloning them.
            match Rc::try_unwrap(r) {
                Ok(r) => args.extend(r.fields.into_iter().map(field)),
                Err(r) => args.extend(r.fields.iter().cloned().map(field)),
            }
        }
        let mut params = Params {
            site,
            names,
            args,
            filled_by: [UNFILLED; MAX_PARAMS],
        };
        let mut pos = 0;
        let name = site.name;
        for (k, a) in params.args.iter().enumerate() {
            let idx = match a.name {
                Some(n) => match slot_of(names, n.sym) {
                    Some(i) => i,
                    None => {
                        let (code, what) = if from_record {
                            ("rtc::field::unknown", "field")
                        } else {
                            ("rtc::arg::unknown", "parameter")
                        };
                        let help = suggest(n.sym.as_str(), names.iter().copied())
                            .unwrap_or_else(|| format!("`{name}` takes: {}", names.join(", ")));
                        return Err(error(
                            code,
                            n.span,
                            format!("`{name}` has no {what} named `{}`", n.sym),
                        )
                        .with_label(format!("unknown {what}"))
                        .with_help(help)
                        .into());
                    }
                },
                None => {
                    pos += 1;
                    if pos > names.len() {
                        return Err(error(
                            "rtc::arg::too_many",
                            a.span,
                            format!(
                                "`{name}` takes at most {} argument{}",
                                names.len(),
                                if names.len() == 1 { "" } else { "s" }
                            ),
                        )
                        .with_label("unexpected argument")
                        .with_help(format!("its parameters are: {}", names.join(", ")))
                        .into());
                    }
                    pos - 1
                }
            };
            if params.filled_by[idx] != UNFILLED {
                return Err(error(
                    "rtc::arg::duplicate",
                    a.span,
                    format!("`{}` is given twice", names[idx]),
                )
                .with_label("second value")
                .with_help("remove one of the two")
                .into());
            }
            // Every argument before this one filled a distinct parameter, so `k` < 32.
            params.filled_by[idx] = k as u8;
        }
        Ok(params)
    }

    fn idx(&self, name: &str) -> usize {
        // The name is usually the very literal the schema lists: try its address first.
        self.names
            .iter()
            .position(|n| std::ptr::eq(*n, name))
            .or_else(|| self.names.iter().position(|n| *n == name))
            .unwrap_or_else(|| panic!("schema of `{}` lacks `{name}`", self.site.name))
    }

    /// An optional argument.
    pub fn get(&mut self, name: &str) -> Option<(Value, Span)> {
        let i = self.idx(name);
        let k = std::mem::replace(&mut self.filled_by[i], UNFILLED);
        let a = self.args.get_mut(k as usize)?;
        Some((std::mem::replace(&mut a.value, Value::Unit), a.span))
    }

    /// A required argument.
    pub fn req(&mut self, name: &str) -> R<(Value, Span)> {
        self.get(name).ok_or_else(|| {
            error(
                "rtc::arg::missing",
                self.site.span,
                format!("missing argument `{name}` in call of `{}`", self.site.name),
            )
            .with_label(format!("`{name}` is required"))
            .with_help(format!("add `{name}: ...`"))
            .into()
        })
    }

    /// A number with a default.
    pub fn num_or(
        &mut self,
        q: &(impl Quote + ?Sized),
        name: &str,
        default: f64,
    ) -> R<(f64, Span)> {
        match self.get(name) {
            Some((v, s)) => Ok((super::types::num(q, &v, s)?, s)),
            None => Ok((default, self.site.span)),
        }
    }

    /// A required number.
    pub fn num(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(f64, Span)> {
        let (v, s) = self.req(name)?;
        Ok((super::types::num(q, &v, s)?, s))
    }

    /// A vector with a default.
    pub fn vec3_or(&mut self, q: &(impl Quote + ?Sized), name: &str, default: DVec3) -> R<DVec3> {
        match self.get(name) {
            Some((v, s)) => super::types::vec3(q, &v, s),
            None => Ok(default),
        }
    }

    /// A required vector.
    pub fn vec3(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(DVec3, Span)> {
        let (v, s) = self.req(name)?;
        Ok((super::types::vec3(q, &v, s)?, s))
    }

    /// A colour with a default.
    pub fn color_or(&mut self, q: &(impl Quote + ?Sized), name: &str, default: DVec3) -> R<DVec3> {
        match self.get(name) {
            Some((v, s)) => super::types::color(q, &v, s),
            None => Ok(default),
        }
    }

    /// A Bool with a default.
    pub fn bool_or(&mut self, q: &(impl Quote + ?Sized), name: &str, default: bool) -> R<bool> {
        match self.get(name) {
            Some((v, s)) => super::types::boolean(q, &v, s),
            None => Ok(default),
        }
    }

    /// An angle with a default.
    pub fn angle_or(
        &mut self,
        q: &(impl Quote + ?Sized),
        name: &str,
        default: f64,
    ) -> R<(f64, Span)> {
        match self.get(name) {
            Some((v, s)) => Ok((super::types::angle(q, &v, s)?, s)),
            None => Ok((default, self.site.span)),
        }
    }
}

/// Range check: `name` must satisfy `ok`, described as `rule` (e.g. "> 0").
pub fn check(ok: bool, name: &str, rule: &str, v: f64, span: Span) -> R<()> {
    if ok && v.is_finite() {
        return Ok(());
    }
    check_shown(false, name, rule, &super::value::fmt_f(v), span)
}

/// Range check with the offending value already formatted (e.g. with its unit).
pub fn check_shown(ok: bool, name: &str, rule: &str, shown: &str, span: Span) -> R<()> {
    if ok {
        return Ok(());
    }
    Err(error(
        "rtc::param::out_of_range",
        span,
        format!("`{name}` must be {rule}, but it is {shown}"),
    )
    .with_label(format!("evaluates to {shown}"))
    .with_help(format!("use a value that is {rule}"))
    .into())
}

/// `v > 0`.
pub fn positive(name: &str, v: f64, span: Span) -> R<()> {
    check(v > 0.0, name, "> 0", v, span)
}

/// `0 <= v <= 1`.
pub fn unit_interval(name: &str, v: f64, span: Span) -> R<()> {
    check((0.0..=1.0).contains(&v), name, "in [0, 1]", v, span)
}
