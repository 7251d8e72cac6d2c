//! Course YAML objects and materials: the official `sphere` (with the textured `radius: [r, pole]`
//! form and `angle`), and the student geometry spellings that map onto IR shapes unambiguously
//! (triangle, plane, box, quad, cylinder, mesh/model).

use crate::num::Norm;
use std::path::Path;

use glam::{DAffine3, DVec3};

use crate::compat::course::{self, CourseMaterial, SceneParts};
use crate::compat::yaml_tree::{YamlKind, YamlNode};
use crate::compat::yaml_values::{self as val, MapView, Triple};
use crate::diag::{Diagnostic, Diagnostics, did_you_mean};
use crate::ir::{Mapping, MaterialId, Object, Shape, Texture};

const TYPES: &[&str] = &[
    "sphere", "triangle", "plane", "box", "quad", "cylinder", "mesh", "model",
];
const MATERIAL_KEYS: &[&str] = &[
    "color", "texture", "ka", "kd", "ks", "n", "reflect", "refract", "eta",
];

/// Reads one entry of `Objects` into `parts`; unknown types are skipped with a warning.
pub(crate) fn object(
    node: &YamlNode,
    scene: &Path,
    parts: &mut SceneParts,
    diags: &mut Diagnostics,
) {
    let Some(mut m) = MapView::new(node, "an object", diags) else {
        return;
    };
    let Some(t) = m.require(&["type"], "this object", "type: sphere", diags) else {
        return;
    };
    let Some(kind) = val::string(t.value, "`type`", diags) else {
        return;
    };
    let lower = kind.to_ascii_lowercase();
    let Some(&kind_name) = TYPES.iter().find(|k| **k == lower) else {
        let mut d = Diagnostic::warning(
            "rtc::yaml::unknown_object",
            t.value.span,
            format!("unknown object type `{kind}`; the object is skipped"),
        )
        .with_label("not a known object type");
        if let Some(g) = did_you_mean(&lower, TYPES.iter().copied()) {
            d = d.with_help(format!("did you mean `{g}`?"));
        }
        diags.push(d);
        return;
    };
    let shape = match kind_name {
        "sphere" => return sphere(m, node, scene, parts, diags),
        "mesh" | "model" => return mesh(m, node, scene, parts, diags, true),
        "triangle" => triangle(&mut m, diags),
        "plane" => plane(&mut m, diags),
        "box" => aabb(&mut m, diags),
        "quad" => quad(&mut m, diags),
        _ => cylinder(&mut m, diags),
    };
    let material = material_entry(&mut m, scene, Mapping::Uv, parts, diags);
    m.finish(&format!("a {kind_name}"), &known_keys(kind_name), diags);
    if let (Some(shape), Some(material)) = (shape, material) {
        parts.objects.push(Object {
            motion: None,
            shape,
            transform: crate::ir::Transform::IDENTITY,
            material: Some(material),
            span: node.span,
            visibility: crate::ir::Visibility::ALL,
        });
    }
}

/// Reads one entry of the student `Models` list (a mesh without a `type` key).
pub(crate) fn model(
    node: &YamlNode,
    scene: &Path,
    parts: &mut SceneParts,
    diags: &mut Diagnostics,
) {
    if let Some(m) = MapView::new(node, "a model", diags) {
        mesh(m, node, scene, parts, diags, false);
    }
}

fn known_keys(kind: &str) -> Vec<&'static str> {
    let mut keys: Vec<&'static str> = match kind {
        "sphere" => vec!["position", "radius", "angle"],
        "triangle" => vec!["point1", "point2", "point3"],
        "plane" => vec!["point", "normal"],
        "box" => vec!["min", "max"],
        "quad" => vec!["p1", "p2", "p3", "p4"],
        "cylinder" => vec!["p1", "p2", "radius"],
        _ => vec!["file", "position", "scale"],
    };
    keys.extend(["type", "material"]);
    keys
}

fn point(
    m: &mut MapView<'_>,
    names: &[&str],
    owner: &str,
    diags: &mut Diagnostics,
) -> Option<DVec3> {
    let example = format!("{}: [0, 0, 0]", names[0]);
    let e = m.require(names, owner, &example, diags)?;
    val::triple(e.value, &format!("`{}`", names[0]), Triple::Point, diags)
}

