//! OpenEXR files of a film: every channel in linear, unclamped `f32` (the object id as `u32`),
//! in one layer with the channel names compositors expect.
//!
//! | film channel | EXR channels | notes |
//! |---|---|---|
//! | colour | `R`, `G`, `B` | linear light |
//! | depth | `Z` | distance from the eye along the ray; `+inf` where no sample hit |
//! | normal | `normal.X`, `normal.Y`, `normal.Z` | world space, facing the viewer |
//! | albedo | `albedo.R`, `albedo.G`, `albedo.B` | the surface colour |
//! | object | `object.id` (`u32`) | scene object index + 1; 0 is the background |
//! | alpha | `A` | the share of the pixel's samples that hit; the colour is premultiplied by it |

use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer, LayerAttributes, SmallVec, Vec2,
    WritableImage,
};

use super::film::{Channel, Film};
use crate::diag::{Diagnostic, IO_ERROR, Severity};
use crate::ir::Color;

/// The EXR channel names of a film channel, one per component it writes.
fn channel_names(c: Channel) -> &'static [&'static str] {
    match c {
        Channel::Color => &["R", "G", "B"],
        Channel::Depth => &["Z"],
        Channel::Normal => &["normal.X", "normal.Y", "normal.Z"],
        Channel::Albedo => &["albedo.R", "albedo.G", "albedo.B"],
        Channel::Object => &["object.id"],
        Channel::Alpha => &["A"],
    }
}

/// The film as OpenEXR bytes (lossless compression).
pub(crate) fn encode(film: &Film) -> Result<Vec<u8>, Diagnostic> {
    let mut list: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    for &c in film.channels() {
        let values = film.channel(c).unwrap_or(&[]);
        for (k, name) in channel_names(c).iter().enumerate() {
            let samples = match c {
                Channel::Object => FlatSamples::U32(values.iter().map(|v| v.x as u32).collect()),
                _ => FlatSamples::F32(values.iter().map(|v| component(*v, k) as f32).collect()),
            };
            list.push(AnyChannel::new(*name, samples));
        }
    }
    let size = Vec2(film.width as usize, film.height as usize);
    let layer = Layer::new(
        size,
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(list),
    );
    let mut cursor = std::io::Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .to_buffered(&mut cursor)
        .map_err(|e| {
            Diagnostic::new(
                Severity::Error,
                IO_ERROR,
                None,
                format!("cannot encode EXR: {e}"),
            )
            .with_help("report this as a bug")
        })?;
    Ok(cursor.into_inner())
}

fn component(c: Color, k: usize) -> f64 {
    match k {
        0 => c.x,
        1 => c.y,
        _ => c.z,
    }
}
