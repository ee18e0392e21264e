//! A ray through a whole solid (thesis §3.3–3.4): its operands' spans combined up the tree by
//! Table 3.1, in one pass over the tree's post-order list with a stack of span lists (no
//! recursion, §3.4.3's bounded depth: preparation checks the stack and the span lists against
//! their capacities, `model::solid_needs_and_box`). Circumstance classification (§3.3.7): when the
//! left operand of `∩` or `−` gives no span, the right operand's subtree is skipped.

use heapless::Vec;

use super::leaf::leaf_spans_into;
use super::spans::{combine_into, Boundary, Span};
use crate::geometry::{Ray, Vector3};
use crate::model::{Extent, PreparedSolidNode, NO_SKIP};
use crate::config::SolidStorage;
use crate::storage::List;
use crate::number::Number;
use crate::shapes::Interval;

/// A ray's first surface on a solid: the ray parameter, the surface's normal in its leaf's
/// object space (outward from the solid: a subtracted operand's turned round; not normalised)
/// and the leaf (its place in the solid's nodes), whose transform and material it has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidHit<N> {
    pub t: N,
    pub normal: Vector3<N>,
    pub leaf: u16,
}

/// The spans of the ray (world space) in the solid whose post-order nodes are `nodes`, handed
/// to `then` (whose result it returns), adding the primitives tested to `leaf_tests`. `None`
/// when the lists would overflow (preparation rules that out) or the list is not a tree.
/// `prune(extent)`: whether the ray cannot meet a part of the solid with that screen extent (a
/// primary ray outside it, §3.3.6); such a part gives no spans and is not walked.
///
/// The lists the walk holds are one list, each a run of it (`starts`): a leaf appends its
/// spans, an operation replaces the last two runs by their combination. Nothing is written
/// before it is used, and only spans are copied, never whole lists.
pub fn solid_spans<N: Number, S: SolidStorage<N>, R>(
    nodes: &[PreparedSolidNode<N>],
    ray: &Ray<N>,
    prune: impl Fn(&Extent) -> bool,
    leaf_tests: &mut u64,
    then: impl FnOnce(&[Span<N>]) -> R,
) -> Option<R> {
    let mut held = S::HeldSpans::<Span<N>>::default();
    let mut starts = S::Lists::<u8>::default();
    let mut index = 0;
    while let Some(node) = nodes.get(index) {
        match node {
            PreparedSolidNode::Leaf { object, skip_to, top, .. } => {
                let start = held.len();
                if *skip_to != NO_SKIP && starts.last().is_some_and(|last| usize::from(*last) == start) {
                    // The left operand of the `∩` or `−` at `skip_to` is empty, so is the result.
                    starts.push(start as u8).ok()?;
                    index = usize::from(*skip_to);
                    continue;
                }
                if let Some(root) = pruned_subtree(nodes, index, usize::from(*top), &prune) {
                    // The whole subtree from this leaf to `root` is off the ray: no spans.
                    starts.push(start as u8).ok()?;
                    index = root + 1;
                    continue;
                }
                *leaf_tests += 1;
                let local = object.object_from_world.ray(ray);
                leaf_spans_into(object.primitive, &local, index as u16, &mut held).ok()?;
                starts.push(start as u8).ok()?;
            }
            PreparedSolidNode::Combine { operation, .. } => {
                let right = usize::from(starts.pop()?);
                let left = usize::from(*starts.last()?);
                let mut combined = S::Spans::<Span<N>>::default();
                let (left_spans, right_spans) = held.get(left..)?.split_at_checked(right.checked_sub(left)?)?;
                if !(left_spans.is_empty() && operation.left_decides_empty()) {
                    combine_into(*operation, left_spans, right_spans, &mut combined).ok()?;
                }
                held.truncate(left);
                for span in combined.iter() {
                    held.push(*span).ok()?;
                }
            }
        }
        index += 1;
    }
    (starts.len() == 1).then(|| then(&held))
}

/// The largest subtree that starts with the leaf at `leaf` and that `prune` rules out: its
/// root's place. The subtrees starting there are a chain from `top` down the left operands to
/// the leaf, tried from the largest; each node's extent is asked once per walk.
#[inline]
fn pruned_subtree<N>(nodes: &[PreparedSolidNode<N>], leaf: usize, top: usize, prune: &impl Fn(&Extent) -> bool) -> Option<usize> {
    let mut root = top;
    loop {
        let node = nodes.get(root)?;
        if prune(node.extent()) {
            return Some(root);
        }
        match node {
            PreparedSolidNode::Combine { left, .. } if root > leaf => root = usize::from(*left),
            _ => return None,
        }
    }
}

