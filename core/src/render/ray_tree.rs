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

use heapless::Vec;

use super::lights::direct_lighting;
use super::secondary::nearest_secondary_hit;
use super::shadow::{shadow_origin, ShadowCache, ShadowCulling};
use super::Statistics;
use super::surface::{NodeColours, SurfacePoint};
use crate::camera::PixelPosition;
use crate::geometry::reflection::{reflected, refracted};
use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::scene::{Optics, Scene};

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
pub(crate) struct TreeContext<'a, 'c, N, C, const MAX_OBJECTS: usize> {
    pub scene: &'a Scene<N, MAX_OBJECTS>,
    pub colours: &'a C,
    pub pixel: PixelPosition,
    pub culling: &'a [ShadowCulling<'c, N>],
}

/// The colour of the tree below the primary hit `root` (whose local term is `local`), or
/// `None` when no secondary ray was spawned (the pixel is then the primary hit alone).
#[inline(never)]
pub(crate) fn trace_tree<N: Number, C: NodeColours<N>, const MAX_OBJECTS: usize, const DEPTH: usize>(
    context: &TreeContext<'_, '_, N, C, MAX_OBJECTS>,
    root: SurfacePoint<N>,
    local: [N; 3],
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
) -> Option<[N; 3]> {
    let scene = context.scene;
    let depth = usize::from(scene.depth).min(DEPTH);
    let mut stack: Vec<Node<N>, DEPTH> = Vec::new();
    let root = Node { at: root, optics: scene.optics(root.object), weight: N::ONE, share: N::ONE, colour: local, next: Branch::Reflected };
    if stack.push(root).is_err() {
        return None;
    }
    let smallest = N::ONE.times_power_of_two(-8);
    let full = N::from_i32(255);
    let mut spawned = false;
    loop {
        let generation = stack.len();
        let Some(node) = stack.last_mut() else { return None };
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
            Some(hit) => surface(context, &ray, hit.object, hit.t, hit.local_normal, statistics, cache),
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
fn surface<N: Number, C: NodeColours<N>, const MAX_OBJECTS: usize>(
    context: &TreeContext<'_, '_, N, C, MAX_OBJECTS>,
    ray: &Ray<N>,
    object: usize,
    t: N,
    local_normal: Vector3<N>,
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
) -> Option<(SurfacePoint<N>, [N; 3])> {
    let scene = context.scene;
    let prepared = scene.objects.get(object)?;
    let at = SurfacePoint::new(prepared.object_from_world.transposed_vector(local_normal), ray, t, object);
    let lighting = direct_lighting(scene, object, at.point, at.normal, ray.direction, prepared.material.power, statistics, cache, context.culling);
    Some((at, context.colours.local(&prepared.material, lighting, context.pixel)))
}
