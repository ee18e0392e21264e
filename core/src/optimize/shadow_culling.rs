//! Shadow-ray culling, beyond the thesis (which tested every other object, digest §4.7): each
//! object keeps a bounding capsule (a segment and a radius: a point for spheres and cubes, the
//! axis for cylinders and cones), and a shadow ray tests an object only when the ray's segment
//! passes within the radius of that segment. The check is a few dot products and one vector
//! length in the number type, against a ray–object test's transform and quadric.
//! It is conservative: the radius is widened before conversion, the closest points of the two
//! segments are found exactly (Ericson, *Real-Time Collision Detection* §5.1.9), nearly
//! parallel segments are always tested, and lengths use `length3` (which never overflows in
//! narrow fixed-point types).
//!
//! Per render, [`ShadowBound::footprint`] gives each object's view from the light (in the
//! number type, linear in the objects) and [`blocker_table`] which objects may shadow which
//! (sweep and prune over the footprints' boxes).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::geometry::Vector3;
use crate::config::Config;
use crate::storage::Index;
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowBound<N> {
    /// The middle of the capsule's segment.
    pub centre: Vector3<N>,
    /// Unit direction of the segment (zero for a point).
    pub axis: Vector3<N>,
    /// Half the length of the segment.
    pub half: N,
    /// Widened radius; `N::MAX` means "always test".
    pub radius: N,
    /// `radius + half`: the radius of a sphere about `centre` holding the capsule.
    pub reach: N,
}

impl<N: Number> crate::storage::Unset for ShadowBound<N> {
    const UNSET: Self = Self::UNSET;
}

impl<N: Number> ShadowBound<N> {
    /// Every byte zero: the value before the acceleration is built.
    pub const UNSET: Self = Self {
        centre: Vector3 { x: N::ZEROED, y: N::ZEROED, z: N::ZEROED },
        axis: Vector3 { x: N::ZEROED, y: N::ZEROED, z: N::ZEROED },
        half: N::ZEROED,
        radius: N::ZEROED,
        reach: N::ZEROED,
    };

    pub fn always() -> Self {
        Self { centre: Vector3::zero(), axis: Vector3::zero(), half: N::ZERO, radius: N::MAX, reach: N::MAX }
    }

    /// The capsule from `start` to `end` with `radius`, widened for rounding.
    pub fn new(start: [f64; 3], end: [f64; 3], radius: f64) -> Self {
        let d = [end[0] - start[0], end[1] - start[1], end[2] - start[2]];
        let length = libm::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        let axis = if length > 0.0 { d.map(|c| c / length) } else { [0.0; 3] };
        let centre = [(start[0] + end[0]) / 2.0, (start[1] + end[1]) / 2.0, (start[2] + end[2]) / 2.0];
        let scale = libm::sqrt(centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2]) + length + radius + 1.0;
        let widened = radius * (1.0 + 1e-3) + 1e-3 * scale;
        let half = length / 2.0 * (1.0 + 1e-9);
        let representable = centre.iter().all(|c| N::can_represent(*c)) && N::can_represent(widened + half);
        if !widened.is_finite() || !representable {
            return Self::always();
        }
        Self {
            centre: Vector3::from_f64(centre),
            axis: Vector3::from_f64(axis),
            half: N::from_f64(half),
            radius: N::from_f64(widened),
            reach: N::from_f64(widened + half),
        }
    }

    /// Whether the segment from `point` along unit `direction` up to `length` may come within
    /// the radius of the capsule's segment.
    #[inline]
    pub fn may_block(&self, point: Vector3<N>, direction: Vector3<N>, length: N) -> bool {
        if self.radius == N::MAX {
            return true;
        }
        // First the sphere about the centre that holds the capsule: behind the point, beyond
        // the light, or off the ray's line in some coordinate.
        let w = self.centre - point;
        let b = direction.dot(w);
        if b < -self.reach || b - self.reach > length {
            return false;
        }
        let off = w - direction * b;
        if off.x.abs() > self.reach || off.y.abs() > self.reach || off.z.abs() > self.reach {
            return false;
        }
        // Then the capsule: the closest points of the two segments (s on the ray in
        // [0, length], t on the axis in [−half, half]).
        let clamp = |value: N, low: N, high: N| if value < low { low } else if value > high { high } else { value };
        let (s, t) = if self.half == N::ZERO {
            (clamp(b, N::ZERO, length), N::ZERO)
        } else {
            let a = direction.dot(self.axis);
            let c = self.axis.dot(w);
            let denominator = N::ONE - a * a;
            if denominator < N::from_f64(1e-4) {
                return true;
            }
            let Some(s) = (b - a * c).checked_div(denominator) else { return true };
            let t = clamp(clamp(s, N::ZERO, length) * a - c, -self.half, self.half);
            let s = clamp(b + t * a, N::ZERO, length);
            (s, clamp(s * a - c, -self.half, self.half))
        };
        let gap = direction * s - self.axis * t - w;
        if gap.x.abs() > self.radius || gap.y.abs() > self.radius || gap.z.abs() > self.radius {
            return false;
        }
        gap.length() <= self.radius
    }
}

