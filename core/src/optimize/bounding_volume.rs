//! The four stored bounding volumes of §4.7.1 (RTRACE.C `volume[4][8]`), one per primitive
//! type, transformed to world space on demand (`transformvolume`) and never stored per object.
//! NaN-safe comparisons (`!(x > y)`) are deliberate.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use crate::geometry::{AffineTransform, Matrix4};
use crate::number::Number;
use crate::model::Primitive;


/// Sides of the polygons circumscribed about the circles of spheres, cylinders and cones.
pub const SIDES: usize = 16;

/// Where primary rays come from, as the silhouettes need it (in `f64`).
#[derive(Clone, Copy, Debug)]
pub enum View {
    Parallel { direction: [f64; 3] },
    Perspective { eye: [f64; 3] },
}

/// The vertices of the regular `SIDES`-gon circumscribing the unit circle: (cos, sin) of
/// 2πk/16 grown by 1/cos(π/16) and a relative 1e-9 (which covers these literals' last-bit
/// rounding). A table, not `libm::sin`/`cos` per object: on a Cortex-M without a double FPU
/// those 32 calls per object were a large part of the Pixelbuffer fill (firmware/README.md).
const RING: [(f64, f64); SIDES] = {
    // cos(2πk/16) for k = 0..4; the rest follow by symmetry.
    const C: [f64; 5] = [1.0, 0.923_879_532_511_286_7, core::f64::consts::FRAC_1_SQRT_2, 0.382_683_432_365_089_8, 0.0];
    const GROW: f64 = 1.019_591_158_208_318_4 * (1.0 + 1e-9); // 1/cos(π/16)
    let mut ring = [(0.0, 0.0); SIDES];
    let mut k = 0;
    while k < SIDES {
        // cos and sin of 2πk/16 from the first quadrant's values.
        let quadrant = k / 4;
        let step = k % 4;
        let (cos, sin) = match quadrant {
            0 => (C[step], C[4 - step]),
            1 => (-C[4 - step], C[step]),
            2 => (-C[step], -C[4 - step]),
            _ => (C[4 - step], -C[step]),
        };
        ring[k] = (cos * GROW, sin * GROW);
        k += 1;
    }
    ring
};
/// Most points a silhouette is built from (8, the volume's vertices, without the
/// `acceleration-tables` feature, which then also leaves out the tight silhouettes to keep the
/// stack small).
pub const MAX_POINTS: usize = if super::build_options::TABLES { 2 * SIDES } else { 8 };

/// The 8 vertices of each primitive's unit volume, in the thesis's order (digest §8.1).
pub const VOLUMES: [[[f64; 3]; 8]; 4] = [
    // cube: the cube itself
    [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 1.0]],
    // sphere: the 2x2x2 box
    [[-1.0, -1.0, -1.0], [1.0, -1.0, -1.0], [1.0, 1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 1.0, 1.0], [-1.0, 1.0, 1.0]],
    // cylinder: 2x2x1, back face at z = 0
    [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0], [-1.0, -1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 1.0, 1.0], [-1.0, 1.0, 1.0]],
    // cone: a pyramid, the apex repeated four times
    [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [-1.0, -1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 1.0, 1.0], [-1.0, 1.0, 1.0]],
];

/// The unit triangle's volume: the triangle itself, its last vertex repeated, twice (it is flat).
const TRIANGLE_VOLUME: [[f64; 3]; 8] = [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0]];

/// The unit disc's volume: its flat square, each corner twice.
const DISC_VOLUME: [[f64; 3]; 8] = [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0], [-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]];

/// The unit disc's faces: its square's four sides and its plane from both sides.
const DISC_FACES: [([f64; 3], f64); 6] =
    [([1.0, 0.0, 0.0], 1.0), ([-1.0, 0.0, 0.0], 1.0), ([0.0, 1.0, 0.0], 1.0), ([0.0, -1.0, 0.0], 1.0), ([0.0, 0.0, 1.0], 0.0), ([0.0, 0.0, -1.0], 0.0)];

/// The unit triangle's faces: its three edges and its plane from both sides.
const TRIANGLE_FACES: [([f64; 3], f64); 6] =
    [([-1.0, 0.0, 0.0], 0.0), ([0.0, -1.0, 0.0], 0.0), ([1.0, 1.0, 0.0], 1.0), ([0.0, 0.0, 1.0], 0.0), ([0.0, 0.0, -1.0], 0.0), ([0.0, 0.0, 1.0], 0.0)];

