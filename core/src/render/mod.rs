//! The per-pixel driver (RTRACE.C `raycast`, PGADPEND.C `pgatrace`, `rgbtrace`) and the
//! statistics of Table 4.2.

mod antialias;
mod direct_lighting;
mod fill;
mod image;
mod mode;
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
mod streamed;
mod surface;

pub use primary::{nearest_hit, nearest_hit_cached, NearestHit};
pub use progressive::{render_pga_pass, render_pga_progressive, render_pga_progressive_sized, render_rgb_pass, render_rgb_progressive, traced_in_pass, PassStatistics, PASSES, PASS_SIZES};
pub use shadow_ray::{in_shadow, in_shadow_cached, in_shadow_culled, shadow_origin, ShadowCache, ShadowCulling};
pub use statistics::Statistics;
pub use streamed::{render_pga_streamed, render_pga_streamed_sized, render_rgb_streamed};
pub use fill::{fill_volumes, fill_volumes_rows};
pub use antialias::ANTIALIAS_ROW;
pub use image::{render_pga, render_pga_rows, render_pga_sized, render_rgb, render_rgb_rows};
pub use pixel_value::{shade_pixel, ShadedPixel};

#[cfg(test)]
mod tests;
