//! Tests of the wide BVH (`bvh.rs`): traversal against brute force, blocks, grouping, threads.

use super::*;
use crate::num::Norm;

fn random_boxes(n: usize, seed: u64) -> Vec<BAabb> {
    let mut seed = seed;
    let mut rnd = move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 33) as f32) / (1u64 << 31) as f32
    };
    (0..n)
        .map(|_| {
            let c = Vec3A::new(rnd(), rnd(), rnd()) * 10.0;
            let h = Vec3A::new(rnd(), rnd(), rnd()) * 0.3 + 0.01;
            BAabb::new(c - h, c + h)
        })
        .collect()
}

fn slab(b: &BAabb, o: DVec3, d: DVec3) -> Option<f64> {
    let inv = d.recip();
    let t0 = (b.min.as_dvec3() - o) * inv;
    let t1 = (b.max.as_dvec3() - o) * inv;
    let near = t0.min(t1).max_element().max(0.0);
    let far = t0.max(t1).min_element();
    (near <= far).then_some(near)
}

/// Closest, any and all agree with brute force on random boxes, for several leaf sizes.
#[test]
fn traversals_match_brute_force() {
    // (boxes, obvhs leaf size, rtc's grouping)
    let cases = [
        (1, 1, 1),
        (5, 1, 1),
        (500, 1, 1),
        (500, 4, 1),
        (3000, 8, 1),
        (5, 1, 4),
        (500, 1, 4),
        (3000, 1, 4),
        (3000, 4, 3),
    ];
    for (n, leaf, group) in cases {
        let boxes = random_boxes(n, 7 + n as u64);
        let ids: Vec<u32> = (0..n as u32).collect();
        let params = BvhBuildParams {
            max_prims_per_leaf: leaf,
            ..BvhBuildParams::medium_build()
        };
        let bvh = Bvh::build_grouped(&boxes, ids, params, group);
        check_brute_force(&bvh, &boxes, &format!("n={n} leaf={leaf} group={group}"));
    }
}

/// Trees over Morton clusters (large meshes and worlds) agree with brute force likewise,
/// clusters of one to eight primitives, counts that leave the last cluster short.
#[test]
fn clustered_traversals_match_brute_force() {
    for (n, cluster) in [(1, 4), (3, 4), (5, 1), (500, 4), (501, 3), (3001, 8)] {
        let boxes = random_boxes(n, 11 + n as u64);
        let ids: Vec<u32> = (0..n as u32).collect();
        let bvh =
            Bvh::build_clustered(n, |i| boxes[i], &ids, cluster, BvhBuildParams::fast_build());
        check_brute_force(&bvh, &boxes, &format!("n={n} cluster={cluster}"));
    }
}

/// Every primitive in exactly one slot; closest, any and all agree with brute force.
fn check_brute_force(bvh: &Bvh, boxes: &[BAabb], label: &str) {
    let n = boxes.len();
    assert_eq!(bvh.order.len(), n);
    let mut sorted = bvh.order.clone();
    sorted.sort_unstable();
    assert!(sorted.iter().enumerate().all(|(i, &x)| i as u32 == x));
    let mut seed = 99u64;
    let mut rnd = move || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
        ((seed >> 33) as f64) / (1u64 << 31) as f64
    };
    for _ in 0..300 {
        let o = DVec3::new(-5.0, rnd() * 10.0, rnd() * 10.0);
        let d = DVec3::new(1.0, rnd() - 0.5, rnd() - 0.5).unit();
        let r = BvhRay::new(o, d, 0.0, f64::INFINITY).unwrap();
        let entry = |i: usize| slab(&boxes[i], o, d);
        let want = (0..n).filter_map(entry).fold(f64::INFINITY, f64::min);
        let mut got = f64::INFINITY;
        bvh.closest(&r, |slot, _| match entry(bvh.order[slot] as usize) {
            Some(t) => {
                got = got.min(t);
                t as f32
            }
            None => f32::INFINITY,
        });
        assert_eq!(got, want, "{label}");
        assert_eq!(
            bvh.any(&r, |slot| entry(bvh.order[slot] as usize).is_some()),
            want.is_finite()
        );
        let mut count = 0;
        bvh.all(&r, |slot| {
            count += entry(bvh.order[slot] as usize).is_some() as usize
        });
        assert_eq!(count, (0..n).filter(|&i| entry(i).is_some()).count());
    }
}

