//! Partial renders: what `rtc render --shard K/N` writes and `rtc merge` reads. A part holds the
//! film's unencoded linear channels (`f64`, so a merged film is bit for bit the single render's)
//! for the rows of its shard, with a header that records the pixel bounds, the scene's
//! fingerprint (the scene and every file it reads) and the fingerprint of the command-line
//! settings that change pixels.
//!
//! Layout: the line `rtc-part 1`, one line of JSON (the header), then the values as
//! little-endian `f64`, for each row of the part from the top, each pixel from the left, each
//! channel in header order, red, green, blue. The header's `payload` is the SHA-256 of those
//! bytes, so a truncated or damaged part is refused.

use std::ops::Range;
use std::path::Path;

use glam::DVec3;

use super::film::{Channel, Film, Stats};
use super::shard::Shard;
use crate::diag::{Diagnostic, Severity};
use crate::ir::limits::{MAX_IMAGE_BYTES, image_bytes};
use crate::ir::{Color, Encoding};
use crate::opt::fingerprint;

/// The first line of every part file.
const MAGIC: &str = "rtc-part 1";

/// One shard's share of a render.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// Fingerprint of the scene and the files it reads.
    pub(crate) scene: String,
    /// Fingerprint of the command-line settings that change pixels.
    pub(crate) settings: String,
    /// Width of the whole image.
    pub(crate) width: u32,
    /// Height of the whole image.
    pub(crate) height: u32,
    /// The film's channels.
    pub(crate) channels: Vec<Channel>,
    /// How the merged colour is quantised.
    pub(crate) encoding: Encoding,
    /// Which shard this is.
    pub(crate) shard: Shard,
    /// The rows it holds, from the top (`shard.bands(height)`).
    pub(crate) rows: Vec<Range<u32>>,
    /// What rendering it took.
    pub(crate) stats: Stats,
    /// The values of its rows, interleaved per pixel as [`Film::new`] takes them.
    pub(crate) values: Vec<Color>,
    /// A JSON document the merge writes beside its image (the object-id layer's sidecar).
    pub sidecar: Option<serde_json::Value>,
}

impl Part {
    /// The shard's rows of a film rendered with `RenderOptions { shard: Some(shard), .. }`.
    pub fn of_film(film: &Film, shard: Shard, scene: String, settings: String) -> Part {
        let rows = shard.bands(film.height);
        let values = rows
            .iter()
            .flat_map(|r| film.interleaved(r.clone()))
            .collect();
        Part {
            scene,
            settings,
            width: film.width,
            height: film.height,
            channels: film.channels().to_vec(),
            encoding: film.encoding,
            shard,
            rows,
            stats: film.stats,
            values,
            sidecar: None,
        }
    }

