//! Colours, materials and textures.

use std::rc::Rc;

use glam::DVec3;

use crate::diag::Diagnostic;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::args::{Params, check, positive, unit_interval};
use crate::eval::error::{R, error, suggest};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::types;
use crate::eval::value::{Mat, Tex, Value};
use crate::ir;
use crate::source::Span;
use crate::syntax::srgb_to_linear;

/// Colour, material and texture constructors.
pub const FNS: &[(&str, BuiltinFn)] = &[
    ("rgb", rgb),
    ("srgb", srgb),
    ("hsv", hsv),
    ("material", material),
    ("checker", checker),
    ("stripes", stripes),
    ("image", image),
];

fn channels(it: &dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<[f64; 3]> {
    if let [one] = a.as_slice()
        && let Some(g) = one.value.as_f64()
    {
        check(g >= 0.0, "value", ">= 0", g, one.span)?;
        return Ok([g; 3]);
    }
    let mut p = Params::new(s, &["r", "g", "b"], a)?;
    let mut out = [0.0; 3];
    for (k, n) in ["r", "g", "b"].iter().enumerate() {
        let (v, sp) = p.num(it, n)?;
        check(v >= 0.0, n, ">= 0", v, sp)?;
        out[k] = v;
    }
    Ok(out)
}

fn rgb(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Color(channels(it, s, a)?.into()))
}

fn srgb(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let c = channels(it, s, a)?;
    Ok(Value::Color(c.map(srgb_to_linear).into()))
}

/// `hsv(hue: Angle, s, v)`: hue is an angle (0deg red, 120deg green), s and v in [0, 1]; the
/// result is the sRGB-encoded colour converted to linear.
fn hsv(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["hue", "s", "v"], a)?;
    let (hv, hs) = p.req("hue")?;
    if let Some(x) = hv.as_f64() {
        // A bare hue is most often a fraction of the colour wheel (0.5) or degrees (120).
        let (deg, turn) = if (0.0..=1.0).contains(&x) {
            (x * 360.0, x)
        } else {
            (x, x / 360.0)
        };
        let fmt = crate::eval::value::fmt_f;
        return Err(types::mismatch(it, "Angle", &hv, hs)
            .with_label("a hue is an angle on the colour wheel")
            .with_help(format!(
                "write `{}deg` (the same as `{}turn`); 0deg is red, 120deg green, 240deg blue",
                fmt(deg),
                fmt(turn)
            ))
            .into());
    }
    let h = types::angle(it, &hv, hs)?;
    let (sat, ss) = p.num(it, "s")?;
    let (val, vs) = p.num(it, "v")?;
    unit_interval("s", sat, ss)?;
    unit_interval("v", val, vs)?;
    let h = h.to_degrees().rem_euclid(360.0) / 60.0;
    let c = val * sat;
    let x = c * (1.0 - (h % 2.0 - 1.0).abs());
    let (r, g, b) = match h as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = val - c;
    Ok(Value::Color(
        [r + m, g + m, b + m].map(srgb_to_linear).into(),
    ))
}

/// Every material field, in positional order.
pub const MAT_FIELDS: &[&str] = &[
    "color",
    "ka",
    "kd",
    "ks",
    "n",
    "reflect",
    "refract",
    "eta",
    "texture",
    "bump",
    "bump_scale",
    "shading",
    "gloss",
    "gloss_samples",
];

