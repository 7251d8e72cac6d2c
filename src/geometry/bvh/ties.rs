//! Many primitives with exactly the same box: built as one, then spliced back in.
//!
//! Why: PLOC merges two nodes only when each is the other's nearest neighbour, and among equal
//! boxes every candidate is equally near, so obvhs's tie rule (the last of equals) pairs almost
//! nothing: each pass over the whole list merges about one pair of a group, and k copies cost
//! k passes. 33,334 copies of one OBJ face took 26 s to build (issue 35). A group of identical
//! boxes has only one sensible tree anyway (any split leaves both halves with the same box), so
//! the builder sees one representative per large group, and the group's members become a
//! balanced subtree of full leaves where the representative's leaf was. The boxes the tree
//! holds are still unions of its primitives' boxes, so every ray is offered the same
//! primitives as before; scenes without a large group build exactly the tree they did.

use std::collections::HashMap;

use obvhs::aabb::Aabb as BAabb;
use obvhs::bvh2::Bvh2;
use obvhs::bvh2::node::Bvh2Node;
use rayon::prelude::*;

/// Groups of identical boxes up to this size go to the builder as they are: their cost is
/// about size² node tests over all passes, negligible here, and leaving them keeps the trees
/// of ordinary scenes (which may repeat a face or an object a few times) exactly as they were.
pub(super) const TIE_GROUP: usize = 64;

/// The large groups of identical boxes in a list, and what the builder sees instead.
pub(super) struct Ties {
    /// For each box the builder sees, the index of the original box it stands for.
    kept: Vec<u32>,
    /// The members of each large group (all with the same box, the first its
    /// representative), by representative.
    groups: HashMap<u32, Vec<u32>>,
}

/// The large groups of `boxes` (more than [`TIE_GROUP`] bit-identical boxes), or `None` when
/// there are none (the usual case: the caller builds as before).
pub(super) fn find(boxes: &[BAabb]) -> Option<Ties> {
    if boxes.len() <= TIE_GROUP {
        return None;
    }
    // Sort by a hash of the box's bits (ties by index, so groups list members in order), then
    // split runs of equal hash by exact equality: a hash collision never groups unequal boxes.
    let mut keys: Vec<(u64, u32)> = boxes
        .par_iter()
        .enumerate()
        .map(|(i, b)| (box_hash(b), i as u32))
        .collect();
    keys.par_sort_unstable();
    let mut groups: HashMap<u32, Vec<u32>> = HashMap::new();
    for run in keys.chunk_by(|a, b| a.0 == b.0) {
        if run.len() <= TIE_GROUP {
            continue;
        }
        let mut members: Vec<u32> = run.iter().map(|k| k.1).collect();
        members.sort_by_key(|&i| (box_bits(&boxes[i as usize]), i));
        for same in
            members.chunk_by(|&a, &b| box_bits(&boxes[a as usize]) == box_bits(&boxes[b as usize]))
        {
            if same.len() > TIE_GROUP {
                groups.insert(same[0], same.to_vec());
            }
        }
    }
    if groups.is_empty() {
        return None;
    }
    let dropped: std::collections::HashSet<u32> = groups
        .values()
        .flat_map(|m| m[1..].iter().copied())
        .collect();
    let kept = (0..boxes.len() as u32)
        .filter(|i| !dropped.contains(i))
        .collect();
    Some(Ties { kept, groups })
}

impl Ties {
    /// The boxes the builder sees: one per kept index.
    pub(crate) fn builder_boxes(&self, boxes: &[BAabb]) -> Vec<BAabb> {
        self.kept.iter().map(|&i| boxes[i as usize]).collect()
    }

