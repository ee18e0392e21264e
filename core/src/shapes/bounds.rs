//! The range of ray parameters a test accepts.

use crate::number::Number;

/// Accepts `0 < t < max`, or `t == max` too when `include_max` is set. Including the bound
/// lets the renderer break exact ties by object order rather than by test order, so that the
/// optimizations, which reorder tests, cannot change the image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval<N> {
    pub max: N,
    pub include_max: bool,
}

impl<N: Number> Interval<N> {
    /// Everything in front of the ray's origin.
    pub fn unbounded() -> Self {
        Self { max: N::MAX, include_max: true }
    }

    pub fn below(max: N) -> Self {
        Self { max, include_max: false }
    }

    pub fn contains(&self, t: N) -> bool {
        t > N::ZERO && (t < self.max || (self.include_max && t == self.max))
    }

    /// Keeps the nearer of the current best and a new candidate that is inside the interval.
    pub fn nearer(&self, best: Option<N>, candidate: N) -> Option<N> {
        if !self.contains(candidate) {
            return best;
        }
        match best {
            Some(t) if t <= candidate => Some(t),
            _ => Some(candidate),
        }
    }
}

/// An [`Interval`] for a ray whose direction was scaled by 2^−`exponent` (see
/// `shapes::scaled_to_unit`): a parameter along the scaled ray is converted back by 2^`exponent`
/// before it is compared, so bounds and ties behave exactly as on the original ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScaledInterval<N> {
    pub interval: Interval<N>,
    pub exponent: i32,
}

impl<N: Number> ScaledInterval<N> {
    /// A parameter along the scaled ray as a parameter along the original ray.
    pub fn unscale(&self, t: N) -> N {
        if self.exponent == 0 {
            t
        } else {
            t.times_power_of_two(self.exponent)
        }
    }

    pub fn contains(&self, t: N) -> bool {
        self.interval.contains(self.unscale(t))
    }
}