/// Laid out in blocks, the tree visits the same primitives in the same order, leaf by
/// leaf, as before (the mesh's nearest hit and its tie-breaking depend on that order); every
/// leaf starts a block and the padding slots map to no primitive.
#[test]
fn blocks_keep_the_visiting_order() {
    for (n, leaf, seed) in [
        (1, 1, 1),
        (7, 4, 2),
        (600, 4, 3),
        (3000, 4, 4),
        (3000, 8, 5),
    ] {
        let boxes = random_boxes(n, seed);
        let params = BvhBuildParams {
            max_prims_per_leaf: leaf,
            ..BvhBuildParams::medium_build()
        };
        let plain = Bvh::build(&boxes, (0..n as u32).collect(), params);
        let blocked = plain.clone().into_blocks();
        let mut ids: Vec<u32> = (blocked.order.iter().copied())
            .filter(|&i| i != u32::MAX)
            .collect();
        ids.sort_unstable();
        assert!(ids.iter().enumerate().all(|(i, &x)| i as u32 == x), "n={n}");
        assert_eq!(blocked.order.len() % BLOCK, 0);
        let mut seed = 17u64;
        let mut rnd = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
            ((seed >> 33) as f64) / (1u64 << 31) as f64
        };
        for _ in 0..200 {
            let o = DVec3::new(-5.0, rnd() * 10.0, rnd() * 10.0);
            let d = DVec3::new(1.0, rnd() - 0.5, rnd() - 0.5).unit();
            let r = BvhRay::new(o, d, 0.0, f64::INFINITY).unwrap();
            // A hit distance per primitive (its box's entry), so t_max shrinks as in a
            // closest-hit search.
            let entry = |i: u32| slab(&boxes[i as usize], o, d).map_or(f32::INFINITY, |t| t as f32);
            let (mut want, mut got) = (Vec::new(), Vec::new());
            plain.closest(&r, |slot, _| {
                want.push(plain.order[slot]);
                entry(plain.order[slot])
            });
            blocked.closest_leaves(&r, |first, count, mut t_max| {
                assert!(count <= MAX_LEAF as usize);
                for slot in first * BLOCK..first * BLOCK + count {
                    got.push(blocked.order[slot]);
                    t_max = t_max.min(entry(blocked.order[slot]));
                }
                t_max
            });
            assert_eq!(got, want, "closest, n={n}");
            let (mut want, mut got) = (Vec::new(), Vec::<u32>::new());
            plain.all(&r, |slot| want.push(plain.order[slot]));
            blocked.any_leaves(&r, |first, count| {
                got.extend(&blocked.order[first * BLOCK..first * BLOCK + count]);
                false
            });
            assert_eq!(got, want, "any, n={n}");
        }
    }
}

/// obvhs builds in parallel; the tree must not depend on the thread count (deterministic
/// output for any `--threads`).
#[test]
fn the_tree_does_not_depend_on_the_thread_count() {
    let boxes = random_boxes(20_000, 5);
    let single = BvhBuildParams {
        max_prims_per_leaf: 1,
        ..BvhBuildParams::very_fast_build()
    };
    let ids: Vec<u32> = (0..20_000).collect();
    // (params, grouping, or 0 for clusters of four)
    for (params, group) in [
        (BvhBuildParams::fast_build(), 1),
        (single, 4),
        (BvhBuildParams::fast_build(), 0),
    ] {
        let build = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| match group {
                0 => Bvh::build_clustered(boxes.len(), |i| boxes[i], &ids, 4, params),
                _ => Bvh::build_grouped(&boxes, ids.clone(), params, group),
            })
        };
        let (a, b) = (build(1), build(3));
        assert_eq!(a.order, b.order);
        assert_eq!(a.nodes.len(), b.nodes.len());
        for (x, y) in a.nodes.iter().zip(&b.nodes) {
            assert_eq!(x.child, y.child);
            assert_eq!(x.planes, y.planes);
        }
    }
}

