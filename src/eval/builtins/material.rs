//! Materials: `material { .. }`, its fields' schema (shared by `with` and `m.field`) and the
//! warnings a material's combination of fields earns.

use std::rc::Rc;

use glam::DVec3;

use crate::diag::Diagnostic;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::args::{Params, check, float_of, int_of};
use crate::eval::error::{R, error, suggest};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::{Mat, Value};
use crate::ir;
use crate::source::Span;

/// The material constructor with its schema.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&MATERIAL, material)];
/// A material's fields, in positional order: `material { .. }`, `m with { .. }` and `m.kd` read
/// their names, types, ranges and defaults here (the defaults are `ir::Material::default()`'s).
pub(crate) static MATERIAL: Sig = Sig::new(
    "material",
    Group::Look,
    "A surface's material (every field optional; `material {}` is the default material).",
    &[
        Param::new(
            "color",
            Ty::Color,
            "the base colour C (replaced by `texture`)",
        )
        .or(Lit::Color([0.8, 0.8, 0.8])),
        unit_coefficient("ka", "the ambient coefficient", 0.2),
        unit_coefficient("kd", "the diffuse coefficient", 0.8),
        unit_coefficient("ks", "the specular coefficient", 0.0),
        Param::new("n", Ty::Float, "the Phong exponent (highlight tightness)")
            .range(Range::Positive)
            .or(Lit::Float(1.0)),
        unit_coefficient("reflect", "the mirror reflection weight", 0.0),
        unit_coefficient("refract", "the transmission weight", 0.0),
        Param::new(
            "eta",
            Ty::Float,
            "the index of refraction inside (outside is 1)",
        )
        .range(Range::Positive)
        .or(Lit::Float(1.0)),
        Param::new("texture", Ty::Texture, "a colour texture replacing `color`").optional(),
        Param::new(
            "bump",
            Ty::Texture,
            "a height texture perturbing the normal",
        )
        .optional(),
        Param::new(
            "bump_scale",
            Ty::Float,
            "the bump strength; only with `bump`",
        )
        .range(Range::NonNegative)
        .or(Lit::Float(1.0)),
        Param::new("shading", Ty::Shading, "the material's own shading model")
            .computed("the scene's"),
        unit_coefficient(
            "gloss",
            "spreads reflected and refracted rays over a cone of half-angle `gloss·90°`",
            0.0,
        ),
        Param::new(
            "gloss_samples",
            Ty::Int,
            "rays per glossy lobe at a camera ray's hit",
        )
        .unit(Unit::Rays)
        .range(Range::Ints(1, crate::ir::limits::MAX_GLOSS_SAMPLES as i64))
        .or(Lit::Int(8)),
        unit_coefficient(
            "filter",
            "the share of the refracted light tinted by the colour (POV-Ray's filter); 0 passes it untinted",
            ir::LANGUAGE_FILTER,
        ),
        Param::new(
            "absorption",
            Ty::Color,
            "Beer–Lambert absorption per unit length inside: light crossing `d` keeps `exp(−absorption·d)`",
        )
        .or(Lit::Color([0.0, 0.0, 0.0])),
        Param::new(
            "fresnel",
            Ty::Bool,
            "reflects `reflect` × the dielectric Fresnel reflectance of `eta`; refracts the rest",
        )
        .or(Lit::Bool(false)),
        Param::new(
            "conserve_energy",
            Ty::Bool,
            "takes the reflected share from the refracted light (POV-Ray's conserve_energy)",
        )
        .or(Lit::Bool(false)),
        unit_coefficient(
            "metallic",
            "how much the highlight takes the surface colour (POV-Ray's metallic)",
            0.0,
        ),
        Param::new(
            "brilliance",
            Ty::Float,
            "the diffuse falloff exponent: diffuse light goes with `(N·L)^brilliance`",
        )
        .range(Range::Positive)
        .or(Lit::Float(1.0)),
        Param::new(
            "emission",
            Ty::Color,
            "light emitted without any light source, times the colour (POV-Ray's emission)",
        )
        .or(Lit::Color([0.0, 0.0, 0.0])),
        Param::new(
            "emission_sides",
            Ty::Int,
            "2 emits on both sides; 1 only on the side the normal points to (the path tracer's rule)",
        )
        .range(Range::Ints(1, 2))
        .or(Lit::Int(2)),
    ],
    "Material",
)
.examples(&["material { color: rgb(0.8, 0.1, 0.1), kd: 0.6, ks: 0.4, n: 32 }", "material { ka: 0, kd: 0.05, ks: 0.5, n: 200, reflect: 0.1, refract: 0.9, eta: 1.5, gloss: 0.1, gloss_samples: 16 }", "material { texture: stripes(size: 0.2), bump: checker(size: 0.1), bump_scale: 0.3, shading: hatching }"]);

