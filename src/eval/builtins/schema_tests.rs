//! The schemas against the code: every schema's examples evaluate, and together they make the
//! built-ins read every parameter the schemas declare (a built-in asking for a name its schema
//! lacks panics, which they would show); and the defaults the schemas state are the IR's named
//! defaults.

use std::path::Path;

use crate::eval::schema::{Absent, Lit, Range, read};
use crate::eval::{EvalOptions, LoopParts};
use crate::source::SourceMap;

/// A scene that binds every schema's examples (`let e1 = sphere(...)`), under a camera.
fn examples_scene() -> String {
    let mut text = String::from("rtc 1.1\ncamera { eye: [0, 0, 10] }\n");
    for (k, example) in super::reference::all()
        .iter()
        .flat_map(|s| s.examples.iter())
        .enumerate()
    {
        text.push_str(&format!("let example_{k} = {example}\n"));
    }
    text
}

/// Calls that read a parameter only on their way to an error (the examples do not fail).
const FAILING: &[&str] = &[
    // `.material(m)` is matched without the schema unless it is wrong.
    "rtc 1.1\nsphere().material(material: 1)",
    // `assert`'s message is read when the condition is false.
    "rtc 1.1\nassert(false, message: \"fails\")",
];

/// Evaluates `text` as a scene file in `docs/` (where the example assets are), serially.
fn evaluate(text: &str) -> crate::ir::Loaded {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/schema_calls.rtc");
    let options = EvalOptions {
        loop_parts: LoopParts::Serial,
        ..EvalOptions::default()
    };
    crate::eval::load_source(&path, text, &mut SourceMap::new(), &options)
}

#[test]
fn every_parameter_a_schema_declares_is_read() {
    for sig in super::reference::all() {
        assert!(!sig.examples.is_empty(), "`{}` has no example", sig.name);
    }
    let loaded = evaluate(&examples_scene());
    let errors: Vec<String> = loaded
        .diagnostics
        .items
        .iter()
        .filter(|d| d.severity == crate::diag::Severity::Error)
        .map(|d| format!("{}: {}", d.code, d.message))
        .collect();
    assert!(errors.is_empty(), "the examples fail: {errors:#?}");
    for text in FAILING {
        assert!(evaluate(text).scene.is_none(), "{text} should fail");
    }
    let mut unread = Vec::new();
    for sig in super::reference::all() {
        if sig.variadic {
            continue; // read as a list of values, without names
        }
        for (i, p) in sig.params.iter().enumerate() {
            if !read::was_read(sig, i) {
                unread.push(format!("`{}` of `{}`", p.name, sig.name));
            }
        }
    }
    assert!(
        unread.is_empty(),
        "declared but never read by the examples (add one that reads it, or remove the parameter): {}",
        unread.join(", ")
    );
}

/// The default a schema states for `name`.
fn default(sig: &crate::eval::schema::Sig, name: &str) -> Lit {
    match sig.param(name).map(|p| p.absent) {
        Some(Absent::Is(l)) => l,
        other => panic!("`{name}` of `{}` has no value default: {other:?}", sig.name),
    }
}

/// The material fields' defaults are `ir::Material::default()`'s.
#[test]
fn material_defaults_are_the_irs() {
    let m = crate::ir::Material::default();
    let sig = &super::material::MATERIAL;
    assert_eq!(default(sig, "color"), Lit::Color(m.color.to_array()));
    for (name, v) in [
        ("ka", m.ka),
        ("kd", m.kd),
        ("ks", m.ks),
        ("n", m.n),
        ("reflect", m.reflect),
        ("refract", m.refract),
        ("eta", m.eta),
        ("gloss", m.gloss),
    ] {
        assert_eq!(default(sig, name), Lit::Float(v), "{name}");
    }
    assert_eq!(
        default(sig, "gloss_samples"),
        Lit::Int(i64::from(m.gloss_samples))
    );
    // The one exception: the language tints refracted light by the colour, the IR's default
    // (the course formats') does not.
    assert_eq!(
        default(sig, "filter"),
        Lit::Float(crate::ir::LANGUAGE_FILTER)
    );
    for (name, v) in [("metallic", m.metallic), ("brilliance", m.brilliance)] {
        assert_eq!(default(sig, name), Lit::Float(v), "{name}");
    }
    assert_eq!(default(sig, "fresnel"), Lit::Bool(m.fresnel));
    assert_eq!(
        default(sig, "conserve_energy"),
        Lit::Bool(m.conserve_energy)
    );
    assert_eq!(default(sig, "emission"), Lit::Color(m.emission.to_array()));
    assert_eq!(
        default(sig, "absorption"),
        Lit::Color(m.absorption.to_array())
    );
}