    /// The file's bytes.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut payload = Vec::with_capacity(self.values.len() * 24);
        for v in &self.values {
            for c in v.to_array() {
                payload.extend_from_slice(&c.to_le_bytes());
            }
        }
        let s = &self.stats;
        let mut header = serde_json::json!({
            "scene": self.scene,
            "settings": self.settings,
            "width": self.width,
            "height": self.height,
            "channels": self.channels.iter().map(|c| c.name()).collect::<Vec<_>>(),
            "encoding": encoding_name(self.encoding),
            "shard": [self.shard.index, self.shard.count],
            "rows": self.rows.iter().map(|r| [r.start, r.end]).collect::<Vec<_>>(),
            "stats": [s.camera_rays, s.secondary_rays, s.shadow_rays, s.refined_pixels, s.cut_rays, s.cut_weight],
            "payload": fingerprint::bytes(&payload),
        });
        if let Some(s) = &self.sidecar {
            header["sidecar"] = s.clone();
        }
        let mut out = format!("{MAGIC}\n{header}\n").into_bytes();
        out.extend_from_slice(&payload);
        out
    }

    /// Reads a part from the bytes of `path`.
    pub fn from_bytes(bytes: &[u8], path: &Path) -> Result<Part, Diagnostic> {
        let bad = |why: &str| {
            Diagnostic::new(
                Severity::Error,
                "rtc::merge::malformed",
                None,
                format!("`{}` is not a readable rtc part: {why}", path.display()),
            )
            .with_help("re-render this shard: `rtc render SCENE --shard K/N -o PART`")
        };
        let mut lines = bytes.splitn(3, |b| *b == b'\n');
        if lines.next() != Some(MAGIC.as_bytes()) {
            return Err(bad("it does not start with `rtc-part 1`"));
        }
        let header = lines.next().ok_or_else(|| bad("the header is missing"))?;
        let payload = lines.next().unwrap_or(&[]);
        let h: serde_json::Value =
            serde_json::from_slice(header).map_err(|_| bad("the header is not JSON"))?;
        let text = |k: &str| h[k].as_str().map(str::to_owned);
        let int = |v: &serde_json::Value| v.as_u64().and_then(|n| u32::try_from(n).ok());
        let pair = |v: &serde_json::Value| Some((int(&v[0])?, int(&v[1])?));
        let missing = |k: &str| bad(&format!("the header has no valid `{k}`"));
        let scene = text("scene").ok_or_else(|| missing("scene"))?;
        let settings = text("settings").ok_or_else(|| missing("settings"))?;
        let width = int(&h["width"]).ok_or_else(|| missing("width"))?;
        let height = int(&h["height"]).ok_or_else(|| missing("height"))?;
        let channels: Vec<Channel> = h["channels"]
            .as_array()
            .and_then(|a| a.iter().map(|c| Channel::named(c.as_str()?)).collect())
            .ok_or_else(|| missing("channels"))?;
        let encoding = text("encoding")
            .and_then(|e| encoding_named(&e))
            .ok_or_else(|| missing("encoding"))?;
        let (k, n) = pair(&h["shard"]).ok_or_else(|| missing("shard"))?;
        let shard = Shard::new(k, n).map_err(|_| missing("shard"))?;
        let rows: Vec<Range<u32>> = h["rows"]
            .as_array()
            .and_then(|a| a.iter().map(|r| pair(r).map(|(a, b)| a..b)).collect())
            .ok_or_else(|| missing("rows"))?;
        // The header's sizes are checked against the file before anything is allocated by
        // them: an image the render would refuse, as many bands as the shard has, and pixel
        // data of the size the rows and channels need (a 266-byte file may claim 2³² rows).
        if image_bytes(width, height, false) > MAX_IMAGE_BYTES {
            return Err(bad(&format!(
                "its header claims a {width}×{height} image, larger than rtc renders"
            )));
        }
        if rows.len() as u64 != shard.band_count(height) {
            return Err(bad(&format!(
                "its rows are not those of shard {k}/{n} of a {height}-row image"
            )));
        }
        let claimed = rows
            .iter()
            .map(|r| u64::from(r.end.saturating_sub(r.start)))
            .sum::<u64>()
            .saturating_mul(u64::from(width))
            .saturating_mul(channels.len() as u64 * 24);
        if claimed != payload.len() as u64 {
            return Err(bad(&format!(
                "its header claims {claimed} bytes of pixels, the file holds {}",
                payload.len()
            )));
        }
        if rows != shard.bands(height) {
            return Err(bad(&format!(
                "its rows are not those of shard {k}/{n} of a {height}-row image"
            )));
        }
        let st = |i: usize| h["stats"][i].as_u64().unwrap_or(0);
        let stats = Stats {
            camera_rays: st(0),
            secondary_rays: st(1),
            shadow_rays: st(2),
            refined_pixels: st(3),
            cut_rays: st(4),
            cut_weight: st(5),
        };
        if text("payload").as_deref() != Some(fingerprint::bytes(payload).as_str()) {
            return Err(bad("its pixel data is truncated or damaged"));
        }
        let pixels: usize = rows.iter().map(|r| r.len()).sum::<usize>() * width as usize;
        if payload.len() != pixels * channels.len() * 24 {
            return Err(bad("its pixel data has the wrong size"));
        }
        let f = |c: &[u8]| f64::from_le_bytes(c.try_into().unwrap_or([0; 8]));
        let values = payload
            .chunks_exact(24)
            .map(|c| DVec3::new(f(&c[0..8]), f(&c[8..16]), f(&c[16..24])))
            .collect();
        Ok(Part {
            scene,
            settings,
            width,
            height,
            channels,
            encoding,
            shard,
            rows,
            stats,
            values,
            sidecar: h.get("sidecar").cloned(),
        })
    }
}

fn encoding_name(e: Encoding) -> &'static str {
    match e {
        Encoding::Linear => "linear",
        Encoding::Srgb => "srgb",
    }
}

fn encoding_named(name: &str) -> Option<Encoding> {
    [Encoding::Linear, Encoding::Srgb]
        .into_iter()
        .find(|e| encoding_name(*e) == name)
}
