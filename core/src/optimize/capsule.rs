//! Bounding capsules seen from the eye, in the number type (§4.7.3 Extents, §4.7.5 Sortlist):
//! each object's screen octagon and its depth bound, computed per frame from a capsule (a
//! segment and a radius: a point for spheres and cubes, the axis for cylinders and cones) with a
//! few products, two square roots and a division per end, and no `f64`.
//!
//! The capsule is convex and so is its projection (a perspective projection maps the convex
//! hull of points in front of the eye to the convex hull of their images), so a linear
//! function of the image position ranges over the projected capsule exactly as over the two
//! projected end balls together. Over a ball, with q = p − eye, the image's `αX + βY` is
//! `const + span·(g·q)/q_z` (g = (α, β, 0), span the eye's distance to the view plane), whose
//! extremes are where the planes through the eye touch the ball:
//! `R± = (a·b ± r·√(a² + (b² − r²)·|g|²)) / (b² − r²)`, a = g·c, b = c_z (c the centre from the
//! eye). For a parallel view the image position is linear in p and the range is `f(c) ± r·|∇f|`.
//! Four such functions (column, row and the two diagonals) give the octagon of
//! [`Extent`].
//!
//! Conservative: the capsule is widened before conversion, every range by 1/8 pixel (the
//! rounding of the number type's rays and hits, as `projection::MARGIN`) plus a relative 2⁻¹⁶
//! and, for fixed point, 2¹⁷ steps of its resolution; a ball that reaches the eye plane covers
//! the whole screen.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::extents::Extent;
use crate::camera::Camera;
use crate::geometry::Vector3;
use crate::number::Number;

/// A capsule: the points within `radius` of the segment from `start` to `end`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Capsule<N> {
    pub start: Vector3<N>,
    pub end: Vector3<N>,
    /// `N::MAX`: unknown (covers everything).
    pub radius: N,
}

impl<N: Number> Capsule<N> {
    pub const UNSET: Self = Self {
        start: Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO },
        end: Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO },
        radius: N::MAX,
    };

    /// From the capsule in `f64` (the object's bounding capsule), widened by a relative 2⁻¹⁶ of
    /// the scene's scale there, which covers the conversion's rounding. `UNSET` when a value does
    /// not fit the type.
    pub fn new(start: [f64; 3], end: [f64; 3], radius: f64) -> Self {
        let largest = start.iter().chain(end.iter()).fold(0.0f64, |m, c| m.max(c.abs()));
        let widened = radius * (1.0 + 1.0 / 65536.0) + (largest + radius) / 65536.0;
        let fits = start.iter().chain(end.iter()).all(|c| N::can_represent(*c)) && N::can_represent(widened) && widened.is_finite();
        if !fits {
            return Self::UNSET;
        }
        Self { start: Vector3::from_f64(start), end: Vector3::from_f64(end), radius: N::from_f64(widened) }
    }
}

/// What a capsule covers on the screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Covered {
    /// The ranges of column, row, column + row and column − row + height − 1 (continuous
    /// image coordinates, not yet widened).
    Ranges([(i32, i32); 4]),
    Whole,
    Invisible,
}

/// The camera's mapping from the view plane to image coordinates, in the number type.
#[derive(Clone, Copy, Debug)]
pub struct ScreenMap<N> {
    pub width: u16,
    pub height: u16,
    /// View-plane x of column 0, y of the bottom row.
    origin: [N; 2],
    /// Pixels per view-plane unit along x and y (zero for a single column or row).
    scale: [N; 2],
    /// View-plane units between samples.
    spacing: [N; 2],
    view_plane: N,
    eye: Option<Vector3<N>>,
    direction: Option<Vector3<N>>,
}

/// The four image functions: column, row, column + row, column − row + height − 1.
const FUNCTIONS: usize = 4;

/// 1/8 pixel: hits are never found farther outside the exact silhouette (`projection::MARGIN`).
const PIXEL_MARGIN_EXPONENT: i32 = -3;