/// `render { }`'s defaults are `ir::RenderSettings::language_defaults()`'s.
#[test]
fn render_defaults_are_the_language_defaults() {
    let d = crate::ir::RenderSettings::language_defaults();
    let sig = &super::settings::RENDER;
    assert_eq!(default(sig, "shadows"), Lit::Bool(d.shadows));
    assert_eq!(default(sig, "glass_shadows"), Lit::Bool(d.glass_shadows));
    assert_eq!(default(sig, "max_depth"), Lit::Int(i64::from(d.max_depth)));
    assert_eq!(
        default(sig, "background"),
        Lit::Color(d.background.to_array())
    );
    assert_eq!(default(sig, "seed"), Lit::Int(d.seed as i64));
    assert_eq!(default(sig, "cutoff"), Lit::Float(d.cutoff));
    assert_eq!(
        default(sig, "spread_light_samples"),
        Lit::Bool(d.light_samples == crate::ir::LightSampling::Spread)
    );
    assert_eq!(default(sig, "flare"), Lit::Bool(d.flare.is_some()));
    assert_eq!(
        d.sampling,
        crate::ir::Sampling::Grid { factor: 1 },
        "`supersampling` defaults to 1"
    );
    assert_eq!(default(sig, "supersampling"), Lit::Int(1));
    assert_eq!(d.shading, crate::ir::ShadingModel::Phong);
    assert_eq!(default(sig, "shading"), Lit::Name("phong"));
    assert_eq!(d.mode, crate::ir::RenderMode::Shaded);
    assert_eq!(default(sig, "mode"), Lit::Name("shaded"));
    assert_eq!(d.ambient, crate::ir::AmbientConvention::PerLight);
    assert_eq!(default(sig, "ambient"), Lit::Name("per_light"));
    assert_eq!(d.encoding, crate::ir::Encoding::Srgb);
    assert_eq!(default(sig, "encoding"), Lit::Name("srgb"));
}

/// `gooch`'s and `flare`'s defaults and ranges are the IR's.
#[test]
fn gooch_and_flare_are_the_irs() {
    let g = crate::ir::GoochParams::default();
    let sig = &super::settings::GOOCH;
    for (name, v) in [("b", g.b), ("y", g.y), ("alpha", g.alpha), ("beta", g.beta)] {
        assert_eq!(default(sig, name), Lit::Float(v), "{name}");
    }
    let f = crate::ir::Flare::default();
    let sig = &super::settings::FLARE;
    let values = [
        Lit::Int(i64::from(f.ghosts)),
        Lit::Float(f.dispersal),
        Lit::Float(f.halo),
        Lit::Int(i64::from(f.streaks)),
        Lit::Float(f.threshold),
        Lit::Float(f.intensity),
    ];
    for ((name, lo, hi), v) in crate::ir::Flare::RANGES.into_iter().zip(values) {
        assert_eq!(default(sig, name), v, "{name}");
        let range = sig.param(name).map(|p| p.range);
        let want = match v {
            Lit::Int(_) => Range::Ints(lo as i64, hi as i64),
            _ => Range::Between(lo, hi),
        };
        assert_eq!(range, Some(want), "{name}");
    }
}
