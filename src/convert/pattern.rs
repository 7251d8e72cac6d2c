//! A pattern texture as rtc source: its constructor, then its modifiers in the order they were
//! written (the reverse of the order a point meets them), then its colour map and space.

use glam::DAffine3;

use super::placement;
use super::text::{color, number, vector};
use crate::ir::{PatternSpace, PatternTexture};
use crate::pattern::{Crackle, Pattern, Turbulence, Warp, WaveShape};

/// `pt` as a chain of calls: `marble().turbulence(0.5).colors([...]).scale(2)`.
pub(crate) fn source(pt: &PatternTexture) -> String {
    let mut out = constructor(&pt.field.pattern, pt.name());
    if let Some(t) = classic_turbulence(&pt.field.pattern) {
        out += &turbulence(t);
    }
    let wave = pt.field.wave;
    if wave.shape != pt.field.pattern.default_wave() {
        out += &match wave.shape {
            WaveShape::Ramp => ".wave(\"ramp\")".into(),
            WaveShape::Triangle => ".wave(\"triangle\")".into(),
            WaveShape::Sine => ".wave(\"sine\")".into(),
            WaveShape::Scallop => ".wave(\"scallop\")".into(),
            WaveShape::Cubic => ".wave(\"cubic\")".into(),
            WaveShape::Poly(e) => format!(".wave(\"poly\", exponent: {})", number(e)),
        };
    }
    if wave.frequency != 1.0 {
        out += &format!(".frequency({})", number(wave.frequency));
    }
    if wave.phase != 0.0 {
        out += &format!(".phase({})", number(wave.phase));
    }
    let stops: Vec<String> = pt
        .map
        .stops()
        .iter()
        .map(|s| {
            let c = s.color;
            if c.filter == 0.0 && c.transmit == 0.0 {
                format!("[{}, {}]", number(s.at), color(c.rgb))
            } else {
                format!(
                    "{{ at: {}, color: {}, filter: {}, transmit: {} }}",
                    number(s.at),
                    color(c.rgb),
                    number(c.filter),
                    number(c.transmit)
                )
            }
        })
        .collect();
    out += &format!(".colors([{}])", stops.join(", "));
    // The point meets the warps first to last: the first was written last.
    for w in pt.field.warps.iter().rev() {
        out += &match w {
            Warp::Turbulence(t) => turbulence(t),
            Warp::Repeat(r) => format!(
                ".repeat({}, width: {}, offset: {}, flip: {})",
                vector(glam::DVec3::AXES[r.axis.min(2)]),
                number(r.width),
                vector(r.offset),
                vector(glam::DVec3::select(
                    r.flip.cmplt(glam::DVec3::ZERO),
                    glam::DVec3::ONE,
                    glam::DVec3::ZERO
                )),
            ),
            Warp::Placement(m) => placed(m),
            Warp::Transform(m) => placed(&m.inverse()),
            Warp::Spherical => ".warp(\"spherical\")".into(),
            Warp::Cylindrical => ".warp(\"cylindrical\")".into(),
            Warp::Toroidal(r) => format!(".warp(\"toroidal\", radius: {})", number(*r)),
        };
    }
    out += &placed(&pt.placement);
    if pt.space == PatternSpace::Uv {
        out += ".uv()";
    }
    out
}

/// The transform methods that compose to `placement` exactly, as an object's (none for the
/// identity).
fn placed(placement: &DAffine3) -> String {
    if *placement == DAffine3::IDENTITY {
        return String::new();
    }
    placement::methods(placement, None).concat()
}

