//! A ray through a whole solid (thesis §3.3–3.4): its operands' spans combined up the tree by
//! Table 3.1, in one pass over the tree's post-order list with a stack of span lists (no
//! recursion, §3.4.3's bounded depth: preparation checks the stack and the span lists against
//! their capacities, `model::solid_needs_and_box`). Circumstance classification (§3.3.7): when the
//! left operand of `∩` or `−` gives no span, the right operand's subtree is skipped.

use heapless::Vec;

use super::leaf::leaf_spans;
use super::spans::{Boundary, Spans};
use crate::geometry::{Ray, Vector3};
use crate::model::{Object, Operation, MAX_SOLID_STACK, MAX_SPANS};
use crate::number::Number;
use crate::shapes::Interval;

/// No skip from this leaf (see [`SolidNode::Leaf`]).
pub const NO_SKIP: u16 = u16::MAX;

/// One node of a solid prepared in a number type, in post-order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SolidNode<N> {
    /// A primitive operand, prepared as any object. `skip_to`: when this leaf starts the right
    /// operand of a `∩` or `−` node, that node's place in the solid (else [`NO_SKIP`]): if the
    /// left operand's spans are empty there, the walk goes straight to it.
    Leaf { object: Object<N>, skip_to: u16 },
    /// Combines the two span lists on top of the stack.
    Combine(Operation),
}

/// A ray's first surface on a solid: the ray parameter, the surface's normal in its leaf's
/// object space (outward from the solid: a subtracted operand's turned round; not normalised)
/// and the leaf (its place in the solid's nodes), whose transform and material it has.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidHit<N> {
    pub t: N,
    pub normal: Vector3<N>,
    pub leaf: u16,
}

/// The spans of the ray (world space) in the solid whose post-order nodes are `nodes`, adding
/// the primitives tested to `leaf_tests`. `None` when a list or the stack would overflow
/// (preparation rules that out) or the list is not a tree.
pub fn solid_spans<N: Number>(nodes: &[SolidNode<N>], ray: &Ray<N>, leaf_tests: &mut u64) -> Option<Spans<N, MAX_SPANS>> {
    let mut stack: Vec<Spans<N, MAX_SPANS>, MAX_SOLID_STACK> = Vec::new();
    let mut index = 0;
    while let Some(node) = nodes.get(index) {
        match node {
            SolidNode::Leaf { object, skip_to } => {
                if *skip_to != NO_SKIP && stack.last().is_some_and(Spans::is_empty) {
                    // The left operand of the `∩` or `−` at `skip_to` is empty, so is the result.
                    stack.push(Spans::EMPTY).ok()?;
                    index = usize::from(*skip_to);
                    continue;
                }
                *leaf_tests += 1;
                let local = object.object_from_world.ray(ray);
                let spans = leaf_spans(object.primitive, &local, index as u16).ok()?;
                stack.push(Spans::widened(&spans)?).ok()?;
            }
            SolidNode::Combine(operation) => {
                let right = stack.pop()?;
                let left = stack.pop()?;
                let combined = if left.is_empty() && operation.left_decides_empty() { Spans::EMPTY } else { Spans::combine(*operation, &left, &right).ok()? };
                stack.push(combined).ok()?;
            }
        }
        index += 1;
    }
    match stack.as_slice() {
        [spans] => Some(*spans),
        _ => None,
    }
}

/// The first boundary of the solid's spans inside `interval`: the ray enters the solid there,
/// or (from inside) leaves it.
pub fn first_hit<N: Number>(nodes: &[SolidNode<N>], ray: &Ray<N>, interval: Interval<N>, leaf_tests: &mut u64) -> Option<SolidHit<N>> {
    let spans = solid_spans(nodes, ray, leaf_tests)?;
    let boundary = spans.iter().flat_map(|span| [span.enter, span.exit]).find(|boundary| interval.contains(boundary.t))?;
    Some(surface(&boundary))
}

/// Whether any boundary of the solid lies inside `interval` (a shadow ray is blocked by the
/// first one it meets).
pub fn occluded<N: Number>(nodes: &[SolidNode<N>], ray: &Ray<N>, interval: Interval<N>, leaf_tests: &mut u64) -> bool {
    solid_spans(nodes, ray, leaf_tests).is_some_and(|spans| spans.iter().any(|span| interval.contains(span.enter.t) || interval.contains(span.exit.t)))
}

fn surface<N: Number>(boundary: &Boundary<N>) -> SolidHit<N> {
    let normal = if boundary.flipped { -boundary.normal } else { boundary.normal };
    SolidHit { t: boundary.t, normal, leaf: boundary.leaf }
}

/// The leaves' skips (see [`SolidNode::Leaf`]) of a post-order list: for each `∩` or `−`
/// node, the first node of its right operand's subtree jumps to it. `starts` is scratch, one
/// entry per node.
pub fn link_skips<N>(nodes: &mut [SolidNode<N>]) -> Option<()> {
    // The first node of each result's subtree, as the walk would hold them.
    let mut starts: Vec<usize, { crate::model::MAX_SOLID_NODES }> = Vec::new();
    let mut skips: Vec<(usize, u16), { crate::model::MAX_SOLID_NODES }> = Vec::new();
    for (index, node) in nodes.iter().enumerate() {
        match node {
            SolidNode::Leaf { .. } => starts.push(index).ok()?,
            SolidNode::Combine(operation) => {
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
        if let Some(SolidNode::Leaf { skip_to, .. }) = nodes.get_mut(leaf) {
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
        solid_spans(nodes, &ray, &mut 0).unwrap().iter().map(|span| (span.enter.t, span.exit.t)).collect()
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