/// A material coefficient in [0, 1].
const fn unit_coefficient(name: &'static str, doc: &'static str, default: f64) -> Param {
    Param::new(name, Ty::Float, doc)
        .range(Range::UnitInterval)
        .or(Lit::Float(default))
}

/// Sets one material field with the type and range checks of its schema ([`MATERIAL`];
/// shared by `material` and `with`).
pub(crate) fn set_mat_field(
    it: &dyn Host,
    m: &mut Mat,
    name: crate::syntax::ast::Name,
    v: &Value,
    span: Span,
) -> R<()> {
    let field = name.sym.as_str();
    let Some(param) = MATERIAL.param(field) else {
        let help = suggest(field, MATERIAL.names())
            .unwrap_or_else(|| format!("materials have: {}", fields().join(", ")));
        return Err(error(
            "rtc::field::unknown",
            name.span,
            format!("materials have no field `{field}`"),
        )
        .with_label("unknown field")
        .with_help(help)
        .into());
    };
    let number = || float_of(it, &MATERIAL, param, v, span);
    match param.name {
        "color" => m.m.color = types::color(it, v, span)?,
        "ka" => m.m.ka = number()?,
        "kd" => m.m.kd = number()?,
        "ks" => m.m.ks = number()?,
        "n" => m.m.n = number()?,
        "reflect" => m.m.reflect = number()?,
        "refract" => m.m.refract = number()?,
        "eta" => m.m.eta = number()?,
        "gloss" => m.m.gloss = number()?,
        "gloss_samples" => m.m.gloss_samples = int_of(it, &MATERIAL, param, v, span)? as u32,
        "filter" => m.m.filter = number()?,
        "absorption" => m.m.absorption = non_negative_color(it, v, span, "absorption")?,
        "fresnel" => m.m.fresnel = types::boolean(it, v, span)?,
        "conserve_energy" => m.m.conserve_energy = types::boolean(it, v, span)?,
        "metallic" => m.m.metallic = number()?,
        "brilliance" => m.m.brilliance = number()?,
        "emission" => m.m.emission = non_negative_color(it, v, span, "emission")?,
        "emission_sides" => {
            m.m.emits_both_sides = int_of(it, &MATERIAL, param, v, span)? == 2;
        }
        "texture" => match v {
            Value::Texture(t) => m.texture = Some(t.clone()),
            other => return Err(types::mismatch(it, "Texture", other, span).into()),
        },
        "bump" => match v {
            Value::Texture(t) => m.bump = Some((t.clone(), m.bump.as_ref().map_or(1.0, |b| b.1))),
            other => return Err(types::mismatch(it, "Texture", other, span).into()),
        },
        "bump_scale" => {
            let x = number()?;
            match &mut m.bump {
                Some(b) => b.1 = x,
                None => {
                    return Err(error(
                        "rtc::param::needs",
                        span,
                        "`bump_scale` without a `bump` texture",
                    )
                    .with_label("nothing to scale")
                    .with_help("add `bump: ...` with a texture, or remove `bump_scale`")
                    .into());
                }
            }
        }
        "shading" => match v {
            Value::Shading(s) => m.m.shading = Some(*s),
            Value::Builtin(b) if b.name == "gooch" => {
                m.m.shading = Some(ir::ShadingModel::Gooch(ir::GoochParams::default()))
            }
            other => return Err(types::mismatch(it, "Shading", other, span).into()),
        },
        other => unreachable!("material field `{other}` has no arm"),
    }
    Ok(())
}

/// A colour of light per channel that cannot be negative (`absorption`, `emission`).
fn non_negative_color(it: &dyn Host, v: &Value, span: Span, name: &str) -> R<DVec3> {
    let c = types::color(it, v, span)?;
    for x in c.to_array() {
        check(x >= 0.0, name, "≥ 0 in every channel", x, span)?;
    }
    Ok(c)
}

