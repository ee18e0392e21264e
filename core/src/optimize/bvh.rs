//! A bounding volume hierarchy over the objects' world boxes, for the shadow rays of scenes of
//! many objects (issue 24; the hierarchical extents the thesis proposes for many objects,
//! §5.2.1, made three-dimensional): a shadow ray visits the boxes along it, O(log n) of them,
//! instead of every object's culling data. Built top-down, each node split where the surface
//! area heuristic (MacDonald and Booth) puts it among 16 bins of the centroids, by the median
//! where that fails or the tree grows deep; once per preparation, in the number type, in
//! storage the caller owns (`Config::Hierarchy`: none on the firmware, whose scenes are small).
//!
//! The boxes contain every object as the tracer intersects it, rounding included (made in
//! `f64` from the geometry recovered from the number type's inverse, then grown by a margin of
//! the scene's size before rounding to the number type), so the objects a ray meets are in
//! boxes it meets: which objects block a shadow ray is unchanged, only fewer are looked at.

use crate::geometry::Vector3;
use crate::number::Number;
use crate::storage::Index;

/// One node: its box, and either its objects (a leaf: `order[first .. first + count]`) or its
/// two children (`count` 0: nodes `first` and `first + 1`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhNode<N> {
    pub low: [N; 3],
    pub high: [N; 3],
    pub first: u32,
    pub count: u32,
}

impl<N: Number> BvhNode<N> {
    pub const UNSET: Self = Self { low: [N::ZEROED; 3], high: [N::ZEROED; 3], first: 0, count: 0 };
}

impl<N: Number> crate::storage::Unset for BvhNode<N> {
    const UNSET: Self = Self::UNSET;
}

/// The most objects a leaf holds.
const LEAF_OBJECTS: usize = 4;
/// Bins of the surface area heuristic.
const BINS: usize = 16;
/// Below this depth the heuristic chooses; deeper, the median (so the depth stays below
/// [`STACK`] whatever the scene).
const HEURISTIC_DEPTH: usize = 32;
/// The nodes a traversal or the build holds at once.
const STACK: usize = 64;

/// A world box in `f64`.
pub type WorldBox = ([f64; 3], [f64; 3]);

/// Builds the hierarchy of `boxes` into `nodes` and `order` (each at least as long as `boxes`;
/// a tree whose leaves hold two or more boxes has fewer nodes than boxes). Each box is a
/// reference to the object `owner(box)` (one object may have several, `optimize::early_split`);
/// the leaves list those objects. Returns the nodes used, 0 (no hierarchy) when the storage
/// is too small or there are no boxes.
pub fn build<N: Number, I: Index>(boxes: &[WorldBox], owner: impl Fn(usize) -> usize, nodes: &mut [BvhNode<N>], order: &mut [I]) -> usize {
    let count = boxes.len();
    if count == 0 || nodes.len() < count || order.len() < count || count > u32::MAX as usize {
        return 0;
    }
    // The margin: a ray's parameter rounded in N moves the point it names by a few units in the
    // last place of the scene's coordinates (or of fixed point's resolution); 2⁻¹⁴ of the
    // scene's size and four steps of resolution are far beyond that in every type.
    let (scene_low, scene_high) = union(boxes.iter());
    let size = (0..3).map(|k| scene_high[k] - scene_low[k]).fold(0.0, f64::max);
    let largest = (0..3).map(|k| scene_low[k].abs().max(scene_high[k].abs())).fold(0.0, f64::max);
    let margin = libm::ldexp(size.max(largest), -14) + 4.0 * N::RESOLUTION.to_f64();
    for (index, place) in order.iter_mut().enumerate().take(count) {
        *place = I::new(index);
    }
    let order = &mut order[..count];
    let centre = |index: &I, axis: usize| boxes.get(index.get()).map_or(0.0, |(low, high)| (low[axis] + high[axis]) / 2.0);
    let mut stack: heapless::Vec<(usize, usize, usize, usize), STACK> = heapless::Vec::new();
    let _ = stack.push((0, 0, count, 0));
    let mut used = 1;
    while let Some((node, start, end, depth)) = stack.pop() {
        let members = order.get(start..end).unwrap_or(&[]);
        let (low, high) = union(members.iter().filter_map(|member| boxes.get(member.get())));
        let (low, high) = (low.map(|c| c - margin), high.map(|c| c + margin));
        let mut made = BvhNode { low: low.map(N::from_f64), high: high.map(N::from_f64), first: start as u32, count: (end - start) as u32 };
        if end - start > LEAF_OBJECTS && stack.len() + 2 <= STACK {
            let members = order.get_mut(start..end).unwrap_or(&mut []);
            let split = split(members, depth, &centre, boxes);
            let middle = start + split;
            made.first = used as u32;
            made.count = 0;
            let _ = stack.push((used, start, middle, depth + 1));
            let _ = stack.push((used + 1, middle, end, depth + 1));
            used += 2;
        }
        if let Some(slot) = nodes.get_mut(node) {
            *slot = made;
        }
    }
    for place in order.iter_mut() {
        *place = I::new(owner(place.get()));
    }
    used
}