impl<N: Number> ScreenMap<N> {
    pub fn new(camera: &Camera<N>) -> Self {
        let (origin, spacing, view_plane) = camera.sampling();
        let inverse = |s: N| if s == N::ZERO { N::ZERO } else { N::ONE.checked_div(s).unwrap_or(N::ZERO) };
        Self {
            width: camera.width(),
            height: camera.height(),
            origin,
            scale: [inverse(spacing[0]), inverse(spacing[1])],
            spacing,
            view_plane,
            eye: camera.eye(),
            direction: camera.parallel_direction(),
        }
    }

    /// The gradients (α, β) of the four functions with respect to the view-plane position
    /// relative to the sample grid's origin, (X − x0, Y − y0): column = α(X − x0),
    /// row = (h − 1) − β(Y − y0), their sum, and column − row + h − 1; and their constant parts.
    fn functions(&self) -> [([N; 2], N); FUNCTIONS] {
        let [sx, sy] = self.scale;
        let last_row = N::from_i32(i32::from(self.height) - 1);
        [([sx, N::ZERO], N::ZERO), ([N::ZERO, -sy], last_row), ([sx, -sy], last_row), ([sx, sy], N::ZERO)]
    }

    /// The ranges of the four functions over the ball, or `None` when it reaches the eye plane
    /// (or the parallel rays run along the view plane); `Some(None)`: wholly behind the eye.
    fn ball(&self, centre: Vector3<N>, radius: N) -> Option<Option<[(N, N); FUNCTIONS]>> {
        let mut ranges = [(N::ZERO, N::ZERO); FUNCTIONS];
        let [x0, y0] = self.origin;
        if let Some(eye) = self.eye {
            let span = self.view_plane - eye.z;
            let c = centre - eye;
            // The ratio is unchanged by scaling c and r together: to about one, so fixed point
            // keeps its precision and its squares their range.
            let largest = c.largest_component().max(radius);
            let exponent = if N::FLOATING_POINT { 0 } else { -largest.binary_exponent().unwrap_or(0) };
            let (c, r) = (c.times_power_of_two(exponent), radius.times_power_of_two(exponent));
            let b = c.z;
            let clearance = b * b - r * r;
            if !(clearance > (b * b).times_power_of_two(-12)) {
                return None;
            }
            if (b > N::ZERO) != (span > N::ZERO) {
                return Some(None);
            }
            let inverse = N::ONE.checked_div(clearance)?;
            for (range, ([alpha, beta], constant)) in ranges.iter_mut().zip(self.functions()) {
                // R is linear in (α, β) for a positive factor: computed for (α, β)/2^k.
                let k = alpha.abs().max(beta.abs()).binary_exponent().unwrap_or(0);
                let (alpha_k, beta_k) = (alpha.times_power_of_two(-k), beta.times_power_of_two(-k));
                let a = alpha_k * c.x + beta_k * c.y;
                let root = r * (a * a + clearance * (alpha_k * alpha_k + beta_k * beta_k)).sqrt();
                let low = ((a * b - root) * inverse).times_power_of_two(k);
                let high = ((a * b + root) * inverse).times_power_of_two(k);
                // The eye's image position plus span times the ratio.
                let base = alpha * (eye.x - x0) + beta * (eye.y - y0) + constant;
                let (u, v) = (base + span * low, base + span * high);
                if near_saturation(u) || near_saturation(v) {
                    return None;
                }
                *range = (u.min(v), u.max(v));
            }
            return Some(Some(ranges));
        }
        let d = self.direction?;
        if !(d.z.abs() > N::ONE.times_power_of_two(-10)) {
            return None;
        }
        let inverse_z = N::ONE.checked_div(d.z)?;
        // X = p.x − (p.z − D)·d.x/d.z, Y likewise: linear in p.
        let (kx, ky) = (d.x * inverse_z, d.y * inverse_z);
        for (range, ([alpha, beta], constant)) in ranges.iter_mut().zip(self.functions()) {
            let slope = -(alpha * kx + beta * ky);
            let value = alpha * (centre.x - x0) + beta * (centre.y - y0) + slope * (centre.z - self.view_plane) + constant;
            let reach = radius * Vector3::new(alpha, beta, slope).length();
            // A fixed-point range saturates silently (fuzzing: a cube 8000 across in fixed16):
            // near the type's limit the ball covers the whole screen instead.
            if near_saturation(value.abs() + reach) {
                return None;
            }
            *range = (value - reach, value + reach);
        }
        Some(Some(ranges))
    }

