//! `height_field(image | f + resolution | heights, smooth, water_level)`: POV-Ray's
//! `height_field`, its grid read from a greyscale image through the asset service (the search
//! order, budgets and diagnostics of image textures), sampled from a function compiled as
//! `pattern(f)` compiles it, or given as rows of numbers (what `rtc convert` writes).

use std::sync::Arc;

use glam::DVec3;

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::{R, error};
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Lit, Param, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::limits::MAX_HEIGHT_FIELD_POINTS;
use crate::ir::{HeightGrid, Shape};
use crate::source::Span;

use super::common::checked;

/// The constructor of this file.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&HEIGHT_FIELD, height_field)];

/// The most points along one side of a sampled grid.
const MAX_SIDE: i64 = 4096;

/// `height_field(image, f, resolution, heights, smooth, water_level)`.
static HEIGHT_FIELD: Sig = Sig::new(
    "height_field",
    Group::Shape,
    "A terrain over the unit square x, z ∈ [0, 1], heights y ∈ [0, 1] (POV-Ray's \
     `height_field`): from a greyscale image, a function sampled on a grid, or rows of \
     numbers; each grid cell is two triangles; a solid below its surface.",
    &[
        Param::new(
            "image",
            Ty::String,
            "a greyscale PNG, JPEG, HDR or EXR (relative to the calling file): grey 0..1 is the \
             height, pixel (0, 0) at x = 0, z = 1; 16-bit PNGs keep all 16 bits",
        )
        .optional(),
        Param::new(
            "f",
            Ty::Fn,
            "instead of `image`: a `fn(p)` giving the height at p = [x, 0, z], compiled like \
             `pattern(f)`, clamped to [0, 1]",
        )
        .optional(),
        Param::new(
            "resolution",
            Ty::Pair(&Ty::Int),
            "with `f`: the grid's `[nx, nz]` points (each 2..=4096)",
        )
        .checked_by_builtin()
        .optional(),
        Param::new(
            "heights",
            Ty::ListOf(&Ty::ListOf(&Ty::Float)),
            "instead of `image`: rows of heights in [0, 1], the first row at z = 0, the first \
             height of a row at x = 0",
        )
        .optional(),
        Param::new("smooth", Ty::Bool, "interpolate vertex normals").or(Lit::Bool(false)),
        Param::new(
            "water_level",
            Ty::Float,
            "the height below which the surface is cut away",
        )
        .unit(Unit::Length)
        .or(Lit::Float(0.0)),
    ],
    "Object",
)
.examples(&[
    "height_field(image: \"../tests/data/pov_twins/height_field_map.png\", smooth: true, water_level: 0.1)",
    "height_field(f: fn(p) { 0.5 + 0.4 * sin(6rad * p.x) * cos(6rad * p.z) }, resolution: [64, 64])",
    "height_field(heights: [[0, 0.5], [0.5, 1]])",
]);

fn height_field(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &HEIGHT_FIELD, a)?;
    let image = p.get("image");
    let f = p.get("f");
    let resolution = p.get("resolution");
    let rows = p.get("heights");
    let smooth = p.bool(it, "smooth")?;
    let (water_level, ws) = p.float(it, "water_level")?;
    let given: Vec<Span> = [&image, &f, &rows]
        .iter()
        .filter_map(|x| x.as_ref().map(|(_, sp)| *sp))
        .collect();
    if given.len() != 1 {
        let (span, message) = match given.get(1) {
            Some(sp) => (
                *sp,
                "a height field takes one of `image`, `f` and `heights`",
            ),
            None => (s.span, "a height field needs `image`, `f` or `heights`"),
        };
        return Err(error("rtc::height_field::source", span, message)
            .with_label(if given.len() > 1 {
                "a second source"
            } else {
                "no heights"
            })
            .with_help(
                "give `image: \"terrain.png\"`, or `f: fn(p) { .. }` with `resolution: [nx, nz]`, or `heights: [[..], ..]`",
            )
            .into());
    }
    if let (None, Some((_, rs))) = (&f, &resolution) {
        return Err(error(
            "rtc::height_field::source",
            *rs,
            "`resolution` samples a function, but no `f` is given",
        )
        .with_label("nothing to sample")
        .with_help("remove `resolution`, or give `f: fn(p) { .. }`")
        .into());
    }
    let (image, grid, span) = if let Some((v, sp)) = image {
        let rel = types::string(it, &v, sp)?;
        let path = crate::eval::assets::existing(it, &rel, sp, "image")?;
        let grid = from_image(it, &path, sp)?;
        (Some(path), grid, sp)
    } else if let Some((v, sp)) = f {
        let Some((res, rs)) = resolution else {
            return Err(error(
                "rtc::arg::missing",
                sp,
                "a height field from a function needs `resolution`",
            )
            .with_label("sampled on what grid?")
            .with_help("add `resolution: [nx, nz]`, e.g. `resolution: [128, 128]`")
            .into());
        };
        let (nx, nz) = side_counts(it, &res, rs)?;
        it.charge((nx * nz * 4) as u64, rs, "a height field's grid")?;
        let program = it.compile_pattern(v, sp)?;
        let mut h = Vec::with_capacity(nx * nz);
        for j in 0..nz {
            for i in 0..nx {
                let x = i as f64 / (nx - 1) as f64;
                let z = j as f64 / (nz - 1) as f64;
                h.push(program.eval(DVec3::new(x, 0.0, z)).clamp(0.0, 1.0) as f32);
            }
        }
        (None, grid(nx, nz, h), sp)
    } else if let Some((v, sp)) = rows {
        (None, from_rows(it, &v, sp)?, sp)
    } else {
        unreachable!("one source is given (checked above)")
    };
    checked(
        Shape::HeightField {
            image,
            heights: Arc::new(grid),
            smooth,
            water_level,
        },
        s,
        &[("heights", span), ("water_level", ws)],
    )
}