/// The faces of each unit volume as half-spaces `n·q ≤ c` in object space (for depth bounds).
/// Unused slots repeat a face.
const FACES: [[([f64; 3], f64); 6]; 4] = [
    [([1.0, 0.0, 0.0], 1.0), ([-1.0, 0.0, 0.0], 0.0), ([0.0, 1.0, 0.0], 1.0), ([0.0, -1.0, 0.0], 0.0), ([0.0, 0.0, 1.0], 1.0), ([0.0, 0.0, -1.0], 0.0)],
    [([1.0, 0.0, 0.0], 1.0), ([-1.0, 0.0, 0.0], 1.0), ([0.0, 1.0, 0.0], 1.0), ([0.0, -1.0, 0.0], 1.0), ([0.0, 0.0, 1.0], 1.0), ([0.0, 0.0, -1.0], 1.0)],
    [([1.0, 0.0, 0.0], 1.0), ([-1.0, 0.0, 0.0], 1.0), ([0.0, 1.0, 0.0], 1.0), ([0.0, -1.0, 0.0], 1.0), ([0.0, 0.0, 1.0], 1.0), ([0.0, 0.0, -1.0], 0.0)],
    [([0.0, 0.0, 1.0], 1.0), ([1.0, 0.0, -1.0], 0.0), ([-1.0, 0.0, -1.0], 0.0), ([0.0, 1.0, -1.0], 0.0), ([0.0, -1.0, -1.0], 0.0), ([0.0, 0.0, 1.0], 1.0)],
];

/// The 8 vertices of the primitive's unit volume: the table's for the four unit primitives; for
/// a torus of tube `R`, its flat box `[−1−R, 1+R]² × [−R, R]`, in the table's vertex order.
pub fn unit_volume(primitive: Primitive) -> [[f64; 3]; 8] {
    match primitive {
        Primitive::Torus(tube) => {
            let (reach, half) = (1.0 + tube.to_f64(), tube.to_f64());
            VOLUMES[1].map(|[x, y, z]| [x * reach, y * reach, z * half])
        }
        // A solid's box is the unit cube through its transform.
        Primitive::Cube | Primitive::Solid(_) => VOLUMES[0],
        Primitive::Sphere => VOLUMES[1],
        // A frustum is never wider than its unit end: the cylinder's box.
        Primitive::Cylinder | Primitive::Frustum(_) => VOLUMES[2],
        Primitive::Cone => VOLUMES[3],
        Primitive::Triangle => TRIANGLE_VOLUME,
        #[cfg(feature = "triangle")]
        Primitive::Patch(_) => TRIANGLE_VOLUME,
        Primitive::Disc => DISC_VOLUME,
    }
}

/// The faces of the primitive's unit volume as half-spaces `n·q ≤ c` (see [`FACES`]).
fn unit_faces(primitive: Primitive) -> [([f64; 3], f64); 6] {
    match primitive {
        Primitive::Torus(tube) => {
            let (reach, half) = (1.0 + tube.to_f64(), tube.to_f64());
            FACES[1].map(|(n, _)| (n, if n[2] != 0.0 { half } else { reach }))
        }
        Primitive::Cube | Primitive::Solid(_) => FACES[0],
        Primitive::Sphere => FACES[1],
        Primitive::Cylinder | Primitive::Frustum(_) => FACES[2],
        Primitive::Cone => FACES[3],
        Primitive::Triangle => TRIANGLE_FACES,
        #[cfg(feature = "triangle")]
        Primitive::Patch(_) => TRIANGLE_FACES,
        Primitive::Disc => DISC_FACES,
    }
}

/// An object's geometry as the tracer renders it: the forward transform recovered in `f64`
/// from the inverse the tracer holds in its number type (so the volumes bound what is actually
/// intersected, rounding included), and that inverse in `f64`.
#[derive(Clone, Copy, Debug)]
pub struct ObjectGeometry {
    pub primitive: Primitive,
    pub world_from_object: Matrix4,
    pub object_from_world: Matrix4,
}

impl ObjectGeometry {
    /// `None` when the inverse cannot be inverted back (then nothing may be culled).
    pub fn new<N: Number>(primitive: Primitive, object_from_world: &AffineTransform<N>) -> Option<Self> {
        let mut rows = [[0.0; 4]; 4];
        for (r, row) in rows.iter_mut().enumerate().take(3) {
            for c in 0..3 {
                row[c] = object_from_world.linear(r, c).to_f64();
            }
        }
        for c in 0..3 {
            rows[3][c] = object_from_world.translation[c].to_f64();
        }
        rows[3][3] = 1.0;
        let inverse = Matrix4 { rows };
        let forward = inverse.affine_inverse()?;
        Some(Self { primitive, world_from_object: forward, object_from_world: inverse })
    }

