//! Roth's ray classification (thesis §3.3; digest §10, "CSG"): where a ray is inside a solid, as
//! a sorted list of spans, and the three set operations on such lists (Table 3.1). A span runs
//! from the surface where the ray enters to the surface where it leaves; each end keeps which
//! leaf of the tree the surface belongs to and whether its normal is flipped (a subtracted
//! operand's surface faces the other way), so the first span's entry gives the hit and its
//! normal.
//!
//! Capacity is in the type (`Spans<N, K>`): at most `K` spans, which preparation derives from the
//! tree (spans(A op B) ≤ spans(A) + spans(B); a convex primitive gives one, a torus two). A
//! result that would need more is an error, never a silently shortened list.
//!
//! Coincident boundaries (operands sharing a face): every boundary within a hair of the same
//! `t` ([`coincident`]: 2⁻¹⁶ of `t`, whatever the number type) is applied before the result is
//! classified, so no sliver is made where two operands share a face, whichever way rounding
//! put their crossings (computed in each operand's own space); the result's surface there is
//! the left operand's. The rule, with its test: the flush faces of `A − B` render as the exact
//! solid (`tests/tests/csg.rs`).

use crate::geometry::Vector3;
pub use crate::model::Operation;
use crate::number::Number;
use crate::storage::List;

/// Where a span starts or ends: the ray parameter, the tree's leaf whose surface it is, whether
/// that surface's normal is to be flipped (the inside of a subtracted operand), and the leaf's
/// outward normal there in its object space (not normalised, not yet flipped).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Boundary<N> {
    pub t: N,
    pub leaf: u16,
    pub flipped: bool,
    pub normal: Vector3<N>,
}

/// The ray inside the solid from `enter` to `exit` (`enter.t ≤ exit.t`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Span<N> {
    pub enter: Boundary<N>,
    pub exit: Boundary<N>,
}

/// More spans than the capacity `K` holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpansOverflow {
    pub capacity: usize,
}

/// At most `K` disjoint spans, in order along the ray. Kept in a `heapless::Vec`: making an
/// empty list writes nothing, and copying one copies only its spans.
#[derive(Clone, Debug, PartialEq)]
pub struct Spans<N, const K: usize> {
    spans: heapless::Vec<Span<N>, K>,
}

impl<N: Number, const K: usize> Spans<N, K> {
    pub const EMPTY: Self = Self { spans: heapless::Vec::new() };

    pub fn len(&self) -> usize {
        self.spans.len()
    }

    pub fn is_empty(&self) -> bool {
        self.spans.is_empty()
    }

    pub fn iter(&self) -> impl Iterator<Item = &Span<N>> + '_ {
        self.spans.iter()
    }

    pub fn as_slice(&self) -> &[Span<N>] {
        &self.spans
    }

    /// The first span, whose entry is the surface a ray from outside sees.
    pub fn first(&self) -> Option<&Span<N>> {
        self.spans.first()
    }

    /// Appends a span after the others (it must not start before the last one ends).
    pub fn push(&mut self, span: Span<N>) -> Result<(), SpansOverflow> {
        self.spans.push(span).map_err(|_| SpansOverflow { capacity: K })
    }

    /// `left operation right` (see [`combine_into`]).
    pub fn combine<const A: usize, const B: usize>(operation: Operation, left: &Spans<N, A>, right: &Spans<N, B>) -> Result<Self, SpansOverflow> {
        let mut result = Self::EMPTY;
        combine_into(operation, &left.spans, &right.spans, &mut result.spans)?;
        Ok(result)
    }
}

/// Where spans are appended: a [`Spans`] list, or any [`List`] of them.
pub trait PushSpan<N> {
    fn push(&mut self, span: Span<N>) -> Result<(), SpansOverflow>;
}

impl<N: Number, const K: usize> PushSpan<N> for Spans<N, K> {
    fn push(&mut self, span: Span<N>) -> Result<(), SpansOverflow> {
        Spans::push(self, span)
    }
}

impl<N: Clone, L: List<Span<N>>> PushSpan<N> for L {
    #[inline(always)]
    fn push(&mut self, span: Span<N>) -> Result<(), SpansOverflow> {
        List::push(self, span).map_err(|_| SpansOverflow { capacity: L::CAPACITY })
    }
}