    /// Turns a tree built over [`Ties::builder_boxes`] into one over every original box:
    /// primitive indices become original indices, and a leaf holding a representative holds
    /// its whole group, split into a balanced subtree of leaves of at most `max_leaf` when it
    /// no longer fits one.
    pub(crate) fn splice(&self, bvh2: &mut Bvh2, boxes: &[BAabb], max_leaf: u32) {
        let max_leaf = max_leaf.max(1) as usize;
        let mut prims: Vec<u32> = Vec::with_capacity(boxes.len());
        let mut members: Vec<u32> = Vec::new();
        for k in 0..bvh2.nodes.len() {
            let node = bvh2.nodes[k];
            if !node.is_leaf() {
                continue;
            }
            members.clear();
            let first = node.first_index as usize;
            for &p in &bvh2.primitive_indices[first..first + node.prim_count as usize] {
                let original = self.kept[p as usize];
                match self.groups.get(&original) {
                    Some(group) => members.extend_from_slice(group),
                    None => members.push(original),
                }
            }
            bvh2.nodes[k] = if members.len() <= max_leaf {
                leaf_node(&members, boxes, &mut prims)
            } else {
                let chunks: Vec<&[u32]> = members.chunks(max_leaf).collect();
                subtree(&chunks, boxes, &mut prims, &mut bvh2.nodes)
            };
        }
        bvh2.primitive_indices = prims;
    }
}

/// A leaf over `members` (original indices, appended to `prims`).
fn leaf_node(members: &[u32], boxes: &[BAabb], prims: &mut Vec<u32>) -> Bvh2Node {
    let first = prims.len() as u32;
    prims.extend_from_slice(members);
    let aabb = members
        .iter()
        .fold(BAabb::empty(), |a, &i| a.union(&boxes[i as usize]));
    Bvh2Node::new(aabb, members.len() as u32, first)
}

/// A balanced binary subtree over `chunks` (one leaf each), its inner nodes' children appended
/// to `nodes` side by side as the tree layout requires; returns its root, for the caller to
/// place. Depth is log₂ of the chunk count.
fn subtree(
    chunks: &[&[u32]],
    boxes: &[BAabb],
    prims: &mut Vec<u32>,
    nodes: &mut Vec<Bvh2Node>,
) -> Bvh2Node {
    if let [one] = chunks {
        return leaf_node(one, boxes, prims);
    }
    let (lo, hi) = chunks.split_at(chunks.len() / 2);
    let left = subtree(lo, boxes, prims, nodes);
    let right = subtree(hi, boxes, prims, nodes);
    let first = nodes.len() as u32;
    let aabb = left.aabb().union(right.aabb());
    nodes.extend([left, right]);
    Bvh2Node::new(aabb, 0, first)
}

/// The bit patterns of a box's corners: equal exactly when the boxes are bit-identical.
fn box_bits(b: &BAabb) -> [u32; 6] {
    let (lo, hi) = (b.min.to_array(), b.max.to_array());
    [lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]].map(f32::to_bits)
}

/// A 64-bit mix of [`box_bits`] (FxHash's constant and rotation: fast, good enough to sort by).
fn box_hash(b: &BAabb) -> u64 {
    box_bits(b).iter().fold(0u64, |h, &x| {
        (h.rotate_left(5) ^ u64::from(x)).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3A;

    fn unit(x: f32) -> BAabb {
        BAabb::new(Vec3A::new(x, 0.0, 0.0), Vec3A::new(x + 1.0, 1.0, 1.0))
    }

    /// Only groups above the threshold are found, with their members in index order.
    #[test]
    fn finds_only_large_groups_of_identical_boxes() {
        let mut boxes: Vec<BAabb> = (0..100).map(|i| unit(i as f32 * 3.0)).collect();
        boxes.extend((0..TIE_GROUP).map(|_| unit(500.0)));
        assert!(find(&boxes).is_none(), "{TIE_GROUP} copies are left alone");
        boxes.extend((0..5).map(|_| unit(700.0)));
        boxes.push(unit(500.0));
        let ties = find(&boxes).expect("a group above the threshold");
        assert_eq!(ties.groups.len(), 1);
        let group = &ties.groups[&100];
        assert_eq!(group.len(), TIE_GROUP + 1);
        assert_eq!(group.last(), Some(&(boxes.len() as u32 - 1)));
        assert!(
            group.windows(2).all(|w| w[0] < w[1]),
            "members in index order"
        );
        assert_eq!(ties.kept.len(), boxes.len() - TIE_GROUP);
    }
}
