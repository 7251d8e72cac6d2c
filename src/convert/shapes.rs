//! Objects, materials and textures as rtc source: one constructor call per object with its
//! placement as transform methods, materials as `material { ... }` records.

use crate::num::Norm;
use std::path::Path;

use glam::{DMat3, DVec3};

use super::placement;
use super::text::{color, number, string, unit_direction, vector};
use crate::ir::{
    Arg, CsgOp, ImageFilter, Mapping, Material, Mix, Object, Scene, ShadingModel, Shape, Texture,
    Visibility,
};

/// Longest line before an object's methods go on lines of their own.
const LINE: usize = 100;

/// How a converted file refers to an asset: by a path relative to the directory it is written to.
pub(crate) type AssetPath<'a> = &'a dyn Fn(&Path) -> String;

/// The fields of the `material { ... }` record of a course material.
pub(crate) fn material(scene: &Scene, m: &Material, asset: AssetPath<'_>) -> Vec<String> {
    let defaults = Material::default();
    let mut fields = Vec::new();
    let textured = m.texture.map(|t| &scene.textures[t.0 as usize]);
    // Written even under a texture, which replaces it: the IR keeps it (white by the course).
    fields.push(format!("color: {}", color(m.color)));
    if let Some(t) = textured {
        fields.push(format!("texture: {}", texture(t, asset)));
    }
    for (name, v) in [("ka", m.ka), ("kd", m.kd), ("ks", m.ks), ("n", m.n)] {
        fields.push(format!("{name}: {}", number(v)));
    }
    fields.push(format!("reflect: {}", number(m.reflect)));
    if m.refract != 0.0 || m.eta != 1.0 {
        fields.push(format!("refract: {}", number(m.refract)));
        fields.push(format!("eta: {}", number(m.eta)));
    }
    if let Some(b) = m.bump {
        let t = &scene.textures[b.texture.0 as usize];
        fields.push(format!("bump: {}", texture(t, asset)));
        fields.push(format!("bump_scale: {}", number(b.scale)));
    }
    if m.gloss != defaults.gloss || m.gloss_samples != defaults.gloss_samples {
        fields.push(format!("gloss: {}", number(m.gloss)));
        fields.push(format!("gloss_samples: {}", m.gloss_samples));
    }
    if let Some(s) = m.shading {
        fields.push(format!("shading: {}", shading(s)));
    }
    finish(m, &defaults, &mut fields);
    fields
}

/// The finish fields of `m` that differ from a language material's (a course material's
/// untinted `filter: 0` among them, so its converted glass stays clear).
fn finish(m: &Material, defaults: &Material, fields: &mut Vec<String>) {
    if m.filter != crate::ir::LANGUAGE_FILTER {
        fields.push(format!("filter: {}", number(m.filter)));
    }
    if m.absorption != defaults.absorption {
        fields.push(format!("absorption: {}", color(m.absorption)));
    }
    if m.fresnel {
        fields.push("fresnel: true".to_string());
    }
    if m.conserve_energy {
        fields.push("conserve_energy: true".to_string());
    }
    if m.metallic != defaults.metallic {
        fields.push(format!("metallic: {}", number(m.metallic)));
    }
    if m.brilliance != defaults.brilliance {
        fields.push(format!("brilliance: {}", number(m.brilliance)));
    }
    if m.emission != defaults.emission {
        fields.push(format!("emission: {}", color(m.emission)));
    }
    if m.emits_both_sides != defaults.emits_both_sides {
        fields.push("emission_sides: 1".to_string());
    }
}

/// A mixed material as its constructor: `material_map(..)` or `layers([..])`, its parts by the
/// names `name` gives their ids (they are written before it: parts come first in the IR).
pub(crate) fn mixed(
    scene: &Scene,
    mix: &Mix,
    name: &dyn Fn(u32) -> String,
    asset: AssetPath<'_>,
) -> String {
    match mix {
        Mix::Map {
            texture,
            stops,
            blend,
        } => {
            let stops: Vec<String> = stops
                .iter()
                .map(|(at, id)| format!("[{}, {}]", number(*at), name(id.0)))
                .collect();
            format!(
                "material_map(pattern: {}, stops: [{}], blend: {blend})",
                self::texture(&scene.textures[texture.0 as usize], asset),
                stops.join(", ")
            )
        }
        Mix::Layers(layers) => {
            let names: Vec<String> = layers.iter().map(|id| name(id.0)).collect();
            format!("layers([{}])", names.join(", "))
        }
    }
}

/// A shading model as the language names it.
pub(crate) fn shading(s: ShadingModel) -> String {
    match s {
        ShadingModel::Phong => "phong".into(),
        ShadingModel::Hatching => "hatching".into(),
        ShadingModel::Gooch(g) => format!(
            "gooch(b: {}, y: {}, alpha: {}, beta: {})",
            number(g.b),
            number(g.y),
            number(g.alpha),
            number(g.beta)
        ),
    }
}

/// The `mapping:` argument of an image texture (nothing for the default, uv).
fn mapping_arg(mapping: Mapping) -> &'static str {
    match mapping {
        Mapping::Uv => "",
        Mapping::Spherical => ", mapping: spherical",
        Mapping::Planar => ", mapping: planar",
        Mapping::Cylindrical => ", mapping: cylindrical",
    }
}