/// `left operation right`, merging the two lists' boundaries in order of `t` (Table 3.1), appended
/// to `out`: the result is inside wherever the operation says, from one boundary where that
/// changes to the next. A boundary of the right operand of a difference becomes a flipped surface.
pub fn combine_into<N: Number>(operation: Operation, left: &[Span<N>], right: &[Span<N>], out: &mut impl PushSpan<N>) -> Result<(), SpansOverflow> {
    let (mut left_events, mut right_events) = (Events::new(left), Events::new(right));
    let (mut in_left, mut in_right) = (false, false);
    let mut open: Option<Boundary<N>> = None;
    loop {
        let first = match (left_events.peek_t(), right_events.peek_t()) {
            (None, None) => break,
            (Some(a), None) => a,
            (None, Some(b)) => b,
            (Some(a), Some(b)) => a.min(b),
        };
        let t = first + coincident(first);
        let was_inside = operation.inside(in_left, in_right);
        // Every boundary at this `t` (within the hair), of either operand, before
        // classifying: a shared face makes no sliver.
        let mut left_surface = None;
        let mut right_surface = None;
        while let Some((boundary, entering)) = left_events.next_at(t) {
            in_left = entering;
            left_surface = Some(boundary);
        }
        while let Some((boundary, entering)) = right_events.next_at(t) {
            in_right = entering;
            right_surface = Some(Boundary { flipped: boundary.flipped != (operation == Operation::Difference), ..boundary });
        }
        let inside = operation.inside(in_left, in_right);
        if inside == was_inside {
            continue;
        }
        // The surface where the result changes: the operand whose change made it (the left
        // one when both changed at once).
        let Some(surface) = left_surface.filter(|_| changes(operation, in_left, in_right, true)).or(right_surface).or(left_surface) else {
            continue;
        };
        if inside {
            open = Some(surface);
        } else if let Some(enter) = open.take() {
            out.push(Span { enter, exit: surface })?;
        }
    }
    Ok(())
}

/// How far apart along the ray two boundaries may be and still count as one surface: 2⁻¹⁶ of
/// `t`. Rounding in each operand's own space puts a shared face's crossings a few units in the
/// last place apart (2⁻²⁴ relative in `f32`); a true feature this thin is below any pixel.
#[inline]
pub fn coincident<N: Number>(t: N) -> N {
    t.abs().times_power_of_two(-16)
}

/// Whether flipping the left (`left == true`) or right operand's state alone would change the
/// result: that operand's surface is the result's boundary.
fn changes(operation: Operation, in_left: bool, in_right: bool, left: bool) -> bool {
    let now = operation.inside(in_left, in_right);
    let other = if left { operation.inside(!in_left, in_right) } else { operation.inside(in_left, !in_right) };
    now != other
}

/// A span list's boundaries in order: each span's entry (entering) then its exit (leaving).
struct Events<'a, N> {
    spans: &'a [Span<N>],
    index: usize,
}

impl<'a, N: Number> Events<'a, N> {
    fn new(spans: &'a [Span<N>]) -> Self {
        Self { spans, index: 0 }
    }

    fn at(&self, index: usize) -> Option<(Boundary<N>, bool)> {
        let span = self.spans.get(index / 2)?;
        Some(if index.is_multiple_of(2) { (span.enter, true) } else { (span.exit, false) })
    }

    fn peek_t(&self) -> Option<N> {
        self.at(self.index).map(|(boundary, _)| boundary.t)
    }