/// How an object's bounding sphere (about the capsule's centre, radius `reach`) is seen from
/// the light, for the per-render shadow table ([`blocker_table`]). All in the number type,
/// widened for its rounding (`margin`): conservative, never exact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightFootprint<N> {
    /// For a point light: the directions from the light that meet the capsule, within a
    /// reach of the chord between the unit directions to its two ends. A shadow ray from P can
    /// meet the object only if the direction from the light to P is among them.
    pub chord: DirectionChord<N>,
    /// What the blocker table compares, pair by pair.
    pub reach: LightReach<N>,
}

/// The part of a [`LightFootprint`] that [`blocker_table`] compares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightReach<N> {
    /// A ball (and so the box `centre ± radius`) holding every direction of the chord's reach
    /// (point light), or the sphere's cross-section seen along the light (directional: the
    /// centre projected on the plane through the origin perpendicular to the light, ± reach).
    /// Two objects whose balls (or boxes) are apart cannot both meet one shadow ray.
    pub centre: Vector3<N>,
    pub radius: N,
    /// The range of distances from the light (directional: of depth along the light) over
    /// the object: a blocker whose `near` is beyond a receiver's `far` lies behind it.
    pub near: N,
    pub far: N,
}

impl<N: Number> LightFootprint<N> {
    /// May meet any shadow ray.
    pub fn always() -> Self {
        Self { chord: DirectionChord::ALWAYS, reach: LightReach::always() }
    }
}

impl<N: Number> LightReach<N> {
    /// May meet any shadow ray.
    pub fn always() -> Self {
        Self { centre: Vector3::zero(), radius: N::MAX, near: -N::MAX, far: N::MAX }
    }

    /// Whether some shadow ray from a point of `receiver` toward the light may meet `blocker`:
    /// their boxes and their balls overlap and the blocker is not wholly behind the receiver.
    #[inline]
    pub fn may_shadow(&self, receiver: &Self) -> bool {
        self.near <= receiver.far && self.meets(receiver)
    }

    /// The part of [`LightReach::may_shadow`] that is the same both ways: the boxes and the
    /// balls overlap.
    #[inline]
    fn meets(&self, other: &Self) -> bool {
        self.overlaps(other) && self.balls_meet(other)
    }

    /// |Δ| ≤ r₁ + r₂ (`length3` never overflows in narrow fixed point; its rounding is far
    /// inside the radii's margins). The same bits either way round: Δ's components only change
    /// sign.
    #[inline]
    fn balls_meet(&self, other: &Self) -> bool {
        if self.radius == N::MAX || other.radius == N::MAX {
            return true;
        }
        let apart = (self.centre - other.centre).length();
        apart - apart.abs().times_power_of_two(N::SQRT_ERROR_EXPONENT) <= self.radius + other.radius
    }

