//! Constructive solid geometry by Roth's ray casting (thesis chapter 3, §3.2–3.4): a solid is a
//! tree of primitives under `∪`, `∩` and `−`, and a ray's hit is the first entry of the spans
//! where it is inside the tree's solid. `spans` holds the span lists and their set operations
//! (Table 3.1, and circumstance classification, §3.3.7), in any number type, with capacity in
//! the type; `leaf` a primitive's own spans; `solid` the walk of a whole solid's tree, its first
//! hit and whether it blocks a shadow ray.

pub mod leaf;
#[cfg(feature = "csg")]
pub mod solid;
pub mod spans;

pub use leaf::{leaf_spans, leaf_spans_into};
pub use spans::{coincident, combine_into, Boundary, Operation, PushSpan, Span, Spans, SpansOverflow};
#[cfg(feature = "csg")]
pub use solid::{first_hit, occluded, solid_spans, SolidHit};
