//! Textures prepared for lookups: images decoded through the asset service, procedural ones
//! with their sizes made usable.

use std::sync::Arc;

use crate::assets;
use crate::diag::Diagnostics;
use crate::ir::limits::Memory;
use glam::DAffine3;

use crate::ir::{Color, ImageFilter, Mapping, PatternSpace, PatternTexture, Texture};
use crate::pattern::{ColorMap, Field, Warp};

pub(crate) use crate::assets::Picture;

/// A texture ready for lookups (by `TextureId`).
#[derive(Clone, Debug)]
pub(crate) enum TextureMap {
    /// A decoded image with its surface mapping, read nearest-texel.
    Image(Arc<Picture>, Mapping),
    /// The same, read bilinearly.
    Bilinear(Arc<Picture>, Mapping),
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
            } => match memory.charge(assets::picture_bytes(path)) {
                Err(over) => {
                    let what = format!("the texture `{}`", path.display());
                    out.push(over.diagnostic(*span, &what));
                }
                Ok(()) => match assets::picture(path) {
                    Ok(pic) => maps.push(match filter {
                        ImageFilter::Nearest => TextureMap::Image(pic, *mapping),
                        ImageFilter::Bilinear => TextureMap::Bilinear(pic, *mapping),
                    }),
                    Err(e) => out.push(e.diagnostic(*span, path)),
                },
            },
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

fn positive(size: f64) -> f64 {
    if size > 0.0 && size.is_finite() {
        size
    } else {
        1.0
    }
}
