//! The integrator of a shaded image: `whitted` (the default) or the path tracer `path(..)`
//! (docs/gi.md), and the sampling budget they share.

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::{R, error};
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir;
use crate::ir::limits::{MAX_BOUNCES, MAX_PATH_SAMPLES, MAX_PIXEL_PATHS};
use crate::source::Span;

/// The integrators' constructors with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&PATH, path)];

/// Named integrators.
pub(crate) fn constants() -> Vec<(&'static str, Value)> {
    vec![("whitted", Value::Integrator(ir::Integrator::Whitted))]
}

/// `path(samples, bounces, roulette)` (the defaults are `ir::PathTracing::DEFAULT`'s).
static PATH: Sig = Sig::new(
    "path",
    Group::Render,
    "The path tracer: global illumination with next-event estimation (docs/gi.md).",
    &[
        Param::new(
            "samples",
            Ty::Int,
            "paths per camera ray (a pixel gets supersampling² · samples)",
        )
        .unit(Unit::Samples)
        .range(Range::Ints(1, MAX_PATH_SAMPLES as i64))
        .or(Lit::Int(ir::PathTracing::DEFAULT.samples as i64)),
        Param::new(
            "bounces",
            Ty::Int,
            "the most scattering events along a path",
        )
        .range(Range::Ints(0, MAX_BOUNCES as i64))
        .or(Lit::Int(ir::PathTracing::DEFAULT.bounces as i64)),
        Param::new(
            "roulette",
            Ty::OneOf(&[Ty::Int, Ty::Bool]),
            "the bounce from which Russian roulette may end a path; `false` never",
        )
        .range(Range::Ints(0, MAX_BOUNCES as i64))
        .or(Lit::Int(ir::PathTracing::DEFAULT.roulette as i64)),
    ],
    "Integrator",
)
.examples(&["path(samples: 64, bounces: 8, roulette: 3)"]);
fn path(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &PATH, a)?;
    let samples = p.int(it, "samples")?.0 as u32;
    let bounces = p.int(it, "bounces")?.0 as u32;
    let roulette = match p.get("roulette") {
        None => ir::PathTracing::DEFAULT.roulette,
        Some((Value::Bool(false), _)) => MAX_BOUNCES,
        Some((Value::Bool(true), _)) => ir::PathTracing::DEFAULT.roulette,
        Some((v @ Value::Int(_), sp)) => p.int_in(it, "roulette", &v, sp)? as u32,
        Some((other, sp)) => {
            return Err(types::mismatch(it, "Int", &other, sp)
                .with_help("write the first bounce it may end, e.g. `3`, or `false`")
                .into());
        }
    };
    Ok(Value::Integrator(ir::Integrator::Path(ir::PathTracing {
        samples,
        bounces,
        roulette,
    })))
}

/// The integrator a `render { integrator: .. }` value names.
pub(super) fn integrator_of(it: &dyn Host, v: Value, sp: Span) -> R<ir::Integrator> {
    match v {
        Value::Integrator(i) => Ok(i),
        Value::Builtin(b) if b.name == "path" => Ok(ir::Integrator::Path(ir::PathTracing::DEFAULT)),
        other => Err(types::mismatch(it, "Integrator", &other, sp)
            .with_help("write `whitted`, `path` or `path(samples: 64, bounces: 8)`")
            .into()),
    }
}

/// The paths one pixel gets (each draws its numbers from one scrambled Sobol' sequence per
/// decision, which holds 2^16 points) must fit the sequence: more would repeat paths exactly.
pub(super) fn check_paths_per_pixel(
    integrator: ir::Integrator,
    sampling: ir::Sampling,
    sp: Span,
) -> R<()> {
    let ir::Integrator::Path(p) = integrator else {
        return Ok(());
    };
    let per_axis = match sampling {
        ir::Sampling::Grid { factor } => factor,
        ir::Sampling::Adaptive { max, .. } => max,
    };
    let total = p.paths_per_pixel(per_axis * per_axis);
    if total <= u64::from(MAX_PIXEL_PATHS) {
        return Ok(());
    }
    let most = (MAX_PIXEL_PATHS / (per_axis * per_axis)).max(1);
    Err(error(
        "rtc::render::samples",
        sp,
        format!(
            "{per_axis}² camera samples × {} paths is {total} paths per pixel, more than {MAX_PIXEL_PATHS}",
            p.samples
        ),
    )
    .with_label("too many paths per pixel")
    .with_help(format!(
        "lower `samples` to {most} or less, or the supersampling; past {MAX_PIXEL_PATHS} paths the random sequence would repeat"
    ))
    .into())
}