    /// `transformvolume`: the 8 world-space vertices of the object's bounding volume.
    pub fn volume(&self) -> [[f64; 3]; 8] {
        unit_volume(self.primitive).map(|v| self.world_from_object.transform_point(v))
    }

    /// World points whose convex hull, seen from the view, covers the object's silhouette
    /// (tighter than the 8-vertex volume): a cube's 8 corners; a cylinder's two cap circles
    /// and a cone's base circle, each circumscribed by a 16-gon (radius 1/cos(π/16)); for a
    /// sphere, its rim (the circle where the viewing cone touches it, in object space) likewise
    /// circumscribed. The cone from the eye (or the parallel prism) through the polygon contains
    /// the object, so projecting the points gives a conservative silhouette. `None` when the eye
    /// is inside a sphere.
    pub fn silhouette_points(&self, view: &View, out: &mut [[f64; 3]; MAX_POINTS]) -> Option<usize> {
        if MAX_POINTS < 2 * SIDES {
            return None;
        }
        let ring = |k: usize| RING[k];
        let world = |p: [f64; 3]| self.world_from_object.transform_point(p);
        match self.primitive {
            // The torus's flat box and a solid's enclosure: their 8 corners, as for the cube.
            Primitive::Cube | Primitive::Torus(_) | Primitive::Solid(_) => {
                for (slot, vertex) in out.iter_mut().zip(self.volume()) {
                    *slot = vertex;
                }
                Some(8)
            }
            Primitive::Cylinder | Primitive::Frustum(_) => {
                let near = if let Primitive::Frustum(taper) = self.primitive { taper.to_f64() } else { 1.0 };
                for k in 0..SIDES {
                    let (x, y) = ring(k);
                    out[2 * k] = world([x * near, y * near, 0.0]);
                    out[2 * k + 1] = world([x, y, 1.0]);
                }
                Some(2 * SIDES)
            }
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => {
                for (slot, vertex) in out.iter_mut().zip(&TRIANGLE_VOLUME[..3]) {
                    *slot = world(*vertex);
                }
                Some(3)
            }
            Primitive::Triangle => {
                for (slot, vertex) in out.iter_mut().zip(&TRIANGLE_VOLUME[..3]) {
                    *slot = world(*vertex);
                }
                Some(3)
            }
            // Its rim, circumscribed by the 16-gon.
            Primitive::Disc => {
                for k in 0..SIDES {
                    let (x, y) = ring(k);
                    out[k] = world([x, y, 0.0]);
                }
                Some(SIDES)
            }
            Primitive::Cone => {
                out[0] = world([0.0; 3]);
                for k in 0..SIDES {
                    let (x, y) = ring(k);
                    out[k + 1] = world([x, y, 1.0]);
                }
                Some(SIDES + 1)
            }
            Primitive::Sphere => {
                let m = &self.object_from_world.rows;
                let (centre, radius, normal) = match *view {
                    View::Perspective { eye } => {
                        let e = self.object_from_world.transform_point(eye);
                        let squared = dot(e, e);
                        if !(squared > 1.0 + 1e-6) {
                            return None;
                        }
                        let length = libm::sqrt(squared);
                        (e.map(|c| c / squared), libm::sqrt(1.0 - 1.0 / squared), e.map(|c| c / length))
                    }
                    View::Parallel { direction: d } => {
                        let v: [f64; 3] = core::array::from_fn(|j| d[0] * m[0][j] + d[1] * m[1][j] + d[2] * m[2][j]);
                        let length = libm::sqrt(dot(v, v));
                        if !(length > 0.0) {
                            return None;
                        }
                        ([0.0; 3], 1.0, v.map(|c| c / length))
                    }
                };
                // An orthonormal basis (a, b) of the rim's plane.
                let helper = if normal[0].abs() < 0.6 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
                let a = normalize(cross(normal, helper));
                let b = cross(normal, a);
                for k in 0..SIDES {
                    let (x, y) = ring(k);
                    out[k] = world(core::array::from_fn(|j| centre[j] + radius * (x * a[j] + y * b[j])));
                }
                Some(SIDES)
            }
        }
    }

    /// For a sphere: its centre and the rows of the 3x3 (p = centre + u·M, |u| ≤ 1).
    pub fn ellipsoid(&self) -> Option<([f64; 3], [[f64; 3]; 3])> {
        (self.primitive == Primitive::Sphere).then(|| {
            let m = &self.world_from_object.rows;
            ([m[3][0], m[3][1], m[3][2]], [[m[0][0], m[0][1], m[0][2]], [m[1][0], m[1][1], m[1][2]], [m[2][0], m[2][1], m[2][2]]])
        })
    }

