//! The Groningen course YAML format (COURSE.md §2): top-level keys, camera, lights and render
//! settings. Objects and materials are in [`crate::compat::yaml_objects`].

use crate::num::Norm;
use std::path::Path;

use crate::compat::course::{self, Draft};
use crate::compat::yaml_objects;
use crate::compat::yaml_tree::{self, YamlKind, YamlNode};
use crate::compat::yaml_values::{self as val, MapView, Triple};
use crate::diag::{Diagnostic, Diagnostics, did_you_mean};
use crate::ir::limits::{MAX_DEPTH, MAX_IMAGE_SIDE, MAX_PIXEL_SAMPLES_PER_AXIS};
use crate::ir::{
    DepthRange, GoochParams, Light, LightKind, RenderMode, Sampling, Scene, ShadingModel,
};
use crate::source::{FileId, Span};

/// Every top-level key the course files use (official spellings).
const TOP_KEYS: &[&str] = &[
    "Eye",
    "Camera",
    "Lights",
    "Objects",
    "RenderMode",
    "Shadows",
    "MaxRecursionDepth",
    "SuperSampling",
    "GoochParameters",
    "Models",
];

/// Parses a course YAML text into a scene, reporting every problem in `diags`.
/// The YAML tree's nodes are charged to `memory`, which the scene carries on.
pub(crate) fn parse(
    text: &str,
    file: FileId,
    path: &Path,
    diags: &mut Diagnostics,
    mut memory: crate::ir::limits::Memory,
) -> Option<Scene> {
    let whole = Span::new(file, 0, 0);
    let errors_before = diags.error_count();
    let Some(root) = yaml_tree::parse_first_document(text, file, diags, &mut memory) else {
        if diags.error_count() == errors_before {
            diags.push(
                Diagnostic::error("rtc::yaml::empty", whole, "the YAML file holds no scene")
                    .with_label("no YAML document here")
                    .with_help("start with `Eye: [200, 200, 1000]`, then `Lights:` and `Objects:`"),
            );
        }
        return None;
    };
    let mut top = MapView::new(&root, "a scene", diags)?;
    let mut draft = Draft::default();

    if let Some(e) = top.get(&["Eye"], diags) {
        draft.camera_written = true;
        if let Some(eye) = val::triple(e.value, "`Eye`", Triple::Point, diags) {
            draft.eye = Some((eye, e.key.span.join(e.value.span)));
        }
    }
    if let Some(e) = top.get(&["Camera"], diags) {
        draft.camera_written = true;
        draft.camera = camera(e.value, e.key.span.join(e.value.span), diags);
    }
    if let Some(e) = top.get(&["Lights"], diags) {
        for item in list(e.value, "`Lights`", diags) {
            if let Some(l) = light(item, diags) {
                draft.lights.push(l);
            }
        }
    }
    if let Some(e) = top.get(&["Objects"], diags) {
        for item in list(e.value, "`Objects`", diags) {
            yaml_objects::object(item, path, &mut draft.scene, diags);
        }
    }
    if let Some(e) = top.get(&["Models"], diags) {
        for item in list(e.value, "`Models`", diags) {
            yaml_objects::model(item, path, &mut draft.scene, diags);
        }
    }
    settings(&mut top, &mut draft, diags);
    top.finish("the scene", TOP_KEYS, diags);
    let scene = draft.finish(
        whole,
        "add `Eye: [200, 200, 1000]` or a `Camera:` block",
        diags,
    )?;
    Some(Scene { memory, ..scene })
}

/// The items of a list; a non-list is reported and yields nothing. An empty value (`Objects:`
/// with nothing under it) is an empty list.
fn list<'n>(node: &'n YamlNode, what: &str, diags: &mut Diagnostics) -> &'n [YamlNode] {
    match &node.kind {
        YamlKind::Seq(items) => items,
        YamlKind::Scalar {
            text,
            quoted: false,
        } if text.is_empty() || text == "~" || text == "null" => &[],
        _ => {
            diags.push(
                Diagnostic::error(
                    "rtc::yaml::type",
                    node.span,
                    format!("expected a list for {what}, found {}", node.describe()),
                )
                .with_label("not a list")
                .with_help("write each item on its own line starting with `- `"),
            );
            &[]
        }
    }
}

