//! A solid's screen extents (thesis §3.3.6, box enclosures, here the extents' octagons): each
//! leaf's is its bounding capsule's, as an object's is (`capsule`); each operation's combines
//! its operands' up the tree: `∪` their hull, `∩` their overlap, `−` the left one's. A primary
//! ray through a pixel outside a node's extent skips the node's whole subtree (`csg::solid`).

use super::capsule::{Capsule, ScreenMap};
use crate::model::{Extent, Operation, PreparedSolidNode};
use crate::number::Number;

/// Sets the extent of each node of one solid (`nodes`, in post-order, linked) as `map` sees
/// it; `capsule_of(place)` is a leaf's bounding capsule (`None`: unknown, the whole screen).
pub fn set_solid_extents<N: Number>(map: &ScreenMap<N>, nodes: &mut [PreparedSolidNode<N>], capsule_of: impl Fn(usize) -> Option<Capsule<N>>) {
    for index in 0..nodes.len() {
        // Post-order: both operands' extents are final before their operation's.
        let combined = match nodes.get(index) {
            Some(PreparedSolidNode::Leaf { .. }) => {
                let capsule = capsule_of(index).unwrap_or(Capsule::UNSET);
                Extent::of_cover(map, &map.cover(&capsule))
            }
            Some(PreparedSolidNode::Combine { operation, left, .. }) => {
                let extent_at = |place: usize| nodes.get(place).map_or(Extent::EVERYWHERE, |node| *node.extent());
                let (left, right) = (extent_at(usize::from(*left)), extent_at(index.wrapping_sub(1)));
                match operation {
                    Operation::Union => left.hull(right),
                    Operation::Intersection => left.overlap(right),
                    Operation::Difference => left,
                }
            }
            None => break,
        };
        if let Some(PreparedSolidNode::Leaf { extent, .. } | PreparedSolidNode::Combine { extent, .. }) = nodes.get_mut(index) {
            *extent = combined;
        }
    }
}