/// Where to split `members` (more than [`LEAF_OBJECTS`]): reordered so that the first part
/// comes first; each part keeps at least two objects.
fn split<I: Index>(members: &mut [I], depth: usize, centre: &impl Fn(&I, usize) -> f64, boxes: &[WorldBox]) -> usize {
    let count = members.len();
    // The centroids' extent picks the axis.
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for member in members.iter() {
        for axis in 0..3 {
            let c = centre(member, axis);
            low[axis] = low[axis].min(c);
            high[axis] = high[axis].max(c);
        }
    }
    let axis = (0..3).fold(0, |best, k| if high[k] - low[k] > high[best] - low[best] { k } else { best });
    let median = |members: &mut [I]| {
        let middle = count / 2;
        members.select_nth_unstable_by(middle, |a, b| centre(a, axis).total_cmp(&centre(b, axis)));
        middle
    };
    let width = high[axis] - low[axis];
    // A width of zero or NaN: nothing to bin.
    if depth >= HEURISTIC_DEPTH || width.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
        return median(members);
    }
    // The surface area heuristic over the bins: the split whose two sides' areas times object
    // counts sum least.
    let bin_of = |member: &I| (((centre(member, axis) - low[axis]) / width * BINS as f64) as usize).min(BINS - 1);
    let mut counts = [0usize; BINS];
    let mut bounds = [([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]); BINS];
    for member in members.iter() {
        let bin = bin_of(member);
        if let (Some(count), Some(bound), Some((object_low, object_high))) = (counts.get_mut(bin), bounds.get_mut(bin), boxes.get(member.get())) {
            *count += 1;
            for k in 0..3 {
                bound.0[k] = bound.0[k].min(object_low[k]);
                bound.1[k] = bound.1[k].max(object_high[k]);
            }
        }
    }
    let mut best = (f64::INFINITY, 0);
    for cut in 1..BINS {
        let side = |range: core::ops::Range<usize>| {
            let (mut n, mut low, mut high) = (0, [f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            for bin in range {
                if let (Some(c), Some(b)) = (counts.get(bin), bounds.get(bin)) {
                    n += c;
                    for k in 0..3 {
                        low[k] = low[k].min(b.0[k]);
                        high[k] = high[k].max(b.1[k]);
                    }
                }
            }
            (n, if n == 0 { 0.0 } else { area(low, high) })
        };
        let ((left, left_area), (right, right_area)) = (side(0..cut), side(cut..BINS));
        if left >= 2 && right >= 2 {
            let cost = left as f64 * left_area + right as f64 * right_area;
            if cost < best.0 {
                best = (cost, cut);
            }
        }
    }
    if best.0 == f64::INFINITY {
        return median(members);
    }
    // Partition in place: the members of the bins below the cut first.
    let mut middle = 0;
    for index in 0..count {
        if members.get(index).is_some_and(|member| bin_of(member) < best.1) {
            members.swap(index, middle);
            middle += 1;
        }
    }
    middle
}

/// Half a box's surface area.
pub(crate) fn area(low: [f64; 3], high: [f64; 3]) -> f64 {
    let d = [0, 1, 2].map(|k| (high[k] - low[k]).max(0.0));
    d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
}

/// The box around the boxes.
fn union<'a>(boxes: impl Iterator<Item = &'a WorldBox>) -> WorldBox {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for (object_low, object_high) in boxes {
        for k in 0..3 {
            low[k] = low[k].min(object_low[k]);
            high[k] = high[k].max(object_high[k]);
        }
    }
    (low, high)
}

/// A built hierarchy: its nodes and the objects its leaves hold.
#[derive(Clone, Copy, Debug)]
pub struct Bvh<'a, N, I> {
    pub nodes: &'a [BvhNode<N>],
    pub order: &'a [I],
}