    /// What the capsule covers: the union of its two end balls' ranges.
    pub fn cover(&self, capsule: &Capsule<N>) -> Covered {
        self.cover_and_stadium(capsule).0
    }

    /// [`ScreenMap::cover`], and the capsule's silhouette as a [`Stadium`] when it is on or
    /// near the screen: each end ball's image lies in the disc about the centre of its column
    /// and row ranges through their corners, and the silhouette in the hull of the two discs.
    pub fn cover_and_stadium(&self, capsule: &Capsule<N>) -> (Covered, Option<Stadium>) {
        if capsule.radius == N::MAX {
            return (Covered::Whole, None);
        }
        let (Some(first), Some(second)) = (self.ball(capsule.start, capsule.radius), self.ball(capsule.end, capsule.radius)) else {
            return (Covered::Whole, None);
        };
        let (first, second) = match (first, second) {
            (None, None) => return (Covered::Invisible, None),
            // One end in front of the eye, one behind: the segment crosses the eye plane.
            (Some(_), None) | (None, Some(_)) => return (Covered::Whole, None),
            (Some(a), Some(b)) => (a, b),
        };
        let stadium = Stadium::of_discs(disc(self.height, &first), disc(self.height, &second));
        let mut out = [(0, 0); FUNCTIONS];
        for (k, slot) in out.iter_mut().enumerate() {
            let (low, high) = (first[k].0.min(second[k].0), first[k].1.max(second[k].1));
            // Diagonals: a hit within the margin of the silhouette along x and y is within
            // twice it along a diagonal.
            let pixels = if k < 2 { 0 } else { 1 };
            let margin = |value: N| {
                N::ONE.times_power_of_two(PIXEL_MARGIN_EXPONENT + pixels)
                    + value.abs().times_power_of_two(-16)
                    + N::RESOLUTION.times_power_of_two(17)
            };
            // ceil(low − m) = −floor(m − low).
            let first = (margin(low) - low).floor_to_i32().saturating_neg();
            let last = (high + margin(high)).floor_to_i32();
            *slot = (first, last);
        }
        (Covered::Ranges(out), stadium)
    }

    /// A lower bound of the ray parameter `t` of any primary-ray hit on the capsule (primary
    /// directions are unit vectors), lowered for rounding; `None` when none is known.
    pub fn depth_bound(&self, capsule: &Capsule<N>) -> Option<N> {
        if capsule.radius == N::MAX {
            return None;
        }
        let bound = if let Some(eye) = self.eye {
            // Perspective: t is the distance from the eye.
            let axis = capsule.end - capsule.start;
            let squared = axis.dot(axis);
            let along = if squared > N::ZERO { (eye - capsule.start).dot(axis).checked_div(squared).unwrap_or(N::ZERO) } else { N::ZERO };
            let along = along.max(N::ZERO).min(N::ONE);
            let nearest = capsule.start + axis * along;
            (eye - nearest).length() - capsule.radius
        } else {
            // Parallel: t = (p.z − D)/d.z.
            let d = self.direction?;
            if !(d.z.abs() > N::ONE.times_power_of_two(-10)) {
                return None;
            }
            let inverse = N::ONE.checked_div(d.z)?;
            let at = |p: Vector3<N>| (p.z - self.view_plane) * inverse;
            at(capsule.start).min(at(capsule.end)) - capsule.radius * inverse.abs()
        };
        // Lowered by a relative 2⁻¹⁰ (as Sortlist's f64 bound by 10⁻³): the hit's own t is
        // rounded in the number type.
        Some(bound - (bound.abs() + N::ONE).times_power_of_two(-10))
    }
}

