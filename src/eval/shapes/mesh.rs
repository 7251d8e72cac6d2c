//! `mesh(...)`: a shape read from a file, which must exist and be Wavefront OBJ, STL, PLY or
//! glTF 2.0 (its extension picks the reader), or written inline ([`super::mesh_inline`]).

use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::{R, error};
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Sig, Ty, Unit};
use crate::eval::value::Value;
use crate::ir::{MeshSource, Shape};
use crate::source::Span;
use std::sync::Arc;

/// `mesh(path | vertices + faces, normals, uv, smooth, use_mtl)`.
pub(super) static MESH: Sig = Sig::new(
    "mesh",
    Group::Shape,
    "A triangle mesh from a Wavefront OBJ, STL, PLY or glTF 2.0 file (by its extension), or written inline as vertices and faces.",
    &[
        Param::new(
            "path",
            Ty::String,
            "the file, relative to the calling file (it must exist); or give `vertices` and `faces`",
        )
        .optional(),
        Param::new(
            "vertices",
            Ty::ListOf(&Ty::Vec3),
            "an inline mesh's vertex positions",
        )
        .unit(Unit::Length)
        .optional(),
        Param::new(
            "faces",
            Ty::ListOf(&Ty::ListOf(&Ty::Int)),
            "an inline mesh's faces: lists of 3 or more vertex indices from 0, counter-clockwise seen from outside (polygons are fanned from their first corner)",
        )
        .optional(),
        Param::new(
            "normals",
            Ty::ListOf(&Ty::Vec3),
            "an inline mesh's normals, one per vertex (used when `smooth`)",
        )
        .optional(),
        Param::new(
            "uv",
            Ty::ListOf(&Ty::Pair(&Ty::Float)),
            "an inline mesh's texture coordinates, one `[u, v]` per vertex",
        )
        .optional(),
        Param::new("smooth", Ty::Bool, "interpolate vertex normals").or(Lit::Bool(false)),
        Param::new(
            "use_mtl",
            Ty::Bool,
            "use the file's materials and colours where present (OBJ: its `.mtl`; glTF: base colours and textures; PLY and glTF: vertex colours)",
        )
        .or(Lit::Bool(false)),
    ],
    "Object",
)
.examples(&[
    "mesh(path: \"../tests/data/course/models/cube.obj\", smooth: true, use_mtl: false)",
    "mesh(vertices: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], faces: [[0, 1, 2, 3]], normals: [Z, Z, Z, Z], uv: [[0, 0], [1, 0], [1, 1], [0, 1]], smooth: true)",
]);
pub(super) fn mesh(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &MESH, a)?;
    let smooth = p.bool(it, "smooth")?;
    let use_mtl = p.bool(it, "use_mtl")?;
    let path = p.get("path");
    let vertices = p.get("vertices");
    let faces = p.get("faces");
    let normals = p.get("normals");
    let uv = p.get("uv");
    let source = match (path, vertices, faces) {
        (Some((rel, ps)), None, None) => {
            if let Some((_, sp)) = normals.as_ref().or(uv.as_ref()) {
                return Err(inline_only(*sp));
            }
            let rel = crate::eval::types::string(it, &rel, ps)?;
            let path = crate::eval::assets::existing(it, &rel, ps, "mesh")?;
            known_format(&path, ps)?;
            MeshSource::File(path)
        }
        (None, Some(v), Some(f)) => {
            MeshSource::Inline(Arc::new(super::mesh_inline::read(it, v, f, normals, uv)?))
        }
        (Some((_, ps)), Some(_), _) | (Some((_, ps)), None, Some(_)) => {
            return Err(error(
                "rtc::mesh::two_sources",
                ps,
                "a mesh is read from a file or written inline, not both",
            )
            .with_label("a file is given here")
            .with_help("remove `path` to use the inline `vertices` and `faces`, or remove those to read the file")
            .into());
        }
        (None, Some((_, sp)), None) => return Err(incomplete("faces", sp)),
        (None, None, Some((_, sp))) => return Err(incomplete("vertices", sp)),
        (None, None, None) => {
            return Err(error(
                "rtc::mesh::no_source",
                s.span,
                "a mesh needs a file or inline data",
            )
            .with_label("neither `path` nor `vertices` and `faces`")
            .with_help("give `path: \"model.obj\"`, or `vertices: [...]` and `faces: [...]`")
            .into());
        }
    };
    Ok(super::common::prim(
        Shape::Mesh {
            source,
            smooth,
            use_mtl,
        },
        s.span,
    ))
}

/// Half an inline mesh: `missing` is the other half.
fn incomplete(missing: &str, span: Span) -> crate::eval::error::EvalError {
    error(
        "rtc::mesh::incomplete",
        span,
        format!("an inline mesh needs both `vertices` and `faces`; `{missing}` is missing"),
    )
    .with_label("given without the other")
    .with_help(format!("add `{missing}: [...]` to the call"))
    .into()
}

/// `normals` or `uv` beside a `path`: a file brings its own.
fn inline_only(span: Span) -> crate::eval::error::EvalError {
    error(
        "rtc::mesh::inline_only",
        span,
        "`normals` and `uv` belong to an inline mesh",
    )
    .with_label("beside a `path`")
    .with_help("a mesh file brings its own normals and texture coordinates; remove this argument")
    .into()
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