impl<N: Number, I: Index> Bvh<'_, N, I> {
    /// Whether `test` is true of an object in a leaf whose box the segment from `origin` along
    /// `direction` for `t` in [0, `max`] meets; the leaves are visited along no particular
    /// order, an object split into several boxes (`optimize::early_split`) maybe more than once.
    pub fn any(&self, origin: Vector3<N>, direction: Vector3<N>, max: N, mut test: impl FnMut(usize) -> bool) -> bool {
        let mut found = false;
        self.visit(origin, direction, max, |index| {
            found = test(index);
            found
        });
        found
    }

    /// Calls `visit` with each object of the leaves the segment meets, until it returns true.
    pub fn visit(&self, origin: Vector3<N>, direction: Vector3<N>, max: N, mut visit: impl FnMut(usize) -> bool) {
        self.walk(origin, direction, max, |index| if visit(index) { Walk::Stop } else { Walk::On });
    }

    /// Calls `visit` with each object of the leaves whose boxes the ray from `origin` along
    /// `direction` meets for `t` in [0, `max`], nearer boxes first, `visit` saying whether to go
    /// on, to stop, or to go on only as far as a `t` (a nearest hit found: farther boxes are
    /// skipped). An object split into several boxes maybe more than once.
    pub fn walk(&self, origin: Vector3<N>, direction: Vector3<N>, max: N, mut visit: impl FnMut(usize) -> Walk<N>) {
        let slabs = Slabs::new(origin, direction);
        let entry = |node: &BvhNode<N>, reach: N| slabs.entry(node, reach);
        let mut reach = max;
        // Each node on the stack with where the ray enters its box: popped, it is skipped
        // only if the reach has shrunk below that since (its box is not tested twice).
        let mut stack: heapless::Vec<(u32, N), STACK> = heapless::Vec::new();
        let Some(root) = self.nodes.first().and_then(|root| entry(root, reach)) else { return };
        let _ = stack.push((0, root));
        while let Some((node, entered)) = stack.pop() {
            let Some(node) = self.nodes.get(node as usize) else { continue };
            if entered > reach {
                continue;
            }
            if node.count == 0 {
                // The nearer child on top, so that it is walked first.
                let children = match self.nodes.get(node.first as usize..node.first as usize + 2) {
                    Some([a, b]) => slabs.entries(a, b, reach),
                    _ => [None, None],
                };
                let order = match children {
                    [Some(a), Some(b)] if b < a => [0, 1],
                    _ => [1, 0],
                };
                for side in order {
                    if let Some(entered) = children.get(side).copied().flatten() {
                        let _ = stack.push((node.first + side as u32, entered));
                    }
                }
                continue;
            }
            let (first, count) = (node.first as usize, node.count as usize);
            for member in self.order.get(first..first + count).unwrap_or(&[]) {
                match visit(member.get()) {
                    Walk::On => {}
                    Walk::Stop => return,
                    Walk::Within(t) => {
                        if t < reach {
                            reach = t;
                        }
                    }
                }
            }
        }
    }
}

/// A ray prepared for the slab test of boxes: its origin, per axis 1/d and the side of the box
/// it enters by.
struct Slabs<N> {
    origin: [N; 3],
    inverse: [N; 3],
    negative: [bool; 3],
    /// Axes along which 1/d cannot be formed (fixed point only): the ray is parallel to them.
    parallel: [bool; 3],
}

impl<N: Number> Slabs<N> {
    fn new(origin: Vector3<N>, direction: Vector3<N>) -> Self {
        // A float's 1/0 is taken as its largest value: the slab's two distances come out of the
        // same arithmetic as any other axis's, huge and of one sign outside the slab (a miss),
        // of both signs inside it.
        let inverse = direction.to_array().map(|component| match N::ONE.checked_div(component) {
            None if N::FLOATING_POINT && component == N::ZERO => Some(N::MAX),
            inverse => inverse,
        });
        Self {
            origin: origin.to_array(),
            inverse: inverse.map(|inverse| inverse.unwrap_or(N::ZERO)),
            negative: inverse.map(|inverse| inverse.is_some_and(|inverse| inverse < N::ZERO)),
            parallel: inverse.map(|inverse| inverse.is_none()),
        }
    }

    /// [`Slabs::entry`] of two siblings, in one call (a call for each cost more).
    #[inline(never)]
    fn entries(&self, a: &BvhNode<N>, b: &BvhNode<N>, reach: N) -> [Option<N>; 2] {
        [self.entry(a, reach), self.entry(b, reach)]
    }

