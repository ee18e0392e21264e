//! The primitives: one closed set (§4.2.5, §5.2.1's torus, and the open frustum and the
//! triangle that Haines' NFF scenes are made of). A new primitive joins here (its variant, keyword
//! and feature), in `shapes/` (its intersection) and in `optimize/bounding_volume.rs` (its
//! bounding volume); docs/architecture.md has the checklist.


/// The four unit primitives of §4.2.5 (fig 4.6), in the thesis's enum order, and the ring torus
/// §5.2.1 proposes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Primitive {
    /// The unit cube `[0,1]^3`.
    Cube,
    /// The unit sphere at the origin.
    Sphere,
    /// Radius 1 about +z, from z = 0 to z = 1, both caps.
    Cylinder,
    /// Apex at the origin, base of radius 1 at z = 1, capped.
    Cone,
    /// The circle of radius 1 about +z in the plane z = 0, swept by a tube of the given radius
    /// (`torus R`, 0 < R < 1: a ring torus).
    Torus(Tube),
    /// An open truncated cone (NFF's `c`): radius `taper` at z = 0 to 1 at z = 1, no caps, seen
    /// from outside and inside (`frustum R`). A taper of 1 is an open cylinder, 0 an open cone.
    Frustum(Taper),
    /// The unit disc, radius 1 about the origin in the plane z = 0, seen from both sides (`disc`):
    /// open, so no solid's operand.
    Disc,
    /// The unit triangle (0,0,0), (1,0,0), (0,1,0) in the plane z = 0, seen from both sides: its
    /// transform maps it onto any triangle (NFF's polygons and patches, split into triangles).
    Triangle,
    /// The unit triangle with a normal at each corner (NFF's `pp`, a polygonal patch): shaded
    /// with the normal interpolated across it. Not a keyword (the NFF reader makes it): no
    /// `Primitive::ALL` entry; to the optimizations and features, a triangle. Only with the
    /// `triangle` feature: its 18 bytes of normals would grow every object of a build without.
    #[cfg(feature = "triangle")]
    Patch(VertexNormals),
    /// A solid of constructive solid geometry (`union`, `intersection`, `difference` … `end`):
    /// to the optimizations the unit cube, which its transform makes the box enclosing the
    /// solid (§3.3.6); its operands are the scene's solid nodes in the range
    /// (`model::solid`, `csg::solid`). Not a keyword: no `Primitive::ALL` entry.
    Solid(SolidRange),
}

/// A ring torus's tube radius, in steps of 2⁻¹⁵ of its major radius (1 to 32767 steps): the
/// format's `torus R` rounded to the nearest step. Whole steps keep `Primitive` a plain value
/// (no number type in the scene's description) and give the radius in every number type
/// exactly, Q16.16 included (`radius`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Tube(u16);

impl Tube {
    /// A step is 2^`STEP_EXPONENT`.
    pub const STEP_EXPONENT: i32 = -15;
    /// `torus 0.25`: the radius `Primitive::ALL` names the torus by.
    pub const QUARTER: Tube = Tube(1 << 13);

    /// `radius` rounded to the nearest step; `None` unless it is a ring torus's, `0 < radius < 1`
    /// (and at least half a step).
    pub fn from_f64(radius: f64) -> Option<Self> {
        let steps = libm::round(libm::ldexp(radius, -Self::STEP_EXPONENT));
        (radius > 0.0 && radius < 1.0 && (1.0..32768.0).contains(&steps)).then_some(Tube(steps as u16))
    }

    /// The radius, exactly.
    pub fn to_f64(self) -> f64 {
        libm::ldexp(f64::from(self.0), Self::STEP_EXPONENT)
    }

    /// The radius in a number type: an integer times a power of two, exact in every type.
    pub fn radius<N: crate::number::Number>(self) -> N {
        N::from_i32(i32::from(self.0)).times_power_of_two(Self::STEP_EXPONENT)
    }

    /// The radius in steps (what the firmware's scene constants write).
    pub const fn steps(self) -> u16 {
        self.0
    }

    /// From a number of steps, clamped to 1 ..= 32767 (the firmware's scene constants, which
    /// write `steps()` of a valid tube).
    pub const fn from_steps(steps: u16) -> Self {
        if steps == 0 {
            Tube(1)
        } else if steps > 32767 {
            Tube(32767)
        } else {
            Tube(steps)
        }
    }
}

