//! Board support: one folder per board, one board per build (a cargo feature). Each provides
//! `Display` (a `display::RowDisplay`: whole rows of grey levels), `init()`
//! and `hold_picture_for_capture()`; the render and the report are shared (main.rs).

#[cfg(all(feature = "lm3s6965evb", feature = "mps2-an386"))]
compile_error!("enable exactly one board feature");

#[cfg(feature = "lm3s6965evb")]
mod lm3s6965evb;
#[cfg(feature = "lm3s6965evb")]
pub use lm3s6965evb::*;

#[cfg(feature = "mps2-an386")]
mod mps2_an386;
#[cfg(feature = "mps2-an386")]
pub use mps2_an386::*;
