//! Geometry: rays, hits, bounds, one file per shape family, CSG, meshes, BVHs, and the [`World`]
//! the renderer queries. [`shape`] is the one home of a shape's validity and bounds.
//!
//! Shapes intersect in their own object space; [`World`] moves rays in and hits out through each
//! object's affine transform (normals by the inverse transpose).

pub mod aabb;
pub mod balls;
pub mod blob;
pub mod bvh;
mod bvh_cluster;
pub mod bvh_packet;
mod bvh_traverse;
pub mod circle;
pub mod cone;
pub mod csg;
pub mod cuboid;
pub mod cylinder;
pub mod disk;
pub mod lanes;
pub mod mesh;
mod mesh_bvh;
pub mod motion;
pub mod plane;
pub mod polygon;
pub mod primitive;
pub mod quad;
pub mod quads;
pub mod quartic;
pub mod ray;
pub mod rounding;
pub mod shape;
pub mod sphere;
pub mod sphere_cull;
pub mod sphere_lanes;
pub mod sphere_packet;
pub mod torus;
pub mod triangle;
pub mod world;

pub use aabb::Aabb;
pub use primitive::{Primitive, SurfaceId};
pub use ray::{Crossing, Hit, MappingFrame, Ray};
pub use world::{SurfaceHit, World, WorldStats};

/// Uniform numbers in [0, 1) from a seeded 64-bit LCG (Knuth's MMIX constants, top 53 bits):
/// reproducible random spheres and rays for unit tests.
#[cfg(test)]
pub(crate) fn test_uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut seed = seed;
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64) / (1u64 << 53) as f64
    }
}
