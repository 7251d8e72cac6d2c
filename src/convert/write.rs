//! The converted file: header, the file's comments at the items they precede, the camera (a
//! course camera as the equivalent `fov`), lights, named materials, objects and the render
//! settings that differ from the language's defaults (a course file's written out).

use std::fmt::Write as _;

use super::comments::{Comment, is_rule};
use super::names::Palette;
use super::shapes::{self, AssetPath};
use super::text::comment;
use super::view::{self, RenderDoc};
use crate::ir::Scene;
use crate::source::Span;

/// What the writer needs besides the scene.
pub(crate) struct Doc<'a> {
    /// The course file's name and its format ("course YAML" or "course `.in`"), for the header;
    /// `None` for the IR of any front end (no course camera rewritten as a field of view).
    pub(crate) origin: Option<(&'a str, &'a str)>,
    /// The file's comments.
    pub(crate) comments: &'a [Comment],
    /// How an asset is referred to from the output's directory.
    pub(crate) asset: AssetPath<'a>,
}

/// Comments sorted to the items of the scene.
#[derive(Default)]
pub(crate) struct Placed {
    /// Before the first item: the file's header.
    header: Vec<usize>,
    /// Per item (in [`items`] order), the comments before it and inside it.
    before: Vec<Vec<usize>>,
    /// After the last item.
    trailing: Vec<usize>,
}

/// The spans of the camera, the lights and the objects, in that order.
pub(crate) fn items(scene: &Scene) -> Vec<Span> {
    std::iter::once(scene.camera.span)
        .chain(scene.lights.iter().map(|l| l.span))
        .chain(scene.objects.iter().map(|o| o.span))
        .collect()
}

/// Gives each comment (except those in `skip`) to the item it is inside, else to the first item
/// after it in the file; those before every item form the header.
pub(crate) fn place(comments: &[Comment], spans: &[Span], skip: &[usize]) -> Placed {
    let mut placed = Placed {
        before: vec![Vec::new(); spans.len()],
        ..Placed::default()
    };
    let first = spans.iter().map(|s| s.start as usize).min().unwrap_or(0);
    for (i, c) in comments.iter().enumerate() {
        if skip.contains(&i) || is_rule(&c.text) {
            continue;
        }
        let inside = spans
            .iter()
            .position(|s| (s.start as usize..s.end as usize).contains(&c.start));
        let next = spans
            .iter()
            .enumerate()
            .filter(|(_, s)| s.start as usize > c.start)
            .min_by_key(|(_, s)| s.start)
            .map(|(k, _)| k);
        match (inside, next) {
            (Some(k), _) => placed.before[k].push(i),
            (None, _) if c.start < first => placed.header.push(i),
            (None, Some(k)) => placed.before[k].push(i),
            (None, None) => placed.trailing.push(i),
        }
    }
    placed
}

/// The whole rtc text.
pub(crate) fn write(scene: &Scene, doc: &Doc<'_>, palette: &Palette, placed: &Placed) -> String {
    let mut out = String::new();
    match doc.origin {
        Some((file_name, format)) => {
            let stem = file_name.rsplit_once('.').map_or(file_name, |p| p.0);
            let _ = writeln!(
                out,
                "// {stem}.rtc: converted by `rtc convert` from {file_name} (a {format} scene); it renders the same image.",
            );
        }
        None => out.push_str(
            "// Written by `rtc convert` from a scene's IR; it evaluates to the same scene.\n",
        ),
    }
    out.push_str("rtc 1.1\n");
    let comments = |ids: &[usize], out: &mut String| {
        for (k, &i) in ids.iter().enumerate() {
            let c = &doc.comments[i];
            // An empty comment that ends a paragraph was spacing before a rule (dropped).
            let next_gap = ids.get(k + 1).is_none_or(|&j| doc.comments[j].after_gap);
            if c.text.trim().is_empty() && next_gap {
                continue;
            }
            if k > 0 && c.after_gap {
                out.push('\n');
            }
            let _ = writeln!(out, "{}", comment(&c.text));
        }
    };
    if !placed.header.is_empty() {
        out.push('\n');
        comments(&placed.header, &mut out);
    }
    out.push('\n');
    comments(&placed.before[0], &mut out);
    out.push_str(&view::camera(&scene.camera, doc.origin.is_some()));
    out.push('\n');
    for (i, l) in scene.lights.iter().enumerate() {
        comments(&placed.before[1 + i], &mut out);
        let _ = writeln!(out, "{}", view::light(l));
    }
    if !palette.entries.is_empty() {
        out.push('\n');
        if doc.origin.is_some() {
            out.push_str(
                "// The course uses ks as the mirror weight, so reflect = ks unless the file gives it.\n",
            );
        }
        let part = |id: u32| palette.entries[palette.entry_of[id as usize]].1.clone();
        for (id, name) in &palette.entries {
            if let Some(mix) = &scene.material(*id).mix {
                let text = shapes::mixed(scene, mix, &part, doc.asset);
                let _ = writeln!(out, "let {name} = {text}");
                continue;
            }
            let fields = shapes::material(scene, scene.material(*id), doc.asset);
            let one_line = format!("let {name} = material {{ {} }}", fields.join(", "));
            if one_line.len() <= 100 {
                let _ = writeln!(out, "{one_line}");
            } else {
                let _ = writeln!(out, "let {name} = material {{\n  {}\n}}", grouped(&fields));
            }
        }
    }
    out.push('\n');
    let name = |id: u32| palette.entries[palette.entry_of[id as usize]].1.clone();
    let first_object = 1 + scene.lights.len();
    for (i, o) in scene.objects.iter().enumerate() {
        comments(&placed.before[first_object + i], &mut out);
        let _ = writeln!(out, "{}", shapes::object(o, &name, doc.asset));
    }
    if !placed.trailing.is_empty() {
        out.push('\n');
        comments(&placed.trailing, &mut out);
    }
    let settings = &scene.settings;
    let render = RenderDoc {
        course: doc.origin.is_some(),
        material: settings.default_material.map(|id| name(id.0)),
        output: settings.output.as_deref().map(doc.asset),
        sky: settings
            .sky
            .map(|s| shapes::texture(&scene.textures[s.texture.0 as usize], doc.asset)),
        fog_pattern: settings
            .fog
            .and_then(|f| f.pattern)
            .map(|p| shapes::texture(&scene.textures[p.texture.0 as usize], doc.asset)),
    };
    let render = view::render(settings, &render);
    if !render.is_empty() {
        out.push('\n');
        out.push_str(&render);
    }
    out
}

/// Material fields on lines of their own kind: the colour, the texture, the Phong coefficients,
/// the mirror and glass weights, then the rest one a line.
fn grouped(fields: &[String]) -> String {
    let kind = |f: &str| match f.split(':').next().unwrap_or("") {
        "ka" | "kd" | "ks" | "n" => 1,
        "reflect" | "refract" | "eta" => 2,
        _ => 0,
    };
    let mut lines: Vec<String> = Vec::new();
    let mut last = 0;
    for f in fields {
        let k = kind(f);
        match lines.last_mut() {
            Some(line) if k != 0 && k == last => {
                line.push_str(", ");
                line.push_str(f);
            }
            _ => lines.push(f.clone()),
        }
        last = k;
    }
    lines.join("\n  ")
}
