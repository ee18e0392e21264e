//! A primitive's spans (thesis §3.3: "the primitive routines must return all t values along the
//! ray, as in/out segments"): where the ray is inside it, from its surface crossings
//! (`Primitive::crossings`, at any `t`, in order). A convex primitive gives one span, a torus up
//! to two. Which stretches between crossings are inside is not guessed from their count: a
//! point between two crossings is tested against the primitive itself, so a tangent crossing
//! (the ray touching the surface: one crossing, or a torus's double root counted once) cannot
//! turn the rest of the ray inside out.

use super::spans::{Boundary, PushSpan, Span, Spans, SpansOverflow};
use crate::geometry::{Ray, Vector3};
use crate::model::Primitive;
use crate::number::Number;

/// The spans of `primitive` (leaf `leaf` of its tree) along `ray`, in object space.
pub fn leaf_spans<N: Number>(primitive: Primitive, ray: &Ray<N>, leaf: u16) -> Result<Spans<N, 2>, SpansOverflow> {
    let mut spans = Spans::EMPTY;
    leaf_spans_into(primitive, ray, leaf, &mut spans)?;
    Ok(spans)
}

/// [`leaf_spans`] appended to `spans` (a solid's walk keeps every list in one).
pub fn leaf_spans_into<N: Number, S: PushSpan<N>>(primitive: Primitive, ray: &Ray<N>, leaf: u16, spans: &mut S) -> Result<(), SpansOverflow> {
    let crossings = primitive.crossings(ray);
    let mut open: Option<Boundary<N>> = None;
    let list: &[(N, Vector3<N>)] = crossings.list.get(..crossings.len).unwrap_or(&[]);
    for (index, &(t, normal)) in list.iter().enumerate() {
        let boundary = Boundary { t, leaf, flipped: false, normal };
        // Inside just after this crossing: the middle of the stretch to the next crossing
        // (beyond the last, the ray has left every closed primitive).
        let inside_after = match list.get(index + 1) {
            Some(&(next, _)) => contains(primitive, ray.at(t + (next - t).times_power_of_two(-1))),
            None => false,
        };
        match (open, inside_after) {
            (None, true) => open = Some(boundary),
            (Some(enter), false) => {
                spans.push(Span { enter, exit: boundary })?;
                open = None;
            }
            // A touch from outside: an empty span where the ray grazes the surface, as a
            // tangent ray hits a quadric.
            (None, false) => spans.push(Span { enter: boundary, exit: boundary })?,
            (Some(_), true) => {}
        }
    }
    Ok(())
}

/// Whether `p` (object space) is inside the unit primitive, boundary included.
pub(crate) fn contains<N: Number>(primitive: Primitive, p: Vector3<N>) -> bool {
    let (zero, one) = (N::ZERO, N::ONE);
    match primitive {
        Primitive::Cube => [p.x, p.y, p.z].iter().all(|c| *c >= zero && *c <= one),
        Primitive::Sphere => p.x * p.x + p.y * p.y + p.z * p.z <= one,
        Primitive::Cylinder => p.x * p.x + p.y * p.y <= one && p.z >= zero && p.z <= one,
        Primitive::Cone => p.x * p.x + p.y * p.y <= p.z * p.z && p.z >= zero && p.z <= one,
        Primitive::Torus(tube) => {
            let r: N = tube.radius();
            let sum = p.x * p.x + p.y * p.y + p.z * p.z + one - r * r;
            sum * sum <= (p.x * p.x + p.y * p.y).times_power_of_two(2)
        }
        // A solid is never its own leaf; open surfaces enclose nothing (and no solid has them).
        Primitive::Solid(_) | Primitive::Frustum(_) | Primitive::Triangle | Primitive::Disc => false,
        #[cfg(feature = "triangle")]
        Primitive::Patch(_) => false,
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::model::Tube;

    fn ray(origin: [f64; 3], direction: [f64; 3]) -> Ray<f64> {
        Ray { origin: Vector3::from_f64(origin), direction: Vector3::from_f64(direction) }
    }

    fn ends(primitive: Primitive, r: Ray<f64>) -> Vec<(f64, f64)> {
        leaf_spans(primitive, &r, 0).unwrap().iter().map(|span| (span.enter.t, span.exit.t)).collect()
    }

    #[test]
    fn convex_primitives_give_one_span_from_entry_to_exit() {
        assert_eq!(ends(Primitive::Sphere, ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0])), [(4.0, 6.0)]);
        assert_eq!(ends(Primitive::Cube, ray([0.5, 0.5, 5.0], [0.0, 0.0, -1.0])), [(4.0, 5.0)]);
        assert_eq!(ends(Primitive::Cylinder, ray([5.0, 0.0, 0.5], [-1.0, 0.0, 0.0])), [(4.0, 6.0)]);
        // From inside: the span starts behind the origin.
        assert_eq!(ends(Primitive::Sphere, ray([0.0, 0.0, 0.0], [0.0, 0.0, 1.0])), [(-1.0, 1.0)]);
        assert!(ends(Primitive::Sphere, ray([0.0, 2.0, 5.0], [0.0, 0.0, -1.0])).is_empty());
        // A tangent ray: an empty span where it touches.
        assert_eq!(ends(Primitive::Sphere, ray([1.0, 0.0, 5.0], [0.0, 0.0, -1.0])), [(5.0, 5.0)]);
    }

    #[test]
    fn a_torus_gives_two_spans_through_both_sides() {
        let torus = Primitive::Torus(Tube::QUARTER);
        let found = ends(torus, ray([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]));
        assert_eq!(found.len(), 2, "{found:?}");
        for ((enter, exit), (want_enter, want_exit)) in found.iter().zip([(3.75, 4.25), (5.75, 6.25)]) {
            assert!((enter - want_enter).abs() < 1e-12 && (exit - want_exit).abs() < 1e-12, "{found:?}");
        }
        // Across one side of the tube only.
        let found = ends(torus, ray([1.0, 0.0, 5.0], [0.0, 0.0, -1.0]));
        assert_eq!(found.len(), 1, "{found:?}");
        assert!((found[0].0 - 4.75).abs() < 1e-12 && (found[0].1 - 5.25).abs() < 1e-12, "{found:?}");
    }
}
