//! Solids of constructive solid geometry as written (thesis chapter 3, §3.2; the format's
//! `union` / `intersection` / `difference` … `end`): a tree of primitives under the set
//! operations of Table 3.1, kept as a list in post-order (each operand before the operation that
//! combines it), so that a ray's spans are made by one pass with a stack and no recursion
//! (`csg::solid`). An operation of more than two operands is written as a chain of binary ones:
//! `difference A B C` is `(A − B) − C`.
//!
//! A solid is one object of the scene ([`Primitive::Solid`](super::Primitive::Solid)): to the
//! optimizations it is its enclosure, a box (§3.3.6), and its operands are the scene's
//! [`SolidNode`]s in the range it names.

use super::extent::Extent;
use super::object::Object;
use super::object_description::ObjectDescription;
use super::primitive::Primitive;
use super::{SceneError, SceneErrorKind};
use crate::geometry::Matrix4;

/// The set operations of Table 3.1: a ray is in `A ∪ B` where it is in either, in `A ∩ B` where
/// it is in both, in `A − B` where it is in `A` and not in `B`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operation {
    Union,
    Intersection,
    Difference,
}

impl Operation {
    /// The keywords that open a solid, in the enum's order.
    pub const ALL: [Operation; 3] = [Operation::Union, Operation::Intersection, Operation::Difference];

    pub const fn name(self) -> &'static str {
        match self {
            Operation::Union => "union",
            Operation::Intersection => "intersection",
            Operation::Difference => "difference",
        }
    }

    /// Whether a ray is in the result, from whether it is in each operand.
    pub const fn inside(self, in_left: bool, in_right: bool) -> bool {
        match self {
            Operation::Union => in_left || in_right,
            Operation::Intersection => in_left && in_right,
            Operation::Difference => in_left && !in_right,
        }
    }

    /// Whether the right operand can be skipped when the ray misses the left one (§3.3.7,
    /// circumstance classification): for `∩` and `−` the result is then empty.
    pub const fn left_decides_empty(self) -> bool {
        !matches!(self, Operation::Union)
    }

    /// The most spans a ray can have in the result, given the most in each operand: a union or
    /// a difference may add one span per span of the right operand, an intersection one fewer.
    pub const fn spans_bound(self, left: usize, right: usize) -> usize {
        match self {
            Operation::Intersection => {
                let sum = left + right;
                if sum == 0 {
                    0
                } else {
                    sum - 1
                }
            }
            Operation::Union | Operation::Difference => left + right,
        }
    }
}

/// The most nodes (primitives and operations) all of a scene's solids hold together.
pub const MAX_SOLID_NODES: usize = 64;
/// The most spans a ray may have in a solid or any part of it: each span list is this long.
pub const MAX_SPANS: usize = 8;
/// The most span lists the post-order walk keeps at once (the deepest chain of right operands,
/// plus one).
pub const MAX_SOLID_STACK: usize = 8;
/// The most spans the walk's lists hold together at any moment (they share one list).
pub const MAX_HELD_SPANS: usize = 24;

/// One node of a solid's tree in post-order (a list of them lives in the description, so the
/// size of the larger variant costs nothing per node beyond the list's).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SolidNode {
    /// A primitive operand: its transform (with every enclosing solid's composed on top) and
    /// its material (its own if it set one, else the nearest enclosing solid's).
    Leaf(ObjectDescription),
    /// Combines the two results before it: the left operand's, then the right one's.
    Combine { operation: Operation, line: u32 },
}

/// No skip from this leaf (see [`PreparedSolidNode::Leaf`]).
pub const NO_SKIP: u16 = u16::MAX;