impl<N: Number> ScreenMap<N> {
    /// A lower bound of `t` for the part of the capsule seen through a block of pixels
    /// (columns and rows inclusive), for a grid cell's entry: the capsule lies within `radius`
    /// of its axis, so an axis point can matter only if it is within `radius` of each plane
    /// bounding the rays through the block (widened by the pixel margin); the bound is the
    /// nearest such axis point's `t` less the radius. `Some(N::MAX)` when no axis point can be
    /// seen there; `None` when no bound is found. Lowered for rounding like
    /// [`ScreenMap::depth_bound`].
    pub fn block_depth_bound(&self, capsule: &Capsule<N>, columns: (u16, u16), rows: (u16, u16)) -> Option<N> {
        if capsule.radius == N::MAX {
            return None;
        }
        let [x0, y0] = self.origin;
        let [sx, sy] = self.spacing;
        // The block's view-plane rectangle, widened by 1/4 pixel.
        let widen = N::ONE.times_power_of_two(-2);
        let last_row = i32::from(self.height) - 1;
        let at = |pixels: u16, spacing: N, origin: N, grow: N| origin + (N::from_i32(i32::from(pixels)) + grow) * spacing;
        let low_x = at(columns.0, sx, x0, -widen);
        let high_x = at(columns.1, sx, x0, widen);
        // Rows run down from the top; y grows up.
        let low_y = y0 + (N::from_i32(last_row - i32::from(rows.1)) - widen) * sy;
        let high_y = y0 + (N::from_i32(last_row - i32::from(rows.0)) + widen) * sy;
        let (a, ab, radius) = (capsule.start, capsule.end - capsule.start, capsule.radius);
        // Constraints g·p + k ≥ 0 on the points seen through the block, each relaxed by the
        // radius: g·(a + s·ab) + k + radius·|g| ≥ 0 for the axis point at s.
        let constraints: [(Vector3<N>, N); 5];
        let depth_of: Vector3<N>;
        let mut depth_offset = N::ZERO;
        let slack: N;
        let perspective = self.eye;
        match perspective {
            Some(e) => {
                let span = self.view_plane - e.z;
                let inverse = N::ONE.checked_div(span)?;
                // X(p) ≥ x ⟺ (p.x − e.x) − (x − e.x)(p.z − e.z)/span ≥ 0.
                let plane = |x: N, axis: usize, sign: N| {
                    let mut g = [N::ZERO; 3];
                    g[axis] = sign;
                    g[2] = -(sign * (x - e.component(axis)) * inverse);
                    let g = Vector3::new(g[0], g[1], g[2]);
                    (g, -g.dot(e))
                };
                // w = (p.z − e.z)/span > 0 in front of the eye whatever the sign of span, so
                // the four side planes keep their signs; the fifth is the eye plane.
                let sign = if span > N::ZERO { N::ONE } else { -N::ONE };
                constraints = [
                    plane(low_x, 0, N::ONE),
                    plane(high_x, 0, -N::ONE),
                    plane(low_y, 1, N::ONE),
                    plane(high_y, 1, -N::ONE),
                    (Vector3::new(N::ZERO, N::ZERO, sign), -(sign * e.z)),
                ];
                depth_of = e;
                slack = radius;
            }
            None => {
                let d = self.direction?;
                if !(d.z.abs() > N::ONE.times_power_of_two(-10)) {
                    return None;
                }
                let inverse = N::ONE.checked_div(d.z)?;
                let (kx, ky) = (d.x * inverse, d.y * inverse);
                // X(p) = p.x − (p.z − D)·kx ≥ x, and so on; t(p) = (p.z − D)/d.z.
                let plane = |x: N, axis: usize, sign: N, k: N| {
                    let mut g = [N::ZERO; 3];
                    g[axis] = sign;
                    g[2] = -(sign * k);
                    (Vector3::new(g[0], g[1], g[2]), sign * (k * self.view_plane - x))
                };
                constraints = [
                    plane(low_x, 0, N::ONE, kx),
                    plane(high_x, 0, -N::ONE, kx),
                    plane(low_y, 1, N::ONE, ky),
                    plane(high_y, 1, -N::ONE, ky),
                    plane(low_x, 0, N::ONE, kx),
                ];
                depth_of = Vector3::new(N::ZERO, N::ZERO, inverse);
                depth_offset = -(self.view_plane * inverse);
                slack = radius * inverse.abs();
            }
        }
        // The range of s ∈ [0, 1] meeting every relaxed constraint.
        let (mut s_low, mut s_high) = (N::ZERO, N::ONE);
        for (g, k) in constraints {
            let length = g.length();
            let value = g.dot(a) + k + radius * length + (g.dot(a).abs() + k.abs() + radius * length).times_power_of_two(-16);
            let rate = g.dot(ab);
            if rate == N::ZERO {
                if value < N::ZERO {
                    return Some(N::MAX);
                }
            } else if let Some(s) = (-value).checked_div(rate) {
                if rate > N::ZERO {
                    s_low = s_low.max(s);
                } else {
                    s_high = s_high.min(s);
                }
            }
        }
        if !(s_low <= s_high) {
            return Some(N::MAX);
        }
        let nearest = match perspective {
            Some(_) => {
                let e = depth_of;
                let squared = ab.dot(ab);
                let s = if squared > N::ZERO {
                    (e - a).dot(ab).checked_div(squared).unwrap_or(s_low).max(s_low).min(s_high)
                } else {
                    s_low
                };
                (a + ab * s - e).length()
            }
            None => {
                let at = |s: N| depth_of.dot(a + ab * s) + depth_offset;
                at(s_low).min(at(s_high))
            }
        };
        let bound = nearest - slack;
        Some(bound - (bound.abs() + N::ONE).times_power_of_two(-10))
    }
}

