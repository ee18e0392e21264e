//! The local term at a hit (digest §6.2, and the thesis's chapter 5 for several lights): the
//! diffuse and specular parts summed over the lights, each times its intensity and the share of
//! it that reaches the point (a shadow ray per light).
//!
//! With one light of intensity one and opaque objects this is the thesis's shading exactly:
//! no multiplication by the intensity or the share is made.

use super::shadow_ray::{light_share, ShadowCache, ShadowCulling};
use super::Statistics;
use crate::geometry::Vector3;
use crate::number::Number;
use crate::light::PreparedLight;
use crate::config::Config;
use crate::scene::Prepared;
use crate::light::{lighting, Lighting};

/// The lighting at `point` on object `object` with the unit `normal` facing the incoming ray
/// `view`; `start` is where shadow rays leave (the point moved off the surface).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn direct_lighting<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    object: usize,
    point: Vector3<N>,
    normal: Vector3<N>,
    view: Vector3<N>,
    power: u32,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
    culling: &[ShadowCulling<'_, N, C::Index>],
) -> Lighting<N> {
    let at = Hit { scene, object, point, normal, view, power };
    let first = at.one_light(scene.light, statistics, &mut cache.last_blocker, culling.first().unwrap_or(&ShadowCulling::NONE));
    // The thesis's case, one light of intensity one: its term as it is.
    if scene.more_lights.is_empty() && scene.light_intensity == N::ONE {
        return first;
    }
    at.with_more_lights(first, statistics, cache, culling)
}

fn scaled<N: Number>(lighting: Lighting<N>, factor: N) -> Lighting<N> {
    Lighting { diffuse: lighting.diffuse * factor, specular: lighting.specular * factor }
}

/// What every light's term at one hit shares.
struct Hit<'a, N, C: Config> {
    scene: &'a Prepared<C>,
    object: usize,
    point: Vector3<N>,
    normal: Vector3<N>,
    view: Vector3<N>,
    power: u32,
}

impl<N: Number, C: Config<Number = N>> Hit<'_, N, C> {
    /// The first light's term scaled by its intensity plus the further lights' terms: out of
    /// line, so that a one-light scene's pixels carry none of it.
    #[inline(never)]
    fn with_more_lights(&self, first: Lighting<N>, statistics: &mut Statistics, cache: &mut ShadowCache<C::Index>, culling: &[ShadowCulling<'_, N, C::Index>]) -> Lighting<N> {
        let scene = self.scene;
        let mut total = if scene.light_intensity != N::ONE { scaled(first, scene.light_intensity) } else { first };
        for ((source, last_blocker), index) in scene.more_lights.iter().zip(cache.more_blockers.iter_mut()).zip(1..) {
            let term = scaled(self.one_light(source.light, statistics, last_blocker, culling.get(index).unwrap_or(&ShadowCulling::NONE)), source.intensity);
            total = Lighting { diffuse: total.diffuse + term.diffuse, specular: total.specular + term.specular };
        }
        total
    }

    /// One light's diffuse and specular at the hit, times the share that reaches it.
    fn one_light(&self, light: PreparedLight<N>, statistics: &mut Statistics, last_blocker: &mut Option<C::Index>, culling: &ShadowCulling<'_, N, C::Index>) -> Lighting<N> {
        let (to_light, light_distance) = match light {
            PreparedLight::Point(position) => {
                let offset = position - self.point;
                let distance = offset.length();
                // As `normalized()`, without computing the length twice.
                let direction = N::ONE.checked_div(distance).map_or(self.normal, |reciprocal| offset * reciprocal);
                (direction, distance)
            }
            PreparedLight::Direction(direction) => (direction, N::MAX),
        };
        // A surface facing away from the light is unlit with or without a shadow ray.
        let faces_light = self.normal.dot(to_light) > N::ZERO;
        let share = if self.scene.shadows && faces_light {
            let start = super::shadow_ray::shadow_origin(self.point, self.normal);
            light_share(self.scene, self.object, start, to_light, light_distance, statistics, last_blocker, culling)
        } else {
            N::ONE
        };
        let lit = lighting(self.normal, to_light, self.view, self.power, share == N::ZERO);
        if share == N::ONE || share == N::ZERO { lit } else { scaled(lit, share) }
    }
}
