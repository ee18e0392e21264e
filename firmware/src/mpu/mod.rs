//! The memory protection (src/fault.rs says why): only the board's flash (read, execute), its
//! RAM (read, write) and its peripherals are accessible; everything else faults. One file per
//! architecture (build.rs sets `cfg(armv6m)`, `cfg(armv7m)` or `cfg(armv8m)` from the board).

#[cfg(armv7m)]
mod armv7m;
#[cfg(armv7m)]
pub use armv7m::protect_memory;

#[cfg(armv8m)]
mod armv8m;
#[cfg(armv8m)]
pub use armv8m::protect_memory;

/// The Cortex-M0 has no MPU: nothing to turn on (src/fault.rs says what that changes).
#[cfg(armv6m)]
pub fn protect_memory() {}