    #[inline]
    fn overlaps(&self, other: &Self) -> bool {
        (0..3).all(|k| self.low(k) <= other.high(k) && other.low(k) <= self.high(k))
    }

    /// The box's low and high ends along axis `k`.
    #[inline]
    fn low(&self, k: usize) -> N {
        self.centre.component(k) - self.radius
    }

    #[inline]
    fn high(&self, k: usize) -> N {
        self.centre.component(k) + self.radius
    }
}

/// A relative 2⁻¹⁶ of `x`, plus 32 steps of a fixed-point type's resolution: the margin that
/// covers the number type's rounding in [`ShadowBound::footprint`] (hundreds of times the
/// rounding of the few operations involved in `f32` and `soft32`, whose mantissas have 24 and
/// 28 bits; a fixed-point type's rounding is absolute).
fn margin<N: Number>(x: N) -> N {
    x.abs().times_power_of_two(-16) + N::RESOLUTION.times_power_of_two(5)
}

impl<N: Number> ShadowBound<N> {
    /// The object's [`LightFootprint`] toward a point light at `position` or a directional
    /// light toward unit `direction`, computed in the number type with a few products and two
    /// square roots (no trigonometry: the cone's cosine is √(1 − sin²)).
    pub fn footprint(&self, light: LightPosition<N>) -> LightFootprint<N> {
        if self.radius == N::MAX {
            return LightFootprint::always();
        }
        match light {
            LightPosition::Point(light) => {
                // Every length below may be off by the square root's relative error, and the
                // shadow rays' "unit" directions too: widen by four times that.
                let slack = |x: N| margin(x) + x.abs().times_power_of_two(N::SQRT_ERROR_EXPONENT + 2);
                let ends = [self.centre - self.axis * self.half, self.centre + self.axis * self.half];
                // The capsule's nearest approach to the light.
                let segment = ends[1] - ends[0];
                let squared = segment.dot(segment);
                let along = if squared > N::ZERO { (light - ends[0]).dot(segment).checked_div(squared).unwrap_or(N::ZERO) } else { N::ZERO };
                let nearest = (ends[0] + segment * along.max(N::ZERO).min(N::ONE) - light).length();
                let radius = self.radius + margin(self.radius) + slack(nearest);
                if !(nearest > radius) {
                    return LightFootprint::always();
                }
                let (a, b) = (ends[0] - light, ends[1] - light);
                let (la, lb) = (a.length(), b.length());
                let (Some(ia), Some(ib), Some(inverse)) = (N::ONE.checked_div(la), N::ONE.checked_div(lb), N::ONE.checked_div(nearest)) else {
                    return LightFootprint::always();
                };
                let (ua, ub) = (a * ia, b * ib);
                // Each point's ball subtends at most the angle whose sine is radius/nearest.
                let sine = radius * inverse;
                let sine = sine + slack(sine);
                let cosine = (N::ONE - sine * sine).sqrt();
                let cosine = cosine - slack(cosine) - slack(N::ONE);
                if !(cosine > N::ZERO) {
                    return LightFootprint::always();
                }
                let ball = ((N::ONE - cosine) + (N::ONE - cosine)).sqrt();
                // The directions to the axis run along the arc from ua to ub, at most the
                // sagitta 1 − √(1 − c²/4) from its chord (c the chord's length).
                let chord = ub - ua;
                let chord_squared = chord.dot(chord);
                let sagitta = N::ONE - (N::ONE - chord_squared.times_power_of_two(-2)).max(N::ZERO).sqrt();
                let reach = ball + sagitta;
                let reach = reach + slack(reach) + slack(N::ONE);
                let inverse_squared = if chord_squared > N::ONE.times_power_of_two(-20) { N::ONE.checked_div(chord_squared).unwrap_or(N::ZERO) } else { N::ZERO };
                let half_chord = chord_squared.sqrt().times_power_of_two(-1);
                // Every direction within the reach of the chord lies in its ends' box widened
                // by the reach (and the box's own rounding).
                let widen = reach + slack(reach);
                let low = Vector3::new(ua.x.min(ub.x), ua.y.min(ub.y), ua.z.min(ub.z)) - Vector3::new(widen, widen, widen);
                let high = Vector3::new(ua.x.max(ub.x), ua.y.max(ub.y), ua.z.max(ub.z)) + Vector3::new(widen, widen, widen);
                LightFootprint { chord: DirectionChord {
                        start: ua,
                        along: chord,
                        inverse_squared,
                        reach_squared: reach * reach,
                        // A point's cone: the cosine of the widened half-angle, as above.
                        cosine,
                        low: QuantizedDirection::new(low).0,
                        high: QuantizedDirection::new(high).0,
                    },
                    reach: LightReach {
                        centre: ua + chord.times_power_of_two(-1),
                        radius: half_chord + slack(half_chord) + reach,
                        near: nearest - radius,
                        far: la.max(lb) + radius,
                    },
                }
            }
            LightPosition::Direction(direction) => {
                let height = self.centre.dot(direction);
                let across = self.centre - direction * height;
                let reach = self.reach + margin(self.reach) + margin(self.centre.largest_component()) + margin(height);
                LightFootprint {
                    chord: DirectionChord::ALWAYS,
                    reach: LightReach {
                        centre: across,
                        radius: reach,
                        near: -height - reach,
                        far: -height + reach,
                    },
                }
            }
        }
    }
}

