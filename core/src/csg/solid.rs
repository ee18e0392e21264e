//! A ray through a whole solid (thesis §3.3–3.4): its operands' spans combined up the tree by
//! Table 3.1, in one pass over the tree's post-order list with a stack of span lists (no
//! recursion, §3.4.3's bounded depth: preparation checks the stack and the span lists against
//! their capacities, `model::solid_needs_and_box`). Circumstance classification (§3.3.7): when the
//! left operand of `∩` or `−` gives no span, the right operand's subtree is skipped.

use heapless::Vec;

use super::leaf::leaf_spans_into;
use super::spans::{combine_into, Boundary, Span};
use crate::geometry::{Ray, Vector3};
use crate::model::{PreparedSolidNode, NO_SKIP};
use crate::model::{MAX_HELD_SPANS, MAX_SOLID_STACK, MAX_SPANS};
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
///
/// The lists the walk holds are one list, each a run of it (`starts`): a leaf appends its
/// spans, an operation replaces the last two runs by their combination. Nothing is written
/// before it is used, and only spans are copied, never whole lists.
pub fn solid_spans<N: Number, R>(nodes: &[PreparedSolidNode<N>], ray: &Ray<N>, leaf_tests: &mut u64, then: impl FnOnce(&[Span<N>]) -> R) -> Option<R> {
    let mut held: Vec<Span<N>, MAX_HELD_SPANS> = Vec::new();
    let mut starts: Vec<u8, MAX_SOLID_STACK> = Vec::new();
    let mut index = 0;
    while let Some(node) = nodes.get(index) {
        match node {
            PreparedSolidNode::Leaf { object, skip_to } => {
                let start = held.len();
                if *skip_to != NO_SKIP && starts.last().is_some_and(|last| usize::from(*last) == start) {
                    // The left operand of the `∩` or `−` at `skip_to` is empty, so is the result.
                    starts.push(start as u8).ok()?;
                    index = usize::from(*skip_to);
                    continue;
                }
                *leaf_tests += 1;
                let local = object.object_from_world.ray(ray);
                leaf_spans_into(object.primitive, &local, index as u16, &mut held).ok()?;
                starts.push(start as u8).ok()?;
            }
            PreparedSolidNode::Combine(operation) => {
                let right = usize::from(starts.pop()?);
                let left = usize::from(*starts.last()?);
                let mut combined: Vec<Span<N>, MAX_SPANS> = Vec::new();
                let (left_spans, right_spans) = held.get(left..)?.split_at_checked(right.checked_sub(left)?)?;
                if !(left_spans.is_empty() && operation.left_decides_empty()) {
                    combine_into(*operation, left_spans, right_spans, &mut combined).ok()?;
                }
                held.truncate(left);
                held.extend_from_slice(&combined).ok()?;
            }
        }
        index += 1;
    }
    (starts.len() == 1).then(|| then(&held))
}

/// The first boundary of the solid's spans inside `interval`: the ray enters the solid there,
/// or (from inside) leaves it.
pub fn first_hit<N: Number>(nodes: &[PreparedSolidNode<N>], ray: &Ray<N>, interval: Interval<N>, leaf_tests: &mut u64) -> Option<SolidHit<N>> {
    solid_spans(nodes, ray, leaf_tests, |spans| spans.iter().flat_map(|span| [span.enter, span.exit]).find(|boundary| interval.contains(boundary.t)).map(|boundary| surface(&boundary)))?
}

/// Whether any boundary of the solid lies inside `interval` (a shadow ray is blocked by the
/// first one it meets).
pub fn occluded<N: Number>(nodes: &[PreparedSolidNode<N>], ray: &Ray<N>, interval: Interval<N>, leaf_tests: &mut u64) -> bool {
    solid_spans(nodes, ray, leaf_tests, |spans| spans.iter().any(|span| interval.contains(span.enter.t) || interval.contains(span.exit.t))).unwrap_or(false)
}

fn surface<N: Number>(boundary: &Boundary<N>) -> SolidHit<N> {
    let normal = if boundary.flipped { -boundary.normal } else { boundary.normal };
    SolidHit { t: boundary.t, normal, leaf: boundary.leaf }
}

/// The leaves' skips (see `PreparedSolidNode::Leaf`) of a post-order list: for each `∩` or `−`
/// node, the first node of its right operand's subtree jumps to it. `starts` is scratch, one
/// entry per node.
pub fn link_skips<N>(nodes: &mut [PreparedSolidNode<N>]) -> Option<()> {
    // The first node of each result's subtree, as the walk would hold them.
    let mut starts: Vec<usize, { crate::model::MAX_SOLID_NODES }> = Vec::new();
    let mut skips: Vec<(usize, u16), { crate::model::MAX_SOLID_NODES }> = Vec::new();
    for (index, node) in nodes.iter().enumerate() {
        match node {
            PreparedSolidNode::Leaf { .. } => starts.push(index).ok()?,
            PreparedSolidNode::Combine(operation) => {
                let right = starts.pop()?;
                let left = starts.pop()?;
                if operation.left_decides_empty() {
                    skips.push((right, u16::try_from(index).ok()?)).ok()?;
                }
                starts.push(left).ok()?;
            }
        }
    }
    for (leaf, to) in skips {
        if let Some(PreparedSolidNode::Leaf { skip_to, .. }) = nodes.get_mut(leaf) {
            *skip_to = to;
        }
    }
    Some(())
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

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
        solid_spans(nodes, &ray, &mut 0, |spans| spans.iter().map(|span| (span.enter.t, span.exit.t)).collect()).unwrap()
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
}