fn grid(nx: usize, nz: usize, h: Vec<f32>) -> HeightGrid {
    HeightGrid {
        nx,
        nz,
        heights: h.into(),
    }
}

/// `resolution: [nx, nz]`, each in 2..=[`MAX_SIDE`].
fn side_counts(it: &dyn Host, v: &Value, span: Span) -> R<(usize, usize)> {
    let Value::List(l) = v else {
        return Err(types::mismatch(it, "[Int, Int]", v, span).into());
    };
    if l.len() != 2 {
        return Err(types::mismatch(it, "[Int, Int]", v, span).into());
    }
    let mut n = [0usize; 2];
    for (k, x) in l.iter().enumerate() {
        let c = types::int(it, x, span)?;
        if !(2..=MAX_SIDE).contains(&c) {
            return Err(error(
                "rtc::param::out_of_range",
                span,
                format!("`resolution` must be in 2..={MAX_SIDE} on each side, but it is {c}"),
            )
            .with_label(format!("evaluates to {c}"))
            .with_help(if c < 2 {
                "a grid needs at least 2 points per side (one cell), e.g. `resolution: [64, 64]`"
                    .to_owned()
            } else {
                format!("sample at most {MAX_SIDE} points per side")
            })
            .into());
        }
        n[k] = c as usize;
    }
    Ok((n[0], n[1]))
}

/// The grid of the image at `path`: its grey values (Rec. 709 luminance of a colour image),
/// the image's top row at z = 1. Refused past [`MAX_HEIGHT_FIELD_POINTS`] from the header,
/// before decoding; the decoded image is charged to the memory budget.
fn from_image(it: &mut dyn Host, path: &std::path::Path, span: Span) -> R<HeightGrid> {
    if let Some((w, h)) = crate::assets::picture_size(path) {
        let points = u64::from(w) * u64::from(h);
        if points > MAX_HEIGHT_FIELD_POINTS {
            return Err(error(
                "rtc::param::out_of_range",
                span,
                format!(
                    "the image `{}` is {w}×{h} = {points} points; a height field has at most {MAX_HEIGHT_FIELD_POINTS}",
                    path.display()
                ),
            )
            .with_label("too many points")
            .with_help("scale the image down to at most 4096×4096 pixels")
            .into());
        }
        if w < 2 || h < 2 {
            return Err(error(
                "rtc::param::degenerate",
                span,
                format!(
                    "the image `{}` is {w}×{h}: a height field needs at least 2×2 points",
                    path.display()
                ),
            )
            .with_label("no cell to make triangles of")
            .with_help("use an image of at least 2×2 pixels")
            .into());
        }
        it.charge(points * 4, span, "a height field's grid")?;
        it.charge(
            crate::assets::picture_bytes(path),
            span,
            "a height field's image",
        )?;
    }
    let pic = crate::assets::picture(path).map_err(|e| e.diagnostic(span, path))?;
    let (w, h) = pic.size();
    let (nx, nz) = (w as usize, h as usize);
    let mut heights = Vec::with_capacity(nx * nz);
    for j in 0..nz {
        // Row j (z = j/(nz − 1)) is the image's row nz − 1 − j from the top (POV-Ray's
        // `Compute_HField`).
        let row = (nz - 1 - j) as u32;
        for i in 0..w {
            let c = pic.texel(i, row);
            let grey = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
            heights.push(grey.clamp(0.0, 1.0) as f32);
        }
    }
    Ok(grid(nx, nz, heights))
}

/// `heights: [[..], ..]`: rows of equal length, the first at z = 0.
fn from_rows(it: &dyn Host, v: &Value, span: Span) -> R<HeightGrid> {
    let Value::List(rows) = v else {
        return Err(types::mismatch(it, "List", v, span).into());
    };
    let nz = rows.len();
    let mut nx = 0;
    let mut h = Vec::new();
    for (j, row) in rows.iter().enumerate() {
        let row: Vec<f64> = match row {
            Value::List(items) => {
                let mut r = Vec::with_capacity(items.len());
                for x in items.iter() {
                    r.push(types::num(it, x, span)?);
                }
                r
            }
            // A row of three numbers in brackets reads as a vector.
            Value::Vec3(x) => x.to_array().to_vec(),
            other => return Err(types::mismatch(it, "List", other, span).into()),
        };
        if j == 0 {
            nx = row.len();
        } else if row.len() != nx {
            return Err(error(
                "rtc::param::out_of_range",
                span,
                format!(
                    "row {j} of `heights` has {} heights, but row 0 has {nx}",
                    row.len()
                ),
            )
            .with_label("rows of different lengths")
            .with_help("give every row the same number of heights")
            .into());
        }
        if (h.len() + row.len()) as u64 > MAX_HEIGHT_FIELD_POINTS {
            return Err(error(
                "rtc::param::out_of_range",
                span,
                format!(
                    "`heights` has more than the {MAX_HEIGHT_FIELD_POINTS} points a height field may have"
                ),
            )
            .with_label("too many points")
            .with_help("use an image for a grid this large")
            .into());
        }
        h.extend(row.iter().map(|&x| x as f32));
    }
    Ok(grid(nx, nz, h))
}