fn direction(
    m: &mut MapView<'_>,
    names: &[&str],
    owner: &str,
    diags: &mut Diagnostics,
) -> Option<DVec3> {
    let example = format!("{}: [0, 1, 0]", names[0]);
    let e = m.require(names, owner, &example, diags)?;
    let v = val::triple(e.value, &format!("`{}`", names[0]), Triple::Point, diags)?;
    if v.norm() == 0.0 {
        diags.push(
            Diagnostic::error(
                "rtc::compat::degenerate",
                e.value.span,
                format!("`{}` is the zero vector", names[0]),
            )
            .with_label("a direction needs a non-zero length"),
        );
        return None;
    }
    Some(v.unit())
}

fn sphere(
    mut m: MapView<'_>,
    node: &YamlNode,
    scene: &Path,
    parts: &mut SceneParts,
    diags: &mut Diagnostics,
) {
    let position = point(&mut m, &["position"], "this sphere", diags);
    let mut pole = None;
    let radius = m
        .require(&["radius"], "this sphere", "radius: 50", diags)
        .and_then(|e| radius(e.value, &mut pole, diags));
    let angle = m
        .get(&["angle"], diags)
        .and_then(|e| val::number(e.value, "`angle`", diags));
    if let Some(e) = m.get(&["axis"], diags) {
        diags.push(
            Diagnostic::warning(
                "rtc::yaml::spelling",
                e.key.span,
                "`axis` read as the texture's north pole",
            )
            .with_label("student spelling")
            .with_help("write `radius: [r, [x, y, z]]` to give the pole"),
        );
        if pole.is_none() {
            pole = pole_vector(e.value, diags);
        }
    }
    let material = material_entry(&mut m, scene, Mapping::Spherical, parts, diags);
    m.finish("a sphere", &known_keys("sphere"), diags);
    let (Some(position), Some(radius), Some(material)) = (position, radius, material) else {
        return;
    };
    let textured = parts
        .materials
        .get(material.0 as usize)
        .is_some_and(|mat| mat.texture.is_some());
    let orientation = (pole.is_some() || angle.is_some() || textured)
        .then(|| (pole.unwrap_or(DVec3::Y), angle.unwrap_or(0.0)));
    let sphere = course::sphere_object(position, radius, orientation, Some(material), node.span);
    parts.objects.push(sphere);
}

/// `radius: r` or `radius: [r, [x, y, z]]` (the list form also gives the texture's north pole).
fn radius(node: &YamlNode, pole: &mut Option<DVec3>, diags: &mut Diagnostics) -> Option<f64> {
    match &node.kind {
        YamlKind::Seq(items) if items.len() == 2 => {
            *pole = pole_vector(&items[1], diags);
            val::positive(&items[0], "the radius", diags)
        }
        YamlKind::Seq(items) => {
            diags.push(
                Diagnostic::error(
                    "rtc::yaml::arity",
                    node.span,
                    format!("`radius` list must have 2 items, found {}", items.len()),
                )
                .with_label("expected a radius and a pole direction")
                .with_help("write `radius: 50` or `radius: [50, [0, 1, 0]]`"),
            );
            None
        }
        _ => val::positive(node, "the radius", diags),
    }
}

fn pole_vector(node: &YamlNode, diags: &mut Diagnostics) -> Option<DVec3> {
    let v = val::triple(node, "the pole", Triple::Point, diags)?;
    if v.norm() == 0.0 {
        diags.push(
            Diagnostic::error(
                "rtc::compat::degenerate",
                node.span,
                "the pole is the zero vector",
            )
            .with_label("the north-pole direction needs a non-zero length")
            .with_help("write a direction such as `[0, 1, 0]`"),
        );
        return None;
    }
    Some(v)
}

fn triangle(m: &mut MapView<'_>, diags: &mut Diagnostics) -> Option<Shape> {
    let a = point(m, &["point1", "vertex1", "v1"], "this triangle", diags);
    let b = point(m, &["point2", "vertex2", "v2"], "this triangle", diags);
    let c = point(m, &["point3", "vertex3", "v3"], "this triangle", diags);
    Some(Shape::Triangle {
        vertices: [a?, b?, c?],
    })
}

fn plane(m: &mut MapView<'_>, diags: &mut Diagnostics) -> Option<Shape> {
    let p = point(m, &["point", "O"], "this plane", diags);
    let n = direction(m, &["normal", "N"], "this plane", diags);
    Some(Shape::Plane {
        point: p?,
        normal: n?,
    })
}

