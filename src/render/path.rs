//! Where a path is: how often it has bounced, the stack of media it travels in and how much it
//! still weighs in its pixel. The state every integrator and the recorder (`rtc why`) share; it
//! imports nothing of the render room.

/// The stack of media a ray is inside (indices of refraction, innermost last); the outside is 1.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Media {
    etas: [f64; 8],
    len: usize,
}

impl PartialEq for Media {
    fn eq(&self, o: &Media) -> bool {
        self.etas[..self.len] == o.etas[..o.len]
    }
}

impl Default for Media {
    fn default() -> Media {
        Media::OUTSIDE
    }
}

impl Media {
    /// Not inside anything (index 1).
    pub(crate) const OUTSIDE: Media = Media {
        etas: [1.0; 8],
        len: 0,
    };

    /// Whether the ray travels outside every object (where fog is).
    pub(crate) fn is_outside(&self) -> bool {
        self.len == 0
    }

    /// The index of the innermost medium.
    pub(crate) fn current(&self) -> f64 {
        if self.len == 0 {
            1.0
        } else {
            self.etas[self.len - 1]
        }
    }

    /// After entering a medium of index `eta` (a full stack forgets its outermost entry).
    fn enter(mut self, eta: f64) -> Media {
        if self.len == self.etas.len() {
            self.etas.copy_within(1.., 0);
            self.len -= 1;
        }
        self.etas[self.len] = eta;
        self.len += 1;
        self
    }

    /// After leaving a medium of index `eta`: its innermost entry is removed (unchanged when the
    /// ray was not known to be inside it, e.g. a camera placed inside glass).
    fn leave(mut self, eta: f64) -> Media {
        if let Some(i) = self.etas[..self.len].iter().rposition(|e| *e == eta) {
            self.etas.copy_within(i + 1..self.len, i);
            self.len -= 1;
        }
        self
    }

    /// Crossing the surface of a medium of index `eta`, leaving it when `inside`: the index on
    /// the near side and the media beyond.
    pub(crate) fn cross(self, eta: f64, inside: bool) -> (f64, Media) {
        if inside {
            (eta, self.leave(eta))
        } else {
            (self.current(), self.enter(eta))
        }
    }
}

/// Where a path is: how often it has bounced, which media it is inside and how much it still
/// weighs in its pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Path {
    /// Bounces so far (0 for a camera ray).
    pub(crate) depth: u32,
    /// The media the ray travels in.
    pub(crate) media: Media,
    /// The product of the scattering weights along the path (1 for a camera ray): what the
    /// insignificance cut-off compares.
    pub(crate) weight: f64,
    /// Whether a mirror reflection lies behind the ray (POV-Ray's reflection rays: objects
    /// marked `.no_reflection()` hide from them, `.no_image()` ones only from the others).
    pub(crate) reflected: bool,
}

impl Path {
    /// A camera ray's path: no bounce yet, outside everything, full weight.
    pub const CAMERA: Path = Path {
        depth: 0,
        media: Media::OUTSIDE,
        weight: 1.0,
        reflected: false,
    };

    /// The path after one more bounce into `media`, scattered with weight `k`.
    pub(crate) fn bounce(self, media: Media, k: f64) -> Path {
        Path {
            depth: self.depth + 1,
            media,
            weight: self.weight * k,
            reflected: self.reflected,
        }
    }

    /// The path after a mirror reflection (glossy or not) into `media` with weight `k`.
    pub(crate) fn reflect(self, media: Media, k: f64) -> Path {
        Path {
            reflected: true,
            ..self.bounce(media, k)
        }
    }

    /// The kind of ray, for objects hidden from some ([`crate::ir::Visibility`]).
    pub(crate) fn ray_kind(&self) -> crate::ir::Visibility {
        if self.reflected {
            crate::ir::Visibility::NO_REFLECTION
        } else {
            crate::ir::Visibility::NO_IMAGE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn media_stack_tracks_nesting() {
        let m = Media::OUTSIDE.enter(1.5).enter(1.33);
        assert_eq!(m.current(), 1.33);
        assert_eq!(m.leave(1.33).current(), 1.5);
        assert_eq!(m.leave(1.5).current(), 1.33);
        assert_eq!(m.leave(1.5).leave(1.33), Media::OUTSIDE);
        assert_eq!(Media::OUTSIDE.leave(2.0), Media::OUTSIDE);
        let mut deep = Media::OUTSIDE;
        for i in 0..20 {
            deep = deep.enter(f64::from(i));
        }
        assert_eq!(deep.current(), 19.0);
    }

    #[test]
    fn crossing_enters_from_outside_and_leaves_from_inside() {
        let (n1, glass) = Media::OUTSIDE.cross(1.5, false);
        assert_eq!((n1, glass.current()), (1.0, 1.5));
        let (n1, out) = glass.cross(1.5, true);
        assert_eq!((n1, out), (1.5, Media::OUTSIDE));
    }
}
