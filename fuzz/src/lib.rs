//! MicroTrace's fuzz targets' checks (see `checks.rs` and docs/fuzzing.md).
#[path = "checks.rs"]
pub mod checks;