/// The directions from a point light that may meet an object: those within `reach` of the
/// chord from `start` to `start + along` (unit directions to the capsule's ends).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionChord<N> {
    pub start: Vector3<N>,
    pub along: Vector3<N>,
    /// 1/|along|², zero for a point.
    pub inverse_squared: N,
    /// reach²; `N::MAX`: every direction.
    pub reach_squared: N,
    /// For a point (`along` zero): the cosine of the cone's widened half-angle about `start`
    /// (the cone test, one dot product).
    pub cosine: N,
    /// The box of the directions within the reach of the chord, in [`QuantizedDirection`]'s
    /// steps: a direction outside is excluded by an integer comparison or
    /// two ([`DirectionChord::outside_box`]), before any arithmetic in the number type.
    pub low: [i16; 3],
    pub high: [i16; 3],
}

/// A direction's components in steps of 2⁻¹⁴, each rounded to an integer by
/// [`Number::to_i32_monotone`] and saturated to `i16`: a unit vector's fit with room. A
/// shadow ray's direction is converted once, and compared with every candidate's box in
/// integers (a comparison in a software number type costs tens of instructions). Any rounding
/// that never decreases as its argument grows keeps the box conservative: d ≥ low gives
/// q(d) ≥ q(low), so q(d) < q(low) proves d < low (and likewise above), whichever way the type
/// rounds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QuantizedDirection(pub [i16; 3]);

/// log₂ of the steps per unit of [`QuantizedDirection`].
const QUANTIZED_EXPONENT: i32 = 14;

impl QuantizedDirection {
    /// Inline: the scaling by a constant power of two then folds into one multiplication.
    #[inline(always)]
    pub fn new<N: Number>(v: Vector3<N>) -> Self {
        let step = |x: N| x.times_power_of_two(QUANTIZED_EXPONENT).to_i32_monotone().clamp(i32::from(i16::MIN), i32::from(i16::MAX)) as i16;
        Self([step(v.x), step(v.y), step(v.z)])
    }
}

