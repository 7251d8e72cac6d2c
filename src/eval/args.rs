//! The arguments of a call: evaluated arguments ([`ArgVal`]), what a built-in learns of its
//! call site ([`CallSite`]), and [`Params`], the schema-checked argument reader every built-in
//! uses (unknown names with did-you-mean, arity, missing values, types and ranges).

use std::cell::RefCell;
use std::rc::Rc;

use glam::DVec3;

use crate::source::Span;
use crate::syntax::ast::Name;
use crate::syntax::intern::Sym;

use super::error::{EvalError, Quote, R, error, suggest};
use super::schema::{Absent, Blame, Checked, Lit, Param, Range, Sig, Ty};
use super::value::Value;

/// An evaluated argument.
#[derive(Clone, Debug)]
pub(crate) struct ArgVal {
    /// `name:` of a named argument.
    pub(crate) name: Option<Name>,
    /// The value.
    pub(crate) value: Value,
    /// Span of the value expression.
    pub(crate) span: Span,
}

/// What a built-in learns about its call site.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CallSite {
    /// The whole call.
    pub(crate) span: Span,
    /// The function's name as called (for messages).
    pub(crate) name: &'static str,
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
pub(crate) fn recycle_args(mut args: Vec<ArgVal>) {
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
pub(crate) struct Params {
    site: CallSite,
    sig: &'static Sig,
    args: Vec<ArgVal>,
    /// `filled_by[i]`: the index in `args` of parameter `i`'s value, or [`UNFILLED`].
    filled_by: [u8; MAX_PARAMS],
}

/// Most parameters a built-in's schema may list.
const MAX_PARAMS: usize = 32;

/// A parameter without a value (yet, or any more).
const UNFILLED: u8 = u8::MAX;

/// The parameter slot named `sym` (its text is fetched once, not once per parameter).
fn slot_of(params: &[Param], sym: Sym) -> Option<usize> {
    let text = sym.as_str();
    params.iter().position(|p| p.name == text)
}

impl Drop for Params {
    /// The argument vector is kept for the next call's arguments.
    fn drop(&mut self) {
        recycle_args(std::mem::take(&mut self.args));
    }
}

impl Params {
    /// Matches `args` to the parameters of `sig`: positional first, then named; a single record
    /// argument (`f { a: 1 }`) supplies named arguments.
    pub(crate) fn new(site: CallSite, sig: &'static Sig, mut args: Vec<ArgVal>) -> R<Params> {
        let names = sig.params;
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
            sig,
            args,
            filled_by: [UNFILLED; MAX_PARAMS],
        };
        let mut pos = 0;
        let name = site.name;
        let list = || sig.names().collect::<Vec<_>>().join(", ");
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
                        let help = suggest(n.sym.as_str(), sig.names())
                            .unwrap_or_else(|| format!("`{name}` takes: {}", list()));
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
                        .with_help(format!("its parameters are: {}", list()))
                        .into());
                    }
                    pos - 1
                }
            };
            if params.filled_by[idx] != UNFILLED {
                return Err(error(
                    "rtc::arg::duplicate",
                    a.span,
                    format!("`{}` is given twice", names[idx].name),
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

    /// The slot of parameter `name`; a name the schema lacks is a bug in the built-in.
    #[inline]
    fn idx(&self, name: &str) -> usize {
        self.sig
            .index(name)
            .unwrap_or_else(|| panic!("schema of `{}` lacks `{name}`", self.site.name))
    }

    /// The argument in slot `i`, taken out of the call.
    #[inline]
    fn take(&mut self, i: usize) -> Option<(Value, Span)> {
        let k = std::mem::replace(&mut self.filled_by[i], UNFILLED);
        let a = self.args.get_mut(k as usize)?;
        Some((std::mem::replace(&mut a.value, Value::Unit), a.span))
    }

    /// An optional argument, unchecked.
    pub(crate) fn get(&mut self, name: &str) -> Option<(Value, Span)> {
        let i = self.idx(name);
        self.take(i)
    }

    /// A required argument, unchecked.
    pub(crate) fn req(&mut self, name: &str) -> R<(Value, Span)> {
        self.get(name).ok_or_else(|| self.missing(name))
    }

    /// Where argument `name` is, if the call gives it (it stays in the call).
    pub(crate) fn given(&self, name: &str) -> Option<Span> {
        let k = self.filled_by[self.idx(name)];
        self.args.get(k as usize).map(|a| a.span)
    }

    /// `rtc::arg::missing` for parameter `name`.
    fn missing(&self, name: &str) -> EvalError {
        error(
            "rtc::arg::missing",
            self.site.span,
            format!("missing argument `{name}` in call of `{}`", self.site.name),
        )
        .with_label(format!("`{name}` is required"))
        .with_help(format!("add `{name}: ...`"))
        .into()
    }

    /// The slot of parameter `name`, which the schema declares of type `ty` (the getter's).
    /// The type is compared in tests and debug builds only: the getters are hot (a loop making
    /// a million spheres), and the lib tests read every parameter of every schema.
    #[inline(always)]
    fn typed(&self, name: &str, ty: Ty) -> usize {
        let i = self.idx(name);
        #[cfg(any(test, debug_assertions))]
        if self.sig.params[i].ty != ty {
            wrong_schema(self.sig, &self.sig.params[i], "it is read as another type");
        }
        #[cfg(not(any(test, debug_assertions)))]
        let _ = ty;
        i
    }

    /// Parameter `name` of type `ty`: its argument through `conv` (type and range), else its
    /// schema default through `lit` (at the call's span), else `rtc::arg::missing`.
    #[inline]
    fn read<T>(
        &mut self,
        name: &str,
        ty: Ty,
        conv: impl FnOnce(&'static Sig, &'static Param, &Value, Span) -> R<T>,
        lit: impl FnOnce(Lit) -> Option<T>,
    ) -> R<(T, Span)> {
        let i = self.typed(name, ty);
        let (sig, param) = (self.sig, &self.sig.params[i]);
        if let Some((v, s)) = self.take(i) {
            return Ok((conv(sig, param, &v, s)?, s));
        }
        match param.absent {
            Absent::Required => Err(self.missing(name)),
            Absent::Is(l) => match lit(l) {
                Some(x) => Ok((x, self.site.span)),
                None => wrong_schema(sig, param, "its default is of another type"),
            },
            Absent::Optional | Absent::Computed(_) => wrong_schema(
                sig,
                param,
                "it has no default: read it with an `_opt` getter",
            ),
        }
    }

    /// Parameter `name` of type `ty` through `conv`, or `None` when the call leaves it out.
    #[inline]
    fn read_opt<T>(
        &mut self,
        name: &str,
        ty: Ty,
        conv: impl FnOnce(&'static Sig, &'static Param, &Value, Span) -> R<T>,
    ) -> R<Option<(T, Span)>> {
        let i = self.typed(name, ty);
        let (sig, param) = (self.sig, &self.sig.params[i]);
        match self.take(i) {
            Some((v, s)) => Ok(Some((conv(sig, param, &v, s)?, s))),
            None => Ok(None),
        }
    }

    /// The number `name`, range-checked, or its default.
    pub(crate) fn float(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(f64, Span)> {
        self.read(
            name,
            Ty::Float,
            |g, p, v, s| float_of(q, g, p, v, s),
            |l| match l {
                Lit::Float(x) => Some(x),
                _ => None,
            },
        )
    }

    /// The number `name`, range-checked, if given.
    pub(crate) fn float_opt(
        &mut self,
        q: &(impl Quote + ?Sized),
        name: &str,
    ) -> R<Option<(f64, Span)>> {
        self.read_opt(name, Ty::Float, |g, p, v, s| float_of(q, g, p, v, s))
    }

    /// The `Int` `name`, range-checked, or its default.
    pub(crate) fn int(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(i64, Span)> {
        self.read(
            name,
            Ty::Int,
            |g, p, v, s| int_of(q, g, p, v, s),
            |l| match l {
                Lit::Int(i) => Some(i),
                _ => None,
            },
        )
    }

    /// The `Int` `name`, range-checked, if given.
    pub(crate) fn int_opt(
        &mut self,
        q: &(impl Quote + ?Sized),
        name: &str,
    ) -> R<Option<(i64, Span)>> {
        self.read_opt(name, Ty::Int, |g, p, v, s| int_of(q, g, p, v, s))
    }

    /// The angle `name` in radians, range-checked, or its default.
    pub(crate) fn angle(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(f64, Span)> {
        self.read(
            name,
            Ty::Angle,
            |g, p, v, s| angle_of(q, g, p, v, s),
            |l| match l {
                Lit::Degrees(d) => Some(d.to_radians()),
                _ => None,
            },
        )
    }

    /// The vector `name`, range-checked, or its default.
    pub(crate) fn vec3(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(DVec3, Span)> {
        self.read(
            name,
            Ty::Vec3,
            |_, p, v, s| vec3_of(q, p, v, s),
            |l| match l {
                Lit::Vec3(x) => Some(DVec3::from_array(x)),
                _ => None,
            },
        )
    }

    /// The vector `name`, range-checked, if given.
    pub(crate) fn vec3_opt(
        &mut self,
        q: &(impl Quote + ?Sized),
        name: &str,
    ) -> R<Option<(DVec3, Span)>> {
        self.read_opt(name, Ty::Vec3, |_, p, v, s| vec3_of(q, p, v, s))
    }

    /// The colour `name`, or its default.
    pub(crate) fn color(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(DVec3, Span)> {
        self.read(
            name,
            Ty::Color,
            |_, _, v, s| super::types::color(q, v, s),
            |l| match l {
                Lit::Color(x) => Some(DVec3::from_array(x)),
                _ => None,
            },
        )
    }

    /// The Bool `name`, or its default.
    pub(crate) fn bool(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<bool> {
        let conv = |_: &Sig, _: &Param, v: &Value, s| super::types::boolean(q, v, s);
        let lit = |l| match l {
            Lit::Bool(b) => Some(b),
            _ => None,
        };
        Ok(self.read(name, Ty::Bool, conv, lit)?.0)
    }

    /// The string `name` (required).
    pub(crate) fn string(&mut self, q: &(impl Quote + ?Sized), name: &str) -> R<(Rc<str>, Span)> {
        let conv = |_: &Sig, _: &Param, v: &Value, s| super::types::string(q, v, s);
        self.read(name, Ty::String, conv, |_| None)
    }

    /// The `Int` `v` (an element of argument `name`) by the type and range of parameter `name`.
    pub(crate) fn int_in(
        &self,
        q: &(impl Quote + ?Sized),
        name: &str,
        v: &Value,
        span: Span,
    ) -> R<i64> {
        int_of(q, self.sig, &self.sig.params[self.idx(name)], v, span)
    }

    /// Whether `x`, computed in place of argument `name` (a default that depends on other
    /// arguments), is in the parameter's range.
    pub(crate) fn in_range(&self, name: &str, x: f64, span: Span) -> R<()> {
        number_in_range(self.sig, &self.sig.params[self.idx(name)], x, span)
    }

    /// The declared range check of `name` for a parameter its built-in checks itself
    /// (`checked_by_builtin`: the rule depends on other arguments), once it knows the rule
    /// applies.
    pub(crate) fn declared_range(&self, name: &str, x: f64, span: Span) -> R<()> {
        let param = &self.sig.params[self.idx(name)];
        if param.range.holds(x) && x.is_finite() {
            Ok(())
        } else {
            Err(out_of_range(self.sig, param, x, span))
        }
    }

    /// The schema's default of the pair of `Int`s `name` (`resolution: [640, 480]`).
    pub(crate) fn default_ints(&self, name: &str) -> [i64; 2] {
        let param = &self.sig.params[self.idx(name)];
        match param.absent {
            Absent::Is(Lit::Ints(pair)) => pair,
            _ => wrong_schema(self.sig, param, "its default is no pair of `Int`s"),
        }
    }

    /// The angle `v` (given for parameter `name`) by its type and range.
    pub(crate) fn angle_in(
        &self,
        q: &(impl Quote + ?Sized),
        name: &str,
        v: &Value,
        span: Span,
    ) -> R<f64> {
        angle_of(q, self.sig, &self.sig.params[self.idx(name)], v, span)
    }
}

/// A schema that does not fit the getter a built-in reads it with: a bug in the built-in.
#[cold]
#[inline(never)]
fn wrong_schema(sig: &Sig, param: &Param, why: &str) -> ! {
    panic!(
        "schema of `{}`: parameter `{}`: {why}",
        sig.name, param.name
    )
}

/// A number for `param` of `sig`: its type, then its range (unless the built-in checks it).
pub(crate) fn float_of(
    q: &(impl Quote + ?Sized),
    sig: &Sig,
    param: &Param,
    v: &Value,
    span: Span,
) -> R<f64> {
    let x = super::types::num(q, v, span)?;
    number_in_range(sig, param, x, span)?;
    Ok(x)
}

/// The range check of a number for `param` of `sig` (unless the built-in checks it). A
/// parameter's rule also refuses infinities and NaN; a function's domain is the rule alone
/// (`sqrt` of infinity is infinity).
#[inline]
fn number_in_range(sig: &Sig, param: &Param, x: f64, span: Span) -> R<()> {
    if param.checked != Checked::OnRead || matches!(param.range, Range::Any) {
        return Ok(());
    }
    if !param.range.holds(x) || (sig.blame == Blame::Param && !x.is_finite()) {
        return Err(out_of_range(sig, param, x, span));
    }
    Ok(())
}

/// An `Int` for `param` of `sig`: its type, then its range (unless the built-in checks it).
pub(crate) fn int_of(
    q: &(impl Quote + ?Sized),
    sig: &Sig,
    param: &Param,
    v: &Value,
    span: Span,
) -> R<i64> {
    let i = super::types::int(q, v, span)?;
    if param.checked == Checked::OnRead && !param.range.holds_int(i) {
        return Err(out_of_range(sig, param, i as f64, span));
    }
    Ok(i)
}

/// An angle (radians) for `param` of `sig`: its type, then its range.
fn angle_of(q: &(impl Quote + ?Sized), sig: &Sig, param: &Param, v: &Value, span: Span) -> R<f64> {
    let a = super::types::angle(q, v, span)?;
    if param.checked == Checked::OnRead && !param.range.holds(a) {
        return Err(out_of_range(sig, param, a, span));
    }
    Ok(a)
}

/// A vector for `param`: its type, then a non-zero vector's rule.
fn vec3_of(q: &(impl Quote + ?Sized), param: &Param, v: &Value, span: Span) -> R<DVec3> {
    let d = super::types::vec3(q, v, span)?;
    if param.checked == Checked::OnRead
        && matches!(param.range, Range::NonZero)
        && (d.length_squared() == 0.0 || !d.is_finite())
    {
        let name = param.name;
        return Err(error(
            "rtc::param::out_of_range",
            span,
            format!("`{name}` must be a non-zero vector"),
        )
        .with_label("this vector has length 0")
        .with_help(format!("give a direction, e.g. `{name}: Y`"))
        .into());
    }
    Ok(d)
}

/// `x` for `param` of `sig` is outside the parameter's range: the parameter's rule, or the
/// function's domain (`sqrt(x)` needs `x` >= 0).
#[cold]
#[inline(never)]
fn out_of_range(sig: &Sig, param: &Param, x: f64, span: Span) -> EvalError {
    let rule = param.range.rule(param.ty);
    match sig.blame {
        Blame::Param if param.ty == Ty::Angle => {
            let shown = format!("{}deg", super::value::fmt_f(x.to_degrees()));
            range_error(param.name, &rule, &shown, span)
        }
        Blame::Param => range_error(param.name, &rule, &super::value::fmt_f(x), span),
        Blame::Function => {
            let (f, name) = (sig.name, param.name);
            let shown = super::value::fmt_f(x);
            error(
                "rtc::param::out_of_range",
                span,
                format!("`{f}({name})` needs `{name}` {rule}, but `{name}` is {shown}"),
            )
            .with_label(format!("evaluates to {shown}"))
            .with_help(format!("pass `{f}` a value that is {rule}"))
            .into()
        }
    }
}

/// Range check: `name` must satisfy `ok`, described as `rule` (e.g. "> 0").
pub(crate) fn check(ok: bool, name: &str, rule: &str, v: f64, span: Span) -> R<()> {
    if ok && v.is_finite() {
        return Ok(());
    }
    check_shown(false, name, rule, &super::value::fmt_f(v), span)
}

/// Range check with the offending value already formatted (e.g. with its unit).
pub(crate) fn check_shown(ok: bool, name: &str, rule: &str, shown: &str, span: Span) -> R<()> {
    if ok {
        return Ok(());
    }
    Err(range_error(name, rule, shown, span))
}

/// `rtc::param::out_of_range`: "`name` must be `rule`, but it is `shown`".
fn range_error(name: &str, rule: &str, shown: &str, span: Span) -> EvalError {
    error(
        "rtc::param::out_of_range",
        span,
        format!("`{name}` must be {rule}, but it is {shown}"),
    )
    .with_label(format!("evaluates to {shown}"))
    .with_help(format!("use a value that is {rule}"))
    .into()
}
