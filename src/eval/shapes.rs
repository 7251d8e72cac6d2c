//! Object constructors with schema-checked parameters, groups, and the CSG list forms.

use crate::num::Norm;
use std::rc::Rc;

use glam::{DAffine3, DVec3};

use super::args::{ArgVal, CallSite};
use super::args::{Params, positive};
use super::error::{R, error};
use super::host::BuiltinFn;
use super::host::Host;
use super::types;
use super::value::{Obj, ObjShape, Value, obj_kind};
use crate::ir::{BlobComponent, CsgOp, Shape};
use crate::source::Span;

/// Object constructors.
pub const FNS: &[(&str, BuiltinFn)] = &[
    ("sphere", sphere),
    ("plane", plane),
    ("box", box_),
    ("triangle", triangle),
    ("quad", quad),
    ("polygon", polygon),
    ("disk", disk),
    ("ring", ring),
    ("cylinder", cylinder),
    ("cone", cone),
    ("torus", torus),
    ("blob", blob),
    ("mesh", mesh),
    ("group", group),
    ("union", union),
    ("intersection", intersection),
    ("difference", difference),
];

/// Checks a shape by geometry's rules (the one home of shape validity, `geometry::shapes`) and
/// makes it a value; a flaw is reported on the span of the parameter it blames (from `spans`),
/// else on the call.
fn checked(shape: Shape, s: CallSite, spans: &[(&str, Span)]) -> R<Value> {
    if let Err(flaw) = crate::geometry::shapes::check(&shape) {
        let span = spans
            .iter()
            .find(|(name, _)| *name == flaw.param)
            .map_or(s.span, |(_, sp)| *sp);
        return Err(flaw.diagnostic(span).into());
    }
    Ok(prim(shape, s.span))
}

fn prim(shape: Shape, span: Span) -> Value {
    Value::Object(Rc::new(Obj {
        shape: ObjShape::Prim(shape),
        transform: DAffine3::IDENTITY,
        material: None,
        motion: None,
        span,
        origin: 0,
    }))
}

fn unit_dir(it: &dyn Host, p: &mut Params, name: &str, default: DVec3) -> R<DVec3> {
    match p.get(name) {
        None => Ok(default),
        Some((v, sp)) => {
            let d = types::vec3(it, &v, sp)?;
            if d.length_squared() == 0.0 || !d.is_finite() {
                return Err(error(
                    "rtc::param::out_of_range",
                    sp,
                    format!("`{name}` must be a non-zero vector"),
                )
                .with_label("this vector has length 0")
                .with_help(format!("give a direction, e.g. `{name}: Y`"))
                .into());
            }
            Ok(d.unit())
        }
    }
}

fn sphere(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["center", "radius"], a)?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let (radius, rs) = p.num_or(it, "radius", 1.0)?;
    checked(Shape::Sphere { center, radius }, s, &[("radius", rs)])
}

fn plane(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["point", "normal"], a)?;
    let point = p.vec3_or(it, "point", DVec3::ZERO)?;
    let normal = unit_dir(it, &mut p, "normal", DVec3::Y)?;
    checked(Shape::Plane { point, normal }, s, &[])
}

fn box_(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["min", "max"], a)?;
    let min = p.vec3_or(it, "min", DVec3::splat(-0.5))?;
    let (max, ms) = match p.get("max") {
        Some((v, sp)) => (types::vec3(it, &v, sp)?, sp),
        None => (DVec3::splat(0.5), s.span),
    };
    checked(Shape::Box { min, max }, s, &[("max", ms)])
}

fn triangle(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["a", "b", "c"], a)?;
    let (va, _) = p.vec3(it, "a")?;
    let (vb, _) = p.vec3(it, "b")?;
    let (vc, cs) = p.vec3(it, "c")?;
    checked(
        Shape::Triangle {
            vertices: [va, vb, vc],
        },
        s,
        &[("c", cs)],
    )
}

fn quad(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["corner", "u", "v"], a)?;
    let corner = p.vec3_or(it, "corner", DVec3::ZERO)?;
    let (u, _) = p.vec3(it, "u")?;
    let (v, vs) = p.vec3(it, "v")?;
    checked(Shape::Quad { corner, u, v }, s, &[("v", vs)])
}

fn polygon(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["points"], a)?;
    let (v, sp) = p.req("points")?;
    let items: Vec<Value> = match &v {
        Value::List(l) => l.to_vec(),
        other => return Err(types::mismatch(it, "List", other, sp).into()),
    };
    let mut points = Vec::with_capacity(items.len());
    for x in &items {
        points.push(types::vec3(it, x, sp)?);
    }
    checked(Shape::Polygon { points }, s, &[("points", sp)])
}

