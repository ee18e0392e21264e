//! What xtask reads from the firmware ELF: the memory footprint (as `size` reports it) and the
//! addresses of the measurement markers.

use object::{Object, ObjectSection, ObjectSymbol, SectionFlags};

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Footprint {
    /// Code and read-only data (`text` of `size`).
    pub text: u64,
    /// Initialised statics: stored in flash, copied to RAM.
    pub data: u64,
    /// Zero-initialised and uninitialised statics (RAM only).
    pub bss: u64,
}

impl Footprint {
    pub fn flash_bytes(&self) -> u64 {
        self.text + self.data
    }
    pub fn static_ram_bytes(&self) -> u64 {
        self.data + self.bss
    }
}

const SHF_WRITE: u64 = 0x1;
const SHF_ALLOC: u64 = 0x2;

/// Sizes by section flags, the way `size`'s Berkeley format counts them.
pub fn footprint(elf: &[u8]) -> Result<Footprint, String> {
    let file = object::File::parse(elf).map_err(|error| format!("not an ELF file: {error}"))?;
    let mut footprint = Footprint::default();
    for section in file.sections() {
        let SectionFlags::Elf { sh_flags } = section.flags() else { continue };
        if sh_flags & SHF_ALLOC == 0 {
            continue;
        }
        // SHT_NOBITS sections (.bss, cortex-m-rt's NOLOAD .uninit) occupy no flash.
        let nobits = matches!(section.kind(), object::SectionKind::UninitializedData | object::SectionKind::UninitializedTls);
        if sh_flags & SHF_WRITE == 0 {
            footprint.text += section.size();
        } else if nobits {
            footprint.bss += section.size();
        } else {
            footprint.data += section.size();
        }
    }
    Ok(footprint)
}

/// The address of the function `name`, without the Thumb bit.
pub fn function_address(elf: &[u8], name: &str) -> Result<u64, String> {
    let file = object::File::parse(elf).map_err(|error| format!("not an ELF file: {error}"))?;
    file.symbols()
        .find(|symbol| symbol.name() == Ok(name))
        .map(|symbol| symbol.address() & !1)
        .ok_or_else(|| format!("the firmware has no symbol `{name}`"))
}
