//! A surface point a ray reached, and how a mode colours the nodes of the ray tree: shared by
//! the primary rays' shading and the ray tree (`render::ray_tree`).

use crate::camera::PixelPosition;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::model::PreparedMaterial;
use crate::light::Lighting;

/// How a node's colour is made in the render's mode: RGB channels on a 0..255 scale.
// Without the `ray-tree` feature only the primary rays' parts are used.
#[cfg_attr(not(feature = "ray-tree"), allow(dead_code))]
pub(crate) trait NodeColours<N> {
    /// The render's pixel.
    type Pixel;
    /// The pixel of a mixed colour (the tree's, clamped).
    fn finish(&self, colour: [N; 3], pixel: PixelPosition) -> Self::Pixel;
    /// The local term of a surface (unclamped).
    fn local(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> [N; 3];
    /// What a ray that leaves the scene sees.
    fn background(&self) -> [N; 3];
}

/// A surface point a ray reached, with what shading it and spawning from it needs.
#[derive(Clone, Copy, Debug)]
#[cfg_attr(not(feature = "ray-tree"), allow(dead_code))]
pub(crate) struct SurfacePoint<N> {
    pub object: usize,
    pub point: Vector3<N>,
    /// Unit, facing the incoming ray.
    pub normal: Vector3<N>,
    /// The incoming ray's unit direction.
    pub direction: Vector3<N>,
    /// Whether the ray came from outside the object (else it is leaving it).
    pub entering: bool,
}

impl<N: Number> SurfacePoint<N> {
    /// The hit at `t` along `ray` on `object`, whose world-space normal (not normalised) is
    /// `world_normal`: the normal turned to face the ray (the thesis's rule for inner sides).
    #[inline(always)]
    pub fn new(world_normal: Vector3<N>, ray: &Ray<N>, t: N, object: usize) -> Self {
        let mut normal = world_normal.normalized().unwrap_or(-ray.direction);
        let entering = normal.dot(ray.direction) <= N::ZERO;
        if !entering {
            normal = -normal;
        }
        Self { object, point: ray.at(t), normal, direction: ray.direction, entering }
    }

    /// Where the point's shadow rays start: the point, or on a patch seen from the side its
    /// normals face, the point lifted onto the smooth surface they describe
    /// (`shapes::triangle::terminator_lift`; `ray` and `t` the hit's).
    #[inline(always)]
    pub fn lit_point(&self, object: &crate::model::Object<N>, ray: &Ray<N>, t: N) -> Vector3<N> {
        #[cfg(feature = "triangle")]
        if let (crate::model::Primitive::Patch(normals), true) = (object.primitive, self.entering) {
            let local = object.object_from_world.ray(ray).at(t);
            if let Some(lift) = object.object_from_world.vector_preimage(crate::shapes::triangle::terminator_lift(local.x, local.y, normals)) {
                return self.point + lift;
            }
        }
        #[cfg(not(feature = "triangle"))]
        let _ = (object, ray, t);
        self.point
    }
}