/// The first boundary of the solid's spans inside `interval`: the ray enters the solid there,
/// or (from inside) leaves it.
pub fn first_hit<N: Number, S: SolidStorage<N>>(nodes: &[PreparedSolidNode<N>], ray: &Ray<N>, interval: Interval<N>, prune: impl Fn(&Extent) -> bool, leaf_tests: &mut u64) -> Option<SolidHit<N>> {
    solid_spans::<N, S, _>(nodes, ray, prune, leaf_tests, |spans| spans.iter().flat_map(|span| [span.enter, span.exit]).find(|boundary| interval.contains(boundary.t)).map(|boundary| surface(&boundary)))?
}

/// Whether any boundary of the solid lies inside `interval` (a shadow ray is blocked by the
/// first one it meets).
pub fn occluded<N: Number, S: SolidStorage<N>>(nodes: &[PreparedSolidNode<N>], ray: &Ray<N>, interval: Interval<N>, leaf_tests: &mut u64) -> bool {
    solid_spans::<N, S, _>(nodes, ray, |_| false, leaf_tests, |spans| spans.iter().any(|span| interval.contains(span.enter.t) || interval.contains(span.exit.t))).unwrap_or(false)
}

fn surface<N: Number>(boundary: &Boundary<N>) -> SolidHit<N> {
    let normal = if boundary.flipped { -boundary.normal } else { boundary.normal };
    SolidHit { t: boundary.t, normal, leaf: boundary.leaf }
}

