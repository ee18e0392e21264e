//! The interrupt part of the vector table, one entry long. cortex-m-rt's generic table fills
//! every vector the architecture allows with its default handler: 240 words on ARMv7-M (960
//! bytes of flash), 480 on ARMv8-M Mainline, 32 on ARMv6-M. The firmware enables no
//! interrupt (the NVIC's enables are clear from reset and nothing sets them), so none of those
//! words is ever read. With cortex-m-rt's `device` feature the table is ours to give
//! (`__INTERRUPTS`, cortex-m-rt's documentation, "`device` feature"); its linker script asks
//! for at least one vector, so IRQ 0 goes to the default handler, which names an unexpected
//! exception or interrupt and fails the run. The handlers a device crate would `PROVIDE` are in
//! its `device.x`, which build.rs writes empty: there are none.

extern "C" {
    /// cortex-m-rt's symbol for the `#[exception] fn DefaultHandler` in main.rs.
    fn DefaultHandler();
}

/// Placed by cortex-m-rt's `link.x` right after the exceptions, at IRQ 0.
#[link_section = ".vector_table.interrupts"]
#[no_mangle]
#[used]
pub static __INTERRUPTS: [unsafe extern "C" fn(); 1] = [DefaultHandler];