impl<N: Number> DirectionChord<N> {
    pub const ALWAYS: Self = Self {
        start: Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO },
        along: Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO },
        inverse_squared: N::ZERO,
        reach_squared: N::MAX,
        cosine: N::MAX,
        low: [i16::MIN; 3],
        high: [i16::MAX; 3],
    };

    /// Whether the direction (from the light, made a [`QuantizedDirection`]) lies outside
    /// the box of the directions the chord may meet: then [`DirectionChord::excludes`] it too.
    #[inline(always)]
    pub fn outside_box(&self, direction: QuantizedDirection) -> bool {
        let QuantizedDirection(d) = direction;
        d[0] < self.low[0] || d[0] > self.high[0] || d[1] < self.low[1] || d[1] > self.high[1] || d[2] < self.low[2] || d[2] > self.high[2]
    }

    /// Whether `direction` (from the light) is farther than the reach from the chord. The
    /// closest point's parameter is rounded, which can only make the distance found larger by
    /// its square times |along|², far inside the reach's margin.
    #[inline(always)]
    pub fn excludes(&self, direction: Vector3<N>) -> bool {
        if self.inverse_squared == N::ZERO {
            // |d − u|² = |d|² + 1 − 2·d·u for the unit u: the dot product decides.
            return self.cosine != N::MAX && direction.dot(self.start) < self.cosine;
        }
        let w = direction - self.start;
        let t = (w.dot(self.along) * self.inverse_squared).max(N::ZERO).min(N::ONE);
        let gap = w - self.along * t;
        gap.dot(gap) > self.reach_squared
    }
}

/// Where the light is, for [`ShadowBound::footprint`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightPosition<N> {
    Point(Vector3<N>),
    /// Unit vector toward the light.
    Direction(Vector3<N>),
}

/// A set of the object numbers below 128, as four 32-bit words: a word's shift, test and
/// trailing-zero count are one instruction each on a 32-bit core, a `u128`'s several.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BlockerSet {
    words: [u32; 4],
}

impl BlockerSet {
    /// Object numbers from this one on are not held: always candidates.
    pub const CAPACITY: usize = 128;

    pub const EMPTY: Self = Self { words: [0; 4] };

    /// The set of [`BlockerSet::words`] (a baked table, `crate::bake`).
    pub const fn from_words(words: [u32; 4]) -> Self {
        Self { words }
    }

    /// Adds `index` (ignored from [`BlockerSet::CAPACITY`] on).
    pub fn insert(&mut self, index: usize) {
        if let Some(word) = self.words.get_mut(index / 32) {
            *word |= 1 << (index % 32);
        }
    }

    pub fn contains(&self, index: usize) -> bool {
        self.words.get(index / 32).is_some_and(|word| word & (1 << (index % 32)) != 0)
    }

    /// The four words: bit `i` of word `w` holds object `32·w + i`.
    pub fn words(self) -> [u32; 4] {
        self.words
    }
}

/// One light's shadow tables by their parts: for a point light each object's cone of directions
/// from it (none for a direction), and each object's blockers among the first 128 (none with a
/// hierarchy) — the tables a render builds (`render/shadow_tables.rs`), or a baked scene's,
/// made at build time for its fixed view and light, bit for bit (`Config::ShadowTables`).
#[derive(Clone, Copy, Debug)]
pub struct ShadowTables<'a, N> {
    pub light_cones: &'a [DirectionChord<N>],
    pub blockers: &'a [BlockerSet],
}

impl<N> crate::storage::Unset for ShadowTables<'_, N> {
    const UNSET: Self = Self { light_cones: &[], blockers: &[] };
}