/// The disc about the centre of a ball's column and row ranges through the farthest corner of
/// its octagon (the rectangle cut by the diagonal ranges), with the pixel margin: (centre,
/// radius) in pixels. For a round image the octagon's corners are 8 % beyond it (the
/// rectangle's would be 41 %).
fn disc<N: Number>(height: u16, ranges: &[(N, N); FUNCTIONS]) -> ([N; 2], N) {
    let [(c1, c2), (r1, r2), (s1, s2), (d1, d2)] = *ranges;
    let half = |low: N, high: N| (high - low).times_power_of_two(-1);
    let centre = [c1 + half(c1, c2), r1 + half(r1, r2)];
    // About the centre: |u| ≤ a, |v| ≤ b, u + v ∈ [σ1, σ2], u − v ∈ [δ1, δ2].
    let (a, b) = (half(c1, c2), half(r1, r2));
    let shift = N::from_i32(i32::from(height) - 1);
    let (sum, difference) = (centre[0] + centre[1], centre[0] - centre[1] + shift);
    let (sigma1, sigma2, delta1, delta2) = (s1 - sum, s2 - sum, d1 - difference, d2 - difference);
    // Squares of hundreds of pixels saturate in fixed point (fuzzing: a cube 8000 across in
    // fixed16 got a disc far too small): the distances are scaled to below 64 first and the
    // radius scaled back. Floating point needs no scaling.
    let largest = [a, b, sigma1, sigma2, delta1, delta2].iter().fold(N::ZERO, |m, value| m.max(value.abs()));
    let exponent = if N::FLOATING_POINT { 0 } else { largest.binary_exponent().map_or(0, |e| (e - 5).max(0)) };
    let scaled = |value: N| value.times_power_of_two(-exponent);
    let (a, b, sigma1, sigma2, delta1, delta2) = (scaled(a), scaled(b), scaled(sigma1), scaled(sigma2), scaled(delta1), scaled(delta2));
    let within = |value: N, limit: N| value.max(-limit).min(limit);
    let mut farthest = N::ZERO;
    let mut consider = |u: N, v: N| farthest = farthest.max(u * u + v * v);
    for u in [a, -a] {
        // On the side u: v within the box and both diagonal bands.
        consider(u, within((sigma1 - u).max(u - delta2), b));
        consider(u, within((sigma2 - u).min(u - delta1), b));
    }
    for v in [b, -b] {
        consider(within((sigma1 - v).max(delta1 + v), a), v);
        consider(within((sigma2 - v).min(delta2 + v), a), v);
    }
    for sigma in [sigma1, sigma2] {
        for delta in [delta1, delta2] {
            consider(within(half(-delta, sigma), a), within(half(delta, sigma), b));
        }
    }
    // Rounded up by a step of the scaled type, so the scaling never shrinks the disc.
    let radius = (farthest.sqrt() + N::RESOLUTION).times_power_of_two(exponent);
    let largest = centre[0].abs().max(centre[1].abs()) + radius;
    let margin = N::ONE.times_power_of_two(PIXEL_MARGIN_EXPONENT) + largest.times_power_of_two(-16) + N::RESOLUTION.times_power_of_two(17);
    (centre, radius + radius.times_power_of_two(N::SQRT_ERROR_EXPONENT) + margin)
}

