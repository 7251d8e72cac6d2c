//! Geometry: rays, hits and bounds at the root; one room each for the shapes
//! ([`shapes`]: each shape family's intersection, with CSG and the root solvers they share),
//! triangle meshes ([`mesh`]), bounding volume hierarchies ([`bvh`]), the packet lanes that
//! trace several rays at once ([`lanes`]) and the [`World`] the renderer queries ([`world`]).
//! [`shapes`] is the one home of a shape's validity and bounds.
//!
//! Shapes intersect in their own object space; [`World`] moves rays in and hits out through each
//! object's affine transform (normals by the inverse transpose). Files import the file that
//! defines an item, never this façade (tests/architecture.rs counts the circles).

pub(crate) mod aabb;
pub mod bvh;
pub mod lanes;
pub mod mesh;
mod motion;
pub(crate) mod ray;
pub mod rounding;
pub(crate) mod shapes;
#[cfg(test)]
pub(crate) mod testing;
pub mod world;

pub use aabb::Aabb;
pub(crate) use ray::MappingFrame;
pub use ray::Ray;
pub use world::{SurfaceHit, World};