    /// Where the ray enters the node's box within [0, `reach`], if it does.
    #[inline(always)]
    fn entry(&self, node: &BvhNode<N>, reach: N) -> Option<N> {
        let (mut near, mut far) = (N::ZERO, reach);
        for axis in 0..3 {
            let (low, high, o) = (node.low[axis], node.high[axis], self.origin[axis]);
            if !N::FLOATING_POINT && self.parallel[axis] {
                if o < low || o > high {
                    return None;
                }
                continue;
            }
            let (enter, exit) = if self.negative[axis] { (high, low) } else { (low, high) };
            let (enter, exit) = ((enter - o) * self.inverse[axis], (exit - o) * self.inverse[axis]);
            if enter > near {
                near = enter;
            }
            if exit < far {
                far = exit;
            }
            if near > far {
                return None;
            }
        }
        Some(near)
    }
}

/// What a walk's visitor says after an object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Walk<N> {
    /// Go on.
    On,
    /// Stop: found.
    Stop,
    /// Go on, but no farther than this `t` (the nearest hit so far).
    Within(N),
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;

    /// Random boxes and random segments: the hierarchy visits every object whose box the
    /// segment meets (checked by brute force in f64), in f64 and f32.
    fn visits_every_box_the_segment_meets<N: Number>() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut random = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut boxes = Vec::new();
        for _ in 0..700 {
            let centre = [100.0 * random(), 100.0 * random(), 10.0 * random()];
            let size = 0.1 + 3.0 * random();
            boxes.push((centre.map(|c| c - size), centre.map(|c| c + size)));
        }
        let mut nodes = std::vec![BvhNode::<N>::UNSET; boxes.len()];
        let mut order = std::vec![0u32; boxes.len()];
        let used = build(&boxes, |index| index, &mut nodes, &mut order);
        assert!(used > 1 && used <= boxes.len(), "{used}");
        let bvh = Bvh { nodes: &nodes[..used], order: &order };
        let mut visited_total = 0;
        for _ in 0..300 {
            let origin = [100.0 * random(), 100.0 * random(), 10.0 * random()];
            let target = [100.0 * random(), 100.0 * random(), 10.0 * random()];
            let direction = [0, 1, 2].map(|k| target[k] - origin[k]);
            let slab = |(low, high): &WorldBox| {
                let (mut near, mut far) = (0.0f64, 1.0f64);
                for k in 0..3 {
                    if direction[k] == 0.0 {
                        if origin[k] < low[k] || origin[k] > high[k] {
                            return false;
                        }
                        continue;
                    }
                    let (a, b) = ((low[k] - origin[k]) / direction[k], (high[k] - origin[k]) / direction[k]);
                    near = near.max(a.min(b));
                    far = far.min(a.max(b));
                }
                near <= far
            };
            let mut visited = Vec::new();
            bvh.visit(Vector3::from_f64(origin), Vector3::from_f64(direction), N::ONE, |index| {
                visited.push(index);
                false
            });
            let mut unique = visited.clone();
            unique.sort_unstable();
            unique.dedup();
            assert_eq!(unique.len(), visited.len(), "an object visited twice");
            for (index, bounds) in boxes.iter().enumerate() {
                if slab(bounds) {
                    assert!(visited.contains(&index), "box {index} met, not visited");
                }
            }
            visited_total += visited.len();
        }
        // Far fewer than every object per segment.
        assert!(visited_total < 300 * 700 / 5, "{visited_total}");
    }

    #[test]
    fn visits_every_box_the_segment_meets_in_every_number_type() {
        visits_every_box_the_segment_meets::<f64>();
        visits_every_box_the_segment_meets::<f32>();
        #[cfg(feature = "fixed-point")]
        {
            visits_every_box_the_segment_meets::<crate::number::Fixed>();
            visits_every_box_the_segment_meets::<crate::number::Fixed16>();
        }
        #[cfg(feature = "soft-float")]
        visits_every_box_the_segment_meets::<crate::number::SoftFloat>();
    }

    #[test]
    fn too_little_storage_builds_nothing() {
        let boxes = [([0.0; 3], [1.0; 3]); 8];
        let mut nodes = [BvhNode::<f32>::UNSET; 4];
        let mut order = [0u16; 8];
        assert_eq!(build(&boxes, |index| index, &mut nodes, &mut order), 0);
    }
}