/// A silhouette in image coordinates, in sixteenths of a pixel: the points within `radius` of
/// the segment between `ends` (the hull of two discs of at most that radius). Integer
/// arithmetic only, for the grid's per-cell rectangles of thin oblique objects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stadium {
    pub ends: [[i16; 2]; 2],
    pub radius: i16,
}

/// Sixteenths of a pixel per pixel.
const SUBPIXELS: i32 = 1 << SUBPIXEL_BITS;
const SUBPIXEL_BITS: u32 = 4;
/// The segment parameter's scale in [`Stadium::block`].
const T_ONE: i32 = 1 << T_BITS;
const T_BITS: u32 = 10;
/// Coordinates beyond this many pixels are not converted (sixteenths fit an `i16`).
const STADIUM_LIMIT: i32 = 2_000;

impl Stadium {
    /// From two discs in pixels; `None` when a value is beyond [`STADIUM_LIMIT`] pixels.
    fn of_discs<N: Number>(first: ([N; 2], N), second: ([N; 2], N)) -> Option<Self> {
        let limit = N::from_i32(STADIUM_LIMIT);
        let fits = |v: N| v.abs() < limit;
        let sixteenths = |v: N| v.times_power_of_two(4).floor_to_i32().clamp(-32_767, 32_767) as i16;
        let radius = first.1.max(second.1);
        if !(fits(first.0[0]) && fits(first.0[1]) && fits(second.0[0]) && fits(second.0[1]) && fits(radius)) {
            return None;
        }
        // Each centre is floored to a sixteenth: one more sixteenth of radius covers that.
        Some(Self {
            ends: [[sixteenths(first.0[0]), sixteenths(first.0[1])], [sixteenths(second.0[0]), sixteenths(second.0[1])]],
            radius: sixteenths(radius).saturating_add(2),
        })
    }

