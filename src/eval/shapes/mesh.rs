//! `mesh(path)`: a shape read from a file, which must exist and be Wavefront OBJ, STL, PLY or
//! glTF 2.0 (its extension picks the reader).

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
    "A triangle mesh from a Wavefront OBJ, STL, PLY or glTF 2.0 file (by its extension).",
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
            "use the file's materials where present (OBJ: its `.mtl`; glTF: base colours)",
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
    known_format(&path, ps)?;
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

/// Meshes are OBJ, STL, PLY or glTF: another format (3DS, FBX...) is refused by its extension
/// before anyone tries to read it as one of those.
fn known_format(path: &std::path::Path, span: Span) -> R<()> {
    if crate::assets::indexed::Format::known(path).is_some() {
        return Ok(());
    }
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    Err(error(
        "rtc::asset::format",
        span,
        format!("`{}` is not a mesh format rtc reads", path.display()),
    )
    .with_label(if ext.is_empty() {
        "no `.obj`, `.stl`, `.ply`, `.gltf` or `.glb` extension".to_owned()
    } else {
        format!("a `.{ext}` file")
    })
    .with_help(
        "meshes are read from `.obj`, `.stl`, `.ply`, `.gltf` and `.glb` files; convert the model to one of them (e.g. with Blender or MeshLab)",
    )
    .into())
}
