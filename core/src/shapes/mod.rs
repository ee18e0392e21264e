//! The four unit primitives of §4.2.5 (fig 4.6), the ring torus (§5.2.1; `torus.rs`, its
//! quartic solved by bracketing in `polynomial.rs`), and NFF's open frustum and triangle, each with `intersect` (nearest hit and its
//! normal, for primary rays) and the cheaper `occluded` (any hit, for shadow rays), in the
//! object's own space (§4.4–4.6, RAYINTER.C).
//!
//! Differences from the thesis's code (see docs/deviations.md):
//! - both roots of each quadric are considered, so a ray that starts inside a primitive sees
//!   its far side (digest §11 B21);
//! - quadrics use the numerically stable forms: the discriminant from the perpendicular vector
//!   (sphere, cylinder) and the near root as `c / q` (Ray Tracing Gems ch. 7);
//! - the cone's side normal is the gradient (x, y, −z) (§11 B3);
//! - a ray component that is exactly zero never divides (no infinities in fixed point);
//! - a tangent ray (zero discriminant) counts as a hit.
//!
//! Each primitive's code is behind its own cargo feature, so a build links only what its
//! scenes use; [`Primitive::is_compiled`] says which are in.

mod bounds;
mod hit;
#[cfg(feature = "cone")]
mod cone;
#[cfg(feature = "cube")]
mod cube;
#[cfg(feature = "cylinder")]
mod cylinder;
#[cfg(feature = "disc")]
mod disc;
#[cfg(feature = "frustum")]
mod frustum;
#[cfg(feature = "torus")]
mod polynomial;
#[cfg(any(feature = "sphere", feature = "cylinder", feature = "cone", feature = "frustum"))]
mod quadratic;
#[cfg(feature = "sphere")]
mod sphere;
#[cfg(feature = "torus")]
mod torus;
#[cfg(feature = "triangle")]
pub(crate) mod triangle;

pub use bounds::{Interval, ScaledInterval};
pub use hit::Hit;

use crate::geometry::Ray;
use crate::number::Number;
use crate::model::Primitive;

impl Primitive {
    /// The nearest hit with `t` inside `interval`, if any.
    pub fn intersect<N: Number>(self, ray: &Ray<N>, interval: Interval<N>) -> Option<Hit<N>> {
        let (scaled, interval) = scaled_to_unit(ray, interval);
        let hit = self.intersect_scaled(&scaled, interval)?;
        Some(Hit { t: interval.unscale(hit.t), normal: hit.normal })
    }

    /// Whether the ray hits the primitive anywhere inside `interval`. Cheaper than
    /// [`Primitive::intersect`]: it stops at the first surface found and computes no normal.
    pub fn occluded<N: Number>(self, ray: &Ray<N>, interval: Interval<N>) -> bool {
        let (scaled, interval) = scaled_to_unit(ray, interval);
        self.occluded_scaled(&scaled, interval)
    }

    #[allow(unused_variables)]
    fn intersect_scaled<N: Number>(self, ray: &Ray<N>, interval: ScaledInterval<N>) -> Option<Hit<N>> {
        match self {
            #[cfg(feature = "cube")]
            Primitive::Cube => cube::intersect(ray, interval),
            #[cfg(feature = "sphere")]
            Primitive::Sphere => sphere::intersect(ray, interval),
            #[cfg(feature = "cylinder")]
            Primitive::Cylinder => cylinder::intersect(ray, interval),
            #[cfg(feature = "cone")]
            Primitive::Cone => cone::intersect(ray, interval),
            #[cfg(feature = "torus")]
            Primitive::Torus(tube) => torus::intersect(ray, interval, tube.radius()),
            #[cfg(feature = "frustum")]
            Primitive::Frustum(taper) => frustum::intersect(ray, interval, taper.radius()),
            #[cfg(feature = "triangle")]
            Primitive::Triangle => triangle::intersect(ray, interval),
            #[cfg(feature = "triangle")]
            Primitive::Patch(normals) => triangle::intersect_patch(ray, interval, normals),
            #[cfg(feature = "disc")]
            Primitive::Disc => disc::intersect(ray, interval),
            // A solid's leaves are intersected by its walk (`csg::solid`), never the solid.
            Primitive::Solid(_) => None,
            // Scene preparation rejects primitives that are not compiled in.
            #[cfg(not(feature = "cube"))]
            Primitive::Cube => None,
            #[cfg(not(feature = "sphere"))]
            Primitive::Sphere => None,
            #[cfg(not(feature = "cylinder"))]
            Primitive::Cylinder => None,
            #[cfg(not(feature = "cone"))]
            Primitive::Cone => None,
            #[cfg(not(feature = "torus"))]
            Primitive::Torus(_) => None,
            #[cfg(not(feature = "frustum"))]
            Primitive::Frustum(_) => None,
            #[cfg(not(feature = "triangle"))]
            Primitive::Triangle => None,
            #[cfg(not(feature = "disc"))]
            Primitive::Disc => None,
        }
    }