fn camera(node: &YamlNode, span: Span, diags: &mut Diagnostics) -> Option<crate::ir::Camera> {
    let mut m = MapView::new(node, "`Camera`", diags)?;
    let eye = m.require(&["eye"], "`Camera`", "eye: [200, 200, 1000]", diags);
    let center = m.require(&["center"], "`Camera`", "center: [200, 200, 0]", diags);
    let up = m.require(&["up"], "`Camera`", "up: [0, 1, 0]", diags);
    let size = m.require(&["viewSize"], "`Camera`", "viewSize: [400, 400]", diags);
    let eye = eye.and_then(|e| val::triple(e.value, "`eye`", Triple::Point, diags));
    let center = center.and_then(|e| val::triple(e.value, "`center`", Triple::Point, diags));
    let up_entry = up;
    let up = up_entry
        .as_ref()
        .and_then(|e| val::triple(e.value, "`up`", Triple::Point, diags));
    let size = size.and_then(|e| view_size(e.value, diags));
    m.finish("`Camera`", &["eye", "center", "up", "viewSize"], diags);
    let up_span = up_entry.map_or(span, |e| e.value.span);
    if up.is_some_and(|u| u.norm() == 0.0) {
        diags.push(
            Diagnostic::error(
                "rtc::compat::degenerate",
                up_span,
                "`up` is the zero vector",
            )
            .with_label("its length is the pixel size and must be positive")
            .with_help("write `up: [0, 1, 0]` for one world unit per pixel"),
        );
        return None;
    }
    let (eye, center, up, size) = (eye?, center?, up?, size?);
    let view = center - eye;
    if view.norm() == 0.0 {
        diags.push(
            Diagnostic::error(
                "rtc::compat::degenerate",
                span,
                "`eye` and `center` are the same point",
            )
            .with_label("the view direction is undefined"),
        );
        return None;
    }
    if view.cross(up).norm() <= 1e-12 * view.norm() * up.norm() {
        diags.push(
            Diagnostic::error(
                "rtc::compat::degenerate",
                up_span,
                "`up` is parallel to the view direction",
            )
            .with_label("up must not point along center − eye"),
        );
        return None;
    }
    Some(course::course_camera(eye, center, up, size, span))
}

fn view_size(node: &YamlNode, diags: &mut Diagnostics) -> Option<[u32; 2]> {
    let YamlKind::Seq(items) = &node.kind else {
        diags.push(
            Diagnostic::error(
                "rtc::yaml::type",
                node.span,
                format!(
                    "expected `[width, height]` for `viewSize`, found {}",
                    node.describe()
                ),
            )
            .with_label("not a list")
            .with_help("write `viewSize: [400, 400]`"),
        );
        return None;
    };
    if items.len() != 2 {
        diags.push(
            Diagnostic::error(
                "rtc::yaml::arity",
                node.span,
                format!("`viewSize` has {} numbers, expected 2", items.len()),
            )
            .with_label(format!("{} numbers", items.len()))
            .with_help("write `viewSize: [width, height]`"),
        );
        return None;
    }
    let w = val::integer(&items[0], "the image width", 1, MAX_IMAGE_SIDE, diags);
    let h = val::integer(&items[1], "the image height", 1, MAX_IMAGE_SIDE, diags);
    Some([w?, h?])
}

fn light(node: &YamlNode, diags: &mut Diagnostics) -> Option<Light> {
    let mut m = MapView::new(node, "a light", diags)?;
    let position = m.require(
        &["position"],
        "this light",
        "position: [-200, 600, 1500]",
        diags,
    );
    let color = m.require(&["color"], "this light", "color: [1.0, 1.0, 1.0]", diags);
    let position = position.and_then(|e| val::triple(e.value, "`position`", Triple::Point, diags));
    let color = color.and_then(|e| val::triple(e.value, "`color`", Triple::Color, diags));
    m.finish("a light", &["position", "color"], diags);
    Some(Light::new(
        LightKind::Point {
            position: position?,
        },
        color?,
        node.span,
    ))
}

