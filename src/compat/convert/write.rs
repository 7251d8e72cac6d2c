//! The converted file: header, the file's comments at the items they precede, the camera as the
//! equivalent `fov`, lights, named materials, objects and the course's render settings written
//! out (they differ from the language's defaults).

use crate::num::Norm;
use std::fmt::Write as _;

use super::comments::{Comment, is_rule};
use super::names::Palette;
use super::shapes::{self, AssetPath};
use super::text::{color, comment, direction, number, vector};
use crate::ir::{
    AmbientConvention, Camera, DepthRange, Encoding, Light, LightKind, Projection, RenderMode,
    RenderSettings, Sampling, Scene, ShadingModel,
};
use crate::source::Span;

/// What the writer needs besides the scene.
pub struct Doc<'a> {
    /// The course file's name, for the header.
    pub file_name: &'a str,
    /// "course YAML" or "course `.in`".
    pub format: &'a str,
    /// The file's comments.
    pub comments: &'a [Comment],
    /// How an asset is referred to from the output's directory.
    pub asset: AssetPath<'a>,
}

/// Comments sorted to the items of the scene.
#[derive(Default)]
pub struct Placed {
    /// Before the first item: the file's header.
    pub header: Vec<usize>,
    /// Per item (in [`items`] order), the comments before it and inside it.
    pub before: Vec<Vec<usize>>,
    /// After the last item.
    pub trailing: Vec<usize>,
}

/// The spans of the camera, the lights and the objects, in that order.
pub fn items(scene: &Scene) -> Vec<Span> {
    std::iter::once(scene.camera.span)
        .chain(scene.lights.iter().map(|l| l.span))
        .chain(scene.objects.iter().map(|o| o.span))
        .collect()
}