fn disk(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["center", "normal", "radius"], a)?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let normal = unit_dir(it, &mut p, "normal", DVec3::Y)?;
    let (radius, rs) = p.num_or(it, "radius", 1.0)?;
    checked(
        Shape::Disk {
            center,
            normal,
            radius,
        },
        s,
        &[("radius", rs)],
    )
}

fn ring(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["center", "normal", "radius", "inner"], a)?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let normal = unit_dir(it, &mut p, "normal", DVec3::Y)?;
    let (radius, rs) = p.num_or(it, "radius", 1.0)?;
    let (inner, is) = p.num_or(it, "inner", 0.5)?;
    checked(
        Shape::Ring {
            center,
            normal,
            radius,
            inner,
        },
        s,
        &[("radius", rs), ("inner", is)],
    )
}

/// Reads `base`/`top`, or `center`/`axis`/`height` (centred on `center` along `axis`), with the
/// span to blame for the top.
fn ends(it: &dyn Host, p: &mut Params) -> R<(DVec3, DVec3, Span)> {
    let base = p.get("base");
    let top = p.get("top");
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let axis = unit_dir(it, p, "axis", DVec3::Y)?;
    let (height, hs) = p.num_or(it, "height", 1.0)?;
    positive("height", height, hs)?;
    Ok(match (base, top) {
        (Some((b, bs)), Some((t, ts))) => {
            let (b, t) = (types::vec3(it, &b, bs)?, types::vec3(it, &t, ts)?);
            (b, t, ts)
        }
        (Some((b, bs)), None) => {
            let b = types::vec3(it, &b, bs)?;
            (b, b + axis * height, hs)
        }
        (None, Some((t, ts))) => {
            let t = types::vec3(it, &t, ts)?;
            (t - axis * height, t, ts)
        }
        (None, None) => (
            center - axis * (height / 2.0),
            center + axis * (height / 2.0),
            hs,
        ),
    })
}

fn cylinder(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(
        s,
        &[
            "radius", "base", "top", "center", "axis", "height", "capped",
        ],
        a,
    )?;
    let (radius, rs) = p.num_or(it, "radius", 1.0)?;
    let (base, top, top_span) = ends(it, &mut p)?;
    let capped = p.bool_or(it, "capped", true)?;
    checked(
        Shape::Cylinder {
            base,
            top,
            radius,
            capped,
        },
        s,
        &[("radius", rs), ("top", top_span)],
    )
}

fn cone(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(
        s,
        &[
            "base_radius",
            "top_radius",
            "base",
            "top",
            "center",
            "axis",
            "height",
            "capped",
        ],
        a,
    )?;
    let (br, bs) = p.num_or(it, "base_radius", 1.0)?;
    let (tr, ts) = p.num_or(it, "top_radius", 0.0)?;
    let (base, top, top_span) = ends(it, &mut p)?;
    let capped = p.bool_or(it, "capped", true)?;
    checked(
        Shape::Cone {
            base,
            top,
            base_radius: br,
            top_radius: tr,
            capped,
        },
        s,
        &[("base_radius", bs), ("top_radius", ts), ("top", top_span)],
    )
}

fn torus(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["major_radius", "minor_radius", "center"], a)?;
    let (major, ms) = p.num(it, "major_radius")?;
    let (minor, ns) = p.num(it, "minor_radius")?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    checked(
        Shape::Torus {
            center,
            major_radius: major,
            minor_radius: minor,
        },
        s,
        &[("major_radius", ms), ("minor_radius", ns)],
    )
}

fn blob(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["components", "threshold"], a)?;
    let (v, sp) = p.req("components")?;
    let Value::List(items) = &v else {
        return Err(types::mismatch(it, "List", &v, sp).into());
    };
    let mut components = Vec::with_capacity(items.len());
    for c in items.iter() {
        let site = CallSite {
            span: sp,
            name: "blob component",
        };
        let arg = ArgVal {
            name: None,
            value: c.clone(),
            span: sp,
        };
        let mut cp = Params::new(site, &["center", "radius", "strength"], vec![arg])?;
        let center = cp.vec3_or(it, "center", DVec3::ZERO)?;
        let (radius, _) = cp.num_or(it, "radius", 1.0)?;
        let (strength, _) = cp.num_or(it, "strength", 1.0)?;
        components.push(BlobComponent {
            center,
            radius,
            strength,
        });
    }
    let (threshold, ts) = p.num_or(it, "threshold", 0.5)?;
    checked(
        Shape::Blob {
            components,
            threshold,
        },
        s,
        &[
            ("components", sp),
            ("radius", sp),
            ("strength", sp),
            ("threshold", ts),
        ],
    )
}

