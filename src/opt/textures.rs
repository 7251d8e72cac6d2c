//! Textures prepared for lookups: images decoded through the asset service, procedural ones
//! with their sizes made usable.

use std::sync::Arc;

use crate::assets;
use crate::diag::Diagnostics;
use crate::ir::limits::Memory;
use glam::DAffine3;

use crate::ir::{Color, ImageFilter, Mapping, PatternSpace, PatternTexture, Texture};
use crate::pattern::{ColorMap, Field, Warp};

pub(crate) use crate::assets::{MipChain, Picture};

/// A texture ready for lookups (by `TextureId`).
#[derive(Clone, Debug)]
pub(crate) enum TextureMap {
    /// A decoded image with its surface mapping, read nearest-texel.
    Image(Arc<Picture>, Mapping),
    /// The same, read bilinearly.
    Bilinear(Arc<Picture>, Mapping),
    /// The same, read trilinearly through its mip chain over the pixel's footprint.
    Mipmap(Arc<MipChain>, Mapping),
    /// A tangent-space normal map (`ir::Texture::NormalMap`), read bilinearly.
    NormalMap(Arc<Picture>, Mapping),
    /// A 3-D checkerboard of cubes: two colours and the cube edge.
    Checker(Color, Color, f64),
    /// Stripes along object-space x: two colours and the stripe width.
    Stripes(Color, Color, f64),
    /// A procedural pattern through its colour map.
    Pattern(Box<PreparedPattern>),
}

/// A pattern texture ready for lookups: its placement and its warps' placements inverted once
/// (the point meets the inverses).
#[derive(Clone, Debug)]
pub(crate) struct PreparedPattern {
    /// The pattern, its warps (placements turned into point maps) and its wave.
    pub(crate) field: Field,
    /// Object (or uv) space → the pattern's own space.
    pub(crate) to_pattern: DAffine3,
    /// Where the point comes from.
    pub(crate) space: PatternSpace,
    /// Value → colour.
    pub(crate) map: ColorMap,
    /// The language's constructor (`marble`), for `rtc why`.
    pub(crate) name: &'static str,
}

impl PreparedPattern {
    /// `p` prepared.
    pub(crate) fn of(p: &PatternTexture) -> PreparedPattern {
        let mut field = p.field.clone();
        for w in &mut field.warps {
            if let Warp::Placement(m) = *w {
                *w = Warp::Transform(m.inverse());
            }
        }
        PreparedPattern {
            field,
            to_pattern: p.placement.inverse(),
            space: p.space,
            map: p.map.clone(),
            name: p.name(),
        }
    }
}

/// Every texture of a scene, decoded; `None` (with the problems in `out`) when one cannot be.
/// Each image is charged to `memory` from its header's size before it is decoded.
pub(crate) fn load_all(
    textures: &[Texture],
    out: &mut Diagnostics,
    memory: &mut Memory,
) -> Option<Vec<TextureMap>> {
    let mut maps = Vec::with_capacity(textures.len());
    for t in textures {
        match t {
            Texture::Image {
                path,
                mapping,
                filter,
                span,
            } => {
                let bytes = image_bytes(path, *filter);
                let decode = || image_map(path, *filter, *mapping);
                maps.extend(decoded(path, *span, bytes, decode, out, memory));
            }
            Texture::NormalMap {
                path,
                mapping,
                span,
            } => {
                let bytes = assets::picture_bytes(path);
                let decode = || Ok(TextureMap::NormalMap(assets::picture(path)?, *mapping));
                maps.extend(decoded(path, *span, bytes, decode, out, memory));
            }
            Texture::Checker { a, b, size } => {
                maps.push(TextureMap::Checker(*a, *b, positive(*size)));
            }
            Texture::Stripes { a, b, size } => {
                maps.push(TextureMap::Stripes(*a, *b, positive(*size)));
            }
            Texture::Pattern(p) => maps.push(TextureMap::Pattern(Box::new(PreparedPattern::of(p)))),
        }
    }
    (maps.len() == textures.len()).then_some(maps)
}

/// The textures meshes' own materials add, decoded as [`load_all`] decodes the scene's (an
/// image from inside a mesh file is decoded already, and was charged when it was).
pub(crate) fn load_mesh_textures(
    textures: &[super::objects::MeshTexture],
    out: &mut Diagnostics,
    memory: &mut Memory,
) -> Option<Vec<TextureMap>> {
    let mut maps = Vec::with_capacity(textures.len());
    for t in textures {
        match t {
            super::objects::MeshTexture::File(t) => {
                // Every image is tried, so every problem is reported.
                maps.extend(load_all(std::slice::from_ref(t), out, memory).unwrap_or_default());
            }
            super::objects::MeshTexture::Decoded(p) => {
                maps.push(TextureMap::Bilinear(p.clone(), Mapping::Uv));
            }
        }
    }
    (maps.len() == textures.len()).then_some(maps)
}

/// The image at `path` decoded by `decode` once `bytes` are charged to `memory`; `None` with
/// the problem in `out` when the budget or the file refuses.
fn decoded(
    path: &std::path::Path,
    span: crate::source::Span,
    bytes: u64,
    decode: impl FnOnce() -> Result<TextureMap, assets::ImageError>,
    out: &mut Diagnostics,
    memory: &mut Memory,
) -> Option<TextureMap> {
    if let Err(over) = memory.charge(bytes) {
        out.push(over.diagnostic(span, &format!("the texture `{}`", path.display())));
        return None;
    }
    decode()
        .map_err(|e| out.push(e.diagnostic(span, path)))
        .ok()
}

/// Bytes an image takes decoded, with its mip chain's third more when it has one.
fn image_bytes(path: &std::path::Path, filter: ImageFilter) -> u64 {
    let bytes = assets::picture_bytes(path);
    match filter {
        ImageFilter::Mipmap => bytes + bytes.div_ceil(3),
        _ => bytes,
    }
}

/// The decoded image at `path` read through `filter`.
fn image_map(
    path: &std::path::Path,
    filter: ImageFilter,
    mapping: Mapping,
) -> Result<TextureMap, assets::ImageError> {
    Ok(match filter {
        ImageFilter::Nearest => TextureMap::Image(assets::picture(path)?, mapping),
        ImageFilter::Bilinear => TextureMap::Bilinear(assets::picture(path)?, mapping),
        ImageFilter::Mipmap => TextureMap::Mipmap(assets::mip_chain(path)?, mapping),
    })
}

fn positive(size: f64) -> f64 {
    if size > 0.0 && size.is_finite() {
        size
    } else {
        1.0
    }
}
