//! Which of the optimizations' larger structures this build compiles in (cargo features).

/// Whether the larger structures beyond the thesis are compiled in (the `acceleration-tables`
/// feature): the grid pool, shadow capsules and tables, and the tight silhouettes.
pub const TABLES: bool = cfg!(feature = "acceleration-tables");

/// Whether the `f64` silhouette algorithms are compiled in (the `f64-silhouettes` feature): the
/// thesis's tuning (its projected volumes) and the eye-plane clip of objects whose capsule
/// reaches the eye. Without it every tuning uses the capsules in the number type, and such an
/// object covers the whole screen: the same image, more rays.
pub const SILHOUETTES: bool = cfg!(feature = "f64-silhouettes");