/// A texture as the rtc expression that makes it.
pub(crate) fn texture(t: &Texture, asset: AssetPath<'_>) -> String {
    match t {
        Texture::NormalMap { path, mapping, .. } => {
            let map = mapping_arg(*mapping);
            format!("normal_map({}{map})", string(&asset(path)))
        }
        Texture::Image {
            path,
            mapping,
            filter,
            ..
        } => {
            let map = mapping_arg(*mapping);
            let filter = match filter {
                ImageFilter::Nearest => "",
                ImageFilter::Bilinear => ", filter: \"bilinear\"",
                ImageFilter::Mipmap => ", filter: \"mipmap\"",
            };
            format!("image({}{map}{filter})", string(&asset(path)))
        }
        Texture::Checker { a, b, size } => pattern("checker", *a, *b, *size),
        Texture::Stripes { a, b, size } => pattern("stripes", *a, *b, *size),
        Texture::Pattern(pt) => super::pattern::source(pt),
    }
}

fn pattern(name: &str, a: DVec3, b: DVec3, size: f64) -> String {
    format!(
        "{name}(size: {}, a: {}, b: {})",
        number(size),
        color(a),
        color(b)
    )
}

/// An object: its constructor, its placement and its material (`names` gives the name of a
/// scene material id). Long forms put each method on its own line; a rotation written as a
/// matrix gets a comment saying where it turns the object's +Y (a course texture's north pole).
pub(crate) fn object(o: &Object, names: &dyn Fn(u32) -> String, asset: AssetPath<'_>) -> String {
    let parts = calls(o, names, asset);
    let m = o.transform.affine().matrix3;
    let note = (m != DMat3::from_diagonal(DVec3::new(m.x_axis.x, m.y_axis.y, m.z_axis.z)))
        .then(|| {
            let pole = m.y_axis.unit_or(Default::default());
            format!(
                "// Rotated so that its +Y (a course texture's north pole) points along [{}, {}, {}].\n",
                crate::diag::number(pole.x),
                crate::diag::number(pole.y),
                crate::diag::number(pole.z)
            )
        });
    let one_line = parts.concat();
    let text = if one_line.len() <= LINE {
        one_line
    } else {
        parts.join("\n  ")
    };
    note.unwrap_or_default() + &text
}

fn shape(o: &Object, names: &dyn Fn(u32) -> String, asset: AssetPath<'_>) -> String {
    if let Some(call) = o.shape.call() {
        let args: Vec<String> = call
            .args
            .iter()
            .enumerate()
            .map(|(k, (name, a))| match a {
                // A mesh's path is its first parameter: written positionally.
                Arg::Path(_) if k == 0 => argument(a, asset),
                _ => format!("{name}: {}", argument(a, asset)),
            })
            .collect();
        return format!("{}({})", call.name, args.join(", "));
    }
    match &o.shape {
        Shape::Csg { op, children } => {
            let kids: Vec<String> = children
                .iter()
                .map(|c| calls(c, names, asset).concat())
                .collect();
            match op {
                CsgOp::Union => format!("union([{}])", kids.join(", ")),
                CsgOp::Merge => format!("union([{}], merge: true)", kids.join(", ")),
                CsgOp::Intersection => format!("intersection([{}])", kids.join(", ")),
                CsgOp::Difference => {
                    format!("difference({}, [{}])", kids[0], kids[1..].join(", "))
                }
                CsgOp::Inverse => format!("{}.inverse()", kids[0]),
                CsgOp::Clip => format!("{}.clipped_by({})", kids[0], kids[1]),
            }
        }
        other => unreachable!("`Shape::call` writes every shape but CSG, not {other:?}"),
    }
}

/// One argument as rtc source.
fn argument(a: &Arg, asset: AssetPath<'_>) -> String {
    match a {
        Arg::Number(v) => number(*v),
        Arg::Point(p) => vector(*p),
        Arg::Direction(n) => unit_direction(*n),
        Arg::Bool(b) => b.to_string(),
        Arg::Path(p) => string(&asset(p)),
        Arg::Str(s) => string(s),
        Arg::Function(f) => super::program::function_source(f)
            .unwrap_or_else(|| string(crate::ir::COMPILED_FUNCTION)),
        Arg::List(items) => {
            let items: Vec<String> = items.iter().map(|x| argument(x, asset)).collect();
            format!("[{}]", items.join(", "))
        }
        Arg::Record(fields) => {
            let fields: Vec<String> = fields
                .iter()
                .map(|(k, v)| format!("{k}: {}", argument(v, asset)))
                .collect();
            format!("{{ {} }}", fields.join(", "))
        }
    }
}

/// The constructor, then the methods that place the object and give its material.
fn calls(o: &Object, names: &dyn Fn(u32) -> String, asset: AssetPath<'_>) -> Vec<String> {
    let mut parts = vec![shape(o, names, asset)];
    parts.extend(placement::methods(
        &o.transform.affine(),
        o.motion.as_deref(),
    ));
    if let Some(m) = o.material {
        parts.push(format!(".material({})", names(m.0)));
    }
    for (flag, method) in [
        (Visibility::NO_SHADOW, ".no_shadow()"),
        (Visibility::NO_IMAGE, ".no_image()"),
        (Visibility::NO_REFLECTION, ".no_reflection()"),
    ] {
        if o.visibility.hides(flag) {
            parts.push(method.to_string());
        }
    }
    parts
}
