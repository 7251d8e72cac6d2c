//! Colour maps: what turns a pattern's value into a colour. Stops are sorted by position; a
//! value between two stops interpolates them linearly, channel by channel, in linear RGB (the
//! renderer's working space: a map written with `srgb(..)` colours blends their linear values,
//! as POV-Ray does with `assumed_gamma 1`). Before the first stop and after the last the end
//! stop's colour holds. Every stop carries POV-Ray's filter and transmit, so a layer over
//! another can let it show through.

use glam::DVec3;

/// A colour with POV-Ray's filter (light through it, tinted by the colour) and transmit (light
/// through it, untinted), both in [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rgbft {
    /// The colour, linear RGB.
    pub rgb: DVec3,
    /// The share of light passing through, tinted by `rgb`.
    pub filter: f64,
    /// The share of light passing through untinted.
    pub transmit: f64,
}

impl Rgbft {
    /// An opaque colour.
    pub const fn opaque(rgb: DVec3) -> Rgbft {
        Rgbft {
            rgb,
            filter: 0.0,
            transmit: 0.0,
        }
    }

    /// `self` laid over `below`: the covered share `1 − filter − transmit` shows `rgb`, the
    /// filtered share shows `below` tinted by `rgb`, the transmitted share `below` as is. The
    /// result keeps `below`'s own filter and transmit, scaled by the share that reaches it.
    pub fn over(self, below: Rgbft) -> Rgbft {
        let through = self.filter * self.rgb + DVec3::splat(self.transmit);
        let reach = (self.filter + self.transmit).clamp(0.0, 1.0);
        Rgbft {
            rgb: self.rgb * self.coverage() + through * below.rgb,
            filter: below.filter * reach,
            transmit: below.transmit * reach,
        }
    }

    /// `self` and `other` blended channel by channel, `other`'s share `w`.
    pub fn lerp(self, other: Rgbft, w: f64) -> Rgbft {
        Rgbft {
            rgb: self.rgb + (other.rgb - self.rgb) * w,
            filter: self.filter + (other.filter - self.filter) * w,
            transmit: self.transmit + (other.transmit - self.transmit) * w,
        }
    }

    /// The share of the surface this colour covers: `1 − filter − transmit`, clamped to [0, 1].
    pub fn coverage(&self) -> f64 {
        (1.0 - self.filter - self.transmit).clamp(0.0, 1.0)
    }
}

/// One stop of a map: a position and the colour there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stop {
    /// Where along the pattern's value.
    pub at: f64,
    /// The colour there.
    pub color: Rgbft,
}

/// A colour map: stops sorted by position (at least one).
#[derive(Clone, Debug, PartialEq)]
pub struct ColorMap {
    stops: Vec<Stop>,
}

impl ColorMap {
    /// The map of `stops`, sorted by position (a stable sort: two stops at one position make a
    /// sharp edge there, the first written below, the second above). `None` when there is no
    /// stop or a position is not finite.
    pub fn new(mut stops: Vec<Stop>) -> Option<ColorMap> {
        if stops.is_empty() || stops.iter().any(|s| !s.at.is_finite()) {
            return None;
        }
        stops.sort_by(|a, b| a.at.total_cmp(&b.at));
        Some(ColorMap { stops })
    }

    /// Black at 0 to white at 1: what a pattern shows with no map of its own (POV-Ray's
    /// default colour map is a rainbow; a grey ramp shows the value itself).
    pub fn grey() -> ColorMap {
        ColorMap {
            stops: vec![
                Stop {
                    at: 0.0,
                    color: Rgbft::opaque(DVec3::ZERO),
                },
                Stop {
                    at: 1.0,
                    color: Rgbft::opaque(DVec3::ONE),
                },
            ],
        }
    }

    /// One stop per tile index: the map of a discrete pattern (checker, hexagon, brick, ...)
    /// whose index `i` shows `colors[i]`.
    pub fn entries(colors: &[DVec3]) -> Option<ColorMap> {
        let stops = colors
            .iter()
            .enumerate()
            .map(|(i, c)| Stop {
                at: i as f64,
                color: Rgbft::opaque(*c),
            })
            .collect();
        ColorMap::new(stops)
    }

    /// The stops, sorted.
    pub fn stops(&self) -> &[Stop] {
        &self.stops
    }

    /// The index of the last stop at or below `v` (0 when `v` is below them all): the stop
    /// `v` fell in, for `rtc why`.
    pub fn stop_index(&self, v: f64) -> usize {
        self.stops.partition_point(|s| s.at <= v).saturating_sub(1)
    }

    /// The colour at `v`: linear between the two stops around it, the end stop's outside.
    #[inline]
    pub fn at(&self, v: f64) -> Rgbft {
        let s = &self.stops;
        let upper = s.partition_point(|stop| stop.at <= v);
        if upper == 0 {
            return s[0].color;
        }
        if upper == s.len() {
            return s[upper - 1].color;
        }
        let (lo, hi) = (s[upper - 1], s[upper]);
        lo.color.lerp(hi.color, (v - lo.at) / (hi.at - lo.at))
    }
}
