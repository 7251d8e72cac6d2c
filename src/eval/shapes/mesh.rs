//! `mesh(path)`: a shape read from a file, which must exist and be Wavefront OBJ.

use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::{R, error};
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Sig, Ty};
use crate::eval::value::Value;
use crate::ir::Shape;
use crate::source::Span;

/// `mesh(path, smooth, use_mtl)`.
pub(super) static MESH: Sig = Sig::new(
    "mesh",
    Group::Shape,
    "A Wavefront OBJ mesh (triangulated).",
    &[
        Param::new(
            "path",
            Ty::String,
            "the file, relative to the calling file (it must exist)",
        ),
        Param::new("smooth", Ty::Bool, "interpolate vertex normals").or(Lit::Bool(false)),
        Param::new(
            "use_mtl",
            Ty::Bool,
            "use the file's `.mtl` materials where present",
        )
        .or(Lit::Bool(false)),
    ],
    "Object",
)
.examples(&["mesh(path: \"../tests/data/course/models/cube.obj\", smooth: true, use_mtl: false)"]);
pub(super) fn mesh(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &MESH, a)?;
    let (rel, ps) = p.string(it, "path")?;
    let path = crate::eval::assets::existing(it, &rel, ps, "mesh")?;
    only_obj(&path, ps)?;
    let smooth = p.bool(it, "smooth")?;
    let use_mtl = p.bool(it, "use_mtl")?;
    Ok(super::common::prim(
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
    Err(error(
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