/// Which objects may shadow which: `blockers[r]` gets `b` (for `b` < 128) when a shadow
/// ray from object `r` may meet object `b` ([`LightReach::may_shadow`]). Sweep and prune
/// (`order` is scratch space, one entry per object): the footprints sorted by their boxes' low
/// x, each compared only with those whose x range overlaps its own, so the work grows with the
/// objects and the overlapping pairs, not with all pairs.
pub fn blocker_table<C: Config<Number = N>, N: Number>(footprints: &[LightReach<N>], order: &mut [C::Index], blockers: &mut [BlockerSet]) {
    let count = footprints.len().min(order.len()).min(blockers.len()).min(C::Index::MAX);
    let (order, blockers) = (&mut order[..count], &mut blockers[..count]);
    blockers.fill(BlockerSet::EMPTY);
    for (index, place) in order.iter_mut().enumerate() {
        *place = C::Index::new(index);
    }
    let low_x = |index: usize| footprints.get(index).map_or(-N::MAX, |f| f.low(0));
    super::sortlist::sort_by_bound::<C, _>(order, low_x);
    sweep(footprints, order, |blocker| blocker < BlockerSet::CAPACITY, |receiver, blocker| {
        if let Some(set) = blockers.get_mut(receiver) {
            set.insert(blocker);
        }
        true
    });
}