    /// The smallest value of `g·p` over the object's bounding volume (exact over the ellipsoid
    /// for a sphere, over the vertices otherwise).
    pub fn min_linear(&self, g: [f64; 3]) -> f64 {
        if let Some((centre, m)) = self.ellipsoid() {
            let mg = m.map(|row| dot(row, g));
            return dot(centre, g) - libm::sqrt(dot(mg, mg));
        }
        self.volume().iter().map(|p| dot(*p, g)).fold(f64::INFINITY, f64::min)
    }

    /// A lower bound of the distance from `eye` to any point of the bounding volume (0 when the
    /// eye may be inside): the largest signed distance to the volume's face planes, and for a
    /// sphere also |eye − centre| minus an upper bound of its largest semi-axis.
    pub fn distance_lower_bound(&self, eye: [f64; 3]) -> f64 {
        let a = &self.object_from_world.rows;
        let mut bound: f64 = 0.0;
        for (n, c) in unit_faces(self.primitive) {
            // n·q with q = p·A + b is w·p + n·b, w = A n.
            let w = [0, 1, 2].map(|i| dot([a[i][0], a[i][1], a[i][2]], n));
            let nb = dot([a[3][0], a[3][1], a[3][2]], n);
            let length = libm::sqrt(dot(w, w));
            if length > 0.0 {
                bound = bound.max((dot(w, eye) + nb - c) / length);
            }
        }
        if let Some((centre, m)) = self.ellipsoid() {
            let d = [eye[0] - centre[0], eye[1] - centre[1], eye[2] - centre[2]];
            bound = bound.max(libm::sqrt(dot(d, d)) - largest_semi_axis(&m));
        }
        bound
    }

    /// A capsule containing the object: segment ends and radius. Cylinders and cones use their
    /// axis, with the radius reaching the 16-gons circumscribed about their circles; spheres and
    /// cubes a point and their bounding sphere.
    pub fn bounding_capsule(&self) -> ([f64; 3], [f64; 3], f64) {
        if self.primitive.has_axis() {
            let start = self.world_from_object.transform_point([0.0; 3]);
            let end = self.world_from_object.transform_point([0.0, 0.0, 1.0]);
            let mut points = [[0.0; 3]; MAX_POINTS];
            // The viewpoint does not matter for these primitives' points.
            let count = self.silhouette_points(&View::Parallel { direction: [0.0, 0.0, 1.0] }, &mut points).unwrap_or(0);
            let radius = points[..count].iter().map(|p| segment_distance(*p, start, end)).fold(0.0, f64::max);
            return (start, end, radius * (1.0 + 1e-9));
        }
        let (centre, radius) = self.bounding_sphere();
        // A long thin triangle (NFF's polygons split into triangles across a face): its longest
        // edge as the segment and the opposite corner's distance from it as the radius, where
        // that capsule is thinner than the sphere, so its screen cover and depth bound follow
        // the triangle. Grown by 2⁻¹⁶ of its largest coordinate for the tracer's rounding (the
        // sphere's margin is in its radius; a thin capsule's is not).
        if let Some(corners) = self.triangle() {
            let length = |k: usize| distance(corners[k], corners[(k + 1) % 3]);
            let longest = (0..3).fold(0, |best, k| if length(k) > length(best) { k } else { best });
            let (start, end, apex) = (corners[longest], corners[(longest + 1) % 3], corners[(longest + 2) % 3]);
            let largest = corners.iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
            let thin = segment_distance(apex, start, end) * (1.0 + 1e-9) + libm::ldexp(largest, -16);
            let area = |length: f64, radius: f64| 2.0 * length * radius + core::f64::consts::PI * radius * radius;
            if area(length(longest), thin) < area(0.0, radius) {
                return (start, end, thin);
            }
        }
        (centre, centre, radius)
    }

    /// The world box of the bounding volume: (low, high).
    pub fn world_box(&self) -> ([f64; 3], [f64; 3]) {
        let mut low = [f64::INFINITY; 3];
        let mut high = [f64::NEG_INFINITY; 3];
        for p in &self.volume() {
            for k in 0..3 {
                low[k] = low[k].min(p[k]);
                high[k] = high[k].max(p[k]);
            }
        }
        (low, high)
    }

    /// A flat triangle's world vertices (a triangle or a patch), `None` for other primitives.
    pub fn triangle(&self) -> Option<[[f64; 3]; 3]> {
        let vertices = self.volume();
        match self.primitive {
            Primitive::Triangle => Some([vertices[0], vertices[1], vertices[2]]),
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => Some([vertices[0], vertices[1], vertices[2]]),
            _ => None,
        }
    }

