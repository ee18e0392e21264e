//! A scene baked into flash: everything that depends on the scene alone (the objects' inverse
//! transforms and materials, the camera, the lights, the shading constants) and everything that
//! depends on its view and lights (the test order, the extents, the depth bounds, the shadow
//! capsules, the screen grid, the shadow tables, the hierarchy) made on the host in the number
//! type and written as one self-contained Rust file (`bake`, with the `alloc` feature), so
//! that it reaches flash already in the number type; the chip's preparation from it
//! ([`Prepared::prepare_baked`]) only copies a few settings and hands the tables to the scene's
//! own [`Config`], whose storage reads them in flash ([`InFlash`](crate::storage::InFlash)).
//! A baked scene's chip runs no `f64` and no preparation code at all.
//!
//! # Examples
//!
//! A board's `build.rs` bakes the scene (`bake`; the `alloc` feature, in
//! `[build-dependencies]`), and its `main.rs` includes the file and prepares it in place:
//!
//! ```
//! # #[cfg(feature = "alloc")] {
//! let text = b"perspective 0 0 10\nlight point 2 10 5\nsphere\n  colour 2\n";
//! let description: microtrace::model::SceneDescription<4> = microtrace::parser::parse(text).unwrap();
//! let source = microtrace::bake::bake(&description, &microtrace::bake::Bake::new(32, 16, microtrace::number::NumberKind::F32)).unwrap();
//! assert!(source.contains("pub struct SceneConfig;"));
//! assert!(source.contains("pub static SCENE: microtrace::bake::BakedScene"));
//! # }
//! ```
//!
//! and on the chip (`OUT_DIR/scene.rs` written by the build script above):
//!
//! ```ignore
//! mod scene { include!(concat!(env!("OUT_DIR"), "/scene.rs")); }
//! static mut PREPARED: microtrace::scene::Prepared<scene::SceneConfig> = microtrace::scene::Prepared::UNPREPARED;
//! prepared.prepare_baked(&scene::SCENE)?;
//! ```

#[cfg(feature = "alloc")]
mod write;
#[cfg(feature = "alloc")]
pub use write::{bake, bake_sizes, Bake, BAKE_CAPACITY};

use crate::camera::Camera;
use crate::config::{Config, PaletteStorage};
use crate::geometry::Vector3;
use crate::light::{PreparedLight, PreparedLightSource};
use crate::model::{Optimizations, Palette, SceneError, SceneErrorKind};
use crate::number::Number;
use crate::optimize::bounding_sphere::BoundingSphere;
use crate::optimize::AccelerationParts;
use crate::scene::{Optics, Prepared, PreparedAntialias};
use crate::shading::ShadingConstants;
use crate::storage::{List, Table};

/// A baked scene's settings and tables, as its file keeps them in flash (`I`: its tables'
/// index type). Every field exists whatever the crate's features, so the file `bake` writes
/// compiles in any build; [`Prepared::prepare_baked`] refuses what the build cannot draw.
#[derive(Debug)]
pub struct BakedScene<'a, N, I = u16> {
    pub camera: Camera<N>,
    pub light: PreparedLight<N>,
    pub light_intensity: N,
    pub more_lights: &'a [PreparedLightSource<N>],
    pub depth: u8,
    pub antialias: Option<PreparedAntialias>,
    /// The ray tree's per-object parts (empty when no object reflects or transmits).
    pub optics: &'a [Optics<N>],
    pub spheres: &'a [BoundingSphere<N>],
    pub constants: ShadingConstants<N>,
    pub background: u8,
    pub shadows: bool,
    pub dither: bool,
    pub optimizations: Optimizations,
    pub palette: &'a Palette,
    /// Each object's eye in its own space, for the baked view.
    pub eyes: &'a [Vector3<N>],
    /// The tables that depend on the view and the lights, for the baked view.
    pub acceleration: AccelerationParts<'a, N, I>,
}

impl<N: Number, C: Config<Number = N>> Prepared<C> {
    /// Prepares the scene in place from its baked parts (its objects are its `Config`'s, in
    /// flash): copies the settings and holds the tables, which depend on the view and the lights
    /// baked with it. Fails, naming the feature, where the build cannot draw what was baked.
    pub fn prepare_baked(&mut self, baked: &BakedScene<'static, N, C::Index>) -> Result<(), SceneError> {
        let too_many = |capacity| SceneError { line: 0, kind: SceneErrorKind::TooManyObjects { capacity } };
        let not_compiled = |feature, statement| SceneError { line: 0, kind: SceneErrorKind::FeatureNotCompiled { feature, statement } };
        if !cfg!(feature = "antialias") && baked.antialias.is_some() {
            return Err(not_compiled("antialias", "antialias"));
        }
        if !cfg!(feature = "ray-tree") && !baked.optics.is_empty() {
            return Err(not_compiled("ray-tree", "reflect"));
        }
        if let Some(object) = self.objects.iter().find(|object| !object.primitive.is_compiled()) {
            return Err(SceneError { line: 0, kind: SceneErrorKind::PrimitiveNotCompiled { primitive: object.primitive.name() } });
        }
        if self.objects.len() > C::MAX_OBJECTS {
            return Err(too_many(C::MAX_OBJECTS));
        }
        self.camera = baked.camera;
        self.light = baked.light;
        self.light_intensity = baked.light_intensity;
        self.more_lights.clear();
        for source in baked.more_lights {
            let capacity = <C::OtherLights<PreparedLightSource<N>> as List<_>>::CAPACITY.saturating_add(1);
            self.more_lights.push(*source).map_err(|_| SceneError { line: 0, kind: SceneErrorKind::TooManyLights { capacity } })?;
        }
        self.depth = baked.depth;
        self.antialias = baked.antialias;
        #[cfg(feature = "ray-tree")]
        {
            self.optics.clear();
            self.spheres.clear();
            for optics in baked.optics {
                self.optics.push(*optics).map_err(|_| too_many(C::MAX_OBJECTS))?;
            }
            for sphere in baked.spheres {
                self.spheres.push(*sphere).map_err(|_| too_many(C::MAX_OBJECTS))?;
            }
            self.space_grid.build(&self.spheres);
            self.transparent = self.optics.iter().any(|optics| optics.transmit > N::ZERO);
        }
        self.constants = baked.constants;
        self.background = baked.background;
        self.shadows = baked.shadows;
        self.dither = baked.dither;
        self.optimizations = baked.optimizations;
        self.palette.hold(baked.palette);
        let eyes = self.eyes.hold(baked.eyes);
        if eyes < baked.eyes.len() || !self.acceleration.hold_parts(&self.camera, self.optimizations, &baked.acceleration) {
            return Err(too_many(eyes));
        }
        Ok(())
    }
}
