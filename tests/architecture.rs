//! The architecture test: every `crate::` and `super::` path in `src/` (in `use` items, grouped
//! `use` lists at any depth, `pub use` re-exports and inline paths in code) is resolved to the
//! top-level module it names, and each top-level module may only use the modules of its row in
//! [`ALLOWED`] (docs/architecture.md has the same table, with the reasons). Comments and string
//! literals are skipped; `super::` inside an inline `mod tests { ... }` resolves to the file's
//! own module. The binary (`src/main.rs`, `src/cli/`) may use everything and is used by nothing.

use std::collections::BTreeSet;
use std::path::Path;

mod architecture_support;
use architecture_support::{Use, module_of, rust_files, uses};

/// Leaves every module may use.
const LEAVES: &[&str] = &["diag", "source", "num", "lanes", "pattern"];

/// Who may import whom (besides the leaves). A new top-level module gets its row here first.
const ALLOWED: &[(&str, &[&str])] = &[
    ("source", &[]),
    ("diag", &[]),
    ("num", &[]),
    ("lanes", &[]),
    ("pattern", &[]),
    ("syntax", &[]),
    ("ir", &[]),
    ("assets", &["ir"]),
    ("eval", &["syntax", "ir", "assets", "geometry"]),
    ("compat", &["ir", "assets"]),
    ("convert", &["ir", "compat", "eval"]),
    ("geometry", &["ir"]),
    ("opt", &["ir", "geometry", "assets"]),
    ("render", &["opt", "geometry", "ir"]),
    ("check", &["ir", "opt", "geometry"]),
    ("loader", &["eval", "compat", "ir"]),
    ("metrics", &[]),
    ("accuracy", &["ir", "opt", "render", "metrics"]),
];

/// Narrower rules inside an allowed edge: `(module, target, the only paths under target it may
/// use)`. Evaluation asks geometry what a shape is (its validity and bounds), never anything
/// that builds or traces. The rtc back end asks the language only which names a scene must
/// not bind (its keywords and built-ins, from the built-ins' schemas).
const ONLY: &[(&str, &str, &[&str])] = &[
    ("eval", "geometry", &["shapes", "aabb", "Aabb"]),
    ("convert", "eval", &["reserved_names"]),
];

/// Items a module may not name although it may use their module: `(module, path)`. The
/// renderer reads the prepared scene, never the IR's shapes. The patterns are pure maths of
/// position: of the other leaves they use `num` only.
const FORBIDDEN: &[(&str, &[&str])] = &[
    ("render", &["ir", "Shape"]),
    ("pattern", &["diag"]),
    ("pattern", &["source"]),
];

