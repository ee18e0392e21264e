//! The FPU's square root for the tracer's `f32`: `vsqrt.f32`. One crate for every board with a
//! single-precision FPU: the QEMU firmware's (firmware/) and the Pico 2 example's. On a target
//! without the hard-float ABI (no FPU) it is empty.
//!
//! The core computes `f32` square roots with libm's `sqrtf`, integer code here (libm has no
//! ARM implementation), and cannot emit the instruction itself: it is `forbid(unsafe_code)`
//! and stable `core` has no `f32` square root (`core::f32::math::sqrt` is unstable in 1.95). So
//! on the boards with an FPU (the mps2-an386's Cortex-M4F, the mps2-an505's and the RP2350's
//! Cortex-M33) the firmware's build.rs, and the Pico 2 example, make the number type
//! `microtrace::number::F32With<VsqrtF32>` for `MICROTRACE_NUMBER=f32`: plain `f32` for every
//! other operation, and this square root.
//!
//! The image stays byte-identical to the host's `f32`: VSQRT is IEEE 754's correctly rounded
//! square root, the same as libm's `sqrtf`. ARMv7-M Architecture Reference Manual (ARM DDI
//! 0403E), chapter A7, VSQRT: `S[d] = FPSqrt(S[m], TRUE)` (the ARMv8-M manual, DDI 0553,
//! says the same of the M33's); the floating-point pseudocode of chapter A2 defines `FPSqrt` as the exact square root rounded once by `FPRound` in the
//! FPSCR's rounding mode, and the floating-point extension's arithmetic as IEEE 754's. The
//! firmware never changes the FPSCR, so the mode is its reset value, round to nearest even,
//! with flush-to-zero and default NaN off: the mode every other `f32` operation here runs in.
//! (`F32With` calls the square root only for finite positive inputs, so NaN, infinity and the
//! sign of zero never reach it.)
//!
//! Not `asm!("vsqrt.f32 {0}, {0}", inout(sreg) x)`: rustc (1.95 here) allows the `sreg`
//! register class, and explicit `s` registers, only with its `vfp2` target feature, which
//! implies double precision and so is off on this single-precision FPU (rust-lang/rust#161826,
//! fixed upstream by rust-lang/rust#159988). So the value comes in a core register and passes
//! through s0, saved and restored around it: five instructions and the compiler's two moves,
//! inlined. (A naked `extern "C"` function, `vsqrt.f32 s0, s0; bx lr`, measured 0.8 % more
//! instructions on snooker: the call and the registers it clobbers.)

#![no_std]
#![cfg(target_abi = "eabihf")]

use microtrace::number::SquareRoot;

/// `vsqrt.f32`: `f32` with the FPU's square root (`NAME = "f32"`, as the host's `f32`, since
/// the results are the same).
#[derive(Clone, Copy, Debug, Default)]
pub struct VsqrtF32;

impl SquareRoot for VsqrtF32 {
    const NAME: &'static str = "f32";

    #[inline]
    fn sqrt(x: f32) -> f32 {
        let mut value = x;
        // SAFETY: the block moves the value through s0, which it saves in a core register
        // first and restores after, so no register the compiler uses changes; it touches no
        // memory and no stack, and its result depends only on its input (the rounding mode
        // never changes): `pure, nomem, nostack`. Not `preserves_flags`: VSQRT may set the
        // FPSCR's cumulative exception bits (inexact), which count as flags to `asm!`.
        // cortex-m-rt enables the FPU before `main`, and the crate is empty but for the
        // hard-float ABI (thumbv7em-none-eabihf, thumbv8m.main-none-eabihf).
        unsafe {
            core::arch::asm!(
                "vmov {saved}, s0",
                "vmov s0, {value}",
                "vsqrt.f32 s0, s0",
                "vmov {value}, s0",
                "vmov s0, {saved}",
                value = inout(reg) value,
                saved = out(reg) _,
                options(pure, nomem, nostack),
            );
        }
        value
    }
}