/// RenderMode, Shadows, MaxRecursionDepth, SuperSampling, GoochParameters (and student spellings).
fn settings(top: &mut MapView<'_>, draft: &mut Draft, diags: &mut Diagnostics) {
    let s = &mut draft.scene.settings;
    let mut gooch_mode = None;
    if let Some(e) = top.get(&["RenderMode"], diags) {
        match render_mode(e.value, diags) {
            Some(Mode::Phong) | None => {}
            Some(Mode::ZBuffer) => s.mode = RenderMode::Depth(DepthRange::Auto),
            Some(Mode::Normal) => s.mode = RenderMode::Normal,
            Some(Mode::Gooch) => gooch_mode = Some(e.value.span),
        }
    }
    if let Some(e) = top.get(&["Shadows", "shadow"], diags) {
        if e.key.scalar() == Some("shadow") {
            spelling(e.key, "Shadows", diags);
        }
        if let Some(b) = val::boolean(e.value, "Shadows", diags) {
            s.shadows = b;
        }
    }
    if let Some(e) = top.get(&["MaxRecursionDepth"], diags)
        && let Some(d) = val::integer(e.value, "`MaxRecursionDepth`", 0, u32::MAX, diags)
    {
        s.max_depth = capped_depth(d, e.value.span, diags);
    }
    if let Some(e) = top.get(&["SuperSampling"], diags)
        && let Some(factor) = super_sampling(e.value, diags)
    {
        s.sampling = Sampling::Grid { factor };
    }
    let params = top
        .get(&["GoochParameters"], diags)
        .and_then(|e| gooch(e.value, gooch_mode.is_some(), diags));
    if gooch_mode.is_some() {
        s.shading = ShadingModel::Gooch(params.unwrap_or_default());
    }
}

/// A depth past [`MAX_DEPTH`] is read as the cap, with a warning: course files were written for
/// renderers without one, and their images do not change past a few bounces.
fn capped_depth(depth: u32, span: Span, diags: &mut Diagnostics) -> u32 {
    if depth <= MAX_DEPTH {
        return depth;
    }
    diags.push(
        Diagnostic::warning(
            "rtc::compat::capped",
            span,
            format!("`MaxRecursionDepth` {depth} is more than rtc traces; it traces {MAX_DEPTH}"),
        )
        .with_label(format!("read as {MAX_DEPTH}"))
        .with_help(format!("write `MaxRecursionDepth: {MAX_DEPTH}` or less")),
    );
    MAX_DEPTH
}

fn spelling(key: &YamlNode, official: &str, diags: &mut Diagnostics) {
    let written = key.scalar().unwrap_or("");
    diags.push(
        Diagnostic::warning(
            "rtc::yaml::spelling",
            key.span,
            format!("`{written}` read as `{official}`"),
        )
        .with_label("non-standard spelling")
        .with_help(format!("write `{official}`")),
    );
}

enum Mode {
    Phong,
    ZBuffer,
    Normal,
    Gooch,
}