fn aabb(m: &mut MapView<'_>, diags: &mut Diagnostics) -> Option<Shape> {
    let min = point(m, &["min"], "this box", diags)?;
    let max = point(m, &["max"], "this box", diags)?;
    Some(Shape::Box { min, max })
}

fn quad(m: &mut MapView<'_>, diags: &mut Diagnostics) -> Option<Shape> {
    let head = m.head();
    let p1 = point(m, &["p1"], "this quad", diags);
    let p2 = point(m, &["p2"], "this quad", diags);
    let p3_span = m.span_of("p3").unwrap_or(head);
    let p3 = point(m, &["p3"], "this quad", diags);
    let p4 = point(m, &["p4"], "this quad", diags);
    let (p1, p2, p3, p4) = (p1?, p2?, p3?, p4?);
    let (u, v) = (p2 - p1, p4 - p1);
    let scale = u.norm().max(v.norm()).max(1.0);
    let expected = p1 + u + v;
    if (expected - p3).norm() > 1e-9 * scale || u.cross(v).norm() == 0.0 {
        diags.push(
            Diagnostic::error(
                "rtc::compat::degenerate",
                p3_span,
                "the quad is not a parallelogram",
            )
            .with_label(format!(
                "p3 must be p2 + p4 − p1 = [{}, {}, {}]",
                expected.x, expected.y, expected.z
            ))
            .with_help("give the corners in order around a parallelogram, or use two triangles"),
        );
        return None;
    }
    Some(Shape::Quad { corner: p1, u, v })
}

fn cylinder(m: &mut MapView<'_>, diags: &mut Diagnostics) -> Option<Shape> {
    let base = point(m, &["p1", "center1", "base"], "this cylinder", diags);
    let top = point(m, &["p2", "center2", "top"], "this cylinder", diags);
    let radius = m
        .require(&["radius", "r"], "this cylinder", "radius: 25", diags)
        .and_then(|e| val::positive(e.value, "the radius", diags));
    let (base, top, radius) = (base?, top?, radius?);
    Some(Shape::Cylinder {
        base,
        top,
        radius,
        capped: true,
    })
}

/// A mesh: `file|filename`, optional `position` and `scale|size` (a number or a triple). Without a
/// material the OBJ's own MTL materials are used.
fn mesh(
    mut m: MapView<'_>,
    node: &YamlNode,
    scene: &Path,
    parts: &mut SceneParts,
    diags: &mut Diagnostics,
    typed: bool,
) {
    let file = m.require(&["file", "filename"], "this mesh", "file: model.obj", diags);
    let path = file.and_then(|e| {
        let name = val::string(e.value, "`file`", diags)?;
        course::find_asset(scene, name, e.value.span, "mesh", diags)
    });
    let position = match m.get(&["position"], diags) {
        Some(e) => val::triple(e.value, "`position`", Triple::Point, diags),
        None => Some(DVec3::ZERO),
    };
    let scale = match m.get(&["scale", "size"], diags) {
        Some(e) => match &e.value.kind {
            YamlKind::Seq(_) => val::triple(e.value, "`scale`", Triple::Point, diags),
            _ => val::positive(e.value, "`scale`", diags).map(DVec3::splat),
        },
        None => Some(DVec3::ONE),
    };
    let has_material = m.get(&["material"], diags);
    let material = match has_material {
        Some(e) => material(e.value, scene, Mapping::Uv, parts, diags).map(Some),
        None => Some(None),
    };
    if !typed {
        m.ignore("type");
    }
    m.finish("a mesh", &known_keys("mesh"), diags);
    let (Some(path), Some(position), Some(scale), Some(material)) =
        (path, position, scale, material)
    else {
        return;
    };
    if scale.min_element() <= 0.0 {
        diags.push(course::out_of_range(
            node.span,
            &format!("{scale}"),
            "the mesh scale",
            "positive",
        ));
        return;
    }
    let mesh = Object {
        motion: None,
        shape: Shape::Mesh {
            source: crate::ir::MeshSource::File(path),
            smooth: false,
            use_mtl: material.is_none(),
        },
        transform: DAffine3::from_scale_rotation_translation(
            scale,
            glam::DQuat::IDENTITY,
            position,
        )
        .into(),
        material,
        span: node.span,
        visibility: crate::ir::Visibility::ALL,
    };
    parts.objects.push(mesh);
}

