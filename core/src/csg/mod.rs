//! Constructive solid geometry by Roth's ray casting (thesis chapter 3, §3.2–3.4): a solid is a
//! tree of primitives under `∪`, `∩` and `−`, and a ray's hit is the first entry of the spans
//! where it is inside the tree's solid. `spans` holds the span lists and their set operations
//! (Table 3.1, and circumstance classification, §3.3.7), in any number type, with capacity in
//! the type; `leaf` a primitive's own spans. The format's solids, the tree's walk and the
//! render's use of it follow them.

pub mod leaf;
pub mod spans;

pub use leaf::leaf_spans;
pub use spans::{Boundary, Operation, Span, Spans, SpansOverflow};