/// One node of a solid prepared in a number type, in post-order (`csg::solid` walks them).
/// Each has its screen extent (§3.3.6: a primary ray through a pixel outside it cannot meet
/// the node's part of the solid; [`Extent::EVERYWHERE`] until the view is known).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PreparedSolidNode<N> {
    /// A primitive operand, prepared as any object. `skip_to`: when this leaf starts the right
    /// operand of a `∩` or `−` node, that node's place in the solid (else [`NO_SKIP`]): if the
    /// left operand's spans are empty there, the walk goes straight to it (§3.3.7). `top`: the
    /// highest node whose subtree starts with this leaf (the leaf's own place if none), where a
    /// pixel's pruning starts.
    Leaf { object: Object<N>, skip_to: u16, top: u16, extent: Extent },
    /// Combines the two span lists on top of the walk's stack; `left` is the left operand's
    /// place (the right one's is just before this node).
    Combine { operation: Operation, left: u16, extent: Extent },
}

impl<N> PreparedSolidNode<N> {
    /// The node's screen extent.
    #[inline]
    pub fn extent(&self) -> &Extent {
        match self {
            PreparedSolidNode::Leaf { extent, .. } | PreparedSolidNode::Combine { extent, .. } => extent,
        }
    }
}

/// What a tree needs to be walked: the most spans along a ray at its root and in any part, and
/// the most span lists the walk holds at once.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct SolidNeeds {
    pub spans: usize,
    pub stack: usize,
    /// The most spans the lists held at once may have together.
    pub held: usize,
}

/// [`SolidNeeds`] of the post-order `nodes` (one solid's), and the box (in world space, as each
/// leaf's transform says) that encloses the solid: the union of the operands' boxes for `∪`,
/// their intersection for `∩`, the left one's for `−` (§3.3.6). `None` if the list is not one
/// whole tree.
pub fn solid_needs_and_box(nodes: &[SolidNode]) -> Option<(SolidNeeds, [[f64; 3]; 2])> {
    let mut needs = SolidNeeds::default();
    let mut root = None;
    walk_boxes(nodes, |enclosure, held| {
        needs.spans = needs.spans.max(held.last().copied().unwrap_or(0));
        needs.stack = needs.stack.max(held.len());
        needs.held = needs.held.max(held.iter().sum());
        root = Some(enclosure);
    })?;
    Some((needs, root?))
}

/// Each node's box in world space, in post-order, handed to `each` with whether the node is a
/// leaf: a leaf's is its own, an operation's its operands' combined as §3.3.6 combines screen
/// boxes (the simulator's overlay draws them). `None` if the list is not one whole tree.
pub fn for_each_node_box(nodes: &[SolidNode], mut each: impl FnMut(bool, [[f64; 3]; 2])) -> Option<()> {
    let mut index = 0;
    walk_boxes(nodes, |enclosure, _| {
        each(matches!(nodes.get(index), Some(SolidNode::Leaf(_))), enclosure);
        index += 1;
    })
}

/// The walk of a tree's boxes: after each node, `after(its box, the most spans of each list
/// held)`; `None` unless the list is one whole tree.
fn walk_boxes(nodes: &[SolidNode], mut after: impl FnMut([[f64; 3]; 2], &[usize])) -> Option<()> {
    // The box and the most spans of each result the walk holds.
    let mut stack: heapless::Vec<[[f64; 3]; 2], MAX_SOLID_NODES> = heapless::Vec::new();
    let mut spans: heapless::Vec<usize, MAX_SOLID_NODES> = heapless::Vec::new();
    for node in nodes {
        match node {
            SolidNode::Leaf(leaf) => {
                let count = if matches!(leaf.primitive, Primitive::Torus(_)) { 2 } else { 1 };
                stack.push(leaf.world_box()).ok()?;
                spans.push(count).ok()?;
            }
            SolidNode::Combine { operation, .. } => {
                let (right, left) = (stack.pop()?, stack.pop()?);
                let (right_spans, left_spans) = (spans.pop()?, spans.pop()?);
                let enclosure = match operation {
                    Operation::Union => [min3(left[0], right[0]), max3(left[1], right[1])],
                    Operation::Intersection => [max3(left[0], right[0]), min3(left[1], right[1])],
                    Operation::Difference => left,
                };
                stack.push(enclosure).ok()?;
                spans.push(operation.spans_bound(left_spans, right_spans)).ok()?;
            }
        }
        after(*stack.last()?, &spans);
    }
    (stack.len() == 1).then_some(())
}

