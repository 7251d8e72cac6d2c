//! Mip-mapped image lookup: a pyramid of ever halved copies of a picture, each texel the box
//! average of the (up to) four texels it covers in the level below, and a lookup that blends
//! the two levels whose texels are nearest in size to the footprint a sample covers (Lance
//! Williams' trilinear filtering, 1983): bilinear within each level, linear between them.

use glam::{DVec2, DVec3};

use super::image::Picture;

/// A picture and its halvings down to one texel.
#[derive(Clone, Debug)]
pub struct MipChain {
    /// Level 0 is the picture itself; level `k + 1` halves level `k` (sizes rounded up).
    levels: Vec<Picture>,
}

impl MipChain {
    /// The pyramid of `picture`: level `k + 1` is `⌈w/2⌉ × ⌈h/2⌉`, each texel the mean of the
    /// texels `(2i, 2j)`, `(2i + 1, 2j)`, `(2i, 2j + 1)` and `(2i + 1, 2j + 1)` of level `k`
    /// that exist (an odd last column or row averages its own two or one).
    pub fn of(picture: &Picture) -> MipChain {
        let mut levels = vec![picture.clone()];
        loop {
            let below = levels.last().expect("level 0");
            let (w, h) = below.size();
            if w == 1 && h == 1 {
                break;
            }
            let (nw, nh) = (w.div_ceil(2), h.div_ceil(2));
            let mut texels = Vec::with_capacity(nw as usize * nh as usize);
            for j in 0..nh {
                for i in 0..nw {
                    let mut sum = DVec3::ZERO;
                    let mut count = 0.0;
                    for (x, y) in [(2 * i, 2 * j), (2 * i + 1, 2 * j), (2 * i, 2 * j + 1)]
                        .into_iter()
                        .chain([(2 * i + 1, 2 * j + 1)])
                    {
                        if x < w && y < h {
                            sum += below.texel(x, y);
                            count += 1.0;
                        }
                    }
                    texels.push(sum / count);
                }
            }
            levels.push(Picture::new(nw, nh, texels).expect("a level has texels"));
        }
        MipChain { levels }
    }

    /// How many levels (1 for a one-texel picture).
    pub fn levels(&self) -> usize {
        self.levels.len()
    }

    /// Level `k` (clamped to the last).
    pub fn level(&self, k: usize) -> &Picture {
        &self.levels[k.min(self.levels.len() - 1)]
    }

    /// The colour at `uv` over a footprint `texels` wide in level 0's texels: the level
    /// `λ = log₂ texels` (0 for footprints up to a texel, the last level beyond the
    /// picture), bilinear within the levels `⌊λ⌋` and `⌊λ⌋ + 1`, blended by `λ − ⌊λ⌋`.
    pub fn lookup(&self, uv: DVec2, texels: f64) -> DVec3 {
        let last = (self.levels.len() - 1) as f64;
        let lambda = if texels > 1.0 {
            libm::log2(texels).min(last)
        } else {
            0.0
        };
        let k = lambda.floor();
        let fine = self.level(k as usize).bilinear(uv);
        let t = lambda - k;
        if t == 0.0 {
            return fine;
        }
        let coarse = self.level(k as usize + 1).bilinear(uv);
        fine + (coarse - fine) * t
    }

    /// Approximate heap bytes (about 4/3 of the picture's).
    pub fn memory(&self) -> usize {
        self.levels.iter().map(Picture::memory).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn picture(w: u32, h: u32, f: impl Fn(u32, u32) -> f64) -> Picture {
        let texels = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| DVec3::splat(f(x, y)))
            .collect();
        Picture::new(w, h, texels).unwrap()
    }

    #[test]
    fn levels_halve_down_to_one_texel_and_keep_the_mean() {
        // A 6×3 picture: levels 6×3, 3×2, 2×1, 1×1; a constant stays constant, and for a
        // power-of-two picture every level keeps the mean exactly.
        let chain = MipChain::of(&picture(6, 3, |_, _| 0.25));
        let sizes: Vec<_> = (0..chain.levels()).map(|k| chain.level(k).size()).collect();
        assert_eq!(sizes, [(6, 3), (3, 2), (2, 1), (1, 1)]);
        assert_eq!(chain.level(3).texel(0, 0), DVec3::splat(0.25));
        let ramp = picture(8, 8, |x, y| f64::from(x + 8 * y) / 63.0);
        let chain = MipChain::of(&ramp);
        assert_eq!(chain.levels(), 4);
        assert!((chain.level(3).texel(0, 0).x - 0.5).abs() < 1e-15);
        // Level 1's first texel is the mean of the four in the corner.
        let want = (0.0 + 1.0 + 8.0 + 9.0) / 4.0 / 63.0;
        assert!((chain.level(1).texel(0, 0).x - want).abs() < 1e-15);
    }

    #[test]
    fn a_footprint_picks_and_blends_levels() {
        // A checkerboard of single texels: up close it is the picture (bilinear at a texel
        // centre), over a footprint of the whole picture its mean, and halfway in log₂
        // between levels 0 and 1 the mean of the two.
        let checker = picture(16, 16, |x, y| f64::from((x + y) % 2));
        let chain = MipChain::of(&checker);
        let centre = DVec2::new(0.5 / 16.0, 0.5 / 16.0);
        assert_eq!(chain.lookup(centre, 0.5), DVec3::ZERO);
        assert_eq!(chain.lookup(centre, 1.0), DVec3::ZERO);
        assert_eq!(chain.lookup(DVec2::splat(0.4), 64.0), DVec3::splat(0.5));
        let between = chain.lookup(centre, 2f64.sqrt());
        assert!((between.x - 0.25).abs() < 1e-12, "{between}");
    }
}
