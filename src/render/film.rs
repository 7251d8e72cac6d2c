//! The film: per pixel, one floating-point value per named channel. The colour channel turns
//! into bytes by the scene's [`Encoding`]: linear (clamp to [0, 1] and truncate `255·c`,
//! COURSE.md §1.4/§2.5: trunc, not round) or sRGB (the IEC 61966-2-1 curve, rounded to the
//! nearest level). A later output (an AOV such as depth or albedo, an EXR layer) is a new
//! [`Channel`] an integrator fills, not a new code path: the tile driver, the averaging and the
//! film carry any number of channels.

use crate::ir::{Color, Encoding};

/// Most channels one film holds.
pub(crate) const MAX_CHANNELS: usize = 8;

/// What a film channel holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Channel {
    /// The image's linear RGB (shaded colour, or the encoded normal or depth of those modes).
    Color,
    /// AOV: distance from the eye to the first hit, the mean over the pixel's samples that hit
    /// (`x`; +∞ where none did).
    Depth,
    /// AOV: the world-space shading normal at the first hit (bumped, facing the viewer), the
    /// mean over the pixel's samples (zero where nothing is hit).
    Normal,
    /// AOV: the surface colour (material or texture) at the first hit, the mean over the
    /// pixel's samples (zero where nothing is hit).
    Albedo,
    /// AOV: the scene object hit by most of the pixel's samples, as `index + 1` in `x` (0: the
    /// background).
    Object,
    /// AOV: the share of the pixel's samples whose camera ray meets something (`x`), the
    /// image's alpha (`render { alpha: true }` adds it).
    Alpha,
}

impl Channel {
    /// Every channel, for reading names back.
    const ALL: [Channel; 6] = [
        Channel::Color,
        Channel::Depth,
        Channel::Normal,
        Channel::Albedo,
        Channel::Object,
        Channel::Alpha,
    ];

    /// The channels `--aov` can ask for (every one but the colour).
    pub const AOVS: [Channel; 5] = [
        Channel::Depth,
        Channel::Normal,
        Channel::Albedo,
        Channel::Object,
        Channel::Alpha,
    ];

    /// The channel's name in files and messages.
    pub fn name(self) -> &'static str {
        match self {
            Channel::Color => "color",
            Channel::Depth => "depth",
            Channel::Normal => "normal",
            Channel::Albedo => "albedo",
            Channel::Object => "object",
            Channel::Alpha => "alpha",
        }
    }

    /// The channel called `name`.
    pub(crate) fn named(name: &str) -> Option<Channel> {
        Channel::ALL.into_iter().find(|c| c.name() == name)
    }
}

/// Per-render counters (integers, so sums are identical for any thread count).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Camera rays traced.
    pub camera_rays: u64,
    /// Reflected and refracted rays traced.
    pub secondary_rays: u64,
    /// Shadow rays tested.
    pub shadow_rays: u64,
    /// Pixels that took the finer grid of adaptive sampling.
    pub refined_pixels: u64,
    /// Secondary rays not traced because their weight was below the insignificance cut-off.
    pub cut_rays: u64,
    /// The summed weight of the cut rays, in units of 2⁻³² ([`CUT_WEIGHT_UNIT`]):
    /// divided by the camera rays, a bound on the mean linear radiance dropped per sample when
    /// what the cut rays would have seen is at most 1.
    pub cut_weight: u64,
}

/// Fixed-point units per unit of weight in [`Stats::cut_weight`] (integers keep the sum the
/// same for any thread count).
pub const CUT_WEIGHT_UNIT: f64 = (1u64 << 32) as f64;

impl Stats {
    /// Adds another tile's counters.
    pub(crate) fn add(&mut self, o: &Stats) {
        self.camera_rays += o.camera_rays;
        self.secondary_rays += o.secondary_rays;
        self.shadow_rays += o.shadow_rays;
        self.refined_pixels += o.refined_pixels;
        self.cut_rays += o.cut_rays;
        self.cut_weight += o.cut_weight;
    }
}

/// A rendered 8-bit RGB image.
pub type Image = image::RgbImage;

/// A rendered image before quantisation.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    channels: Vec<Channel>,
    /// Per channel, its values row by row from the top (unclamped averages of the samples).
    layers: Vec<Vec<Color>>,
    /// What it took.
    pub stats: Stats,
    /// How [`Film::to_image`] quantises the colour channel.
    pub(crate) encoding: Encoding,
}

impl Film {
    /// A film from `values` interleaved per pixel (`channels.len()` values each, row by row).
    pub(crate) fn new(
        width: u32,
        height: u32,
        channels: &[Channel],
        values: Vec<Color>,
        stats: Stats,
        encoding: Encoding,
    ) -> Film {
        let n = channels.len().max(1);
        let layers = if n == 1 {
            vec![values]
        } else {
            (0..n)
                .map(|c| values.iter().skip(c).step_by(n).copied().collect())
                .collect()
        };
        Film {
            width,
            height,
            channels: channels.to_vec(),
            layers,
            stats,
            encoding,
        }
    }

    /// The channels this film holds.
    pub(crate) fn channels(&self) -> &[Channel] {
        &self.channels
    }

