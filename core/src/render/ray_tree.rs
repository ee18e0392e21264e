//! The ray tree (thesis §5.2.2, after Whitted 1980): at a hit, the local term plus
//! `kr·reflected + kt·transmitted`, each node's colour clamped to full scale.
//!
//! No recursion: the tree is walked depth first with an explicit stack of nodes whose capacity
//! `DEPTH` is a const generic, so the stack a render needs is bounded by the type. A node
//! spawns its reflected ray, then its transmitted one; the tree stops at the scene's `depth`
//! (generations, the primary hit being the first) and where a branch's weight (the product of
//! the shares down to it) falls below 1/256. Media do not nest: a ray entering an object goes
//! from air (index 1) into the object's `ior`, a ray leaving goes back into air. Total internal
//! reflection sends the transmitted share along the mirror direction.
//!
//! Secondary rays start off the surface by the shadow rays' offset (`shadow_origin`), on the
//! side they travel into: a reflected ray on the incoming side, a refracted one on the far side.

use super::direct_lighting::direct_lighting;
use super::intersect::NearestHit;
use super::secondary::nearest_secondary_hit;
use super::shadow_ray::{shadow_origin, ShadowCache, ShadowCulling};
use super::Statistics;
use super::surface::{NodeColours, SurfacePoint};
use crate::camera::PixelPosition;
use crate::geometry::reflection::{reflected, refracted};
use crate::geometry::Ray;
use crate::number::Number;
use crate::config::Config;
use crate::storage::List;
use crate::scene::{Optics, Prepared};

/// One node of the tree on the stack.
#[derive(Clone, Copy, Debug)]
struct Node<N> {
    at: SurfacePoint<N>,
    optics: Optics<N>,
    /// The product of the shares from the primary hit down to this node.
    weight: N,
    /// The share of this node's colour in its parent's (kr or kt of the parent).
    share: N,
    colour: [N; 3],
    next: Branch,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Branch {
    Reflected,
    Transmitted,
    Done,
}

/// What the walk needs besides the stack.
pub(crate) struct TreeContext<'a, 'c, N, Colours, C: Config> {
    pub scene: &'a Prepared<C>,
    pub colours: &'a Colours,
    pub pixel: PixelPosition,
    pub culling: &'a [ShadowCulling<'c, N, C::Index>],
}

/// The colour of the tree below the primary hit `root` (whose local term is `local`), or
/// `None` when no secondary ray was spawned (the pixel is then the primary hit alone).
#[inline(never)]
pub(crate) fn trace_tree<N: Number, Colours: NodeColours<N>, C: Config<Number = N>>(
    context: &TreeContext<'_, '_, N, Colours, C>,
    root: SurfacePoint<N>,
    local: [N; 3],
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
) -> Option<[N; 3]> {
    let scene = context.scene;
    let depth = usize::from(scene.depth).min(C::TREE_DEPTH);
    let mut stack = C::TreeStack::<Node<N>>::default();
    let root = Node { at: root, optics: scene.optics(root.object), weight: N::ONE, share: N::ONE, colour: local, next: Branch::Reflected };
    if stack.push(root).is_err() {
        return None;
    }
    let smallest = N::ONE.times_power_of_two(-8);
    let full = N::from_i32(255);
    let mut spawned = false;
    loop {
        let generation = stack.len();
        let node = stack.last_mut()?;
        let (share, next) = match node.next {
            Branch::Reflected => (node.optics.reflect, Branch::Transmitted),
            Branch::Transmitted => (node.optics.transmit, Branch::Done),
            Branch::Done => {
                let colour = node.colour.map(|c| c.max(N::ZERO).min(full));
                let share = node.share;
                stack.pop();
                match stack.last_mut() {
                    Some(parent) => {
                        for (total, part) in parent.colour.iter_mut().zip(colour) {
                            *total = *total + share * part;
                        }
                        continue;
                    }
                    None => return spawned.then_some(colour),
                }
            }
        };
        let branch = node.next;
        node.next = next;
        let weight = node.weight * share;
        if share <= N::ZERO || generation >= depth || weight < smallest {
            continue;
        }
        let at = node.at;
        let ray = match branch {
            Branch::Reflected => Ray { origin: shadow_origin(at.point, at.normal), direction: reflected(at.direction, at.normal) },
            _ => {
                let (from, into) = if at.entering { (N::ONE, node.optics.ior) } else { (node.optics.ior, N::ONE) };
                match refracted(at.direction, at.normal, from, into) {
                    Some(direction) => Ray { origin: shadow_origin(at.point, -at.normal), direction },
                    // Total internal reflection: the whole transmitted share is mirrored.
                    None => Ray { origin: shadow_origin(at.point, at.normal), direction: reflected(at.direction, at.normal) },
                }
            }
        };
        spawned = true;
        if let Some(count) = statistics.secondary_rays.get_mut(generation - 1) {
            *count += 1;
        }
        let child = match nearest_secondary_hit(scene, &ray, statistics) {
            Some(hit) => surface(context, &ray, &hit, statistics, cache),
            None => None,
        };
        match child {
            Some((at, colour)) => {
                let child = Node { at, optics: scene.optics(at.object), weight, share, colour, next: Branch::Reflected };
                // The depth check above keeps the stack within its capacity.
                let _ = stack.push(child);
            }
            None => {
                if let Some(node) = stack.last_mut() {
                    for (total, part) in node.colour.iter_mut().zip(context.colours.background()) {
                        *total = *total + share * part;
                    }
                }
            }
        }
    }
}

