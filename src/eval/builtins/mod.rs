//! The built-in functions and constants: their table by name and id (the functions themselves
//! are in this folder's files and in the shape, transform and random-stream files), each with
//! its schema (`eval::schema`), and the names a scene should not rebind.

#[cfg(test)]
mod doc_tables;
mod fog;
mod integrator;
mod lights;
pub(crate) mod lists;
mod looks;
mod material;
mod math;
mod mixes;
pub(crate) mod noise;
mod patterns;
mod projection;
#[cfg(test)]
mod reference;
mod scene;
#[cfg(test)]
mod schema_tests;
mod settings;

pub(crate) use material::{fields as material_fields, mat_warnings, set_mat_field};
pub(crate) use math::{CROSS, DISTANCE, DOT, LENGTH, MAX, MIN, NORMALIZE};

use crate::syntax::intern::Sym;

use super::host::BuiltinFn;
use super::schema::Sig;
use super::value::{Builtin, Value};

/// Every built-in function with its schema, in the order of their ids.
fn functions() -> Vec<(&'static Sig, BuiltinFn)> {
    [
        math::FNS,
        lists::FNS,
        looks::FNS,
        material::FNS,
        patterns::FNS,
        noise::FNS,
        mixes::FNS,
        scene::FNS,
        lights::FNS,
        settings::FNS,
        integrator::FNS,
        fog::FNS,
        super::shapes::FNS,
        super::shapes::COMPOUND_FNS,
        super::shapes::REVOLVE_FNS,
        super::shapes::ISOSURFACE_FNS,
        super::shapes::HEIGHT_FIELD_FNS,
        super::shapes::SWEEP_FNS,
        super::transform::FNS,
        super::rng::FNS,
    ]
    .concat()
}

/// The implementations by id ([`Builtin::id`]).
static FUNCTIONS: std::sync::LazyLock<Vec<BuiltinFn>> =
    std::sync::LazyLock::new(|| functions().into_iter().map(|(_, f)| f).collect());

/// The implementation of the built-in with id `id`.
pub(crate) fn function(id: u16) -> BuiltinFn {
    FUNCTIONS[usize::from(id)]
}

fn table() -> Vec<(&'static str, Value)> {
    let mut t: Vec<(&'static str, Value)> = Vec::new();
    for (id, (sig, _)) in functions().into_iter().enumerate() {
        let id = u16::try_from(id).expect("fewer than 65,536 built-ins");
        t.push((sig.name, Value::Builtin(Builtin { name: sig.name, id })));
    }
    t.extend(math::constants());
    t.extend(settings::constants());
    t.extend(integrator::constants());
    t
}

thread_local! {
    static GLOBALS: super::fxhash::FxHashMap<Sym, Value> = table().into_iter().map(|(k, v)| (Sym::new(k), v)).collect();
}

/// A built-in by name.
pub(crate) fn global(sym: Sym) -> Option<Value> {
    GLOBALS.with(|g| g.get(&sym).cloned())
}

/// Every built-in name (for did-you-mean).
pub(crate) fn global_names() -> Vec<&'static str> {
    GLOBALS.with(|g| g.keys().map(|k| k.as_str()).collect())
}

/// Every name a scene should not bind at the top level (what `rtc convert` must not name a
/// material): the language's keywords, `param` (it starts a declaration), every built-in
/// function and constant, and the frame's `frame`, `time` and `fps`. Sorted.
pub(crate) fn reserved_names() -> Vec<&'static str> {
    let mut names: Vec<&'static str> = crate::syntax::KEYWORDS.to_vec();
    names.push("param");
    names.extend(table().into_iter().map(|(name, _)| name));
    names.extend(super::params::FRAME_BUILTINS);
    names.sort_unstable();
    names.dedup();
    names
}
