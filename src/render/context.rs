//! The per-tile state threaded through a render: the current camera sample's random numbers,
//! the tile's counters, the light cells the sample takes, and buffers an integrator reuses from
//! packet to packet. At the bottom of the render room: shading and the integrators read it,
//! it reads neither.

use std::any::Any;

use super::deal::LightShare;
use super::film::Stats;
use super::sampler::Rng;

/// The most surface points (and camera samples) shaded side by side: a pixel's 4×4 samples
/// (the shading models' and the Whitted integrator's packets).
pub(crate) const BATCH: usize = crate::lanes::WIDTH;

/// Mutable per-tile state threaded through shading: the sample's random numbers and counters.
pub struct Ctx {
    /// Random numbers of the current camera sample.
    pub(crate) rng: Rng,
    /// Counters of the current tile.
    pub stats: Stats,
    /// Which cells of each area light the current camera sample takes.
    pub(crate) lights: LightShare,
    /// Reused buffers of the packets an integrator traces.
    pub(crate) scratch: Scratch,
}

impl Ctx {
    /// The state a tile starts with: no counts, every light cell, empty buffers.
    pub fn new() -> Ctx {
        Ctx {
            rng: Rng::new(0, 0, 0, 0),
            stats: Stats::default(),
            lights: LightShare::ALL,
            scratch: Scratch::default(),
        }
    }
}

impl Default for Ctx {
    fn default() -> Ctx {
        Ctx::new()
    }
}

/// Buffers reused from packet to packet (one per recursion depth in use), typed by the
/// integrator that fills them: the context does not know the integrators' types, so a tile's
/// buffers are kept as `Any` and a buffer of another type is never handed out.
#[derive(Default)]
pub(crate) struct Scratch {
    // Boxed so that taking and giving back moves a pointer, not a kilobytes-large buffer.
    free: Vec<Box<dyn Any + Send>>,
}

impl Scratch {
    /// A buffer of type `T` (holding whatever the last packet left), or a new one.
    pub(crate) fn take<T: Default + Send + 'static>(&mut self) -> Box<T> {
        match self.free.pop().map(|b| b.downcast::<T>()) {
            Some(Ok(b)) => b,
            Some(Err(other)) => {
                self.free.push(other);
                Box::default()
            }
            None => Box::default(),
        }
    }

    /// Gives a buffer back for the next packet.
    pub(crate) fn give<T: Send + 'static>(&mut self, b: Box<T>) {
        self.free.push(b);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scratch_hands_back_buffers_of_the_asked_type_only() {
        let mut s = Scratch::default();
        let mut a: Box<[u8; 4]> = s.take();
        a[0] = 7;
        s.give(a);
        let b: Box<[u8; 4]> = s.take();
        assert_eq!(b[0], 7, "the buffer given back is reused");
        s.give(b);
        let c: Box<u64> = s.take();
        assert_eq!(*c, 0, "a buffer of another type is never handed out");
        let d: Box<[u8; 4]> = s.take();
        assert_eq!(d[0], 7, "and the other buffer is kept");
    }
}
