//! The world's queries for a packet of rays ([`crate::geometry::lanes`]): the loose spheres
//! are tested on all rays at once ([`crate::geometry::lanes::sphere_packet`]); everything else
//! ray by ray, as [`World::intersect_after`] and [`World::occluded_among`] test it. Each ray
//! gets exactly the answer it gets alone.

use super::{BALL, Ball, SphereHit, World};
use crate::geometry::lanes::RayLanes;
use crate::geometry::lanes::cull::Among;
use crate::geometry::lanes::sphere_packet::{NO_SPHERE, PacketHits};
use crate::geometry::ray::Ray;
use crate::lanes::{self, Lanes, Mask};

impl SphereHit {
    /// The nearest loose sphere of a ray from a packet query ([`World::nearest_packet`]):
    /// lane `i` of `hits`.
    pub(crate) fn of_lane(hits: &PacketHits, i: usize) -> SphereHit {
        SphereHit((hits.sphere[i] != NO_SPHERE).then(|| (hits.sphere[i] as usize, hits.t[i])))
    }
}

impl World {
    /// Whether every object is a loose sphere (no BVH, nothing unbounded or of another
    /// kind): then a packet's loose-sphere answers are the whole answers.
    pub(crate) fn balls_only(&self) -> bool {
        self.loose.is_empty() && self.bvh.is_none()
    }

    /// Whether the world has loose spheres (the packet queries' fast part).
    pub(crate) fn has_loose_spheres(&self) -> bool {
        !self.spheres.is_empty()
    }

    /// [`World::nearest_sphere`] of every ray of `live` (the loose spheres of `among` only).
    #[inline]
    pub(crate) fn nearest_packet(
        &self,
        rays: &RayLanes,
        live: Mask,
        t_min: f64,
        t_max: f64,
        among: Among,
    ) -> PacketHits {
        self.spheres.nearest_packet(rays, live, t_min, t_max, among)
    }

    /// The loose sphere at lane position `k` of a packet query.
    pub(crate) fn loose_ball(&self, k: u32) -> &Ball {
        &self.balls[(self.sphere_ids[k as usize] & !BALL) as usize]
    }

    /// [`World::occluded_among`] of every ray of `live` (at times `time`), each in
    /// (t_min, t_max[i]): the rays something blocks.
    pub(crate) fn occluded_packet(
        &self,
        rays: &RayLanes,
        time: &Lanes,
        live: Mask,
        t_min: f64,
        t_max: &Lanes,
        among: Among,
    ) -> Mask {
        let mut blocked = if self.spheres.is_empty() {
            0
        } else {
            self.spheres.any_packet(rays, live, t_min, t_max, among)
        };
        let rest = live & !blocked;
        if !self.balls_only() && rest != 0 {
            // Everything else through the packet queries (a mesh's BVH tested once per node
            // for all the rays).
            let one: [Ray; lanes::WIDTH] = std::array::from_fn(|i| {
                Ray::new(rays.origin.get(i), rays.dir.get(i)).at_time(time[i])
            });
            blocked |= self.occluded_past_packet(&one, t_min, t_max, rest);
        }
        blocked
    }
}