/// A patch's normals at its corners (0,0,0), (1,0,0), (0,1,0), in object space: the world
/// normals carried back through the transform (so that the shading normal interpolated here
/// and carried forward as any object's is the world normals' interpolation), scaled together
/// so that the largest component is 1, in steps of 2⁻¹⁵ (exact in every number type, and a
/// plain value as [`Tube`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct VertexNormals(pub [[i16; 3]; 3]);

impl VertexNormals {
    /// A step is 2^`STEP_EXPONENT`.
    pub const STEP_EXPONENT: i32 = -15;

    /// The three normals scaled together and rounded to steps; `None` when all are zero or
    /// any is not finite.
    pub fn from_f64(normals: [[f64; 3]; 3]) -> Option<Self> {
        let largest = normals.iter().flatten().fold(0.0f64, |m, c| if c.abs() > m { c.abs() } else { m });
        if !(largest > 0.0 && largest.is_finite()) {
            return None;
        }
        let step = |c: f64| libm::round(c / largest * 32767.0) as i16;
        Some(Self(normals.map(|n| n.map(step))))
    }

    /// The normal at barycentric (u, v): (1 − u − v)·n₀ + u·n₁ + v·n₂ (not normalised).
    pub fn at<N: crate::number::Number>(self, u: N, v: N) -> crate::geometry::Vector3<N> {
        let [n0, n1, n2] = self.0.map(|n| n.map(|c| N::from_i32(i32::from(c)).times_power_of_two(Self::STEP_EXPONENT)));
        let w = N::ONE - u - v;
        crate::geometry::Vector3::new(w * n0[0] + u * n1[0] + v * n2[0], w * n0[1] + u * n1[1] + v * n2[1], w * n0[2] + u * n1[2] + v * n2[2])
    }
}

/// An open frustum's radius at z = 0, in steps of 2⁻¹⁵ of its radius at z = 1 (0 to 32768
/// steps): exact in every number type, as [`Tube`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Taper(u16);

impl Taper {
    /// A step is 2^`STEP_EXPONENT`.
    pub const STEP_EXPONENT: i32 = -15;
    /// `frustum 0.5`: the taper `Primitive::ALL` names the frustum by.
    pub const HALF: Taper = Taper(1 << 14);
    /// An open cylinder.
    pub const CYLINDER: Taper = Taper(1 << 15);

    /// `radius` rounded to the nearest step; `None` unless `0 ≤ radius ≤ 1`.
    pub fn from_f64(radius: f64) -> Option<Self> {
        (0.0..=1.0).contains(&radius).then(|| Taper(libm::round(libm::ldexp(radius, -Self::STEP_EXPONENT)) as u16))
    }

    /// The radius at z = 0, exactly.
    pub fn to_f64(self) -> f64 {
        libm::ldexp(f64::from(self.0), Self::STEP_EXPONENT)
    }

    /// The radius at z = 0 in a number type (exact in every type).
    pub fn radius<N: crate::number::Number>(self) -> N {
        N::from_i32(i32::from(self.0)).times_power_of_two(Self::STEP_EXPONENT)
    }

    /// The radius in steps (what the firmware's scene constants write).
    pub const fn steps(self) -> u16 {
        self.0
    }

    /// From a number of steps, clamped to 0 ..= 32768.
    pub const fn from_steps(steps: u16) -> Self {
        if steps > 1 << 15 {
            Taper(1 << 15)
        } else {
            Taper(steps)
        }
    }
}

impl Primitive {
    /// One of each kind (the torus with a quarter tube, the frustum with a half taper): for the
    /// keywords, the features, tests.
    pub const ALL: [Primitive; 8] = [
        Primitive::Cube,
        Primitive::Sphere,
        Primitive::Cylinder,
        Primitive::Cone,
        Primitive::Torus(Tube::QUARTER),
        Primitive::Frustum(Taper::HALF),
        Primitive::Triangle,
        Primitive::Disc,
    ];