    /// A rectangle within the block (columns and rows inclusive) holding every pixel of it whose
    /// sample point lies in the stadium; `None` when there is none. The segment clipped to the
    /// block widened by the radius (Liang–Barsky, its parameter rounded outward), boxed, and
    /// widened by the radius again.
    pub fn block(&self, columns: (u16, u16), rows: (u16, u16)) -> Option<((u16, u16), (u16, u16))> {
        let r = i32::from(self.radius);
        let low = [i32::from(columns.0) * SUBPIXELS - r, i32::from(rows.0) * SUBPIXELS - r];
        let high = [i32::from(columns.1) * SUBPIXELS + r, i32::from(rows.1) * SUBPIXELS + r];
        let [[p0, p1], [q0, q1]] = self.ends;
        let (p, q) = ([i32::from(p0), i32::from(p1)], [i32::from(q0), i32::from(q1)]);
        let d = [q[0] - p[0], q[1] - p[1]];
        let bounds = [columns, rows];
        let mut out = [(0u16, 0u16); 2];
        // The pixels whose sample (16·index) lies in [lo, hi] along axis k, within the block.
        let pixels = |k: usize, lo: i32, hi: i32| -> Option<(u16, u16)> {
            let (first, last) = (ceil_shift(lo, SUBPIXEL_BITS), hi >> SUBPIXEL_BITS);
            let (block_first, block_last) = bounds.get(k).map_or((0, -1), |b| (i32::from(b.0), i32::from(b.1)));
            let (first, last) = (first.max(block_first), last.min(block_last));
            (first <= last).then_some((first as u16, last as u16))
        };
        if d == [0, 0] {
            // A disc (a sphere's silhouette): its box, as the segment's path below gives it.
            for (k, slot) in out.iter_mut().enumerate() {
                if p[k] < low[k] || p[k] > high[k] {
                    return None;
                }
                *slot = pixels(k, p[k] - r, p[k] + r)?;
            }
            return Some((out[0], out[1]));
        }
        let (mut t0, mut t1) = (0, T_ONE);
        for k in 0..2 {
            let (pk, dk, lk, hk) = (p[k], d[k], low[k], high[k]);
            if dk == 0 {
                if pk < lk || pk > hk {
                    return None;
                }
                continue;
            }
            let (a, b) = ((lk - pk) * T_ONE, (hk - pk) * T_ONE);
            let (enter, leave) = if dk > 0 { (a, b) } else { (b, a) };
            t0 = t0.max(divide_floor(enter, dk));
            t1 = t1.min(divide_ceil(leave, dk));
        }
        if t0 > t1 {
            return None;
        }
        for (k, slot) in out.iter_mut().enumerate() {
            let (u, v) = (p[k] * T_ONE + d[k] * t0, p[k] * T_ONE + d[k] * t1);
            *slot = pixels(k, (u.min(v) >> T_BITS) - r, ceil_shift(u.max(v), T_BITS) + r)?;
        }
        Some((out[0], out[1]))
    }
}

impl Stadium {
    /// Whether the sample point of pixel (column, row) lies in the stadium: its squared
    /// distance to the segment against the squared radius, in `i64` (a product that would
    /// overflow counts as inside).
    #[inline]
    pub fn contains(&self, column: u16, row: u16) -> bool {
        let [[a0, a1], [b0, b1]] = self.ends;
        let (a, b) = ([i64::from(a0), i64::from(a1)], [i64::from(b0), i64::from(b1)]);
        let point = [i64::from(column) * i64::from(SUBPIXELS), i64::from(row) * i64::from(SUBPIXELS)];
        let r = i64::from(self.radius);
        let d = [b[0] - a[0], b[1] - a[1]];
        let w = [point[0] - a[0], point[1] - a[1]];
        let along = w[0] * d[0] + w[1] * d[1];
        let squared = d[0] * d[0] + d[1] * d[1];
        let from = |p: [i64; 2]| {
            let v = [point[0] - p[0], point[1] - p[1]];
            v[0] * v[0] + v[1] * v[1]
        };
        if along <= 0 || squared == 0 {
            return from(a) <= r * r;
        }
        if along >= squared {
            return from(b) <= r * r;
        }
        // Perpendicular: |w × d|² ≤ r²·|d|².
        let cross = w[0] * d[1] - w[1] * d[0];
        match (cross.checked_mul(cross), (r * r).checked_mul(squared)) {
            (Some(left), Some(right)) => left <= right,
            _ => true,
        }
    }
}

/// ⌊a / b⌋ for b ≠ 0 (wrapping: the operands here are far from `i32::MIN`).
fn divide_floor(a: i32, b: i32) -> i32 {
    if b == 0 {
        return a;
    }
    let quotient = a.wrapping_div(b);
    if a.wrapping_rem(b) != 0 && ((a < 0) != (b < 0)) {
        quotient - 1
    } else {
        quotient
    }
}

/// ⌈a / 2^bits⌉ (an arithmetic shift is ⌊a / 2^bits⌋).
fn ceil_shift(a: i32, bits: u32) -> i32 {
    -(a.wrapping_neg() >> bits)
}

/// ⌈a / b⌉ for b ≠ 0.
fn divide_ceil(a: i32, b: i32) -> i32 {
    -divide_floor(a.wrapping_neg(), b)
}