fn mesh(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["path", "smooth", "use_mtl"], a)?;
    let (pv, ps) = p.req("path")?;
    let rel = types::string(it, &pv, ps)?;
    let path = super::assets::existing(it, &rel, ps, "mesh")?;
    only_obj(&path, ps)?;
    let smooth = p.bool_or(it, "smooth", false)?;
    let use_mtl = p.bool_or(it, "use_mtl", false)?;
    Ok(prim(
        Shape::Mesh {
            path,
            smooth,
            use_mtl,
        },
        s.span,
    ))
}

/// Meshes are Wavefront OBJ: another format (STL, PLY, glTF...) is refused by its extension
/// before anyone tries to read it as OBJ.
fn only_obj(path: &std::path::Path, span: Span) -> R<()> {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    if ext == "obj" {
        return Ok(());
    }
    Err(crate::eval::error::error(
        "rtc::asset::format",
        span,
        format!("`{}` is not a Wavefront OBJ file", path.display()),
    )
    .with_label(if ext.is_empty() {
        "no `.obj` extension".to_owned()
    } else {
        format!("a `.{ext}` file")
    })
    .with_help(
        "only OBJ meshes are read; convert the model to `.obj` (e.g. with Blender or MeshLab)",
    )
    .into())
}

/// Flattens nested lists of objects (as `for` produces) into `out`.
pub fn collect_objects(it: &dyn Host, v: &Value, span: Span, out: &mut Vec<Obj>) -> R<()> {
    match v {
        Value::Object(o) => out.push((**o).clone()),
        Value::List(l) => {
            for x in l.iter() {
                collect_objects(it, x, span, out)?;
            }
        }
        Value::Unit => {}
        other => return Err(types::mismatch(it, "Object", other, span).into()),
    }
    Ok(())
}

fn object_list(it: &dyn Host, p: &mut Params, name: &str) -> R<(Vec<Obj>, Span)> {
    let (v, sp) = p.req(name)?;
    let mut out = Vec::new();
    collect_objects(it, &v, sp, &mut out)?;
    Ok((out, sp))
}

fn group(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["children"], a)?;
    let (children, _) = object_list(it, &mut p, "children")?;
    Ok(Value::Object(Rc::new(Obj {
        shape: ObjShape::Group(Rc::new(children)),
        transform: DAffine3::IDENTITY,
        material: None,
        motion: None,
        span: s.span,
        origin: 0,
    })))
}

fn csg_node(it: &dyn Host, op: CsgOp, children: Vec<Obj>, sp: Span, s: CallSite) -> R<Value> {
    if let Err(flaw) = crate::geometry::shapes::csg_operands(children.len()) {
        return Err(flaw.diagnostic(sp).into());
    }
    for c in &children {
        require_closed(it, c, sp)?;
    }
    Ok(Value::Object(Rc::new(Obj {
        shape: ObjShape::Csg(op, super::operands::Operands::new(children)),
        transform: DAffine3::IDENTITY,
        material: None,
        motion: None,
        span: s.span,
        origin: 0,
    })))
}

fn union(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["objects", "merge"], a)?;
    let (children, sp) = object_list(it, &mut p, "objects")?;
    let op = if p.bool_or(it, "merge", false)? {
        CsgOp::Merge
    } else {
        CsgOp::Union
    };
    csg_node(it, op, children, sp, s)
}

fn intersection(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["objects"], a)?;
    let (children, sp) = object_list(it, &mut p, "objects")?;
    csg_node(it, CsgOp::Intersection, children, sp, s)
}

fn difference(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["base", "cutters"], a)?;
    let (bv, bs) = p.req("base")?;
    let Value::Object(base) = &bv else {
        return Err(types::mismatch(it, "Object", &bv, bs).into());
    };
    let (cutters, sp) = object_list(it, &mut p, "cutters")?;
    let mut children = vec![(**base).clone()];
    children.extend(cutters);
    csg_node(it, CsgOp::Difference, children, sp, s)
}

/// CSG needs solids with an inside: open surfaces are rejected (geometry's rule,
/// `geometry::shapes::encloses_volume`).
pub fn require_closed(it: &dyn Host, o: &Obj, span: Span) -> R<()> {
    let _ = it;
    let open = match &o.shape {
        // A mesh file's closedness is checked when the preparation stage loads it.
        ObjShape::Prim(s) => !crate::geometry::shapes::encloses_volume(s, &|_, _| true),
        ObjShape::Group(ch) => {
            for c in ch.iter() {
                require_closed(it, c, span)?;
            }
            false
        }
        _ => false,
    };
    if open {
        let mut d = error("rtc::csg::open_operand", span, format!("a {} has no inside, so it cannot take part in CSG", obj_kind(o)))
            .with_label("an open surface")
            .with_help("use a closed solid (sphere, box, capped cylinder, torus, ...), or a `group` instead of CSG");
        if o.span != span {
            d = d.with_secondary(o.span, "made here");
        }
        return Err(d.into());
    }
    Ok(())
}
