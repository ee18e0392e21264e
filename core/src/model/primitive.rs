//! The primitives: one closed set (§4.2.5). A new primitive joins here (its variant, keyword
//! and feature), in `shapes/` (its intersection) and in `optimize/bounding_volume.rs` (its
//! bounding volume); docs/architecture.md has the checklist.

/// The four unit primitives of §4.2.5 (fig 4.6), in the thesis's enum order.
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
}

impl Primitive {
    pub const ALL: [Primitive; 4] = [Primitive::Cube, Primitive::Sphere, Primitive::Cylinder, Primitive::Cone];

    /// Whether this build contains the primitive's intersection code.
    pub const fn is_compiled(self) -> bool {
        match self {
            Primitive::Cube => cfg!(feature = "cube"),
            Primitive::Sphere => cfg!(feature = "sphere"),
            Primitive::Cylinder => cfg!(feature = "cylinder"),
            Primitive::Cone => cfg!(feature = "cone"),
        }
    }

    /// The keyword (the thesis's `nameof` table).
    pub const fn name(self) -> &'static str {
        match self {
            Primitive::Cube => "cube",
            Primitive::Sphere => "sphere",
            Primitive::Cylinder => "cylinder",
            Primitive::Cone => "cone",
        }
    }
}