/// Why `from` may not use `u`, if it may not.
fn violation(from: &str, u: &Use) -> Option<String> {
    let target = u.absolute.first()?.as_str();
    if target == from || LEAVES.contains(&target) {
        return forbidden(from, u);
    }
    let Some((_, allowed)) = ALLOWED.iter().find(|(m, _)| *m == from) else {
        return Some(format!(
            "module `{from}` has no row in the allowed-imports table; add it first"
        ));
    };
    if !allowed.contains(&target) {
        return Some(format!(
            "module `{from}` may not import `{target}` (allowed: {})",
            allowed
                .iter()
                .chain(LEAVES)
                .copied()
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    if let Some((_, _, only)) = ONLY.iter().find(|(m, t, _)| *m == from && *t == target) {
        let under = u.absolute.get(1).map(String::as_str).unwrap_or("");
        if !only.contains(&under) {
            return Some(format!(
                "module `{from}` may use only `{target}::{{{}}}`",
                only.join(", ")
            ));
        }
    }
    forbidden(from, u)
}

fn forbidden(from: &str, u: &Use) -> Option<String> {
    FORBIDDEN
        .iter()
        .find(|(m, path)| {
            *m == from
                && u.absolute
                    .starts_with(&path.iter().map(|s| s.to_string()).collect::<Vec<_>>())
        })
        .map(|(_, path)| format!("module `{from}` may not name `{}`", path.join("::")))
}

#[test]
fn every_module_imports_only_what_its_row_allows() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let src = root.join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut problems = Vec::new();
    let mut seen = 0;
    let mut modules = BTreeSet::new();
    for file in &files {
        let rel = file
            .strip_prefix(root)
            .unwrap_or(file)
            .display()
            .to_string();
        if rel == "src/main.rs" || rel.starts_with("src/cli/") {
            continue; // the binary: uses everything through `rtc::`
        }
        let module = module_of(file, &src);
        let Some(top) = module.first().cloned() else {
            continue; // lib.rs: the module list
        };
        modules.insert(top.clone());
        let text = std::fs::read_to_string(file).expect("read source");
        for u in uses(&text, &module) {
            seen += 1;
            if u.absolute.first().is_some_and(|t| t == "cli") {
                problems.push(format!(
                    "{rel}:{}: `{}`: nothing imports the CLI",
                    u.line, u.written
                ));
            } else if let Some(why) = violation(&top, &u).or_else(|| wall(&module, &u)) {
                problems.push(format!("{rel}:{}: `{}`: {why}", u.line, u.written));
            }
        }
    }
    assert!(seen > 300, "only {seen} paths found: is the parser broken?");
    for m in &modules {
        assert!(
            ALLOWED.iter().any(|(a, _)| a == m),
            "top-level module `{m}` has no row in the allowed-imports table"
        );
    }
    assert!(
        problems.is_empty(),
        "{} forbidden import(s):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn the_allowed_table_has_no_cycles() {
    // Depth-first search over the allowed edges.
    fn visit(m: &str, stack: &mut Vec<String>) -> Result<(), String> {
        if let Some(at) = stack.iter().position(|s| s == m) {
            return Err(format!("{} -> {m}", stack[at..].join(" -> ")));
        }
        stack.push(m.to_string());
        let next = ALLOWED
            .iter()
            .find(|(a, _)| *a == m)
            .map_or(&[][..], |(_, b)| *b);
        for n in next {
            visit(n, stack)?;
        }
        stack.pop();
        Ok(())
    }
    for (m, _) in ALLOWED {
        visit(m, &mut Vec::new()).unwrap_or_else(|cycle| panic!("cycle: {cycle}"));
    }
}

#[test]
fn the_parser_finds_grouped_inline_and_reexported_paths() {
    let src = r#"
        use crate::geometry::{Aabb, shape::{self, check}, csg::*};
        pub use super::film::{Channel, Stats};
        // use crate::render::Not; a comment is no import
        /* crate::render::NotEither */
        fn f() -> u32 { let s = "crate::render::NorAString"; crate::opt::prepare(x); 'a' as u32 }
        fn g<'a>(x: &'a str) { super::super::ir::Shape::Sphere; }
        pub(crate) fn h() {}
        mod tests {
            use super::*;
            use super::inner::thing;
        }
        use crate::assets;
    "#;
    let module = vec!["render".to_string(), "texture".to_string()];
    let got: Vec<(String, String)> = uses(src, &module)
        .into_iter()
        .map(|u| (u.written, u.absolute.join("::")))
        .collect();
    let want = [
        ("crate::geometry::Aabb", "geometry::Aabb"),
        ("crate::geometry::shape", "geometry::shape"),
        ("crate::geometry::shape::check", "geometry::shape::check"),
        ("crate::geometry::csg", "geometry::csg"),
        ("super::film::Channel", "render::film::Channel"),
        ("super::film::Stats", "render::film::Stats"),
        ("crate::opt::prepare", "opt::prepare"),
        ("super::super::ir::Shape::Sphere", "ir::Shape::Sphere"),
        ("super", "render::texture"),
        ("super::inner::thing", "render::texture::inner::thing"),
        ("crate::assets", "assets"),
    ];
    let want: Vec<(String, String)> = want
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect();
    assert_eq!(got, want);
}

#[test]
fn a_wrong_import_is_a_violation() {
    let at = |written: &str| Use {
        written: written.to_string(),
        absolute: written.split("::").skip(1).map(String::from).collect(),
        line: 1,
    };
    assert!(violation("geometry", &at("crate::render::Film")).is_some());
    assert!(violation("eval", &at("crate::geometry::World")).is_some());
    assert!(violation("eval", &at("crate::geometry::shapes::bounds")).is_none());
    assert!(violation("eval", &at("crate::geometry::bvh::Bvh")).is_some());
    assert!(violation("render", &at("crate::ir::Shape")).is_some());
    assert!(violation("render", &at("crate::ir::Material")).is_none());
    assert!(violation("compat", &at("crate::eval::value")).is_some());
    // The rtc back end reads the IR (and a course file through its front end); no front end
    // uses it.
    assert!(violation("convert", &at("crate::ir::Scene")).is_none());
    assert!(violation("convert", &at("crate::eval::reserved_names")).is_none());
    assert!(violation("convert", &at("crate::eval::load_file")).is_some());
    assert!(violation("compat", &at("crate::convert::to_source")).is_some());
    assert!(violation("eval", &at("crate::convert::to_source")).is_some());
    assert!(violation("ir", &at("crate::diag::Diagnostic")).is_none());
    // The lane vectors are a leaf: every room may use them, they use no room.
    assert!(violation("render", &at("crate::lanes::V3")).is_none());
    assert!(violation("lanes", &at("crate::geometry::lanes::RayLanes")).is_some());
    assert!(violation("newthing", &at("crate::ir::Scene")).is_some());
    // The patterns are a leaf every stage may use, which uses no other leaf but `num`.
    assert!(violation("render", &at("crate::pattern::Pattern")).is_none());
    assert!(violation("ir", &at("crate::pattern::Pattern")).is_none());
    assert!(violation("pattern", &at("crate::num::Norm")).is_none());
    assert!(violation("pattern", &at("crate::diag::Diagnostic")).is_some());
    assert!(violation("pattern", &at("crate::ir::Scene")).is_some());
    // Inside a room: a shading model calling an integrator, the scattering layer reading the
    // path state's room above it.
    let module = |m: &str| m.split("::").map(String::from).collect::<Vec<_>>();
    let phong = module("render::shading::phong");
    assert!(wall(&phong, &at("crate::render::integrator::whitted::Whitted")).is_some());
    assert!(wall(&phong, &at("crate::render::scatter::Lobe")).is_none());
    assert!(wall(&phong, &at("crate::render::shading::surface::Surface")).is_none());
    // A built-in reaching the interpreter instead of its host.
    let math = module("eval::builtins::math");
    assert!(wall(&math, &at("crate::eval::interp::Interp")).is_some());
    assert!(wall(&math, &at("crate::eval::host::Host")).is_none());
    let schema = module("eval::schema");
    assert!(wall(&schema, &at("crate::eval::value::Value")).is_some());
    assert!(wall(&schema, &at("crate::diag::number")).is_none());
    let scatter = module("render::scatter::glossy");
    assert!(wall(&scatter, &at("crate::render::path::Media")).is_some());
    assert!(wall(&scatter, &at("crate::render::scatter::specular::reflect")).is_none());
    assert!(
        wall(
            &module("render::view"),
            &at("crate::render::pixel::average")
        )
        .is_some()
    );
}

/// The largest circle of files allowed in each room (the largest strongly connected component
/// of its file import graph; a room not listed may have none). Lower a number when a room is
/// untangled; never raise one. Issue 33 measured before → after: render 15 → 1, geometry 30 → 3
/// (the world and its two helpers), syntax 8 → 7 (the grammar in a file of its own), eval 24 → 2
/// (a value holds a module, a module holds values; built-ins reach the interpreter only through
/// `eval::host::Host`).
const MAX_CIRCLE: &[(&str, usize)] = &[
    ("accuracy", 4),
    ("cli", 2),
    ("eval", 2),
    ("geometry", 3),
    ("ir", 3),
    ("syntax", 7),
];

/// Walls inside a room: `(module, modules it may not import)`, by module path prefix (a file
/// of `module` or below it; its own sub-modules are always allowed). The bottom of the render
/// room (path state, the per-tile context, the view, the scattering layer) knows nothing above
/// it; shading models never call an integrator. In geometry, the root files (rays, bounds,
/// rounding, motion) know no sub-room; a shape knows no world, BVH, lanes or mesh; a BVH knows
/// no shape; only the world knows the world.
const WALLS: &[(&str, &[&str])] = &[
    ("geometry::ray", GEOMETRY_ROOMS),
    ("geometry::aabb", GEOMETRY_ROOMS),
    ("geometry::rounding", GEOMETRY_ROOMS),
    ("geometry::motion", GEOMETRY_ROOMS),
    (
        "geometry::shapes",
        &[
            "geometry::world",
            "geometry::bvh",
            "geometry::lanes",
            "geometry::mesh",
        ],
    ),
    (
        "geometry::bvh",
        &[
            "geometry::world",
            "geometry::shapes",
            "geometry::lanes",
            "geometry::mesh",
        ],
    ),
    (
        "geometry::lanes",
        &["geometry::world", "geometry::bvh", "geometry::mesh"],
    ),
    ("geometry::mesh", &["geometry::world"]),
    ("render::path", &["render"]),
    ("render::scatter", &["render"]),
    (
        "render::context",
        &[
            "render::integrator",
            "render::shading",
            "render::pixel",
            "render::view",
        ],
    ),
    (
        "render::view",
        &["render::integrator", "render::shading", "render::pixel"],
    ),
    (
        "render::record",
        &["render::integrator", "render::shading", "render::pixel"],
    ),
    (
        "render::shading",
        &["render::integrator", "render::pixel", "render::view"],
    ),
    ("render::integrator", &["render::pixel"]),
    // eval: the schemas of the built-ins are a leaf (data, no values); values, types and
    // arguments know no interpreter; built-ins, operators, members, methods and constructors
    // reach it only through `eval::host::Host`.
    ("eval::schema", &["eval"]),
    ("eval::value", EVAL_CORE),
    ("eval::types", EVAL_CORE),
    ("eval::error", EVAL_CORE),
    ("eval::args", EVAL_CORE),
    ("eval::host", EVAL_CORE),
    ("eval::options", EVAL_CORE),
    ("eval::parts", EVAL_CORE),
    ("eval::lower", EVAL_CORE),
    ("eval::modules", EVAL_CORE),
    ("eval::params", EVAL_CORE),
    ("eval::builtins", EVAL_CORE),
    ("eval::shapes", EVAL_CORE),
    ("eval::transform", EVAL_CORE),
    ("eval::motion", EVAL_CORE),
    ("eval::rng", EVAL_CORE),
    ("eval::bounds", EVAL_CORE),
    ("eval::assets", EVAL_CORE),
    ("eval::with", EVAL_CORE),
    ("eval::ops", EVAL_CORE),
    ("eval::members", EVAL_CORE),
    ("eval::methods", EVAL_CORE),
];

/// The interpreter proper (its state and the evaluation of statements, calls and modules, all
/// under `eval/interp/`) and the library reader that runs it.
const EVAL_CORE: &[&str] = &["eval::interp", "eval::library"];

/// The sub-rooms of geometry.
const GEOMETRY_ROOMS: &[&str] = &[
    "geometry::shapes",
    "geometry::bvh",
    "geometry::lanes",
    "geometry::mesh",
    "geometry::world",
];

/// Why a file of module `from` (its full path) may not use `u` by the walls inside its room.
fn wall(from: &[String], u: &Use) -> Option<String> {
    let from_path = from.join("::");
    let to = u.absolute.join("::");
    let under =
        |path: &str, prefix: &str| path == prefix || path.starts_with(&format!("{prefix}::"));
    for (module, banned) in WALLS {
        if !under(&from_path, module) || under(&to, module) {
            continue;
        }
        if let Some(b) = banned.iter().find(|b| under(&to, b)) {
            return Some(format!(
                "`{module}` may not import `{b}` (a wall inside its room)"
            ));
        }
    }
    None
}

#[test]
fn no_room_has_a_larger_circle_than_its_cap() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let graph = architecture_support::graph::FileGraph::of_crate(root);
    // `RTC_ARCH_EDGES=eval` prints that room's file imports, to see what closes a circle.
    if let Ok(room) = std::env::var("RTC_ARCH_EDGES") {
        for (a, targets) in graph.edges.iter().enumerate() {
            if graph.rooms[a] == room {
                let names: Vec<&str> = targets.iter().map(|&b| graph.files[b].as_str()).collect();
                eprintln!("{} -> {}", graph.files[a], names.join(" "));
            }
        }
    }
    let mut problems = Vec::new();
    for (room, circle) in graph.largest_circles() {
        eprintln!("{room:>10}: largest circle {} file(s)", circle.len());
        if circle.len() > 1 {
            eprintln!("            {}", circle.join(" "));
        }
        let cap = MAX_CIRCLE
            .iter()
            .find(|(r, _)| *r == room)
            .map_or(1, |(_, c)| *c);
        if circle.len() > cap {
            problems.push(format!(
                "room `{room}`: a circle of {} files (cap {cap}): {}",
                circle.len(),
                circle.join(", ")
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