    /// The kind's place in [`Primitive::ALL`] (a torus of any tube is 4, a frustum of any taper
    /// 5; a solid, 8, after them).
    pub const fn index(self) -> usize {
        match self {
            Primitive::Cube => 0,
            Primitive::Sphere => 1,
            Primitive::Cylinder => 2,
            Primitive::Cone => 3,
            Primitive::Torus(_) => 4,
            Primitive::Frustum(_) => 5,
            Primitive::Triangle => 6,
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => 6,
            Primitive::Disc => 7,
            Primitive::Solid(_) => 8,
        }
    }

    /// Whether the surface encloses a volume: only a closed primitive can be a solid's operand
    /// (an open frustum or a triangle has no inside to combine).
    pub const fn is_closed(self) -> bool {
        match self {
            Primitive::Frustum(_) | Primitive::Triangle | Primitive::Disc => false,
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => false,
            Primitive::Cube | Primitive::Sphere | Primitive::Cylinder | Primitive::Cone | Primitive::Torus(_) | Primitive::Solid(_) => true,
        }
    }

    /// Whether the primitive lies along its z axis, within radius 1 of it from z = 0 to z = 1
    /// (a cylinder, a cone, a frustum): its bounding capsule and its depth bounds follow the
    /// axis (`optimize`); any other is bounded by a ball.
    pub const fn has_axis(self) -> bool {
        match self {
            Primitive::Cylinder | Primitive::Cone | Primitive::Frustum(_) => true,
            Primitive::Cube | Primitive::Sphere | Primitive::Torus(_) | Primitive::Triangle | Primitive::Disc | Primitive::Solid(_) => false,
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => false,
        }
    }

    /// Whether this build contains the primitive's intersection code.
    pub const fn is_compiled(self) -> bool {
        match self {
            Primitive::Cube => cfg!(feature = "cube"),
            Primitive::Sphere => cfg!(feature = "sphere"),
            Primitive::Cylinder => cfg!(feature = "cylinder"),
            Primitive::Cone => cfg!(feature = "cone"),
            Primitive::Torus(_) => cfg!(feature = "torus"),
            Primitive::Frustum(_) => cfg!(feature = "frustum"),
            Primitive::Triangle => cfg!(feature = "triangle"),
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => true,
            Primitive::Disc => cfg!(feature = "disc"),
            Primitive::Solid(_) => cfg!(feature = "csg"),
        }
    }

    /// The keyword (the thesis's `nameof` table).
    pub const fn name(self) -> &'static str {
        match self {
            Primitive::Cube => "cube",
            Primitive::Sphere => "sphere",
            Primitive::Cylinder => "cylinder",
            Primitive::Cone => "cone",
            Primitive::Torus(_) => "torus",
            Primitive::Frustum(_) => "frustum",
            Primitive::Triangle => "triangle",
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => "patch",
            Primitive::Disc => "disc",
            Primitive::Solid(_) => "solid",
        }
    }

    /// The primitive's own axis-aligned box (a solid's is the unit cube, see [`Primitive::Solid`]).
    pub fn local_box(self) -> [[f64; 3]; 2] {
        match self {
            Primitive::Cube | Primitive::Solid(_) => [[0.0; 3], [1.0; 3]],
            Primitive::Sphere => [[-1.0; 3], [1.0; 3]],
            Primitive::Cylinder | Primitive::Cone | Primitive::Frustum(_) => [[-1.0, -1.0, 0.0], [1.0, 1.0, 1.0]],
            Primitive::Triangle => [[0.0; 3], [1.0, 1.0, 0.0]],
            #[cfg(feature = "triangle")]
            Primitive::Patch(_) => [[0.0; 3], [1.0, 1.0, 0.0]],
            Primitive::Disc => [[-1.0, -1.0, 0.0], [1.0, 1.0, 0.0]],
            Primitive::Torus(tube) => {
                let (r, outer) = (tube.to_f64(), 1.0 + tube.to_f64());
                [[-outer, -outer, -r], [outer, outer, r]]
            }
        }
    }
}

/// Where a solid's nodes are in the scene's list: `count` nodes from `first`, the last its root.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SolidRange {
    pub first: u16,
    pub count: u16,
}

impl SolidRange {
    pub fn nodes(self) -> core::ops::Range<usize> {
        usize::from(self.first)..usize::from(self.first) + usize::from(self.count)
    }
}