/// `.turbulence(..)` with the parameters that differ from the defaults.
fn turbulence(t: &Turbulence) -> String {
    let d = Turbulence::NONE;
    let amount = if t.amount.x == t.amount.y && t.amount.y == t.amount.z {
        number(t.amount.x)
    } else {
        vector(t.amount)
    };
    let mut out = format!(".turbulence({amount}");
    if t.fractal.octaves != d.fractal.octaves {
        out += &format!(", octaves: {}", t.fractal.octaves);
    }
    if t.fractal.omega != d.fractal.omega {
        out += &format!(", omega: {}", number(t.fractal.omega));
    }
    if t.fractal.lambda != d.fractal.lambda {
        out += &format!(", lambda: {}", number(t.fractal.lambda));
    }
    if t.seed != 0 {
        out += &format!(", seed: {}", t.seed);
    }
    out + ")"
}

/// The turbulence a classic pattern holds itself, if any.
fn classic_turbulence(p: &Pattern) -> Option<&Turbulence> {
    match p {
        Pattern::Marble { turbulence }
        | Pattern::Wood { turbulence }
        | Pattern::Spiral1 { turbulence, .. }
        | Pattern::Spiral2 { turbulence, .. } => (!turbulence.is_none()).then_some(turbulence),
        _ => None,
    }
}

/// The constructor call of a pattern.
fn constructor(p: &Pattern, pt_name: &str) -> String {
    let seeded = |name: &str, seed: u32| {
        if seed == 0 {
            format!("{name}()")
        } else {
            format!("{name}(seed: {seed})")
        }
    };
    match p {
        Pattern::Gradient { axis } => format!("gradient(axis: {})", vector(*axis)),
        Pattern::Checker => "checker(size: 1, a: rgb(0, 0, 0), b: rgb(1, 1, 1))".into(),
        Pattern::Hexagon
        | Pattern::Radial
        | Pattern::Onion
        | Pattern::Spherical
        | Pattern::Cylindrical
        | Pattern::Boxed
        | Pattern::Planar
        | Pattern::Square
        | Pattern::Triangular
        | Pattern::Marble { .. }
        | Pattern::Wood { .. }
        | Pattern::Leopard => format!("{}()", pt_name),
        Pattern::Brick { size, mortar } => {
            format!(
                "brick(size: {}, mortar: {})",
                vector(*size),
                number(*mortar)
            )
        }
        Pattern::Spiral1 { arms, .. } => format!("spiral1(arms: {})", number(*arms)),
        Pattern::Spiral2 { arms, .. } => format!("spiral2(arms: {})", number(*arms)),
        Pattern::Agate {
            turb,
            fractal,
            seed,
        } => {
            let mut s = format!("agate(turb: {}, seed: {seed})", number(*turb));
            if *fractal != crate::pattern::Fractal::default() {
                s += &turbulence(&Turbulence {
                    amount: glam::DVec3::ONE,
                    fractal: *fractal,
                    seed: 0,
                });
            }
            s
        }
        Pattern::Bozo { seed } => seeded("bozo", *seed),
        Pattern::Granite { seed } => seeded("granite", *seed),
        Pattern::Ripples {
            frequency,
            phase,
            count,
        } => format!(
            "ripples(frequency: {}, phase: {}, count: {count})",
            number(*frequency),
            number(*phase)
        ),
        Pattern::Waves {
            frequency,
            phase,
            count,
        } => format!(
            "waves(frequency: {}, phase: {}, count: {count})",
            number(*frequency),
            number(*phase)
        ),
        Pattern::Wrinkles { seed } => seeded("wrinkles", *seed),
        Pattern::Dents { seed } => seeded("dents", *seed),
        Pattern::Crackle { form, seed } => {
            let form = match form {
                Crackle::F1 => "f1",
                Crackle::F2 => "f2",
                Crackle::Edges => "edges",
            };
            format!("crackle(form: \"{form}\", seed: {seed})")
        }
        Pattern::Cells { seed } => seeded("cells", *seed),
        Pattern::Function(f) => format!(
            "pattern({})",
            super::program::function_source(f)
                .unwrap_or_else(|| super::text::string(crate::ir::COMPILED_FUNCTION))
        ),
    }
}
