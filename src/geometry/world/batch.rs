//! The world's queries for a batch of rays at once (a pixel's camera rays, its hit points'
//! shadow rays): each ray gets exactly the answer of the one-ray query, and meshes fixed in
//! place trace the batch as a packet (`geometry::bvh::packet`).

use super::{Among, BALL, GeoHit, Ray, SphereHit, SurfaceHit, World};
use crate::geometry::bvh::packet::PACKET;

impl World {
    /// Whether object `id` is a node that traces rays as a packet.
    fn packets(&self, id: u32) -> bool {
        id & BALL == 0 && self.nodes[id as usize].packets()
    }

    /// [`World::intersect_after`] of a batch of rays (packets of up to [`PACKET`]): `out[i]`
    /// is bit for bit `intersect_after(&rays[i], t_min, t_max, first[i])`.
    pub fn intersect_batch_after(
        &self,
        rays: &[Ray],
        t_min: f64,
        t_max: f64,
        first: &[SphereHit],
        out: &mut [Option<SurfaceHit>],
    ) {
        assert!(first.len() >= rays.len() && out.len() >= rays.len());
        for (k, rays) in rays.chunks(PACKET).enumerate() {
            let at = k * PACKET;
            self.intersect_packet_after(rays, t_min, t_max, &first[at..], &mut out[at..]);
        }
    }

    /// [`World::intersect_batch_after`] of one packet.
    fn intersect_packet_after(
        &self,
        rays: &[Ray],
        t_min: f64,
        t_max: f64,
        first: &[SphereHit],
        out: &mut [Option<SurfaceHit>],
    ) {
        let n = rays.len();
        let mut best: [Option<(GeoHit, u32)>; PACKET] = [None; PACKET];
        let mut far = [t_max; PACKET];
        let mut best_sphere = [None; PACKET];
        for i in 0..n {
            if let Some((k, t)) = first[i].0 {
                far[i] = t;
                best_sphere[i] = Some((self.sphere_ids[k], t));
            }
        }
        // The loose objects in their order, as `intersect_past` tests them for each ray.
        for &id in &self.loose {
            if self.packets(id) {
                let limits = far;
                self.nodes[id as usize].intersect_packet(
                    &rays[..n],
                    t_min,
                    &limits[..n],
                    |i, h| {
                        far[i] = h.t;
                        best[i] = Some((h, id));
                    },
                );
            } else {
                for i in 0..n {
                    if let Some(h) = self.hit(id, &rays[i], t_min, far[i]) {
                        far[i] = h.t;
                        best[i] = Some((h, id));
                    }
                }
            }
        }
        for i in 0..n {
            self.nearest_in_bvh(&rays[i], t_min, far[i], &mut best[i]);
            out[i] = self.nearest_hit(&rays[i], best[i], best_sphere[i]);
        }
    }

    /// [`World::occluded_among`] of a batch of rays with their own `t_max` (packets of up to
    /// [`PACKET`]): `out[i]` is `occluded_among(&rays[i], t_min, t_max[i], among)`.
    pub fn occluded_batch_among(
        &self,
        rays: &[Ray],
        t_min: f64,
        t_max: &[f64],
        among: Among,
        out: &mut [bool],
    ) {
        assert!(t_max.len() >= rays.len() && out.len() >= rays.len());
        for (k, rays) in rays.chunks(PACKET).enumerate() {
            let at = k * PACKET;
            self.occluded_packet_among(rays, t_min, &t_max[at..], among, &mut out[at..]);
        }
    }

    /// [`World::occluded_batch_among`] of one packet.
    fn occluded_packet_among(
        &self,
        rays: &[Ray],
        t_min: f64,
        t_max: &[f64],
        among: Among,
        out: &mut [bool],
    ) {
        let n = rays.len();
        let all = if n == 0 { 0 } else { u32::MAX >> (32 - n) };
        let mut spheres = 0u32;
        for i in 0..n {
            if self.spheres.any_among(&rays[i], t_min, t_max[i], among) {
                spheres |= 1 << i;
            }
        }
        let blocked = spheres | self.occluded_past_packet(rays, t_min, t_max, all & !spheres);
        for (i, o) in out.iter_mut().enumerate().take(n) {
            *o = blocked >> i & 1 == 1;
        }
    }

    /// The rays of `live` (bit `i` for `rays[i]`) that something other than the loose
    /// spheres blocks in (t_min, t_max[i]): [`World::occluded_among`]'s second half, the
    /// packet-tracing objects tested once for all of them.
    pub(crate) fn occluded_past_packet(
        &self,
        rays: &[Ray],
        t_min: f64,
        t_max: &[f64],
        live: u32,
    ) -> u32 {
        let n = rays.len();
        let mut done = 0u32;
        for &id in &self.loose {
            if done == live {
                break;
            }
            if self.packets(id) {
                done |= self.nodes[id as usize].occluded_packet(
                    &rays[..n],
                    t_min,
                    &t_max[..n],
                    live & !done,
                );
            } else {
                for i in 0..n {
                    if (live & !done) >> i & 1 == 1 && self.blocks(id, &rays[i], t_min, t_max[i]) {
                        done |= 1 << i;
                    }
                }
            }
        }
        for i in 0..n {
            if (live & !done) >> i & 1 == 1 && self.occluded_in_bvh(&rays[i], t_min, t_max[i]) {
                done |= 1 << i;
            }
        }
        done & live
    }
}
