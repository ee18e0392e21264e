//! MicroTrace: a `no_std` ray tracer for a microcontroller with a small display, and the same
//! tracer on a desktop: a re-creation of the ray tracer of Eugene Curran's 1989 MSc thesis
//! *Ray Tracing Under The Microcomputer* (Dublin City University). No allocator, no `unsafe`;
//! generic over the number type (`f32`, `f64`, fixed point, a software float for cores without
//! an FPU) and over where the pixels go ([`pixel::PixelSink`], or any embedded-graphics
//! `DrawTarget`).
//!
//! # Quick start
//!
//! Parse a scene (the `.mts` format: docs/scene-format.md in the repository; Haines' NFF too,
//! [`parser::parse_file`]), fit it to the display, prepare it in a number type, render:
//!
//! ```
//! use microtrace::prelude::*;
//!
//! let text = b"window -2 2 -1 1\nviewplane 0\nperspective 0 0 10\nlight point 2 10 5\nshadows on\nsphere\n  colour 2\n";
//! let mut description: SceneDescription<8> = parse(text)?;
//! // The window is widened about its centre so that pixels stay square.
//! description.fit_to_size(64, 32);
//! let scene = Scene::<f32, 8>::prepare(&description)?;
//! let mut pixels = [0u8; 64 * 32];
//! let mut frame = FrameBuffer::new(&mut pixels, 64, 32).ok_or("the buffer's size")?;
//! render(&scene, Pga, Whole, &mut frame, &mut Statistics::default());
//! // Each pixel is a palette index; `scene.palette` maps it to a colour.
//! assert_ne!(pixels[32 * 16 + 32], scene.background_index());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Onto an embedded-graphics display, in one call
//!
//! [`render::draw`] renders onto any `DrawTarget` whose colour converts from `Rgb888`: PGA mode
//! through the scene's look-up table ([`render::Colours::Palette`]) or RGB mode
//! ([`render::Colours::Rgb`]). A display of another size than the scene's is an error.
//!
//! ```
//! use embedded_graphics::mock_display::MockDisplay;
//! use embedded_graphics::pixelcolor::Rgb565;
//! use microtrace::prelude::*;
//!
//! let text = b"window -2 2 -2 2\nviewplane 0\nperspective 0 0 10\nlight point 2 10 5\nsphere\n";
//! let mut description: SceneDescription<4> = parse(text)?;
//! description.fit_to_size(64, 64);
//! let scene = Scene::<f32, 4>::prepare(&description)?;
//! let mut display = MockDisplay::<Rgb565>::new();
//! draw(&scene, Colours::Rgb, &mut display)?;
//! // A display of another size is refused, with what to do about it.
//! let mut small = MockDisplay::<Rgb565>::new();
//! let mut prepared_for_another = description.clone();
//! prepared_for_another.fit_to_size(128, 64);
//! let other = Scene::<f32, 4>::prepare(&prepared_for_another)?;
//! assert!(draw(&other, Colours::Rgb, &mut small).is_err());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # A scene built in code
//!
//! A [`model::Description`] can be made without any text; preparation checks it against the
//! format's ranges as the parser checks text ([`model::Description::validate`]), with the same
//! messages.
//!
//! ```
//! use microtrace::model::{Light, ObjectDescription, Primitive, Projection, SceneDescription, Viewport, Window};
//! use microtrace::prelude::*;
//!
//! let mut description = SceneDescription::<4>::default();
//! description.viewport = Viewport { x1: 0, x2: 31, y1: 0, y2: 15 };
//! description.window = Window { x1: -2.0, x2: 2.0, y1: -1.0, y2: 1.0 };
//! description.view_plane = 0.0;
//! description.projection = Projection::Perspective { eye: [0.0, 0.0, 10.0] };
//! description.light = Light::Point([2.0, 10.0, 5.0]);
//! let mut ball = ObjectDescription::new(Primitive::Sphere, 0);
//! ball.material.colour = 2;
//! description.objects.push(ball).map_err(|_| "full")?;
//! let scene = Scene::<f32, 4>::prepare(&description)?;
//! assert_eq!(scene.viewport().width(), 32);
//! // What the format would refuse is refused here too.
//! description.objects[0].material.colour = 200;
//! let error = Scene::<f32, 4>::prepare(&description).unwrap_err();
//! assert_eq!(error.kind.to_string(), "colour: `200` is out of range (must be an integer from 0 to 15)");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # On a chip: bake the scene
//!
//! A board should not parse: [`bake`] (host-only, the `alloc` feature) prepares the scene at
//! build time in the chip's number type and writes one Rust file — its own `Config` and every
//! table as a `static` in flash — which the chip includes and prepares in place with
//! `Prepared::prepare_baked` (a few hundred instructions, no `f64`, no parser linked).
//! docs/your-board.md in the repository, and `firmware/examples/your-board`, show the ten lines
//! of `build.rs` and the one call in `main.rs`.
//!
//! # Modules (thesis sections in brackets)
//!
//! - [`model`]: what a scene is made of, as written: primitives, view, materials, lights,
//!   colours, the description and its checks, the error type. Imports nothing above `geometry`.
//! - [`parser`]: the `.mts` scene format and Haines' NFF.
//! - [`scene`]: the prepared, render-ready scene in a number type (§4.7 `preprocess`).
//! - [`render`]: the one render door ([`render::render`]), [`render::draw`], the statistics of
//!   Table 4.2.
//! - [`pixel`]: where pixels go: [`pixel::PixelSink`], a framebuffer, the embedded-graphics
//!   adapters and colour maps.
//! - [`bake`]: a scene baked into flash for a chip.
//! - [`config`], [`storage`]: the build's tables and capacities in one type, and the storage
//!   they are read through (arrays, the heap, or flash).
//! - [`number`]: the number types the tracer is generic over.
//! - [`geometry`], [`camera`], [`light`], [`shapes`], [`csg`], [`shading`], [`optimize`],
//!   [`formats`]: the tracer's parts — vectors and transforms (§1.5.1), the camera (§4.3), the
//!   lights and shading terms (§4.2.4), the primitives' intersections (§4.5–4.6), solids
//!   (chapter 3), the PGA and RGB shading, the optimizations (§4.7), the thesis's image files
//!   (§4.2.2–4.2.3).
#![no_std]
#![forbid(unsafe_code)]
// Cargo.toml denies unwrap/expect/panic in the core; its unit tests may use them.
#![cfg_attr(test, allow(clippy::unwrap_used, clippy::expect_used, clippy::panic))]
#![warn(missing_debug_implementations)]

#[cfg(feature = "alloc")]
extern crate alloc;

pub mod bake;
pub mod camera;
pub mod config;
pub mod csg;
pub mod formats;
pub mod geometry;
pub mod light;
pub mod model;
pub mod number;
pub mod optimize;
pub mod parser;
pub mod pixel;
pub mod render;
pub mod scene;
pub mod shading;
pub mod shapes;
pub mod storage;

/// The README's examples, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeExamples;

/// What the quick starts use: parse, prepare, render, draw.
pub mod prelude {
    pub use crate::model::{SceneDescription, SceneError};
    pub use crate::number::NumberKind;
    pub use crate::parser::{parse, parse_file};
    pub use crate::pixel::{FrameBuffer, PixelSink, PixelSource};
    #[cfg(feature = "embedded-graphics")]
    pub use crate::render::{draw, Colours};
    pub use crate::render::{render, Pga, Rgb, Statistics, Streamed, Whole};
    pub use crate::scene::{Prepared, Scene};
}