    /// Every channel's values interleaved per pixel (the layout [`Film::new`] takes), for
    /// the rows `rows`.
    pub(crate) fn interleaved(&self, rows: std::ops::Range<u32>) -> Vec<Color> {
        let w = self.width as usize;
        let (a, b) = (rows.start as usize * w, rows.end as usize * w);
        (a..b)
            .flat_map(|i| self.layers.iter().map(move |l| l[i]))
            .collect()
    }

    /// A channel's values row by row from the top, if the film holds it.
    pub(crate) fn channel(&self, c: Channel) -> Option<&[Color]> {
        let i = self.channels.iter().position(|x| *x == c)?;
        self.layers.get(i).map(Vec::as_slice)
    }

    /// Appends a channel computed by a separate pass (an AOV), its values row by row.
    pub(crate) fn push_channel(&mut self, c: Channel, values: Vec<Color>) {
        self.channels.push(c);
        self.layers.push(values);
    }

    /// The colour channel (every integrator fills it).
    pub fn color(&self) -> &[Color] {
        self.channel(Channel::Color).unwrap_or(&[])
    }

    /// The colour of pixel (x, y), y = 0 at the top.
    pub fn get(&self, x: u32, y: u32) -> Color {
        self.color()[y as usize * self.width as usize + x as usize]
    }

    /// Quantises the colour channel to 8-bit RGB with the film's encoding.
    pub fn to_image(&self) -> Image {
        let bytes = self
            .color()
            .iter()
            .flat_map(|c| encode(*c, self.encoding))
            .collect();
        Image::from_raw(self.width, self.height, bytes).unwrap_or_default()
    }
}

impl Film {
    /// The 8-bit RGBA image of a film with an alpha channel (`None` without one): the alpha is
    /// `round(255·a)`, the colour the premultiplied film colour divided by `a` (straight alpha,
    /// as PNG stores it), encoded as [`Film::to_image`] encodes; black where `a` is 0.
    pub fn to_rgba(&self) -> Option<image::RgbaImage> {
        let alpha = self.channel(Channel::Alpha)?;
        let bytes = self
            .color()
            .iter()
            .zip(alpha)
            .flat_map(|(c, a)| {
                let a = a.x.clamp(0.0, 1.0);
                let [r, g, b] = if a > 0.0 {
                    encode(*c / a, self.encoding)
                } else {
                    [0; 3]
                };
                [r, g, b, libm::round(255.0 * a) as u8]
            })
            .collect();
        image::RgbaImage::from_raw(self.width, self.height, bytes)
    }
}

/// One colour as bytes in `encoding` (NaN becomes 0 in both).
pub(crate) fn encode(c: Color, encoding: Encoding) -> [u8; 3] {
    match encoding {
        Encoding::Linear => to_bytes(c),
        Encoding::Srgb => {
            let q = |v: f64| (255.0 * linear_to_srgb(v.clamp(0.0, 1.0)) + 0.5) as u8;
            [q(c.x), q(c.y), q(c.z)]
        }
    }
}

/// `trunc(255·clamp(c, 0, 1))` per channel (NaN becomes 0): the linear encoding.
fn to_bytes(c: Color) -> [u8; 3] {
    let q = |v: f64| (255.0 * v.clamp(0.0, 1.0)) as u8;
    [q(c.x), q(c.y), q(c.z)]
}

/// The sRGB transfer curve (IEC 61966-2-1) for a linear value in [0, 1]. `libm::pow`, not
/// `f64::powf`, so the bytes are the same on every CPU and C library.
fn linear_to_srgb(c: f64) -> f64 {
    if c <= 0.0031308 {
        12.92 * c
    } else {
        1.055 * libm::pow(c, 1.0 / 2.4) - 0.055
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn quantisation_truncates_and_clamps() {
        assert_eq!(to_bytes(DVec3::new(1.0, 0.999, 0.5)), [255, 254, 127]);
        assert_eq!(to_bytes(DVec3::new(7.0, -1.0, f64::NAN)), [255, 0, 0]);
    }

    #[test]
    fn interleaved_values_split_into_channels() {
        let v = |x: f64| DVec3::splat(x);
        let film = Film::new(
            2,
            1,
            &[Channel::Color, Channel::Color],
            vec![v(1.0), v(2.0), v(3.0), v(4.0)],
            Stats::default(),
            Encoding::Linear,
        );
        assert_eq!(
            film.layers,
            vec![vec![v(1.0), v(3.0)], vec![v(2.0), v(4.0)]]
        );
        assert_eq!(film.get(1, 0), v(3.0));
    }

    #[test]
    fn srgb_rounds_and_clamps() {
        let e = |v: f64| encode(DVec3::splat(v), Encoding::Srgb)[0];
        assert_eq!(e(0.0), 0);
        assert_eq!(e(1.0), 255);
        assert_eq!(e(7.0), 255);
        assert_eq!(e(-1.0), 0);
        assert_eq!(e(f64::NAN), 0);
        // Linear 0.2158605 is sRGB 0.5019608 = 128/255.
        assert_eq!(e(0.21586050011389926), 128);
    }
}