    #[allow(unused_variables)]
    fn occluded_scaled<N: Number>(self, ray: &Ray<N>, interval: ScaledInterval<N>) -> bool {
        match self {
            #[cfg(feature = "cube")]
            Primitive::Cube => cube::occluded(ray, interval),
            #[cfg(feature = "sphere")]
            Primitive::Sphere => sphere::occluded(ray, interval),
            #[cfg(feature = "cylinder")]
            Primitive::Cylinder => cylinder::occluded(ray, interval),
            #[cfg(feature = "cone")]
            Primitive::Cone => cone::occluded(ray, interval),
            #[cfg(feature = "torus")]
            Primitive::Torus(tube) => torus::occluded(ray, interval, tube.radius()),
            #[cfg(feature = "frustum")]
            Primitive::Frustum(taper) => frustum::occluded(ray, interval, taper.radius()),
            #[cfg(feature = "triangle")]
            Primitive::Triangle => triangle::occluded(ray, interval),
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => triangle::occluded(ray, interval),
            #[cfg(feature = "disc")]
            Primitive::Disc => disc::occluded(ray, interval),
            Primitive::Solid(_) => false,
            #[cfg(not(feature = "cube"))]
            Primitive::Cube => false,
            #[cfg(not(feature = "sphere"))]
            Primitive::Sphere => false,
            #[cfg(not(feature = "cylinder"))]
            Primitive::Cylinder => false,
            #[cfg(not(feature = "cone"))]
            Primitive::Cone => false,
            #[cfg(not(feature = "torus"))]
            Primitive::Torus(_) => false,
            #[cfg(not(feature = "frustum"))]
            Primitive::Frustum(_) => false,
            #[cfg(not(feature = "triangle"))]
            Primitive::Triangle => false,
            #[cfg(not(feature = "disc"))]
            Primitive::Disc => false,
        }
    }
}

/// Every crossing of a ray with a primitive's surface, at any `t` (behind the origin too), in
/// order along the ray, with the outward normal there (not normalised): what CSG's spans are
/// made of (`csg::leaf_spans`). At most four (a torus); a convex primitive has two, or one where
/// the ray touches it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossings<N> {
    pub list: [(N, crate::geometry::Vector3<N>); 4],
    pub len: usize,
}

impl<N: Number> Crossings<N> {
    pub fn iter(&self) -> impl Iterator<Item = &(N, crate::geometry::Vector3<N>)> + '_ {
        self.list.iter().take(self.len)
    }

    /// Sorted by `t` from any order; `None` entries are skipped.
    fn sorted<const K: usize>(found: [Option<(N, crate::geometry::Vector3<N>)>; K], unscale: impl Fn(N) -> N) -> Self {
        let mut crossings = Self { list: [(N::ZERO, crate::geometry::Vector3::zero()); 4], len: 0 };
        for (t, normal) in found.into_iter().flatten() {
            let t = unscale(t);
            let Some(slot) = crossings.list.get_mut(crossings.len) else { break };
            *slot = (t, normal);
            crossings.len += 1;
            // Insertion: move it back past later crossings.
            let mut index = crossings.len - 1;
            while index > 0 && crossings.list.get(index - 1).is_some_and(|before| before.0 > t) {
                if let Some([before, here]) = crossings.list.get_mut(index - 1..=index) {
                    core::mem::swap(before, here);
                }
                index -= 1;
            }
        }
        crossings
    }
}

impl Primitive {
    /// Every crossing of the ray with the primitive's surface (see [`Crossings`]).
    #[allow(unused_variables)]
    pub fn crossings<N: Number>(self, ray: &Ray<N>) -> Crossings<N> {
        let (scaled, interval) = scaled_to_unit(ray, Interval::unbounded());
        let unscale = |t: N| interval.unscale(t);
        let ray = &scaled;
        match self {
            #[cfg(feature = "cube")]
            Primitive::Cube => Crossings::sorted(cube::crossings(ray), unscale),
            #[cfg(feature = "sphere")]
            Primitive::Sphere => Crossings::sorted(sphere::crossings(ray), unscale),
            #[cfg(feature = "cylinder")]
            Primitive::Cylinder => Crossings::sorted(cylinder::crossings(ray), unscale),
            #[cfg(feature = "cone")]
            Primitive::Cone => Crossings::sorted(cone::crossings(ray), unscale),
            #[cfg(feature = "torus")]
            Primitive::Torus(tube) => Crossings::sorted(torus::all_crossings(ray, tube.radius()), unscale),
            #[cfg(feature = "frustum")]
            Primitive::Frustum(taper) => Crossings::sorted(frustum::crossings(ray, taper.radius()), unscale),
            #[cfg(feature = "triangle")]
            Primitive::Triangle => Crossings::sorted(triangle::crossings(ray), unscale),
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => Crossings::sorted(triangle::crossings(ray), unscale),
            #[cfg(feature = "disc")]
            Primitive::Disc => Crossings::sorted(disc::crossings(ray), unscale),
            Primitive::Solid(_) => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "cube"))]
            Primitive::Cube => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "sphere"))]
            Primitive::Sphere => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "cylinder"))]
            Primitive::Cylinder => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "cone"))]
            Primitive::Cone => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "torus"))]
            Primitive::Torus(_) => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "frustum"))]
            Primitive::Frustum(_) => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "triangle"))]
            Primitive::Triangle => Crossings::sorted::<0>([], unscale),
            #[cfg(not(feature = "disc"))]
            Primitive::Disc => Crossings::sorted::<0>([], unscale),
        }
    }
}

/// The ray with its direction scaled by a power of two so that its largest component lies in
/// [1, 2), and the interval that converts parameters back. Object-space directions have
/// components of about one over the object's size; in fixed point their squares (the
/// quadratics' A) keep few significant bits for large objects (a cone 7000 units across missed
/// by hundreds of units in Q32.32). A power of two would change no floating-point result, so
/// floats skip it.
fn scaled_to_unit<N: Number>(ray: &Ray<N>, interval: Interval<N>) -> (Ray<N>, ScaledInterval<N>) {
    if N::FLOATING_POINT {
        return (*ray, ScaledInterval { interval, exponent: 0 });
    }
    let exponent = ray.direction.largest_component().binary_exponent().unwrap_or(0);
    let scaled = Ray { origin: ray.origin, direction: ray.direction.times_power_of_two(-exponent) };
    (scaled, ScaledInterval { interval, exponent: -exponent })
}

#[cfg(test)]
mod tests;
