//! An inline mesh's lists read into [`InlineMesh`]: every vertex a finite point (in single
//! precision, as a mesh file's), every face 3 or more indices of existing vertices (fanned from
//! the first corner, as the file readers fan), per-vertex normals and texture coordinates, and
//! at least one face with area, so preparing it cannot fail but for the memory budget.

use glam::{DVec3, Vec3A};

use crate::eval::error::{EvalError, R, error};
use crate::eval::host::Host;
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::InlineMesh;
use crate::ir::limits::MAX_TRIANGLES;
use crate::source::Span;

/// The inline mesh of `vertices` and `faces` (each with its argument's span) and the optional
/// per-vertex `normals` and `uv`.
pub(super) fn read(
    it: &dyn Host,
    (vertices, vs): (Value, Span),
    (faces, fs): (Value, Span),
    normals: Option<(Value, Span)>,
    uv: Option<(Value, Span)>,
) -> R<InlineMesh> {
    let vertices = points(it, &vertices, vs, "vertices")?;
    let triangles = triangles(it, &faces, fs, vertices.len())?;
    let normals = match normals {
        Some((v, sp)) => {
            let n = points(it, &v, sp, "normals")?;
            same_count(n.len(), vertices.len(), "normals", sp)?;
            n
        }
        None => Vec::new(),
    };
    let uvs = match uv {
        Some((v, sp)) => {
            let items = list(it, &v, sp)?;
            let mut uvs = Vec::with_capacity(items.len());
            for (k, x) in items.iter().enumerate() {
                let p = super::common::pair(it, x, sp)?;
                if !p.is_finite() {
                    return Err(not_finite("uv", k, sp));
                }
                uvs.push(p);
            }
            same_count(uvs.len(), vertices.len(), "uv", sp)?;
            uvs
        }
        None => Vec::new(),
    };
    // The asset's rule, in the asset's precision: a face whose corners collapse in single
    // precision is dropped there, and a mesh needs one face left.
    let has_area = |t: &[u32; 3]| {
        let [a, b, c] = t.map(|i| Vec3A::from(vertices[i as usize].as_vec3()));
        (b - a).cross(c - a) != Vec3A::ZERO
    };
    if !triangles.iter().any(has_area) {
        return Err(error(
            "rtc::mesh::no_area",
            fs,
            "no face of this mesh has any area",
        )
        .with_label("every face's corners are in a line")
        .with_help("give each face three corners that are not in a line")
        .into());
    }
    Ok(InlineMesh {
        vertices,
        triangles,
        normals,
        uvs,
    })
}

/// The list in `v`.
fn list<'a>(it: &dyn Host, v: &'a Value, span: Span) -> R<&'a [Value]> {
    match v {
        Value::List(items) => Ok(items),
        other => Err(types::mismatch(it, "List", other, span).into()),
    }
}

/// A list of points, each finite in single precision.
fn points(it: &dyn Host, v: &Value, span: Span, what: &str) -> R<Vec<DVec3>> {
    let items = list(it, v, span)?;
    if items.len() > MAX_TRIANGLES {
        return Err(too_many(what, items.len(), span));
    }
    let mut out = Vec::with_capacity(items.len());
    for (k, x) in items.iter().enumerate() {
        let p = types::vec3(it, x, span)?;
        if !p.as_vec3().is_finite() {
            return Err(not_finite(what, k, span));
        }
        out.push(p);
    }
    Ok(out)
}

/// The faces, fanned into triangles of indices below `count`.
fn triangles(it: &dyn Host, v: &Value, span: Span, count: usize) -> R<Vec<[u32; 3]>> {
    let faces = list(it, v, span)?;
    let mut out = Vec::with_capacity(faces.len());
    for (k, face) in faces.iter().enumerate() {
        // `[0, 1, 2]` is a vector literal: its three numbers are the indices.
        let corners: Vec<Value> = match face {
            Value::Vec3(v) => v.to_array().map(Value::Float).to_vec(),
            other => list(it, other, span)?.to_vec(),
        };
        if corners.len() < 3 {
            return Err(error(
                "rtc::mesh::short_face",
                span,
                format!(
                    "face {k} has {} corner{}; a face needs at least 3",
                    corners.len(),
                    if corners.len() == 1 { "" } else { "s" }
                ),
            )
            .with_label("in these faces")
            .with_help("list three or more vertex indices per face, e.g. `[0, 1, 2]`")
            .into());
        }
        let mut ids = Vec::with_capacity(corners.len());
        for c in &corners {
            let i = match c {
                Value::Float(x) if x.fract() == 0.0 && x.abs() < 1e18 => *x as i64,
                other => types::int(it, other, span)?,
            };
            if i < 0 || i as u64 >= count as u64 {
                return Err(error(
                    "rtc::mesh::bad_index",
                    span,
                    format!(
                        "face {k} names vertex {i}, but the vertices are numbered 0 to {}",
                        count.saturating_sub(1) as i64
                    ),
                )
                .with_label("in these faces")
                .with_help(format!(
                    "use indices from 0 to {} (one per vertex, counting from 0)",
                    count.saturating_sub(1)
                ))
                .into());
            }
            ids.push(i as u32);
        }
        for w in 1..ids.len() - 1 {
            out.push([ids[0], ids[w], ids[w + 1]]);
        }
        if out.len() > MAX_TRIANGLES {
            return Err(too_many("triangles", out.len(), span));
        }
    }
    Ok(out)
}

fn same_count(got: usize, want: usize, what: &str, span: Span) -> R<()> {
    if got == want {
        return Ok(());
    }
    Err(error(
        "rtc::mesh::count_mismatch",
        span,
        format!("{got} `{what}` for {want} vertices"),
    )
    .with_label("one per vertex is needed")
    .with_help(format!(
        "give exactly one `{what}` entry per vertex, in the vertices' order"
    ))
    .into())
}

fn not_finite(what: &str, k: usize, span: Span) -> EvalError {
    error(
        "rtc::mesh::not_finite",
        span,
        format!("entry {k} of `{what}` is not a finite number in single precision"),
    )
    .with_label("in this list")
    .with_help("meshes are stored in single precision: keep coordinates within ±3.4e38")
    .into()
}

fn too_many(what: &str, n: usize, span: Span) -> EvalError {
    error(
        "rtc::mesh::too_large",
        span,
        format!("this inline mesh has {n} {what}; at most {MAX_TRIANGLES} are supported"),
    )
    .with_label("too many")
    .with_help("split the mesh, or read it from a file")
    .into()
}
