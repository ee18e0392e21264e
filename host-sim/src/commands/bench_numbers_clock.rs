//! The calling thread's CPU time: what `bench --numbers` times renders with, so that time spent
//! waiting while other programs hold the cores (this machine is shared) is not counted.

use std::time::Duration;

/// The CPU time the calling thread has used so far, or `None` where the platform has no
/// per-thread clock (the caller then falls back to wall-clock time).
#[cfg(unix)]
pub fn thread_cpu_time() -> Option<Duration> {
    let mut now = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `now` is a valid, writable timespec for the duration of the call.
    let status = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut now) };
    if status != 0 {
        return None;
    }
    Some(Duration::new(u64::try_from(now.tv_sec).ok()?, u32::try_from(now.tv_nsec).ok()?))
}

#[cfg(not(unix))]
pub fn thread_cpu_time() -> Option<Duration> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_thread_clock_advances_with_work() {
        let Some(before) = thread_cpu_time() else { return };
        let mut sum = 0u64;
        for value in 0..20_000_000u64 {
            sum = sum.wrapping_add(std::hint::black_box(value));
        }
        std::hint::black_box(sum);
        let after = thread_cpu_time().unwrap();
        assert!(after > before, "{before:?} then {after:?}");
    }
}
