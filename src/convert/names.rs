//! Names for the materials of a converted scene: the course files give each object its own
//! material, so identical ones are shared under one `let`, named after the comment the file
//! puts on them (`material: # blue`, `#Blue sphere`), else after their texture, role or colour.

use std::path::Path;

use crate::eval::reserved_names;
use crate::ir::{Material, MaterialId, Scene, Texture};
use crate::source::Span;

/// Words that name the object rather than its material (`#Blue sphere` names the colour).
const OBJECT_WORDS: &[&str] = &[
    "sphere", "spheres", "ball", "object", "material", "the", "a", "an", "triangle", "plane",
    "box", "quad", "cylinder", "mesh", "model",
];

/// The materials of the rtc file: one per distinct course material, with its name.
#[derive(Debug)]
pub(crate) struct Palette {
    /// Distinct materials in first-use order: a representative id and the chosen name.
    pub(crate) entries: Vec<(MaterialId, String)>,
    /// For every scene material id, its entry.
    pub(crate) entry_of: Vec<usize>,
}

/// Groups equal materials and names each group; `hint(id)` is the comment that names material
/// `id` in the file, if any.
pub(crate) fn palette(scene: &Scene, hint: impl Fn(MaterialId) -> Option<String>) -> Palette {
    let mut entries: Vec<(MaterialId, String)> = Vec::new();
    let mut entry_of = Vec::with_capacity(scene.materials.len());
    for i in 0..scene.materials.len() {
        let id = MaterialId(i as u32);
        let same = entries
            .iter()
            .position(|(rep, _)| same_material(scene, *rep, id));
        let at = same.unwrap_or_else(|| {
            let base = hint(id)
                .and_then(|h| from_comment(&h))
                .unwrap_or_else(|| by_look(scene, scene.material(id)));
            let name = unique(&base, entries.iter().map(|(_, n)| n.as_str()));
            entries.push((id, name));
            entries.len() - 1
        });
        entry_of.push(at);
    }
    Palette { entries, entry_of }
}

/// Equal apart from where they were written (textures compared by what they are, not by id).
fn same_material(scene: &Scene, a: MaterialId, b: MaterialId) -> bool {
    let strip = |m: &Material| Material {
        span: Span::default(),
        texture: None,
        ..m.clone()
    };
    let texture = |m: &Material| {
        m.texture.map(|t| match &scene.textures[t.0 as usize] {
            Texture::Image {
                path,
                mapping,
                filter,
                ..
            } => Texture::Image {
                path: path.clone(),
                mapping: *mapping,
                filter: *filter,
                span: Span::default(),
            },
            other => other.clone(),
        })
    };
    let (ma, mb) = (scene.material(a), scene.material(b));
    strip(ma) == strip(mb) && texture(ma) == texture(mb)
}

/// An identifier from a short comment (`# blue` → `blue`, `#Blue sphere` → `blue`); `None` for
/// a comment that is a sentence rather than a name.
fn from_comment(text: &str) -> Option<String> {
    let words: Vec<String> = text
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .map(str::to_ascii_lowercase)
        .filter(|w| !OBJECT_WORDS.contains(&w.as_str()))
        .collect();
    if words.is_empty() || words.len() > 3 {
        return None;
    }
    let name = words.join("_");
    (name.len() <= 24).then(|| identifier(&name))
}

/// A valid, unreserved identifier from lower-case words: not a keyword, nor a built-in name a
/// top-level `let` would hide from the rest of the file (the language's list of them).
fn identifier(name: &str) -> String {
    let mut n = name.to_string();
    if n.starts_with(|c: char| c.is_ascii_digit()) {
        n.insert_str(0, "m_");
    }
    if reserved_names().binary_search(&n.as_str()).is_ok() {
        n.push_str("_material");
    }
    n
}

/// A name from what the material looks like: its texture's file, glass, or its colour.
fn by_look(scene: &Scene, m: &Material) -> String {
    if let Some(Texture::Image { path, .. }) = m.texture.map(|t| &scene.textures[t.0 as usize]) {
        let stem = Path::new(path)
            .file_stem()
            .map(|s| s.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default();
        let clean: String = stem
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        let clean = clean.trim_matches('_');
        if !clean.is_empty() {
            return identifier(clean);
        }
    }
    if m.refract > 0.0 {
        return "glass".into();
    }
    colour_name(m.color.x, m.color.y, m.color.z).into()
}

/// The everyday name of a linear RGB colour.
fn colour_name(r: f64, g: f64, b: f64) -> &'static str {
    let (hi, lo) = (r.max(g).max(b), r.min(g).min(b));
    if hi < 0.05 {
        return "black";
    }
    if hi - lo < 0.1 * hi.max(0.5) {
        return match hi {
            h if h > 0.9 => "white",
            h if h > 0.6 => "light_grey",
            h if h > 0.3 => "grey",
            _ => "dark_grey",
        };
    }
    let d = hi - lo;
    let hue = if hi == r {
        60.0 * ((g - b) / d).rem_euclid(6.0)
    } else if hi == g {
        60.0 * ((b - r) / d + 2.0)
    } else {
        60.0 * ((r - g) / d + 4.0)
    };
    match hue {
        h if h < 15.0 => "red",
        h if h < 40.0 => "orange",
        h if h < 70.0 => "yellow",
        h if h < 160.0 => "green",
        h if h < 200.0 => "cyan",
        h if h < 260.0 => "blue",
        h if h < 290.0 => "purple",
        h if h < 340.0 => "magenta",
        _ => "red",
    }
}

/// `base`, or `base_2`, `base_3`, ... when taken.
fn unique<'a>(base: &str, taken: impl Iterator<Item = &'a str> + Clone) -> String {
    let free = |n: &str| !taken.clone().any(|t| t == n);
    if free(base) {
        return base.to_string();
    }
    (2..)
        .map(|i| format!("{base}_{i}"))
        .find(|n| free(n))
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_from_comments() {
        assert_eq!(from_comment(" blue").as_deref(), Some("blue"));
        assert_eq!(from_comment("Blue sphere").as_deref(), Some("blue"));
        assert_eq!(
            from_comment(" light grey floor").as_deref(),
            Some("light_grey_floor")
        );
        assert_eq!(from_comment(" normal").as_deref(), Some("normal_material"));
        assert_eq!(from_comment(" 3d").as_deref(), Some("m_3d"));
        assert_eq!(
            from_comment(" eta = 1 so it should be only transparent"),
            None
        );
        assert_eq!(from_comment(" sphere"), None);
    }

    #[test]
    fn names_from_colours() {
        assert_eq!(colour_name(1.0, 0.0, 0.0), "red");
        assert_eq!(colour_name(1.0, 0.5, 0.0), "orange");
        assert_eq!(colour_name(1.0, 0.8, 0.0), "yellow");
        assert_eq!(colour_name(0.0, 1.0, 0.0), "green");
        assert_eq!(colour_name(0.0, 0.0, 1.0), "blue");
        assert_eq!(colour_name(0.4, 0.4, 0.4), "grey");
        assert_eq!(colour_name(1.0, 1.0, 1.0), "white");
        assert_eq!(unique("red", ["red", "red_2"].into_iter()), "red_3");
    }
}