fn min3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0].min(b[0]), a[1].min(b[1]), a[2].min(b[2])]
}

fn max3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0].max(b[0]), a[1].max(b[1]), a[2].max(b[2])]
}

impl ObjectDescription {
    /// The world-space box around the object: its primitive's own box through its transform.
    pub fn world_box(&self) -> [[f64; 3]; 2] {
        let [low, high] = self.primitive.local_box();
        let mut enclosure = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
        for corner in 0..8 {
            let p = [
                if corner & 1 == 0 { low[0] } else { high[0] },
                if corner & 2 == 0 { low[1] } else { high[1] },
                if corner & 4 == 0 { low[2] } else { high[2] },
            ];
            let world = self.world_from_object.transform_point(p);
            enclosure = [min3(enclosure[0], world), max3(enclosure[1], world)];
        }
        enclosure
    }
}

/// The transform that makes the unit cube the box enclosing the solid whose post-order nodes are
/// `nodes` (its object's `world_from_object`, §3.3.6), once every leaf's transform is final:
/// each leaf must be invertible (an error names its line) and the tree must fit the walk's
/// capacities (an error names `line`, the solid's).
pub fn enclosing_transform(nodes: &[SolidNode], line: u32) -> Result<Matrix4, SceneError> {
    for node in nodes {
        if let SolidNode::Leaf(leaf) = node {
            if leaf.world_from_object.affine_inverse().is_none() {
                return Err(SceneError::new(leaf.line, SceneErrorKind::SingularTransform));
            }
        }
    }
    let error = |kind| SceneError::new(line, kind);
    let (needs, enclosure) = solid_needs_and_box(nodes).ok_or(error(SceneErrorKind::SingularTransform))?;
    if needs.spans > MAX_SPANS {
        return Err(error(SceneErrorKind::SolidTooComplex { what: "spans along a ray", needs: needs.spans, capacity: MAX_SPANS }));
    }
    if needs.held > MAX_HELD_SPANS {
        return Err(error(SceneErrorKind::SolidTooComplex { what: "spans held at once by the walk", needs: needs.held, capacity: MAX_HELD_SPANS }));
    }
    if needs.stack > MAX_SOLID_STACK {
        return Err(error(SceneErrorKind::SolidTooComplex { what: "span lists held at once by the walk", needs: needs.stack, capacity: MAX_SOLID_STACK }));
    }
    // An empty enclosure (operands whose boxes do not meet) leaves nothing to see; the union of
    // the leaves' boxes still bounds it and keeps the transform invertible.
    let enclosure = if (0..3).all(|axis| enclosure[1][axis] > enclosure[0][axis]) {
        enclosure
    } else {
        nodes.iter().filter_map(|node| if let SolidNode::Leaf(leaf) = node { Some(leaf.world_box()) } else { None }).fold(
            [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]],
            |[low, high], [a, b]| [min3(low, a), max3(high, b)],
        )
    };
    let size: [f64; 3] = core::array::from_fn(|axis| enclosure[1][axis] - enclosure[0][axis]);
    let mut world_from_box = Matrix4::IDENTITY;
    if size.iter().any(|extent| !(*extent > 0.0 && extent.is_finite())) {
        return Err(error(SceneErrorKind::SingularTransform));
    }
    world_from_box.scale(size);
    world_from_box.translate(enclosure[0]);
    if world_from_box.affine_inverse().is_none() {
        return Err(error(SceneErrorKind::SingularTransform));
    }
    Ok(world_from_box)
}