fn render_mode(node: &YamlNode, diags: &mut Diagnostics) -> Option<Mode> {
    let Some(text) = node.scalar().map(str::trim) else {
        diags.push(
            Diagnostic::error(
                "rtc::yaml::type",
                node.span,
                format!("expected a render mode name, found {}", node.describe()),
            )
            .with_label("not a name")
            .with_help("write `RenderMode: \"phong\"`"),
        );
        return None;
    };
    const MODES: [&str; 4] = ["phong", "zbuffer", "normal", "gooch"];
    let lower = text.to_ascii_lowercase();
    let mode = match lower.as_str() {
        "phong" => Mode::Phong,
        "zbuffer" => Mode::ZBuffer,
        "normal" => Mode::Normal,
        "gooch" => Mode::Gooch,
        _ if text.parse::<f64>().is_ok() => {
            diags.push(
                Diagnostic::warning(
                    "rtc::yaml::unknown_value",
                    node.span,
                    format!("render mode `{text}` is a number; using phong"),
                )
                .with_label("the course names render modes")
                .with_help(
                    "write `RenderMode: \"phong\"`, `\"zbuffer\"`, `\"normal\"` or `\"gooch\"`",
                ),
            );
            return None;
        }
        _ => {
            let mut d = Diagnostic::error(
                "rtc::yaml::unknown_value",
                node.span,
                format!("unknown render mode `{text}`"),
            )
            .with_label("not a render mode");
            d = match did_you_mean(&lower, MODES) {
                Some(g) => d.with_help(format!("did you mean `\"{g}\"`?")),
                None => d.with_help("use `\"phong\"`, `\"zbuffer\"`, `\"normal\"` or `\"gooch\"`"),
            };
            diags.push(d);
            return None;
        }
    };
    if text != lower {
        diags.push(
            Diagnostic::warning(
                "rtc::yaml::spelling",
                node.span,
                format!("render mode `{text}` read as `{lower}`"),
            )
            .with_label("non-standard spelling")
            .with_help(format!("write `\"{lower}\"`")),
        );
    }
    Some(mode)
}

fn super_sampling(node: &YamlNode, diags: &mut Diagnostics) -> Option<u32> {
    if node.scalar().is_some() {
        let f = val::integer(
            node,
            "`SuperSampling`",
            1,
            MAX_PIXEL_SAMPLES_PER_AXIS,
            diags,
        )?;
        diags.push(
            Diagnostic::warning(
                "rtc::yaml::spelling",
                node.span,
                format!("`SuperSampling: {f}` read as a {f}×{f} grid"),
            )
            .with_label("the course writes a map here")
            .with_help(format!("write `SuperSampling: {{factor: {f}}}`")),
        );
        return Some(f);
    }
    let mut m = MapView::new(node, "`SuperSampling`", diags)?;
    let factor = m
        .require(&["factor"], "`SuperSampling`", "factor: 4", diags)
        .and_then(|e| val::integer(e.value, "`factor`", 1, MAX_PIXEL_SAMPLES_PER_AXIS, diags));
    if let Some(p) = m.get(&["pattern"], diags)
        && !p
            .value
            .scalar()
            .is_some_and(|t| t.trim().eq_ignore_ascii_case("grid"))
    {
        diags.push(
            Diagnostic::warning(
                "rtc::yaml::unknown_value",
                p.value.span,
                format!(
                    "sampling pattern {} is not supported; using a grid",
                    p.value.describe()
                ),
            )
            .with_label("ignored"),
        );
    }
    m.finish("`SuperSampling`", &["factor"], diags);
    factor
}

fn gooch(node: &YamlNode, used: bool, diags: &mut Diagnostics) -> Option<GoochParams> {
    let mut m = MapView::new(node, "`GoochParameters`", diags)?;
    let mut p = GoochParams::default();
    for (name, slot) in [
        ("b", &mut p.b),
        ("y", &mut p.y),
        ("alpha", &mut p.alpha),
        ("beta", &mut p.beta),
    ] {
        if let Some(e) = m.get(&[name], diags)
            && let Some(v) = val::non_negative(e.value, &format!("`{name}`"), diags)
        {
            *slot = v;
        }
    }
    m.finish("`GoochParameters`", &["b", "y", "alpha", "beta"], diags);
    if !used {
        diags.push(
            Diagnostic::warning(
                "rtc::yaml::unused",
                node.span,
                "`GoochParameters` has no effect",
            )
            .with_label("only used when `RenderMode` is \"gooch\"")
            .with_help("add `RenderMode: \"gooch\"` or remove these parameters"),
        );
    }
    Some(p)
}