/// The surface point a secondary ray hit and its local colour.
fn surface<N: Number, Colours: NodeColours<N>, C: Config<Number = N>>(
    context: &TreeContext<'_, '_, N, Colours, C>,
    ray: &Ray<N>,
    hit: &NearestHit<N>,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
) -> Option<(SurfacePoint<N>, [N; 3])> {
    let scene = context.scene;
    let object = hit.object;
    let prepared = super::intersect::surface_of(scene, hit)?;
    let at = SurfacePoint::new(prepared.object_from_world.transposed_vector(hit.local_normal), ray, hit.t, object);
    let lighting = direct_lighting(scene, object, at.lit_point(prepared, ray, hit.t), at.normal, ray.direction, prepared.material.power, statistics, cache, context.culling);
    Some((at, context.colours.local(&prepared.material, lighting, context.pixel)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Vector3;
    use crate::parser::parse;

    /// A refracted ray that enters a glass ball starts just inside it and must find the ball's
    /// far side (no missed exit, no hit at the entry point), down to grazing entries, in every
    /// number type; and leaving again it must not find the ball at its exit point.
    fn refracted_rays_find_the_far_side<N: Number>() {
        let text = b"sphere\n  scale 20 30 25\n  rotate y 30\n  translate 5 -7 -40\n  transmit 1\n  ior 1.5\n";
        let description = parse::<1>(text).unwrap();
        let scene = crate::scene::Scene::<N, 1>::prepare(&description).unwrap();
        let object = &scene.objects[0];
        let mut exits = 0;
        for step in 0..400 {
            // Rays from z = 100 toward the ball, offsets up to 0.999 of its half-width.
            let offset = -0.999 + 1.998 * f64::from(step) / 399.0;
            let direction = Vector3::<N>::from_f64([0.0, 0.0, -1.0]);
            let ray = Ray { origin: Vector3::from_f64([5.0 + 20.0 * offset * 0.8, -7.0 + 3.0 * offset, 100.0]), direction };
            let Some(hit) = object.primitive.intersect(&object.object_from_world.ray(&ray), crate::shapes::Interval::unbounded()) else { continue };
            let at = SurfacePoint::new(object.object_from_world.transposed_vector(hit.normal), &ray, hit.t, 0);
            assert!(at.entering, "{}", N::NAME);
            let Some(inside) = refracted(at.direction, at.normal, N::ONE, N::from_f64(1.5)) else { panic!("{}: no refraction into glass", N::NAME) };
            let inner = Ray { origin: shadow_origin(at.point, -at.normal), direction: inside };
            let far = nearest_secondary_hit(&scene, &inner, &mut Statistics::default()).unwrap_or_else(|| panic!("{} offset {offset}: missed the far side", N::NAME));
            let exit = SurfacePoint::new(object.object_from_world.transposed_vector(far.local_normal), &inner, far.t, 0);
            assert!(!exit.entering, "{} offset {offset}: the far side was seen from outside", N::NAME);
            // The chord is more than the offset's length: not the entry point found again.
            assert!((exit.point - at.point).length() > N::from_f64(0.01), "{} offset {offset}: found the entry point", N::NAME);
            if let Some(out) = refracted(exit.direction, exit.normal, N::from_f64(1.5), N::ONE) {
                let outer = Ray { origin: shadow_origin(exit.point, -exit.normal), direction: out };
                assert!(nearest_secondary_hit(&scene, &outer, &mut Statistics::default()).is_none(), "{} offset {offset}: met the ball again leaving it", N::NAME);
                exits += 1;
            }
        }
        assert!(exits > 300, "{}: {exits} rays left the ball", N::NAME);
    }

    #[test]
    fn a_refracted_ray_finds_the_far_side_in_every_number_type() {
        refracted_rays_find_the_far_side::<f64>();
        refracted_rays_find_the_far_side::<f32>();
        #[cfg(feature = "fixed-point")]
        refracted_rays_find_the_far_side::<crate::number::Fixed>();
        #[cfg(feature = "soft-float")]
        refracted_rays_find_the_far_side::<crate::number::SoftFloat>();
    }
}