/// The material fields' names, in order (for messages and members).
pub(crate) fn fields() -> Vec<&'static str> {
    MATERIAL.names().collect()
}

/// Energy warnings after a material is complete.
pub(crate) fn mat_warnings(it: &mut dyn Host, m: &Mat, span: Span) {
    if m.m.kd + m.m.ks > 1.0 + 1e-9 {
        it.warn(
            Diagnostic::warning("rtc::material::energy", span, "`kd + ks` is greater than 1")
                .with_label(format!("kd + ks = {}", crate::eval::value::fmt_f(m.m.kd + m.m.ks)))
                .with_help("lower `kd` or `ks` so the surface does not reflect more light than it receives"),
        );
    }
    // With `fresnel` or `conserve_energy` the refraction keeps `refract·(1 − kr)`: never more
    // than the mirror leaves.
    if m.m.reflect + m.m.refract > 1.0 + 1e-9 && !m.m.fresnel && !m.m.conserve_energy {
        it.warn(
            Diagnostic::warning(
                "rtc::material::energy",
                span,
                "`reflect + refract` is greater than 1",
            )
            .with_label(format!(
                "reflect + refract = {}",
                crate::eval::value::fmt_f(m.m.reflect + m.m.refract)
            ))
            .with_help("lower `reflect` or `refract` so their sum is at most 1"),
        );
    }
    if m.m.gloss > 0.0 && m.m.reflect == 0.0 && m.m.refract == 0.0 {
        it.warn(
            Diagnostic::warning(
                "rtc::material::gloss_unused",
                span,
                "`gloss` does nothing on a material that neither reflects nor refracts",
            )
            .with_label("gloss blurs reflected and refracted rays; this material casts none")
            .with_help("give it `reflect` (e.g. `reflect: 0.3`) or `refract` for gloss to blur, or remove `gloss`; for a broader highlight lower `n`"),
        );
    }
    if m.m.fresnel && m.m.reflect == 0.0 {
        it.warn(
            Diagnostic::warning(
                "rtc::material::fresnel_unused",
                span,
                "`fresnel` does nothing on a material that does not reflect",
            )
            .with_label("fresnel scales the mirror weight `reflect`, which is 0 here")
            .with_help(
                "give it `reflect: 1` (a clear dielectric: glass, water), or remove `fresnel`",
            ),
        );
    }
    if m.m.absorption != DVec3::ZERO && m.m.refract == 0.0 {
        it.warn(
            Diagnostic::warning(
                "rtc::material::absorption_unused",
                span,
                "`absorption` does nothing on a material that does not refract",
            )
            .with_label("absorption dims light travelling inside; no ray enters this material")
            .with_help("give it `refract` (e.g. `refract: 0.9, eta: 1.5`), or remove `absorption`"),
        );
    }
    let c = m.m.color;
    if c.max_element() > 1.0 {
        let bytes = c.to_array().map(|x| x.round().clamp(0.0, 255.0) as u8);
        let hex = format!("#{:02x}{:02x}{:02x}", bytes[0], bytes[1], bytes[2]);
        let shown = c.to_array().map(crate::eval::value::fmt_f).join(", ");
        it.warn(
            Diagnostic::warning(
                "rtc::material::color_range",
                span,
                "a material colour has a channel above 1: colours run from 0 to 1",
            )
            .with_label(format!("`color` is [{shown}]: it will be blown out"))
            .with_help(format!(
                "for 0–255 values write `{hex}`, or divide by 255 (`rgb({shown}) / 255`); only lights may exceed 1"
            )),
        );
    }
}

fn material(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &MATERIAL, a)?;
    let mut m = Mat {
        m: ir::Material {
            span: s.span,
            filter: ir::LANGUAGE_FILTER,
            ..ir::Material::default()
        },
        texture: None,
        bump: None,
        mix: None,
        made: it.next_made(),
    };
    for f in MATERIAL.names() {
        if let Some((v, sp)) = p.get(f) {
            let name = crate::syntax::ast::Name {
                sym: crate::syntax::intern::Sym::new(f),
                span: sp,
            };
            set_mat_field(it, &mut m, name, &v, sp)?;
        }
    }
    mat_warnings(it, &m, s.span);
    Ok(Value::Material(Rc::new(m)))
}