/// Sets one material field with type and range checks (shared by `material` and `with`).
pub fn set_mat_field(
    it: &dyn Host,
    m: &mut Mat,
    name: crate::syntax::ast::Name,
    v: &Value,
    span: Span,
) -> R<()> {
    let field = name.sym.as_str();
    let unit = |m: &mut f64| -> R<()> {
        let x = types::num(it, v, span)?;
        unit_interval(field, x, span)?;
        *m = x;
        Ok(())
    };
    match field {
        "color" => m.m.color = types::color(it, v, span)?,
        "ka" => unit(&mut m.m.ka)?,
        "kd" => unit(&mut m.m.kd)?,
        "ks" => unit(&mut m.m.ks)?,
        "reflect" => unit(&mut m.m.reflect)?,
        "refract" => unit(&mut m.m.refract)?,
        "n" => {
            let x = types::num(it, v, span)?;
            positive("n", x, span)?;
            m.m.n = x;
        }
        "eta" => {
            let x = types::num(it, v, span)?;
            positive("eta", x, span)?;
            m.m.eta = x;
        }
        "gloss" => unit(&mut m.m.gloss)?,
        "gloss_samples" => {
            let x = types::int(it, v, span)?;
            let max = crate::ir::limits::MAX_GLOSS_SAMPLES;
            check(
                (1..=i64::from(max)).contains(&x),
                "gloss_samples",
                &format!("in 1..={max}"),
                x as f64,
                span,
            )?;
            m.m.gloss_samples = x as u32;
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
            let x = types::num(it, v, span)?;
            check(x >= 0.0, "bump_scale", ">= 0", x, span)?;
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
        other => {
            let help = suggest(other, MAT_FIELDS.iter().copied())
                .unwrap_or_else(|| format!("materials have: {}", MAT_FIELDS.join(", ")));
            return Err(error(
                "rtc::field::unknown",
                name.span,
                format!("materials have no field `{other}`"),
            )
            .with_label("unknown field")
            .with_help(help)
            .into());
        }
    }
    Ok(())
}

/// Energy warnings after a material is complete.
pub fn mat_warnings(it: &mut dyn Host, m: &Mat, span: Span) {
    if m.m.kd + m.m.ks > 1.0 + 1e-9 {
        it.warn(
            Diagnostic::warning("rtc::material::energy", span, "`kd + ks` is greater than 1")
                .with_label(format!("kd + ks = {}", crate::eval::value::fmt_f(m.m.kd + m.m.ks)))
                .with_help("lower `kd` or `ks` so the surface does not reflect more light than it receives"),
        );
    }
    if m.m.reflect + m.m.refract > 1.0 + 1e-9 {
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
    let mut p = Params::new(s, MAT_FIELDS, a)?;
    let mut m = Mat {
        m: ir::Material {
            span: s.span,
            ..ir::Material::default()
        },
        texture: None,
        bump: None,
        made: it.next_made(),
    };
    for f in MAT_FIELDS {
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

fn pattern(it: &dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<(DVec3, DVec3, f64)> {
    let mut p = Params::new(s, &["size", "a", "b"], a)?;
    let (size, ss) = p.num_or(it, "size", 1.0)?;
    positive("size", size, ss)?;
    let ca = p.color_or(it, "a", DVec3::ONE)?;
    let cb = p.color_or(it, "b", DVec3::ZERO)?;
    Ok((ca, cb, size))
}

fn checker(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (a, b, size) = pattern(it, s, a)?;
    Ok(Value::Texture(Rc::new(Tex {
        t: ir::Texture::Checker { a, b, size },
        made: it.next_made(),
    })))
}

fn stripes(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (a, b, size) = pattern(it, s, a)?;
    Ok(Value::Texture(Rc::new(Tex {
        t: ir::Texture::Stripes { a, b, size },
        made: it.next_made(),
    })))
}

fn image(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["path", "mapping"], a)?;
    let (pv, ps) = p.req("path")?;
    let rel = types::string(it, &pv, ps)?;
    let path = crate::eval::assets::existing(it, &rel, ps, "image")?;
    let mapping = match p.get("mapping") {
        None => ir::Mapping::Uv,
        Some((Value::Mapping(m), _)) => m,
        Some((other, sp)) => return Err(types::mismatch(it, "Mapping", &other, sp).into()),
    };
    Ok(Value::Texture(Rc::new(Tex {
        t: ir::Texture::Image {
            path,
            mapping,
            span: ps,
        },
        made: it.next_made(),
    })))
}