/// Grouping keeps every primitive once and leaves of at most `group`, in fewer nodes (a
/// third fewer for these overlapping boxes, three quarters fewer for the 1M-sphere grid).
#[test]
fn grouping_shrinks_the_tree() {
    let boxes = random_boxes(20_000, 11);
    let params = BvhBuildParams {
        max_prims_per_leaf: 1,
        ..BvhBuildParams::very_fast_build()
    };
    let single = Bvh::build(&boxes, (0..20_000).collect(), params);
    let grouped = Bvh::build_grouped(&boxes, (0..20_000).collect(), params, 4);
    let mut sorted = grouped.order.clone();
    sorted.sort_unstable();
    assert!(sorted.iter().enumerate().all(|(i, &x)| i as u32 == x));
    let leaves = grouped.nodes.iter().flat_map(|n| n.child);
    let leaves: Vec<_> = leaves.filter(|&c| c != EMPTY && c & LEAF != 0).collect();
    assert!(leaves.iter().all(|&c| leaf_parts(c).1 <= 4));
    assert_eq!(
        leaves.iter().map(|&c| leaf_parts(c).1).sum::<usize>(),
        20_000
    );
    assert!(
        grouped.nodes.len() * 3 < single.nodes.len() * 2,
        "{} grouped nodes vs {} single",
        grouped.nodes.len(),
        single.nodes.len()
    );
}

/// Axis-parallel rays (zero direction components) and negative directions still find boxes.
#[test]
fn axis_parallel_and_backward_rays() {
    let boxes = random_boxes(200, 3);
    let bvh = Bvh::build(&boxes, (0..200).collect(), BvhBuildParams::medium_build());
    for (i, b) in boxes.iter().enumerate() {
        let c = b.center().as_dvec3();
        for d in [
            DVec3::X,
            -DVec3::X,
            DVec3::Y,
            -DVec3::Y,
            DVec3::Z,
            -DVec3::Z,
        ] {
            let o = c - 20.0 * d;
            let r = BvhRay::new(o, d, 0.0, f64::INFINITY).unwrap();
            let mut seen = false;
            bvh.all(&r, |slot| seen |= bvh.order[slot] as usize == i);
            assert!(seen, "box {i} along {d}");
            let r = BvhRay::new(o, -d, 0.0, f64::INFINITY).unwrap();
            let mut behind = false;
            bvh.all(&r, |slot| behind |= bvh.order[slot] as usize == i);
            assert!(!behind, "box {i} behind a ray along {}", -d);
        }
    }
}