impl Extent {
    /// The octagon from [`ScreenMap::cover`]'s ranges, clipped to the screen.
    pub fn of_cover<N: Number>(screen: &ScreenMap<N>, covered: &Covered) -> Self {
        let ranges = match covered {
            Covered::Ranges(ranges) => ranges,
            Covered::Whole => {
                return Self { first_column: 0, last_column: screen.width - 1, first_row: 0, last_row: screen.height - 1, diagonal: [0, u16::MAX, 0, u16::MAX] }
            }
            Covered::Invisible => return Self::EMPTY,
        };
        #[allow(clippy::unnecessary_lazy_evaluations, reason = "left as written while the optimizations are being reworked elsewhere")]
        let clip = |(low, high): (i32, i32), count: i32| -> Option<(u16, u16)> {
            let (first, last) = (low.max(0), high.min(count - 1));
            (first <= last).then(|| (first as u16, last as u16))
        };
        let (width, height) = (i32::from(screen.width), i32::from(screen.height));
        let diagonal_count = width + height - 1;
        match (clip(ranges[0], width), clip(ranges[1], height), clip(ranges[2], diagonal_count), clip(ranges[3], diagonal_count)) {
            (Some((first_column, last_column)), Some((first_row, last_row)), Some((s1, s2)), Some((d1, d2))) => {
                Self { first_column, last_column, first_row, last_row, diagonal: [s1, s2, d1, d2] }
            }
            _ => Self::EMPTY,
        }
    }
}

/// Whether a screen coordinate lies within a quarter of the number type's largest value, where
/// a fixed-point sum may have saturated (never for floating point's).
fn near_saturation<N: Number>(value: N) -> bool {
    value.abs() >= N::MAX.times_power_of_two(-2)
}

#[cfg(test)]
mod tests {
    use super::Stadium;

    /// A small deterministic generator (xorshift), so the test needs no crate.
    fn next(state: &mut u32) -> u32 {
        *state ^= *state << 13;
        *state ^= *state >> 17;
        *state ^= *state << 5;
        *state
    }

    /// Every pixel of a block whose sample lies in the stadium is inside `block`'s rectangle,
    /// and the rectangle lies in the block: for discs (a sphere's silhouette, the fast path),
    /// axis-aligned and oblique segments.
    #[test]
    fn a_block_holds_every_pixel_of_the_stadium_in_it() {
        let mut state = 0x2545_f491;
        let coordinate = |state: &mut u32, span: u32| (next(state) % span) as i16 - 160;
        let (mut nonempty, mut discs) = (0, 0);
        for case in 0..3000 {
            let first = [coordinate(&mut state, 1600), coordinate(&mut state, 1000)];
            let second = match case % 4 {
                0 => first,
                1 => [first[0], coordinate(&mut state, 1000)],
                2 => [coordinate(&mut state, 1600), first[1]],
                _ => [coordinate(&mut state, 1600), coordinate(&mut state, 1000)],
            };
            let stadium = Stadium { ends: [first, second], radius: (next(&mut state) % 200) as i16 + 1 };
            let c0 = (next(&mut state) % 90) as u16;
            let r0 = (next(&mut state) % 60) as u16;
            let columns = (c0, c0 + (next(&mut state) % 12) as u16);
            let rows = (r0, r0 + (next(&mut state) % 8) as u16);
            let found = stadium.block(columns, rows);
            if let Some(((a, b), (c, d))) = found {
                nonempty += 1;
                discs += usize::from(first == second);
                assert!(a <= b && c <= d && a >= columns.0 && b <= columns.1 && c >= rows.0 && d <= rows.1, "{stadium:?} {columns:?} {rows:?} -> {found:?}");
            }
            for row in rows.0..=rows.1 {
                for column in columns.0..=columns.1 {
                    if stadium.contains(column, row) {
                        let inside = found.is_some_and(|((a, b), (c, d))| (a..=b).contains(&column) && (c..=d).contains(&row));
                        assert!(inside, "{stadium:?} {columns:?} {rows:?}: pixel ({column}, {row}) is in the stadium, not in {found:?}");
                    }
                }
            }
        }
        assert!(nonempty > 300 && discs > 20, "the cases must reach the stadiums: {nonempty} nonempty, {discs} discs");
    }
}
