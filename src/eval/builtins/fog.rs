//! `fog { .. }`: POV-Ray's fog, constant or (with `altitude`) ground fog, optionally thinned by
//! a pattern; a part of the render settings (`render { fog: .. }`).

use std::rc::Rc;

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::{R, error};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::{FogVal, Value};
use crate::ir;

/// The fog constructor with its schema.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&FOG, fog)];

/// `fog { color:, distance:, filter:, transmit:, offset:, altitude: }`: POV-Ray's fog, constant
/// or (with `altitude`) ground fog.
static FOG: Sig = Sig::new(
    "fog",
    Group::Render,
    "Fog along every ray outside objects: after a distance `d` a ray keeps `max(exp(−d/distance), transmit)` of its light and takes the rest from `color` (POV-Ray's fog).",
    &[
        Param::new("color", Ty::Color, "the fog's colour"),
        Param::new(
            "distance",
            Ty::Float,
            "the distance over which a ray keeps 1/e of its light",
        )
        .unit(Unit::Length)
        .range(Range::Positive),
        Param::new(
            "filter",
            Ty::Float,
            "the share of the light kept tinted by the fog's colour",
        )
        .range(Range::UnitInterval)
        .or(Lit::Float(0.0)),
        Param::new(
            "transmit",
            Ty::Float,
            "the least share of the light kept, however far",
        )
        .range(Range::UnitInterval)
        .or(Lit::Float(0.0)),
        Param::new(
            "offset",
            Ty::Float,
            "ground fog: the height (along +Y) up to which it is full",
        )
        .unit(Unit::Length)
        .or(Lit::Float(0.0)),
        Param::new(
            "altitude",
            Ty::Float,
            "ground fog: the height scale of its falloff above `offset` (density `1/(1 + h²)`, `h = (y − offset)/altitude`); without it the fog is constant",
        )
        .unit(Unit::Length)
        .range(Range::Positive)
        .optional(),
        Param::new(
            "pattern",
            Ty::Texture,
            "a pattern thinning the fog where its value is high, read at the midpoint of each ray segment (POV-Ray's fog turbulence)",
        )
        .optional(),
        Param::new(
            "pattern_depth",
            Ty::Float,
            "how strongly the pattern thins the fog (POV-Ray's `turb_depth`)",
        )
        .range(Range::UnitInterval)
        .or(Lit::Float(0.5)),
    ],
    "Fog",
)
.examples(&[
    "fog { color: rgb(0.7, 0.7, 0.8), distance: 20 }",
    "fog { color: rgb(1, 1, 1), distance: 5, transmit: 0.2, offset: 0.5, altitude: 1 }",
    "fog { color: rgb(0.8, 0.8, 0.8), distance: 10, pattern: bozo().scale(2), pattern_depth: 0.7 }",
]);
fn fog(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &FOG, a)?;
    let offset = p.float(it, "offset")?.0;
    let ground = p
        .float_opt(it, "altitude")?
        .map(|(altitude, _)| ir::GroundFog { offset, altitude });
    let depth = p.float(it, "pattern_depth")?.0;
    let pattern = match p.get("pattern") {
        Some((Value::Texture(t), sp)) => {
            // Read at points in the world: an image or a uv-space pattern has nothing there.
            let world =
                matches!(&t.t, ir::Texture::Pattern(p) if p.space == ir::PatternSpace::Object);
            if !world {
                return Err(error(
                    "rtc::render::fog",
                    sp,
                    "a fog's `pattern` must be a pattern read in space",
                )
                .with_label("not a pattern, or read in uv space")
                .with_help("use a pattern such as `bozo()` or `granite()`, without `.uv()`")
                .into());
            }
            Some((t, depth))
        }
        Some((other, sp)) => return Err(types::mismatch(it, "Texture", &other, sp).into()),
        None => None,
    };
    Ok(Value::Fog(Rc::new(FogVal {
        fog: ir::Fog {
            color: p.color(it, "color")?.0,
            distance: p.float(it, "distance")?.0,
            filter: p.float(it, "filter")?.0,
            transmit: p.float(it, "transmit")?.0,
            ground,
            pattern: None,
        },
        pattern,
    })))
}
