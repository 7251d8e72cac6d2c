//! Tests of the mesh's packet queries (`Mesh::intersect_packet`, `Mesh::occluded_packet`)
//! against the one-ray queries, bit for bit.

use super::*;

/// A height field of `n` × `n` unit squares split into triangles (every interior edge and
/// vertex shared), a few of its triangles twice (exact ties), and random triangles above it.
fn test_mesh(n: usize, rnd: &mut impl FnMut() -> f64) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let mut vertices = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let h = ((i * 7 + j * 3) % 5) as f32 * 0.25;
            vertices.push(Vec3::new(i as f32, h, j as f32));
        }
    }
    let at = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    let mut triangles = Vec::new();
    for j in 0..n {
        for i in 0..n {
            triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    for k in (0..triangles.len()).step_by(7) {
        triangles.push(triangles[k]);
    }
    for _ in 0..40 {
        let base = vertices.len() as u32;
        let c = Vec3::new(rnd() as f32, 2.0 + rnd() as f32, rnd() as f32) * n as f32;
        for _ in 0..3 {
            let p = Vec3::new(rnd() as f32, rnd() as f32, rnd() as f32) * 2.0;
            vertices.push(c + p);
        }
        triangles.push([base, base + 1, base + 2]);
    }
    (vertices, triangles)
}

fn bits(h: &Option<MeshHit>) -> Option<[u64; 12]> {
    h.map(|h| {
        [
            h.t.to_bits(),
            h.geometric.x.to_bits(),
            h.geometric.y.to_bits(),
            h.geometric.z.to_bits(),
            h.shading.x.to_bits(),
            h.shading.y.to_bits(),
            h.shading.z.to_bits(),
            h.uv.x.to_bits(),
            h.uv.y.to_bits(),
            h.error.x.to_bits(),
            h.error.z.to_bits(),
            h.material.map_or(u64::MAX, u64::from),
        ]
    })
}

/// Packets of rays as the renderer makes them: from one eye through the grid's vertices and
/// edge midpoints (rays through shared edges and vertices), from one eye in random
/// directions, and from points on the surface towards one light; each query of a packet
/// equals the one-ray query of each of its rays.
#[test]
fn packets_match_single_rays_bit_for_bit() {
    let mut rnd = crate::geometry::testing::test_uniform(42);
    let n = 12;
    let (vertices, triangles) = test_mesh(n, &mut rnd);
    let normals: Vec<[Vec3; 3]> = triangles
        .iter()
        .map(|t| t.map(|i| (vertices[i as usize] + Vec3::Y).unit()))
        .collect();
    let parts = MeshParts {
        vertices: &vertices,
        triangles: &triangles,
        normals: &normals,
        uvs: &[],
        colors: &[],
        material_of: &[],
    };
    let packets = test_packets(n, &vertices, &mut rnd);
    // The tree of a small mesh and the clustered tree of a large one alike.
    for mesh in [
        Mesh::build(parts),
        Mesh::build_with(parts, crate::geometry::mesh::bvh::clustered),
    ] {
        check_packets(&mesh, n as f64, &packets, &mut rnd);
    }
}

/// The clustered tree (large meshes) finds for every ray the same nearest `t` and the same
/// any-hit answer as the per-triangle tree: grouping changes only the order of the tests.
/// The mesh's triangle count is not a multiple of four, so the last cluster is short.
#[test]
fn clustered_tree_finds_what_the_per_triangle_tree_finds() {
    let mut rnd = crate::geometry::testing::test_uniform(5);
    let n = 12;
    let (vertices, triangles) = test_mesh(n, &mut rnd);
    assert_ne!(triangles.len() % 4, 0);
    let parts = MeshParts {
        vertices: &vertices,
        triangles: &triangles,
        normals: &[],
        uvs: &[],
        colors: &[],
        material_of: &[],
    };
    let whole = Mesh::build_with(parts, crate::geometry::mesh::bvh::per_triangle);
    let clustered = Mesh::build_with(parts, crate::geometry::mesh::bvh::clustered);
    let (mut hits, mut blocked) = (0, 0);
    for rays in test_packets(n, &vertices, &mut rnd) {
        for r in &rays {
            let (a, b) = (
                whole.intersect(r, 0.0, f64::INFINITY),
                clustered.intersect(r, 0.0, f64::INFINITY),
            );
            assert_eq!(
                a.map(|h| h.t.to_bits()),
                b.map(|h| h.t.to_bits()),
                "ray {r:?}"
            );
            hits += a.is_some() as usize;
            for limit in [0.5, 5.0, f64::INFINITY] {
                let shadow = whole.occluded(r, 0.0, limit);
                assert_eq!(shadow, clustered.occluded(r, 0.0, limit), "ray {r:?}");
                blocked += shadow as usize;
            }
        }
    }
    assert!(
        hits > 1000 && blocked > 1000,
        "{hits} hits, {blocked} blocked"
    );
    // Short meshes: one cluster of one to four triangles, and more.
    for count in 1..=6 {
        let small = MeshParts {
            triangles: &triangles[..count],
            ..parts
        };
        let (whole, clustered) = (
            Mesh::build_with(small, crate::geometry::mesh::bvh::per_triangle),
            Mesh::build_with(small, crate::geometry::mesh::bvh::clustered),
        );
        for rays in test_packets(n, &vertices, &mut rnd).iter().take(20) {
            for r in rays {
                let t = |m: &Mesh| m.intersect(r, 0.0, f64::INFINITY).map(|h| h.t.to_bits());
                assert_eq!(t(&whole), t(&clustered), "{count} triangles, ray {r:?}");
            }
        }
    }
}

/// Packets of rays as the renderer makes them over [`test_mesh`]'s grid of `n`: from one eye
/// through the grid's vertices and edge midpoints, and from one eye in random directions.
fn test_packets(n: usize, vertices: &[Vec3], rnd: &mut impl FnMut() -> f64) -> Vec<Vec<Ray>> {
    let mut packets: Vec<Vec<Ray>> = Vec::new();
    let size = n as f64;
    for k in 0..60 {
        let eye = DVec3::new(rnd() * size, 6.0 + rnd() * 4.0, rnd() * size);
        let mut rays = Vec::new();
        for r in 0..PACKET {
            let (i, j) = ((k * 5 + r) % (n + 1), (k * 3 + r / 4) % (n + 1));
            let v = vertices[j * (n + 1) + i].as_dvec3();
            // Through a vertex, or the midpoint of an edge to its neighbour.
            let target = match r % 3 {
                0 => v,
                1 => (v + vertices[j * (n + 1) + (i + 1).min(n)].as_dvec3()) * 0.5,
                _ => v + DVec3::new(rnd() - 0.5, 0.0, rnd() - 0.5) * 0.01,
            };
            rays.push(Ray::new(eye, (target - eye).unit()));
        }
        packets.push(rays);
        let spread = 0.05 + rnd();
        let centre = DVec3::new(rnd() - 0.5, -1.0, rnd() - 0.5);
        packets.push(
            (0..PACKET)
                .map(|_| {
                    let d = centre + DVec3::new(rnd() - 0.5, 0.0, rnd() - 0.5) * spread;
                    Ray::new(eye, d.unit())
                })
                .collect(),
        );
    }
    packets
}

/// Each query of each packet equals the one-ray query of each of its rays, bit for bit, and
/// shadow rays from the hits towards a light (some limited short of it) likewise.
fn check_packets(mesh: &Mesh, size: f64, packets: &[Vec<Ray>], rnd: &mut impl FnMut() -> f64) {
    let mut hits_seen = 0;
    for rays in packets {
        for len in [rays.len(), 9, 1] {
            let rays = &rays[..len];
            let t_min: Vec<f64> = rays.iter().map(|_| 0.0).collect();
            let t_max: Vec<f64> = rays.iter().map(|_| f64::INFINITY).collect();
            let mut got = vec![None; len];
            mesh.intersect_packet(rays, &t_min, &t_max, |i, h| got[i] = Some(h));
            for (i, r) in rays.iter().enumerate() {
                let want = mesh.intersect(r, 0.0, f64::INFINITY);
                assert_eq!(bits(&got[i]), bits(&want), "ray {r:?}");
                hits_seen += want.is_some() as usize;
            }
            // Shadow rays from the hit points towards a light, some limited short of it.
            let light = DVec3::new(rnd() * size, 20.0, rnd() * size);
            let mut shadow = Vec::new();
            let mut limit = Vec::new();
            for (r, h) in rays.iter().zip(&got) {
                let Some(h) = h else { continue };
                let p = r.at(h.t) + h.geometric * 1e-4;
                let to = light - p;
                shadow.push(Ray::new(p, to.unit()));
                limit.push(to.norm() * if rnd() < 0.3 { rnd() } else { 1.0 });
            }
            let from: Vec<f64> = shadow.iter().map(|_| 0.0).collect();
            let active = (1u32 << shadow.len()) - 1;
            let occluded = mesh.occluded_packet(&shadow, &from, &limit, active);
            for (i, r) in shadow.iter().enumerate() {
                let want = mesh.occluded(r, 0.0, limit[i]);
                assert_eq!(occluded >> i & 1 == 1, want, "shadow ray {r:?}");
            }
            // A ray left out of the mask is reported unoccluded.
            if shadow.len() > 1 {
                let some = mesh.occluded_packet(&shadow, &from, &limit, active & !1);
                assert_eq!(some & 1, 0);
                assert_eq!(some, occluded & !1);
            }
        }
    }
    assert!(hits_seen > 1000, "{hits_seen}");
}

/// Ties: a packet through a triangle stored twice finds the same one of the two as a ray
/// traced alone (the packet retraces such a ray), and limits per ray are kept.
#[test]
fn ties_and_limits_match_single_rays() {
    let vertices = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(1.0, 0.0, 1.0),
    ];
    // The same triangle five times over (ties in one leaf and across leaves), and another.
    let mut triangles = vec![[0, 1, 2]; 5];
    triangles.push([1, 3, 2]);
    let uvs: Vec<[Vec2; 3]> = (0..triangles.len())
        .map(|k| [Vec2::splat(k as f32); 3])
        .collect();
    let mesh = Mesh::build(MeshParts {
        vertices: &vertices,
        triangles: &triangles,
        normals: &[],
        uvs: &uvs,
        colors: &[],
        material_of: &[],
    });
    let mut rnd = crate::geometry::testing::test_uniform(7);
    for _ in 0..50 {
        let eye = DVec3::new(rnd(), 1.0 + rnd(), rnd());
        let rays: Vec<Ray> = (0..PACKET)
            .map(|_| {
                let target = DVec3::new(rnd(), 0.0, rnd());
                Ray::new(eye, (target - eye).unit())
            })
            .collect();
        let t_min: Vec<f64> = (0..PACKET).map(|k| (k % 3) as f64 * 0.3).collect();
        let t_max: Vec<f64> = (0..PACKET).map(|k| 1.0 + (k % 4) as f64).collect();
        let mut got = vec![None; PACKET];
        mesh.intersect_packet(&rays, &t_min, &t_max, |i, h| {
            assert!(got[i].replace(h).is_none(), "two hits for one ray");
        });
        for (i, r) in rays.iter().enumerate() {
            let want = mesh.intersect(r, t_min[i], t_max[i]);
            assert_eq!(bits(&got[i]), bits(&want));
            assert_eq!(got[i].map(|h| h.uv), want.map(|h| h.uv));
        }
    }
}