    /// A sphere containing the bounding volume: (centre, radius).
    pub fn bounding_sphere(&self) -> ([f64; 3], f64) {
        let volume = self.volume();
        let (low, high) = self.world_box();
        let centre = [0, 1, 2].map(|k| (low[k] + high[k]) / 2.0);
        let radius = volume.iter().map(|p| distance(*p, centre)).fold(0.0, f64::max);
        if let Some((ellipsoid_centre, m)) = self.ellipsoid() {
            let semi_axis = largest_semi_axis(&m);
            if semi_axis < radius {
                return (ellipsoid_centre, semi_axis);
            }
        }
        (centre, radius)
    }
}

/// An upper bound of the largest singular value of `m`: the square root of the largest
/// Gershgorin row sum of `m·mᵀ` (exact for a rotation times a uniform scale).
pub(crate) fn largest_semi_axis(m: &[[f64; 3]; 3]) -> f64 {
    let gram = |i: usize, j: usize| dot(m[i], m[j]);
    let row_sum = |i: usize| (0..3).map(|j| gram(i, j).abs()).sum::<f64>();
    libm::sqrt(row_sum(0).max(row_sum(1)).max(row_sum(2))) * (1.0 + 1e-12)
}

pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn normalize(v: [f64; 3]) -> [f64; 3] {
    let length = libm::sqrt(dot(v, v));
    v.map(|c| c / length)
}

fn segment_distance(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let squared = dot(ab, ab);
    let t = if squared > 0.0 { (dot(ap, ab) / squared).clamp(0.0, 1.0) } else { 0.0 };
    distance(p, [a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]])
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    libm::sqrt(dot(d, d))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn triangle_geometry(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> ObjectGeometry {
        let rows = [[b[0] - a[0], b[1] - a[1], b[2] - a[2], 0.0], [c[0] - a[0], c[1] - a[1], c[2] - a[2], 0.0], [0.0, 0.0, 1.0, 0.0], [a[0], a[1], a[2], 1.0]];
        let world_from_object = Matrix4 { rows };
        ObjectGeometry { primitive: Primitive::Triangle, world_from_object, object_from_world: world_from_object.affine_inverse().unwrap() }
    }

    /// A long thin triangle's capsule runs along its longest edge, far thinner than its
    /// bounding sphere, and holds every point of it; a fat triangle keeps the sphere.
    #[test]
    fn a_thin_triangles_capsule_follows_its_longest_edge() {
        let (a, b, c) = ([1.0, 2.0, 3.0], [41.0, 32.0, 3.0], [21.0, 17.2, 3.0]);
        let geometry = triangle_geometry(a, b, c);
        assert_eq!(geometry.triangle(), Some([a, b, c]));
        let (start, end, radius) = geometry.bounding_capsule();
        assert!((start, end) == (a, b) || (start, end) == (b, a), "{start:?} {end:?}");
        assert!(radius < 1.0 && radius < geometry.bounding_sphere().1 / 20.0, "{radius}");
        for i in 0..=20 {
            for j in 0..=(20 - i) {
                let (u, v) = (f64::from(i) / 20.0, f64::from(j) / 20.0);
                let p = [0, 1, 2].map(|k| a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]));
                assert!(segment_distance(p, start, end) <= radius, "{p:?}");
            }
        }
        let fat = triangle_geometry([0.0; 3], [1.0, 0.0, 0.0], [0.5, 0.9, 0.0]);
        let (start, end, _) = fat.bounding_capsule();
        assert_eq!(start, end, "a point: the sphere");
    }

    /// The table is the regular 16-gon around the unit circle, grown only by the margin: each
    /// vertex is libm's cos/sin times 1/cos(π/16)·(1 + 1e-9) to the last bits, and every edge's
    /// midpoint lies outside the unit circle (so the polygon circumscribes it).
    #[test]
    fn the_ring_table_circumscribes_the_unit_circle() {
        let grow = 1.0 / libm::cos(core::f64::consts::PI / SIDES as f64) * (1.0 + 1e-9);
        for (k, (x, y)) in RING.iter().enumerate() {
            let angle = 2.0 * core::f64::consts::PI * k as f64 / SIDES as f64;
            assert!((x - libm::cos(angle) * grow).abs() < 1e-15 && (y - libm::sin(angle) * grow).abs() < 1e-15, "vertex {k}");
            let (next_x, next_y) = RING[(k + 1) % SIDES];
            let midpoint = ((x + next_x) / 2.0, (y + next_y) / 2.0);
            assert!(midpoint.0 * midpoint.0 + midpoint.1 * midpoint.1 > 1.0, "edge {k}");
        }
    }
}
