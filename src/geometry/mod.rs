//! Geometry: rays, hits, bounds, one file per shape family, and the [`World`] the renderer queries.
//!
//! Shapes intersect in their own object space; [`World`] moves rays in and hits out through each
//! object's affine transform (normals by the inverse transpose).

pub mod aabb;
pub mod plane;
pub mod ray;
pub mod sphere;
pub mod world;

pub use aabb::Aabb;
pub use ray::{Hit, Ray};
pub use world::{SurfaceHit, World};
