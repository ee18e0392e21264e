//! The per-pixel driver (RTRACE.C `raycast`, PGADPEND.C `pgatrace`, `rgbtrace`) and the
//! statistics of Table 4.2.

#[cfg(feature = "antialias")]
mod antialias;
mod coverage;
mod direct_lighting;
#[cfg(feature = "embedded-graphics")]
mod draw;
mod fill;
mod intersect;
mod mode;
mod order;
mod pixel_value;
mod primary;
#[cfg(feature = "ray-tree")]
mod ray_tree;
#[cfg(feature = "ray-tree")]
mod secondary;
mod progressive;
mod shadow_ray;
mod shadow_tables;
mod statistics;
mod surface;
mod walk;

#[cfg(feature = "embedded-graphics")]
pub use draw::{draw, Colours, SizeMismatch};
pub use intersect::NearestHit;
pub use primary::{nearest_hit, nearest_hit_cached};
pub use order::{render, Order, Pass, Pga, PixelMode, Progressive, Rgb, Rows, Streamed, Whole};
pub use progressive::{traced_in_pass, PassStatistics, PASSES, PASS_SIZES};
pub use shadow_tables::built_shadow_tables;
pub use shadow_ray::{in_shadow, in_shadow_cached, in_shadow_culled, shadow_origin, BlockersBeyond, ShadowCache, ShadowCulling};
pub use statistics::Statistics;
pub use fill::{fill_volumes, fill_volumes_rows};
pub use pixel_value::{shade_pixel, ShadedPixel};

#[cfg(test)]
mod tests;