/// The sweep of [`blocker_table`], over `order` sorted by the boxes' low x: calls
/// `pair(receiver, blocker)` for every pair whose boxes meet where the blocker may shadow the
/// receiver, for the blockers `wanted` (so that no test is spent on a pair not kept), until
/// `pair` returns `false`. Its work is the pairs whose x ranges overlap: for objects spread
/// over a plane, about n·√n.
#[inline(always)]
pub fn sweep<N: Number, I: Index>(footprints: &[LightReach<N>], order: &[I], wanted: impl Fn(usize) -> bool, mut pair: impl FnMut(usize, usize) -> bool) {
    for (position, &first) in order.iter().enumerate() {
        let Some(a) = footprints.get(first.get()) else { continue };
        for &second in order.iter().skip(position + 1) {
            let Some(b) = footprints.get(second.get()) else { continue };
            if b.low(0) > a.high(0) {
                break;
            }
            let (i, j) = (first.get(), second.get());
            // `b.may_shadow(a)` and `a.may_shadow(b)`, their common part once.
            let (b_shadows_a, a_shadows_b) = (wanted(j) && b.near <= a.far, wanted(i) && a.near <= b.far);
            if !(b_shadows_a || a_shadows_b) || !a.meets(b) {
                continue;
            }
            if (b_shadows_a && !pair(i, j)) || (a_shadows_b && !pair(j, i)) {
                return;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::Arrays;

    /// A small linear congruential generator: the same spheres every run.
    struct Random(u64);

    impl Random {
        fn next(&mut self) -> f64 {
            self.0 = self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }

        fn between(&mut self, low: f64, high: f64) -> f64 {
            low + (high - low) * self.next()
        }
    }

    /// Whether the segment from `p` to `p + length·d` (unit `d`) meets the sphere, in f64.
    fn segment_meets_sphere(p: [f64; 3], d: [f64; 3], length: f64, centre: [f64; 3], radius: f64) -> bool {
        let w = [0, 1, 2].map(|k| centre[k] - p[k]);
        let along = (w[0] * d[0] + w[1] * d[1] + w[2] * d[2]).clamp(0.0, length);
        let gap = [0, 1, 2].map(|k| p[k] + along * d[k] - centre[k]);
        gap[0] * gap[0] + gap[1] * gap[1] + gap[2] * gap[2] <= radius * radius
    }

    /// Every blocker that some shadow ray from a surface point of a receiver really meets is in
    /// the receiver's row of the table, for a point and a directional light, in each type; and
    /// the table is not trivially full.
    fn the_table_keeps_every_real_blocker<N: Number>() {
        let mut random = Random(7);
        let mut listed = 0u32;
        let mut pairs = 0u32;
        for scene in 0..40 {
            let count = 12;
            let spheres: [([f64; 3], f64); 12] = core::array::from_fn(|_| {
                ([random.between(-40.0, 40.0), random.between(-10.0, 10.0), random.between(-40.0, 40.0)], random.between(0.5, 6.0))
            });
            let bounds: [ShadowBound<N>; 12] = spheres.map(|(centre, radius)| ShadowBound::new(centre, centre, radius));
            let point = [random.between(-60.0, 60.0), random.between(30.0, 90.0), random.between(-60.0, 60.0)];
            let toward = [random.between(-1.0, 1.0), 1.0, random.between(-1.0, 1.0)];
            let norm = libm::sqrt(toward.iter().map(|c| c * c).sum::<f64>());
            let toward = toward.map(|c| c / norm);
            let light = if scene % 2 == 0 { LightPosition::Point(Vector3::from_f64(point)) } else { LightPosition::Direction(Vector3::from_f64(toward)) };
            let footprints = bounds.map(|bound| bound.footprint(light).reach);
            let (mut order, mut table) = ([0u16; 12], [BlockerSet::EMPTY; 12]);
            blocker_table::<Arrays<N, 12>, N>(&footprints, &mut order, &mut table);
            for receiver in 0..count {
                let (centre, radius) = spheres[receiver];
                for blocker in (0..count).filter(|b| *b != receiver) {
                    pairs += 1;
                    let bit = table[receiver].contains(blocker);
                    listed += u32::from(bit);
                    // Sample the receiver's surface.
                    for i in 0..24 {
                        for j in 0..12 {
                            let (a, b) = (core::f64::consts::TAU * f64::from(i) / 24.0, core::f64::consts::PI * (f64::from(j) + 0.5) / 12.0);
                            let normal = [libm::cos(a) * libm::sin(b), libm::cos(b), libm::sin(a) * libm::sin(b)];
                            let p = [0, 1, 2].map(|k| centre[k] + radius * normal[k]);
                            let (d, length) = if scene % 2 == 0 {
                                let v = [0, 1, 2].map(|k| point[k] - p[k]);
                                let length = libm::sqrt(v.iter().map(|c| c * c).sum::<f64>());
                                (v.map(|c| c / length), length)
                            } else {
                                (toward, 1e9)
                            };
                            let (other, other_radius) = spheres[blocker];
                            if segment_meets_sphere(p, d, length, other, other_radius) {
                                assert!(bit, "{}: scene {scene}: receiver {receiver} is shadowed by {blocker}, not in the table", N::NAME);
                                // A point's cone, and its box, keep the ray's direction.
                                let chord = bounds[blocker].footprint(light).chord;
                                let from_light = Vector3::<N>::from_f64(d.map(|c| -c));
                                assert!(!chord.excludes(from_light) && !chord.outside_box(QuantizedDirection::new(from_light)), "{}: scene {scene}: the cone of {blocker} excludes a ray that meets it", N::NAME);
                            }
                        }
                    }
                }
            }
        }
        // An approximate square root (6 %) widens every cone so far that most pairs stay.
        if N::SQRT_ERROR_EXPONENT < -10 {
            assert!(listed < pairs / 2, "{}: the table lists {listed} of {pairs} pairs", N::NAME);
        }
    }

    /// Distance from `p` to the segment from `a` to `b`, in f64.
    fn to_segment(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
        let ab = [0, 1, 2].map(|k| b[k] - a[k]);
        let ap = [0, 1, 2].map(|k| p[k] - a[k]);
        let squared: f64 = ab.iter().map(|c| c * c).sum();
        let t = if squared > 0.0 { (ap.iter().zip(&ab).map(|(x, y)| x * y).sum::<f64>() / squared).clamp(0.0, 1.0) } else { 0.0 };
        libm::sqrt((0..3).map(|k| (a[k] + t * ab[k] - p[k]).powi(2)).sum::<f64>())
    }

    /// Rods (capsules) toward a point light: every blocker that a shadow ray from a point of a
    /// receiver really meets is in the receiver's row, and the ray's direction from the light
    /// passes the blocker's chord test (`DirectionChord::excludes`) and lies in its box
    /// (`DirectionChord::outside_box`).
    fn rods_keep_every_real_blocker<N: Number>() {
        let mut random = Random(11);
        for scene in 0..12 {
            let rods: [([f64; 3], [f64; 3], f64); 8] = core::array::from_fn(|_| {
                let start = [random.between(-40.0, 40.0), random.between(-10.0, 10.0), random.between(-40.0, 40.0)];
                let end = [0, 1, 2].map(|k| start[k] + random.between(-30.0, 30.0));
                (start, end, random.between(0.5, 4.0))
            });
            let bounds = rods.map(|(start, end, radius)| ShadowBound::<N>::new(start, end, radius));
            let light = [random.between(-60.0, 60.0), random.between(40.0, 90.0), random.between(-60.0, 60.0)];
            let footprints = bounds.map(|bound| bound.footprint(LightPosition::Point(Vector3::from_f64(light))));
            let (mut order, mut table) = ([0u16; 8], [BlockerSet::EMPTY; 8]);
            blocker_table::<Arrays<N, 8>, N>(&footprints.map(|footprint| footprint.reach), &mut order, &mut table);
            for receiver in 0..8 {
                let (start, end, radius) = rods[receiver];
                for blocker in (0..8).filter(|b| *b != receiver) {
                    let (b_start, b_end, b_radius) = rods[blocker];
                    for s in 0..=8 {
                        let q = [0, 1, 2].map(|k| start[k] + (end[k] - start[k]) * f64::from(s) / 8.0);
                        for i in 0..12 {
                            for j in 0..6 {
                                let (a, b) = (core::f64::consts::TAU * f64::from(i) / 12.0, core::f64::consts::PI * (f64::from(j) + 0.5) / 6.0);
                                let p = [q[0] + radius * libm::cos(a) * libm::sin(b), q[1] + radius * libm::cos(b), q[2] + radius * libm::sin(a) * libm::sin(b)];
                                // Does the segment from p to the light meet the blocker? (sampled)
                                let meets = (0..=200).any(|step| {
                                    let u = f64::from(step) / 200.0;
                                    let x = [0, 1, 2].map(|k| p[k] + (light[k] - p[k]) * u);
                                    to_segment(x, b_start, b_end) <= b_radius
                                });
                                if !meets {
                                    continue;
                                }
                                assert!(table[receiver].contains(blocker), "{}: scene {scene}: rod {receiver} shadowed by {blocker}, not in the table", N::NAME);
                                let v = [0, 1, 2].map(|k| p[k] - light[k]);
                                let length = libm::sqrt(v.iter().map(|c| c * c).sum::<f64>());
                                let direction = Vector3::<N>::from_f64(v.map(|c| c / length));
                                assert!(!footprints[blocker].chord.excludes(direction), "{}: scene {scene}: the chord of {blocker} excludes a ray that meets it", N::NAME);
                                let quantized = QuantizedDirection::new(direction);
                                assert!(!footprints[blocker].chord.outside_box(quantized), "{}: scene {scene}: the box of {blocker}'s chord excludes a ray that meets it", N::NAME);
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn rods_toward_a_point_light_keep_every_real_blocker() {
        rods_keep_every_real_blocker::<f64>();
        rods_keep_every_real_blocker::<f32>();
        #[cfg(feature = "fixed-point")]
        rods_keep_every_real_blocker::<crate::number::Fixed>();
        #[cfg(feature = "soft-float")]
        rods_keep_every_real_blocker::<crate::number::SoftFloat>();
    }

    #[test]
    fn the_blocker_table_is_conservative_and_selective() {
        the_table_keeps_every_real_blocker::<f64>();
        the_table_keeps_every_real_blocker::<f32>();
        #[cfg(feature = "fixed-point")]
        {
            the_table_keeps_every_real_blocker::<crate::number::Fixed>();
            the_table_keeps_every_real_blocker::<crate::number::Fixed16>();
        }
        #[cfg(feature = "soft-float")]
        the_table_keeps_every_real_blocker::<crate::number::SoftFloat>();
        #[cfg(feature = "micromath")]
        the_table_keeps_every_real_blocker::<crate::number::F32Micro>();
    }
}