    /// The next boundary if it is at `t` or before.
    fn next_at(&mut self, t: N) -> Option<(Boundary<N>, bool)> {
        let event = self.at(self.index).filter(|(boundary, _)| boundary.t <= t)?;
        self.index += 1;
        Some(event)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;

    fn boundary(t: f64, leaf: u16) -> Boundary<f64> {
        Boundary { t, leaf, flipped: false, normal: Vector3::zero() }
    }

    fn spans(leaf: u16, list: &[(f64, f64)]) -> Spans<f64, 4> {
        let mut result = Spans::EMPTY;
        for &(enter, exit) in list {
            result.push(Span { enter: boundary(enter, leaf), exit: boundary(exit, leaf) }).unwrap();
        }
        result
    }

    fn ends(result: &Spans<f64, 4>) -> Vec<(f64, u16, bool, f64, u16, bool)> {
        result.iter().map(|s| (s.enter.t, s.enter.leaf, s.enter.flipped, s.exit.t, s.exit.leaf, s.exit.flipped)).collect()
    }

    #[test]
    fn table_3_1_on_overlapping_spans() {
        let (a, b) = (spans(0, &[(1.0, 4.0)]), spans(1, &[(2.0, 6.0)]));
        let union = Spans::<f64, 4>::combine(Operation::Union, &a, &b).unwrap();
        assert_eq!(ends(&union), [(1.0, 0, false, 6.0, 1, false)]);
        let both = Spans::<f64, 4>::combine(Operation::Intersection, &a, &b).unwrap();
        assert_eq!(ends(&both), [(2.0, 1, false, 4.0, 0, false)]);
        // A − B: A's entry, then B's entry as A's exit, its normal flipped.
        let difference = Spans::<f64, 4>::combine(Operation::Difference, &a, &b).unwrap();
        assert_eq!(ends(&difference), [(1.0, 0, false, 2.0, 1, true)]);
        // B − A: A's exit is where B − A begins, flipped.
        let reverse = Spans::<f64, 4>::combine(Operation::Difference, &b, &a).unwrap();
        assert_eq!(ends(&reverse), [(4.0, 0, true, 6.0, 1, false)]);
    }

    #[test]
    fn a_hole_through_the_middle_makes_two_spans() {
        // A cube minus a cylinder along the ray's path through its middle: in, out at the hole,
        // in again after it, out.
        let (a, b) = (spans(0, &[(1.0, 9.0)]), spans(1, &[(4.0, 6.0)]));
        let difference = Spans::<f64, 4>::combine(Operation::Difference, &a, &b).unwrap();
        assert_eq!(ends(&difference), [(1.0, 0, false, 4.0, 1, true), (6.0, 1, true, 9.0, 0, false)]);
        // A torus's two spans unite with a sphere's one bridging them.
        let torus = spans(0, &[(1.0, 2.0), (5.0, 6.0)]);
        let sphere = spans(1, &[(1.5, 5.5)]);
        let union = Spans::<f64, 4>::combine(Operation::Union, &torus, &sphere).unwrap();
        assert_eq!(ends(&union), [(1.0, 0, false, 6.0, 0, false)]);
    }

    #[test]
    fn empty_and_disjoint_operands() {
        let (a, none) = (spans(0, &[(1.0, 2.0)]), Spans::<f64, 4>::EMPTY);
        assert_eq!(ends(&Spans::<f64, 4>::combine(Operation::Union, &a, &none).unwrap()), ends(&a));
        assert!(Spans::<f64, 4>::combine(Operation::Intersection, &a, &none).unwrap().is_empty());
        assert_eq!(ends(&Spans::<f64, 4>::combine(Operation::Difference, &a, &none).unwrap()), ends(&a));
        assert!(Spans::<f64, 4>::combine(Operation::Difference, &none, &a).unwrap().is_empty());
        let b = spans(1, &[(3.0, 4.0)]);
        assert_eq!(Spans::<f64, 4>::combine(Operation::Union, &a, &b).unwrap().len(), 2);
        assert!(Spans::<f64, 4>::combine(Operation::Intersection, &a, &b).unwrap().is_empty());
        assert!(Operation::Difference.left_decides_empty() && Operation::Intersection.left_decides_empty());
        assert!(!Operation::Union.left_decides_empty());
    }

    #[test]
    fn shared_faces_make_no_zero_length_spans() {
        // A cube minus a cube flush with its front face: both entered at t = 1; the rest of A
        // behind B's back face at 3 remains, entered through B's (flipped) back face.
        let (a, b) = (spans(0, &[(1.0, 5.0)]), spans(1, &[(1.0, 3.0)]));
        let difference = Spans::<f64, 4>::combine(Operation::Difference, &a, &b).unwrap();
        assert_eq!(ends(&difference), [(3.0, 1, true, 5.0, 0, false)]);
        // Two solids that touch at t = 2 unite into one span, not two.
        let (c, d) = (spans(0, &[(1.0, 2.0)]), spans(1, &[(2.0, 3.0)]));
        let union = Spans::<f64, 4>::combine(Operation::Union, &c, &d).unwrap();
        assert_eq!(ends(&union), [(1.0, 0, false, 3.0, 1, false)]);
        // Identical operands: A ∩ A = A, A − A = nothing, A ∪ A = A.
        let twin = spans(1, &[(1.0, 5.0)]);
        assert_eq!(Spans::<f64, 4>::combine(Operation::Intersection, &a, &twin).unwrap().len(), 1);
        assert!(Spans::<f64, 4>::combine(Operation::Difference, &a, &twin).unwrap().is_empty());
        assert_eq!(Spans::<f64, 4>::combine(Operation::Union, &a, &twin).unwrap().len(), 1);
    }

    #[test]
    fn a_result_beyond_the_capacity_is_an_error() {
        let a = spans(0, &[(0.0, 1.0), (2.0, 3.0), (4.0, 5.0)]);
        let b = spans(1, &[(6.0, 7.0), (8.0, 9.0)]);
        assert_eq!(Spans::<f64, 4>::combine(Operation::Union, &a, &b), Err(SpansOverflow { capacity: 4 }));
        assert_eq!(Spans::<f64, 8>::combine(Operation::Union, &a, &b).unwrap().len(), 5);
    }
}