/// Links a post-order list's nodes (see [`PreparedSolidNode`]): each leaf's skip (for each
/// `∩` or `−` node, the first node of its right operand's subtree jumps to it) and its `top`,
/// each operation's left operand. `None` unless the list is one tree within the capacity.
pub fn link_nodes<N>(nodes: &mut [PreparedSolidNode<N>]) -> Option<()> {
    const NODES: usize = crate::model::MAX_SOLID_NODES;
    if nodes.len() > NODES {
        return None;
    }
    // Each result the walk would hold: its subtree's first node and its root.
    let mut held: Vec<(u16, u16), NODES> = Vec::new();
    let (mut skips, mut tops, mut lefts) = ([NO_SKIP; NODES], [0u16; NODES], [0u16; NODES]);
    for (index, node) in nodes.iter().enumerate() {
        let place = u16::try_from(index).ok()?;
        match node {
            PreparedSolidNode::Leaf { .. } => {
                *tops.get_mut(index)? = place;
                held.push((place, place)).ok()?;
            }
            PreparedSolidNode::Combine { operation, .. } => {
                let (right_first, _) = held.pop()?;
                let (left_first, left_root) = held.pop()?;
                if operation.left_decides_empty() {
                    *skips.get_mut(usize::from(right_first))? = place;
                }
                *lefts.get_mut(index)? = left_root;
                // Ancestors come later in post-order: the last written is the highest.
                *tops.get_mut(usize::from(left_first))? = place;
                held.push((left_first, place)).ok()?;
            }
        }
    }
    if held.len() != 1 {
        return None;
    }
    for (index, node) in nodes.iter_mut().enumerate() {
        match node {
            PreparedSolidNode::Leaf { skip_to, top, .. } => (*skip_to, *top) = (*skips.get(index)?, *tops.get(index)?),
            PreparedSolidNode::Combine { left, .. } => *left = *lefts.get(index)?,
        }
    }
    Some(())
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::string::String;
    use std::vec::Vec;
    use std::format;

    use super::*;
    use crate::model::SolidRange;
    use crate::parser::parse;
    use crate::scene::Scene;

    /// The spans (enter, exit) of a ray in the first object of `text`, a solid.
    fn spans_of(text: &str, origin: [f64; 3], direction: [f64; 3]) -> Vec<(f64, f64)> {
        let description = parse::<4>(text.as_bytes()).unwrap();
        let scene = Scene::<f64, 4>::prepare(&description).unwrap();
        let nodes = scene.solid(scene.objects[0].primitive);
        assert!(matches!(scene.objects[0].primitive, crate::model::Primitive::Solid(SolidRange { first: 0, .. })));
        let ray = Ray { origin: Vector3::from_f64(origin), direction: Vector3::from_f64(direction) };
        solid_spans::<_, heapless::Vec<PreparedSolidNode<f64>, 8>, _>(nodes, &ray, |_| false, &mut 0, |spans| spans.iter().map(|span| (span.enter.t, span.exit.t)).collect()).unwrap()
    }

    #[test]
    fn a_lens_is_where_both_spheres_are() {
        let lens = "intersection\n sphere\n  scale 60 60 60\n  translate 0 0 -50\n sphere\n  scale 60 60 60\n  translate 0 0 50\nend\n";
        let found = spans_of(lens, [0.0, 0.0, 100.0], [0.0, 0.0, -1.0]);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!((found[0].0 - 90.0).abs() < 1e-9 && (found[0].1 - 110.0).abs() < 1e-9, "{found:?}");
        // Off the axis beyond the lens's rim (radius √(60² − 50²) = 33.2): nothing.
        assert!(spans_of(lens, [40.0, 0.0, 100.0], [0.0, 0.0, -1.0]).is_empty());
    }

    #[test]
    fn a_difference_leaves_a_hole() {
        let drilled = "difference\n cube\n  scale 10 10 10\n cylinder\n  scale 2 2 20\n  translate 5 5 -5\nend\n";
        let found = spans_of(drilled, [-5.0, 5.0, 5.0], [1.0, 0.0, 0.0]);
        assert_eq!(found, [(5.0, 8.0), (12.0, 15.0)]);
        assert!(spans_of(drilled, [5.0, 5.0, 50.0], [0.0, 0.0, -1.0]).is_empty());
    }

    /// `(A ∪ B) − C`'s nodes with each node's extent marked by its place (in `first_column`).
    fn marked_nodes() -> Vec<PreparedSolidNode<f64>> {
        let text = "difference\n union\n  sphere\n  sphere\n   translate 3 0 0\n end\n sphere\n  translate 0 0 1\nend\n";
        let description = parse::<4>(text.as_bytes()).unwrap();
        let scene = Scene::<f64, 4>::prepare(&description).unwrap();
        let mut nodes = scene.solid(scene.objects[0].primitive).to_vec();
        for (place, node) in nodes.iter_mut().enumerate() {
            let (PreparedSolidNode::Leaf { extent, .. } | PreparedSolidNode::Combine { extent, .. }) = node;
            extent.first_column = place as u16;
        }
        nodes
    }

    #[test]
    fn the_nodes_are_linked_for_skips_and_pruning() {
        let nodes = marked_nodes();
        let links: Vec<String> = nodes
            .iter()
            .map(|node| match node {
                PreparedSolidNode::Leaf { skip_to, top, .. } => format!("leaf skip {skip_to} top {top}"),
                PreparedSolidNode::Combine { operation, left, .. } => format!("{} left {left}", operation.name()),
            })
            .collect();
        let no = NO_SKIP;
        assert_eq!(links, [format!("leaf skip {no} top 4"), format!("leaf skip {no} top 1"), "union left 0".into(), "leaf skip 4 top 3".into(), "difference left 2".into()]);
    }

    #[test]
    fn a_pruned_part_is_not_walked() {
        let nodes = marked_nodes();
        // Along x through both spheres of the union, below the subtracted one.
        let ray = Ray { origin: Vector3::from_f64([-5.0, 0.0, -0.5]), direction: Vector3::from_f64([1.0, 0.0, 0.0]) };
        let walk = |pruned: &[u16]| {
            let mut tests = 0;
            let spans = solid_spans::<_, heapless::Vec<PreparedSolidNode<f64>, 8>, _>(&nodes, &ray, |extent| pruned.contains(&extent.first_column), &mut tests, |spans| spans.len()).unwrap();
            (spans, tests)
        };
        assert_eq!(walk(&[]), (2, 3));
        // The second sphere off the ray: one span, that sphere untested.
        assert_eq!(walk(&[1]), (1, 2));
        // The union off the ray: the difference is empty, the subtracted sphere skipped too.
        assert_eq!(walk(&[2]), (0, 0));
        assert_eq!(walk(&[4]), (0, 0));
    }
}
