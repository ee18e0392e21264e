//! Host I/O through semihosting (docs: shared/research/qemu.md, "Semihosting file I/O"):
//! binary files in QEMU's working directory, text on its standard output, and the exit status.
//! `cortex_m_semihosting::hio` reaches only stdout/stderr, so files go through `syscall!`.

use cortex_m_semihosting::{debug, syscall};

/// SYS_OPEN modes (ISO C `fopen` modes by number): 1 = "rb", 5 = "wb".
#[cfg_attr(all(not(feature = "lm3s6965evb"), not(microtrace_fault_test)), allow(dead_code))]
const MODE_READ_BINARY: usize = 1;
const MODE_WRITE_BINARY: usize = 5;

/// A host file open for writing; closed on drop.
pub struct HostFile {
    handle: usize,
}

impl HostFile {
    /// Creates or truncates `path`, which must end in a NUL byte.
    pub fn create(path: &[u8]) -> Option<Self> {
        debug_assert_eq!(path.last(), Some(&0));
        // SAFETY: the argument block names a NUL-terminated path that outlives the call.
        let handle = unsafe { syscall!(OPEN, path.as_ptr(), MODE_WRITE_BINARY, path.len() - 1) };
        (handle != usize::MAX).then_some(Self { handle })
    }

    /// Writes all of `bytes`; false when the host wrote fewer.
    pub fn write_all(&mut self, bytes: &[u8]) -> bool {
        // SAFETY: the block points at `bytes` for the duration of the call. SYS_WRITE returns
        // the number of bytes *not* written.
        let not_written = unsafe { syscall!(WRITE, self.handle, bytes.as_ptr(), bytes.len()) };
        not_written == 0
    }
}

impl Drop for HostFile {
    fn drop(&mut self) {
        // SAFETY: closes a handle this value owns.
        unsafe { syscall!(CLOSE, self.handle) };
    }
}

/// Whether the host has a readable file at `path` (NUL-terminated). Used by the screen capture
/// (lm3s6965evb) and the fault test.
#[cfg_attr(all(not(feature = "lm3s6965evb"), not(microtrace_fault_test)), allow(dead_code))]
pub fn host_file_exists(path: &[u8]) -> bool {
    debug_assert_eq!(path.last(), Some(&0));
    // SAFETY: as in `HostFile::create`.
    let handle = unsafe { syscall!(OPEN, path.as_ptr(), MODE_READ_BINARY, path.len() - 1) };
    if handle == usize::MAX {
        return false;
    }
    // SAFETY: closes the handle just opened.
    unsafe { syscall!(CLOSE, handle) };
    true
}

/// Writes text to QEMU's standard output; failures are ignored (nothing else could report them).
pub fn print(text: &str) {
    if let Ok(mut stdout) = cortex_m_semihosting::hio::hstdout() {
        let _ = stdout.write_all(text.as_bytes());
    }
}

/// Ends the QEMU run with status 0 (success) or 1.
pub fn exit(success: bool) -> ! {
    debug::exit(if success { debug::EXIT_SUCCESS } else { debug::EXIT_FAILURE });
    // Only reached without a semihosting host (a real board): stop here.
    loop {
        cortex_m::asm::wfi();
    }
}