/// Gives each comment (except those in `skip`) to the item it is inside, else to the first item
/// after it in the file; those before every item form the header.
pub fn place(comments: &[Comment], spans: &[Span], skip: &[usize]) -> Placed {
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
pub fn write(scene: &Scene, doc: &Doc<'_>, palette: &Palette, placed: &Placed) -> String {
    let mut out = String::new();
    let stem = doc
        .file_name
        .rsplit_once('.')
        .map_or(doc.file_name, |p| p.0);
    let _ = writeln!(
        out,
        "// {stem}.rtc: converted by `rtc convert` from {} (a {} scene); it renders the same image.",
        doc.file_name, doc.format
    );
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
    out.push_str(&camera(&scene.camera));
    out.push('\n');
    for (i, l) in scene.lights.iter().enumerate() {
        comments(&placed.before[1 + i], &mut out);
        let _ = writeln!(out, "{}", light(l));
    }
    if !palette.entries.is_empty() {
        out.push_str(
            "\n// The course uses ks as the mirror weight, so reflect = ks unless the file gives it.\n",
        );
        for (id, name) in &palette.entries {
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
    out.push('\n');
    out.push_str(&render(&scene.settings));
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

/// The camera. The course camera (|up| = the size of a pixel at `center`) becomes the field of
/// view that makes a pixel at `center` exactly |up| wide, or, where no angle does that to the
/// last bit, `course: true` (the language's course camera); `up` keeps its length either way.
fn camera(c: &Camera) -> String {
    let mut out = String::new();
    let view = match c.projection {
        Projection::Perspective { fov_y } => format!("fov: {}rad", number(fov_y)),
        Projection::Course => {
            let size = c.up.norm();
            let width = if size == 1.0 {
                "one unit".to_string()
            } else {
                format!("|up| = {} units", number(size))
            };
            let _ = writeln!(
                out,
                "// The course camera: {}×{} pixels {width} wide on the plane through `center` (COURSE.md §2.4).",
                c.width, c.height
            );
            match course_fov(c) {
                Some(fov) => {
                    out.push_str(
                        "// The field of view 2·atan(h·|up| / (2·distance(eye, center))) gives the same rays.\n",
                    );
                    format!("fov: {fov}")
                }
                None => {
                    out.push_str(
                        "// No field of view gives this pixel size to the last bit, so `course: true` keeps it.\n",
                    );
                    "course: true".to_string()
                }
            }
        }
    };
    let _ = writeln!(
        out,
        "camera {{\n  eye: {}, center: {}, up: {}\n  {view}, resolution: [{}, {}]",
        vector(c.eye),
        vector(c.center),
        direction(c.up),
        c.width,
        c.height
    );
    if c.aperture > 0.0 {
        let _ = writeln!(
            out,
            "  aperture: {}, focus: {}",
            number(c.aperture),
            number(c.focus_distance)
        );
    }
    out.push_str("}\n");
    out
}

/// The `fov` of a course camera, `2 * atan(a / d)` with a = h·|up|/2 and d = |center − eye|,
/// when the renderer's pixel for it (`render::camera`: 2·d·tan(fov/2)/h, with `libm` as here)
/// is |up| to the bit.
fn course_fov(c: &Camera) -> Option<String> {
    let size = c.up.norm();
    let d = (c.center - c.eye).norm();
    let h = f64::from(c.height);
    let a = h * size / 2.0;
    let fov = 2.0 * libm::atan(a / d);
    let pixel = 2.0 * d * libm::tan(0.5 * fov) / h;
    (pixel == size).then(|| format!("2 * atan({} / {})", number(a), number(d)))
}

fn light(l: &Light) -> String {
    match l.kind {
        LightKind::Point { position } => format!(
            "point_light {{ position: {}, color: {} }}",
            vector(position),
            color(l.color)
        ),
        LightKind::Area {
            corner,
            u,
            v,
            samples,
        } => format!(
            "area_light {{ corner: {}, u: {}, v: {}, samples: [{}, {}], color: {} }}",
            vector(corner),
            vector(u),
            vector(v),
            samples[0],
            samples[1],
            color(l.color)
        ),
    }
}

/// Every setting the course gives, and those where the language's defaults differ from the
/// course's (shadows, bounces, encoding, cut-off), so the file says what it renders.
fn render(s: &RenderSettings) -> String {
    let mut fields = vec![
        format!("shadows: {}", s.shadows),
        format!("max_depth: {}", s.max_depth),
    ];
    match s.sampling {
        Sampling::Grid { factor: 1 } => {}
        Sampling::Grid { factor } => fields.push(format!("supersampling: {factor}")),
        Sampling::Adaptive {
            min,
            max,
            threshold,
        } => fields.push(format!(
            "supersampling: adaptive(min: {min}, max: {max}, threshold: {})",
            number(threshold)
        )),
    }
    match s.mode {
        RenderMode::Shaded => {}
        RenderMode::Normal => fields.push("mode: normal".into()),
        RenderMode::Depth(DepthRange::Auto) => fields.push("mode: depth".into()),
        RenderMode::Depth(DepthRange::Fixed { near, far }) => fields.push(format!(
            "mode: depth(near: {}, far: {})",
            number(near),
            number(far)
        )),
    }
    if s.shading != ShadingModel::Phong {
        fields.push(format!("shading: {}", shapes::shading(s.shading)));
    }
    if s.ambient == AmbientConvention::Once {
        fields.push("ambient: once".into());
    }
    if s.background != glam::DVec3::ZERO {
        fields.push(format!("background: {}", color(s.background)));
    }
    if s.seed != 0 {
        fields.push(format!("seed: {}", s.seed));
    }
    if s.glass_shadows {
        fields.push("glass_shadows: true".into());
    }
    let encoding = match s.encoding {
        Encoding::Linear => "linear",
        Encoding::Srgb => "srgb",
    };
    fields.push(format!("encoding: {encoding}"));
    fields.push(format!("cutoff: {}", number(s.cutoff)));
    let why = "// The course's settings, written out where the language's defaults differ (shadows on,\n\
               // 5 bounces, sRGB output, a cut-off): `encoding: linear` writes trunc(255·c) like the\n\
               // course and `cutoff: 0` traces every ray.\n";
    let one_line = format!("render {{ {} }}", fields.join(", "));
    if one_line.len() <= 100 {
        format!("{why}{one_line}\n")
    } else {
        format!("{why}render {{\n  {}\n}}\n", fields.join("\n  "))
    }
}
