//! Whether a point lies inside a closed mesh, for the lints that look for a light or the eye
//! shut inside an opaque object (`check::enclosed`): the parity of a ray's crossings.
//!
//! A ray from the point crosses a closed surface an odd number of times exactly when the point
//! is inside. A ray through an edge or a vertex can count one crossing twice or not at all, so
//! three rays in unrelated directions vote. The test is brute force over the triangles (a lint
//! asks for a handful of points, each linear in the mesh), in f64 on the file's vertices.

use glam::DVec3;

use super::obj::MeshAsset;

/// Three directions unlikely to run along an edge of a mesh someone modelled (not axes, not
/// diagonals, not in a common plane).
const DIRECTIONS: [[f64; 3]; 3] = [
    [0.577_215_664, 0.309_016_994, 0.751_988_12],
    [-0.414_213_562, 0.732_050_808, -0.540_302_306],
    [0.267_949_192, -0.847_998_304, 0.457_657_554],
];

impl MeshAsset {
    /// Whether `p` (in the file's coordinates) is inside the surface; meaningful for a closed
    /// mesh ([`MeshAsset::is_closed`]).
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        if !(self.min.cmple(p).all() && p.cmple(self.max).all()) {
            return false;
        }
        let votes = DIRECTIONS
            .iter()
            .filter(|d| self.crossings(p, DVec3::from(**d)) % 2 == 1)
            .count();
        votes >= 2
    }

    /// How many triangles the ray from `p` along `dir` crosses (Möller–Trumbore, `t > 0`).
    fn crossings(&self, p: DVec3, dir: DVec3) -> usize {
        let vertex = |i: u32| self.vertices[i as usize].as_dvec3();
        self.triangles
            .iter()
            .filter(|t| {
                let (a, b, c) = (vertex(t[0]), vertex(t[1]), vertex(t[2]));
                let (e1, e2) = (b - a, c - a);
                let h = dir.cross(e2);
                let det = e1.dot(h);
                if det == 0.0 {
                    return false;
                }
                let s = p - a;
                let u = s.dot(h) / det;
                let q = s.cross(e1);
                let v = dir.dot(q) / det;
                let t = e2.dot(q) / det;
                (0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && t > 0.0
            })
            .count()
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    /// A unit cube of twelve triangles holds its centre and points near its faces, and not
    /// points outside, beside or in line with it.
    #[test]
    fn a_cube_holds_its_inside() {
        let dir = std::env::temp_dir().join(format!("rtc-inside-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("cube.obj");
        std::fs::write(
            &path,
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
             f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n\
             f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n",
        )
        .unwrap();
        let cube = MeshAsset::load(Path::new(&path), false).unwrap();
        assert!(cube.is_closed());
        for inside in [[0.5, 0.5, 0.5], [0.01, 0.99, 0.5], [0.5, 0.5, 0.999]] {
            assert!(cube.contains(DVec3::from(inside)), "{inside:?}");
        }
        for outside in [
            [1.5, 0.5, 0.5],
            [-0.5, 0.5, 0.5],
            [0.5, 0.5, 2.0],
            [3.0, 3.0, 3.0],
        ] {
            assert!(!cube.contains(DVec3::from(outside)), "{outside:?}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
