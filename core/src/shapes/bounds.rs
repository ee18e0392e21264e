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
