//! Noise built-ins: the pattern module's noises as functions of a point (`noise(p)`,
//! `fbm(p, octaves: 4)`, ...), for any computation and for functions compiled into patterns
//! (`pattern(f)`, `eval::compile`), which compute the same bits through
//! [`crate::pattern::program::NoiseFn`].

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::R;
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty};
use crate::eval::value::Value;
use crate::pattern::program::NoiseFn;
use crate::pattern::{Crackle, Fractal};

/// The noise functions with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&NOISE, noise),
    (&SNOISE, snoise),
    (&VNOISE, vnoise),
    (&FBM, fbm),
    (&TURBULENCE, turbulence),
    (&WORLEY, worley),
];

/// The point every noise reads.
const P: Param = Param::new("p", Ty::Vec3, "the point");
/// The seed of every noise.
pub(crate) const SEED: Param = Param::new(
    "seed",
    Ty::Int,
    "another seed gives another noise of the same look",
)
.range(Range::Ints(0, u32::MAX as i64))
.or(Lit::Int(0));
/// `octaves`, `omega` and `lambda` of the fractal sums.
const OCTAVES: Param = Param::new("octaves", Ty::Int, "how many octaves of noise")
    .range(Range::Ints(1, 16))
    .or(Lit::Int(6));
const OMEGA: Param = Param::new(
    "omega",
    Ty::Float,
    "each octave's weight relative to the one before",
)
.range(Range::NonNegative)
.or(Lit::Float(0.5));
const LAMBDA: Param = Param::new(
    "lambda",
    Ty::Float,
    "each octave's frequency relative to the one before",
)
.range(Range::Positive)
.or(Lit::Float(2.0));
/// Worley's form.
const FORM: Param = Param::new(
    "form",
    Ty::String,
    "which distance: \"f1\" (nearest point), \"f2\" (second nearest) or \"edges\" (F2 − F1)",
)
.checked_by_builtin()
.or(Lit::Name("\"f1\""));

/// The names `form` takes, in the order of [`form_of`].
pub(crate) const FORMS: &[&str] = &["f1", "f2", "edges"];

/// The Worley distance a `form` names.
pub(crate) fn form_of(name: &str) -> Option<Crackle> {
    match name {
        "f1" => Some(Crackle::F1),
        "f2" => Some(Crackle::F2),
        "edges" => Some(Crackle::Edges),
        _ => None,
    }
}

/// `noise(p, seed)`.
pub(crate) static NOISE: Sig = Sig::new(
    "noise",
    Group::Noise,
    "Smooth noise in [0, 1], mean 0.5: the noise of `bozo` (Perlin's improved noise).",
    &[P, SEED],
    "Float",
)
.examples(&["noise([0.5, 1.5, 2])"]);
/// `snoise(p, seed)`.
pub(crate) static SNOISE: Sig = Sig::new(
    "snoise",
    Group::Noise,
    "Signed smooth noise, mean 0, within ±1.04: what `fbm` sums.",
    &[P, SEED],
    "Float",
)
.examples(&["snoise([0.5, 1.5, 2], seed: 3)"]);
/// `vnoise(p, seed)`.
pub(crate) static VNOISE: Sig = Sig::new(
    "vnoise",
    Group::Noise,
    "Three independent signed noises as a vector (each like `snoise`).",
    &[P, SEED],
    "Vec3",
)
.examples(&["vnoise([0.5, 1.5, 2])"]);
/// `fbm(p, octaves, omega, lambda, seed)`.
pub(crate) static FBM: Sig = Sig::new(
    "fbm",
    Group::Noise,
    "Fractal Brownian motion: the sum over octaves i of omegaⁱ·snoise(lambdaⁱ·p); mean 0.",
    &[P, OCTAVES, OMEGA, LAMBDA, SEED],
    "Float",
)
.examples(&["fbm([0.5, 1.5, 2], octaves: 4)"]);
/// `turbulence(p, octaves, omega, lambda, seed)`.
pub(crate) static TURBULENCE: Sig = Sig::new(
    "turbulence",
    Group::Noise,
    "Perlin's turbulence: the sum over octaves i of omegaⁱ·|snoise(lambdaⁱ·p)|; at least 0.",
    &[P, OCTAVES, OMEGA, LAMBDA, SEED],
    "Float",
)
.examples(&["turbulence([0.5, 1.5, 2], octaves: 4)"]);
/// `worley(p, form, seed)`.
pub(crate) static WORLEY: Sig = Sig::new(
    "worley",
    Group::Noise,
    "Worley's cellular noise: the distance to the nearest feature point (one per unit cell), the second nearest, or their difference (0 on the cell walls); unclamped.",
    &[P, FORM, SEED],
    "Float",
)
.examples(&["worley([0.5, 1.5, 2])", "worley([0.5, 1.5, 2], form: \"edges\")"]);

/// The point and seed of `sig`'s call.
fn point_and_seed(it: &dyn Host, p: &mut Params) -> R<(glam::DVec3, u32)> {
    let (point, _) = p.vec3(it, "p")?;
    let (seed, _) = p.int(it, "seed")?;
    Ok((point, seed as u32))
}

/// The fractal of a call of `fbm` or `turbulence`.
fn fractal(it: &dyn Host, p: &mut Params) -> R<Fractal> {
    let (octaves, _) = p.int(it, "octaves")?;
    let (omega, _) = p.float(it, "omega")?;
    let (lambda, _) = p.float(it, "lambda")?;
    Ok(Fractal {
        octaves: octaves as u32,
        omega,
        lambda,
    })
}

/// The value of `f` at `point` as a language value.
fn value(f: NoiseFn, point: glam::DVec3) -> Value {
    let v = f.eval(point);
    if f.width() == 3 {
        Value::Vec3(v)
    } else {
        Value::Float(v.x)
    }
}

fn noise(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &NOISE, a)?;
    let (point, seed) = point_and_seed(it, &mut p)?;
    Ok(value(NoiseFn::Unit { seed }, point))
}

fn snoise(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SNOISE, a)?;
    let (point, seed) = point_and_seed(it, &mut p)?;
    Ok(value(NoiseFn::Signed { seed }, point))
}

fn vnoise(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &VNOISE, a)?;
    let (point, seed) = point_and_seed(it, &mut p)?;
    Ok(value(NoiseFn::Vector { seed }, point))
}

fn fbm(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &FBM, a)?;
    let fractal = fractal(it, &mut p)?;
    let (point, seed) = point_and_seed(it, &mut p)?;
    Ok(value(NoiseFn::Fbm { fractal, seed }, point))
}

fn turbulence(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &TURBULENCE, a)?;
    let fractal = fractal(it, &mut p)?;
    let (point, seed) = point_and_seed(it, &mut p)?;
    Ok(value(NoiseFn::Turbulence { fractal, seed }, point))
}

fn worley(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &WORLEY, a)?;
    let form = match p.get("form") {
        None => Crackle::F1,
        Some((Value::Str(f), sp)) => match form_of(&f) {
            Some(form) => form,
            None => {
                return Err(
                    super::super::texture_methods::bad_choice("form", &f, FORMS, sp).into(),
                );
            }
        },
        Some((other, sp)) => {
            return Err(crate::eval::types::mismatch(it, "String", &other, sp).into());
        }
    };
    let (point, seed) = point_and_seed(it, &mut p)?;
    Ok(value(NoiseFn::Worley { form, seed }, point))
}