/// Packets offer each ray exactly the leaves it meets alone, and find the same nearest
/// distance and the same any-hit answers: coherent packets (one origin, close directions,
/// some straddling an axis so their signs differ), packets of nearby origins, and packets of
/// unrelated rays, with per-ray limits.
#[test]
fn packets_match_single_rays() {
    use crate::geometry::bvh::packet::PACKET;
    use std::collections::BTreeSet;
    let boxes = random_boxes(3000, 21);
    let params = BvhBuildParams {
        max_prims_per_leaf: 4,
        ..BvhBuildParams::medium_build()
    };
    let bvh = Bvh::build(&boxes, (0..3000).collect(), params).into_blocks();
    let mut rnd = crate::geometry::testing::test_uniform(5);
    // The leaf's nearest box entry, as a hit distance for the closest-hit search.
    let hit = |first: usize, count: usize, o: DVec3, d: DVec3| {
        (first * BLOCK..first * BLOCK + count)
            .filter_map(|s| slab(&boxes[bvh.order[s] as usize], o, d))
            .fold(f32::INFINITY, |m, t| m.min(t as f32))
    };
    for k in 0..300 {
        let eye = DVec3::new(-5.0, rnd() * 10.0, rnd() * 10.0);
        let centre = DVec3::new(1.0, rnd() - 0.5, rnd() - 0.5);
        let spread = [0.001, 0.05, 1.0][k % 3];
        let rays: Vec<(DVec3, DVec3, f64)> = (0..PACKET)
            .map(|_| {
                let o = match k % 4 {
                    0 | 1 => eye,
                    2 => eye + DVec3::new(rnd(), rnd(), rnd()) * 0.1,
                    _ => DVec3::new(rnd(), rnd(), rnd()) * 10.0,
                };
                let mut d = centre + DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5) * spread;
                if k % 4 == 3 {
                    d = DVec3::new(rnd() - 0.5, rnd() - 0.5, rnd() - 0.5);
                }
                // Straddling the y axis: some rays go up, some down.
                if k % 5 == 0 {
                    d.y = (rnd() - 0.5) * 1e-3;
                }
                let t_max = if rnd() < 0.3 {
                    rnd() * 12.0
                } else {
                    f64::INFINITY
                };
                (o, d.unit(), t_max)
            })
            .collect();
        let bvh_rays: Vec<BvhRay> = rays
            .iter()
            .map(|&(o, d, t)| BvhRay::new(o, d, 0.0, t).unwrap())
            .collect();
        let active = ((1u32 << PACKET) - 1) & !(1 << (k % PACKET));
        // Every leaf offered, per ray.
        let mut offered = vec![BTreeSet::new(); PACKET];
        let none = bvh.any_leaves_packet(&bvh_rays, active, |r, first, count| {
            assert!(offered[r].insert((first, count)), "a leaf offered twice");
            false
        });
        assert_eq!(none, 0);
        let mut far = [0.0; PACKET];
        for (f, r) in far.iter_mut().zip(&bvh_rays) {
            *f = r.t_max;
        }
        bvh.closest_leaves_packet(&bvh_rays, active, &mut far, |r, first, count, t_max| {
            t_max.min(hit(first, count, rays[r].0, rays[r].1))
        });
        // Rays that stop at the first leaf holding an even primitive.
        let even = |first: usize, count: usize| {
            (first * BLOCK..first * BLOCK + count).any(|s| bvh.order[s].is_multiple_of(2))
        };
        let stopped =
            bvh.any_leaves_packet(&bvh_rays, active, |_, first, count| even(first, count));
        for (r, br) in bvh_rays.iter().enumerate() {
            let (o, d, _) = rays[r];
            if active >> r & 1 == 0 {
                assert!(offered[r].is_empty());
                assert_eq!(stopped >> r & 1, 0);
                continue;
            }
            let mut alone = BTreeSet::new();
            bvh.any_leaves(br, |first, count| {
                alone.insert((first, count));
                false
            });
            assert_eq!(offered[r], alone, "packet {k} ray {r}");
            let mut want = br.t_max;
            bvh.closest_leaves(br, |first, count, t_max| {
                want = t_max.min(hit(first, count, o, d));
                want
            });
            assert_eq!(far[r].to_bits(), want.to_bits(), "packet {k} ray {r}");
            assert_eq!(stopped >> r & 1 == 1, bvh.any_leaves(br, even));
        }
    }
}

/// The depth of the wide tree (a chain of one node per level when the builder cannot pair).
fn depth(bvh: &Bvh) -> usize {
    let mut deepest = 0;
    let mut stack = vec![(0usize, 1usize)];
    while let Some((n, d)) = stack.pop() {
        deepest = deepest.max(d);
        for &c in &bvh.nodes[n].child {
            if c != EMPTY && c & LEAF == 0 {
                stack.push((c as usize, d + 1));
            }
        }
    }
    deepest
}

/// Thousands of bit-identical boxes among ordinary ones (the same OBJ face repeated, issue 35)
/// build a shallow tree, one leaf per few copies, and every traversal still agrees with brute
/// force, whether built per primitive, grouped or over clusters. Before ties were spliced the
/// builder paired one couple of copies per pass: a chain as deep as the copies were many.
#[test]
fn identical_boxes_build_a_balanced_tree() {
    let mut boxes = random_boxes(300, 5);
    let copy = boxes[7];
    boxes.extend(std::iter::repeat_n(copy, 5000));
    boxes.extend(std::iter::repeat_n(boxes[11], 300));
    boxes.extend(random_boxes(300, 6));
    let n = boxes.len();
    let ids: Vec<u32> = (0..n as u32).collect();
    let medium = BvhBuildParams {
        max_prims_per_leaf: 4,
        ..BvhBuildParams::medium_build()
    };
    let plain = Bvh::build(&boxes, ids.clone(), medium);
    let grouped = Bvh::build_grouped(&boxes, ids.clone(), BvhBuildParams::fast_build(), 4);
    let clustered = Bvh::build_clustered(n, |i| boxes[i], &ids, 4, BvhBuildParams::fast_build());
    for (bvh, label) in [
        (&plain, "plain"),
        (&grouped, "grouped"),
        (&clustered, "clustered"),
    ] {
        check_brute_force(bvh, &boxes, label);
        // log₈ of the 5,000 copies in leaves of four is 4 levels; the rest adds a few.
        assert!(depth(bvh) <= 16, "{label}: depth {}", depth(bvh));
    }
}