/// The required `material:` of an object; `None` after an error.
fn material_entry(
    m: &mut MapView<'_>,
    scene: &Path,
    mapping: Mapping,
    parts: &mut SceneParts,
    diags: &mut Diagnostics,
) -> Option<MaterialId> {
    let example = "material: {color: [1, 1, 1], ka: 0.2, kd: 0.8, ks: 0, n: 1}";
    let e = m.require(&["material"], "this object", example, diags)?;
    material(e.value, scene, mapping, parts, diags)
}

/// A course material map: `color` or `texture`, `ka kd ks n`, optional `reflect refract eta`.
fn material(
    node: &YamlNode,
    scene: &Path,
    mapping: Mapping,
    parts: &mut SceneParts,
    diags: &mut Diagnostics,
) -> Option<MaterialId> {
    let mut m = MapView::new(node, "a material", diags)?;
    let color_entry = m.get(&["color"], diags);
    let texture = m.get(&["texture"], diags);
    let color = match (&color_entry, &texture) {
        (Some(c), _) => val::triple(c.value, "`color`", Triple::Color, diags),
        (None, Some(_)) => Some(DVec3::ONE),
        (None, None) => {
            diags.push(
                Diagnostic::error(
                    "rtc::yaml::missing_key",
                    m.head(),
                    "the material has no `color`",
                )
                .with_label("`color` or `texture` is missing here")
                .with_help("add `color: [1.0, 1.0, 1.0]`"),
            );
            None
        }
    };
    if let (Some(c), Some(t)) = (&color_entry, &texture) {
        diags.push(
            Diagnostic::warning(
                "rtc::yaml::unused",
                c.key.span,
                "`texture` replaces `color`",
            )
            .with_label("this colour is not used")
            .with_secondary(t.key.span, "the texture"),
        );
    }
    let texture = texture.and_then(|e| {
        let name = val::string(e.value, "`texture`", diags)?;
        let path = course::find_asset(scene, name, e.value.span, "texture", diags)?;
        Some(parts.add_texture(Texture::Image {
            path,
            mapping,
            filter: crate::ir::ImageFilter::Nearest,
            span: e.value.span,
        }))
    });
    let coef = |m: &mut MapView<'_>, name: &str, example: &str, diags: &mut Diagnostics| {
        m.require(&[name], "the material", example, diags)
            .and_then(|e| val::non_negative(e.value, &format!("`{name}`"), diags))
    };
    let ka = coef(&mut m, "ka", "ka: 0.2", diags);
    let kd = coef(&mut m, "kd", "kd: 0.8", diags);
    let ks = coef(&mut m, "ks", "ks: 0.5", diags);
    let n = coef(&mut m, "n", "n: 32", diags);
    let reflect = m
        .get(&["reflect"], diags)
        .and_then(|e| val::non_negative(e.value, "`reflect`", diags));
    let refract = match m.get(&["refract", "kt"], diags) {
        Some(e) => {
            if e.key.scalar() == Some("kt") {
                diags.push(
                    Diagnostic::warning(
                        "rtc::yaml::spelling",
                        e.key.span,
                        "`kt` read as `refract`",
                    )
                    .with_label("student spelling")
                    .with_help("write `refract`"),
                );
            }
            val::non_negative(e.value, "`refract`", diags)
        }
        None => Some(0.0),
    };
    let eta_entry = m.get(&["eta"], diags);
    let eta = match &eta_entry {
        Some(e) => val::number(e.value, "`eta`", diags),
        None => Some(1.0),
    };
    m.finish("a material", MATERIAL_KEYS, diags);
    let (color, ka, kd, ks, n, refract, eta) = (color?, ka?, kd?, ks?, n?, refract?, eta?);
    let eta = if eta > 0.0 {
        eta
    } else {
        let span = eta_entry.map_or(node.span, |e| e.value.span);
        let text = format!("{eta}");
        if refract > 0.0 {
            diags.push(course::out_of_range(
                span,
                &text,
                "`eta`",
                "positive for a refracting material",
            ));
            return None;
        }
        diags.push(
            Diagnostic::warning(
                "rtc::compat::out_of_range",
                span,
                format!("`eta` {text} is not positive"),
            )
            .with_label("ignored: the material does not refract")
            .with_help("remove `eta` or write `eta: 1`"),
        );
        1.0
    };
    let course = CourseMaterial {
        color,
        texture,
        ka,
        kd,
        ks,
        n,
        reflect,
        refract,
        eta,
        span: node.span,
    };
    Some(parts.add_material(course.to_ir()))
}
