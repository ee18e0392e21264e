//! What xtask reads from the firmware ELF: the memory footprint (as `size` reports it), the
//! addresses of the measurement markers, and the audit of what is linked: which function
//! symbols are double-precision routines, panic paths or `core::fmt` ([`audit`]).

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

/// The demangled names of the ELF's symbols (what a build test looks for: a feature's code
/// linked or left out).
pub fn symbol_names(elf: &[u8]) -> Result<Vec<String>, String> {
    let file = object::File::parse(elf).map_err(|error| format!("not an ELF file: {error}"))?;
    Ok(file.symbols().filter_map(|symbol| symbol.name().ok().map(demangle)).collect())
}

/// What the linked-code audit looks for in the firmware's function symbols.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum LinkedKind {
    /// Double-precision arithmetic: compiler-builtins' soft-float routines (`__adddf3`,
    /// `__aeabi_dmul`, `__aeabi_f2d`, ...) and libm's `f64` functions (`libm::math::sqrt::sqrt`,
    /// the exported `fmin`, ...).
    F64,
    /// Panic paths: `core::panicking::*`, bounds and slice-index failures, `panic_const_*`,
    /// `panic_fmt`, `unwrap_failed`/`expect_failed` and the panic handler.
    Panic,
    /// `core::fmt` formatting.
    Fmt,
}

/// One function symbol the audit lists.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkedSymbol {
    /// The name in the ELF, as `llvm-nm` prints it without `--demangle`.
    pub name: String,
    /// Demangled without the hash (`{:#}` of rustc-demangle); the name itself when it is not mangled.
    pub demangled: String,
}

/// The function symbols of each kind, sorted by demangled name. A symbol may be of more than
/// one kind (a formatting function in a panic path).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LinkedAudit {
    pub f64: Vec<LinkedSymbol>,
    pub panic: Vec<LinkedSymbol>,
    pub fmt: Vec<LinkedSymbol>,
}

impl LinkedAudit {
    /// `linked-audit.txt`: a heading with the count for each kind, then its symbols, one a line
    /// (the demangled name, then the ELF's name when that differs).
    pub fn text(&self) -> String {
        let mut text = String::new();
        for (heading, symbols) in [
            ("f64 routines (double-precision soft float and libm f64)", &self.f64),
            ("panic symbols", &self.panic),
            ("core::fmt symbols", &self.fmt),
        ] {
            text += &format!("{heading}: {}\n", symbols.len());
            for symbol in symbols {
                if symbol.name == symbol.demangled {
                    text += &format!("  {}\n", symbol.name);
                } else {
                    text += &format!("  {}  ({})\n", symbol.demangled, symbol.name);
                }
            }
        }
        text
    }
}

/// Classifies the ELF's function symbols (`STT_FUNC`, local ones too, as `llvm-nm` lists them).
pub fn audit(elf: &[u8]) -> Result<LinkedAudit, String> {
    let file = object::File::parse(elf).map_err(|error| format!("not an ELF file: {error}"))?;
    let mut audit = LinkedAudit::default();
    for symbol in file.symbols() {
        if symbol.kind() != object::SymbolKind::Text {
            continue;
        }
        let Ok(name) = symbol.name() else { continue };
        if name.is_empty() {
            continue;
        }
        let demangled = demangle(name);
        let entry = LinkedSymbol { name: name.to_owned(), demangled: demangled.clone() };
        for kind in classify(name, &demangled) {
            let list = match kind {
                LinkedKind::F64 => &mut audit.f64,
                LinkedKind::Panic => &mut audit.panic,
                LinkedKind::Fmt => &mut audit.fmt,
            };
            if !list.contains(&entry) {
                list.push(entry.clone());
            }
        }
    }
    for list in [&mut audit.f64, &mut audit.panic, &mut audit.fmt] {
        list.sort_by(|a, b| (&a.demangled, &a.name).cmp(&(&b.demangled, &b.name)));
    }
    Ok(audit)
}

/// A symbol name demangled (Rust legacy `_ZN...E` or v0 `_R...`) without its hash or crate
/// disambiguators; other names as they are.
pub fn demangle(name: &str) -> String {
    match rustc_demangle::try_demangle(name) {
        Ok(demangled) => format!("{demangled:#}"),
        Err(_) => name.to_owned(),
    }
}

/// The kinds of one function symbol, from its ELF name and its demangled name.
pub fn classify(name: &str, demangled: &str) -> Vec<LinkedKind> {
    let mut kinds = Vec::new();
    if is_f64(name, demangled) {
        kinds.push(LinkedKind::F64);
    }
    if is_panic(demangled) {
        kinds.push(LinkedKind::Panic);
    }
    if demangled.contains("core::fmt::") {
        kinds.push(LinkedKind::Fmt);
    }
    kinds
}

/// libm's `f64` functions by their C names (compiler-builtins also exports some unmangled:
/// `fmin`, `fmax`, ...). Their `f32` versions add an `f` (`sqrtf`, `floorf`, `lgammaf_r`);
/// `erf` and `modf` end in `f` but are `f64`.
const LIBM_F64: [&str; 63] = [
    "acos", "acosh", "asin", "asinh", "atan", "atan2", "atanh", "cbrt", "ceil", "copysign", "cos", "cosh", "erf",
    "erfc", "exp", "exp10", "exp2", "expm1", "fabs", "fdim", "floor", "fma", "fmax", "fmaximum", "fmaximum_num",
    "fmin", "fminimum", "fminimum_num", "fmod", "frexp", "hypot", "ilogb", "j0", "j1", "jn", "ldexp", "lgamma",
    "lgamma_r", "log", "log10", "log1p", "log2", "logb", "modf", "nextafter", "pow", "remainder", "remquo", "rint",
    "round", "roundeven", "scalbn", "sin", "sincos", "sinh", "sqrt", "tan", "tanh", "tgamma", "trunc", "y0", "y1",
    "yn",
];

fn is_f64(name: &str, demangled: &str) -> bool {
    // The routine's own name: the last path segment (`compiler_builtins::float::add::__adddf3`),
    // or the name when it is not mangled (`__aeabi_dadd`, `fmin`).
    let last = demangled.rsplit("::").next().unwrap_or(demangled);
    let unmangled = name == demangled;
    let builtin = unmangled || demangled.starts_with("compiler_builtins::");
    if builtin && (is_aeabi_f64(last) || is_libgcc_f64(last)) {
        return true;
    }
    if unmangled && LIBM_F64.contains(&name) {
        return true;
    }
    is_libm_f64_path(demangled)
}

/// The ARM run-time ABI's double-precision helpers: `__aeabi_dadd`, `__aeabi_dcmplt`,
/// `__aeabi_d2iz`, `__aeabi_cdcmple`, and the conversions to double, `__aeabi_i2d`,
/// `__aeabi_ui2d`, `__aeabi_l2d`, `__aeabi_ul2d`, `__aeabi_f2d`. Not `__aeabi_div0`.
fn is_aeabi_f64(name: &str) -> bool {
    let Some(rest) = name.strip_prefix("__aeabi_") else { return false };
    (rest.starts_with('d') && !rest.starts_with("div")) || rest.starts_with("cd") || rest.ends_with("2d")
}

/// libgcc's names for soft double (mode `df`): `__adddf3`, `__eqdf2`, `__floatsidf`,
/// `__extendsfdf2`, `__fixdfsi`, `__fixunsdfdi`, `__truncdfsf2`, `__adddf3vfp`, ...
fn is_libgcc_f64(name: &str) -> bool {
    let Some(rest) = name.strip_prefix("__") else { return false };
    let rest = rest.strip_suffix("vfp").unwrap_or(rest);
    let base = rest.trim_end_matches(|c: char| c.is_ascii_digit());
    !base.is_empty()
        && (base.ends_with("df")
            || ["fixdf", "fixunsdf", "truncdf", "extenddf"].iter().any(|prefix| base.starts_with(prefix)))
}

/// A function of libm's `f64` modules: `libm::math::<module>::...` where the module is an `f64`
/// function (`sqrt`, `floor`, `atan2`) or one of its helpers (`k_cos`, `rem_pio2`, `acos::r`);
/// not the `f32`/`f16`/`f128` ones (`sqrtf`, `k_cosf`, `rem_pio2f`, `fabsf16`), nor the
/// type-generic `generic`, `support` and `arch` modules, whose precision the name does not say.
fn is_libm_f64_path(demangled: &str) -> bool {
    let Some(rest) = demangled.strip_prefix("libm::math::") else { return false };
    let Some((module, _)) = rest.split_once("::") else { return false };
    if LIBM_F64.contains(&module) {
        return true;
    }
    if ["generic", "support", "arch"].contains(&module) || module.is_empty() {
        return false;
    }
    let stem = module.strip_suffix("_r").unwrap_or(module);
    !(stem.ends_with('f') || stem.ends_with("f16") || stem.ends_with("f128"))
}

/// Panic paths, by demangled name.
fn is_panic(demangled: &str) -> bool {
    const NAMES: [&str; 12] = [
        "core::panicking::",
        "panic_bounds_check",
        "slice_index_fail",
        "slice_start_index_len_fail",
        "slice_end_index_len_fail",
        "slice_index_order_fail",
        "panic_const_",
        "panic_fmt",
        "unwrap_failed",
        "expect_failed",
        "rust_begin_unwind",
        "panic_already_borrowed",
    ];
    NAMES.iter().any(|part| demangled.contains(part))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Names as they are in the mps2-an386 f32 snooker firmware (`llvm-nm`), and ones like them.
    fn kinds(name: &str) -> Vec<LinkedKind> {
        classify(name, &demangle(name))
    }

    #[test]
    fn demangles_both_manglings_without_hashes() {
        assert_eq!(demangle("_ZN4libm4math4sqrt4sqrt17hd7d7d20bebe527c6E"), "libm::math::sqrt::sqrt");
        assert_eq!(
            demangle("_RNvNtNtCs7NhdfSRABLd_17compiler_builtins5float3add8___adddf3"),
            "compiler_builtins::float::add::__adddf3"
        );
        assert_eq!(demangle("_RNvNtCs7ldSeZOOJos_4core9panicking18panic_bounds_check"), "core::panicking::panic_bounds_check");
        assert_eq!(demangle("__aeabi_dadd"), "__aeabi_dadd");
    }

    #[test]
    fn double_precision_routines_are_found() {
        for name in [
            // Linked today (llvm-nm of the mps2-an386 f32 snooker build).
            "__aeabi_dadd",
            "__aeabi_dsub",
            "__aeabi_dmul",
            "__aeabi_ddiv",
            "__aeabi_dcmpeq",
            "__aeabi_dcmplt",
            "__aeabi_dcmple",
            "__aeabi_dcmpge",
            "__aeabi_dcmpgt",
            "__aeabi_dcmpun",
            "__aeabi_d2f",
            "__aeabi_d2iz",
            "__aeabi_d2uiz",
            "__aeabi_f2d",
            "__aeabi_i2d",
            "__aeabi_ui2d",
            "_RNvNtNtCs7NhdfSRABLd_17compiler_builtins5float3add8___adddf3",
            "_RNvNtNtCs7NhdfSRABLd_17compiler_builtins5float3div8___divdf3",
            "_RNvNtNtCs7NhdfSRABLd_17compiler_builtins5float3mul8___muldf3",
            "fmax",
            "fmin",
            "_ZN4libm4math4sqrt4sqrt17hd7d7d20bebe527c6E",
            "_ZN4libm4math4asin4asin17h42645843f1de5fc7E",
            "_ZN4libm4math4acos1r17h4cd3c6608e1ff0ebE",
            "_ZN4libm4math4ceil4ceil17he60d88514a2cdcd2E",
            "_ZN4libm4math5floor5floor17h1fcb41bcd201901dE",
            "_ZN4libm4math5k_cos5k_cos17h7c00a1bb5d3d0df3E",
            "_ZN4libm4math5k_sin5k_sin17hee53dd3558037485E",
            "_ZN4libm4math6scalbn6scalbn17h23335301ab7b5636E",
            "_ZN4libm4math8rem_pio28rem_pio26medium17h98a3556b0a14b275E",
            // Others of the same families.
            "__aeabi_l2d",
            "__aeabi_ul2d",
            "__aeabi_d2lz",
            "__aeabi_cdcmple",
            "__subdf3",
            "__extendsfdf2",
            "__truncdfsf2",
            "__fixdfsi",
            "__fixunsdfsi",
            "__floatsidf",
            "__floatunsidf",
            "__eqdf2",
            "__ledf2",
            "__gedf2",
            "__unorddf2",
            "__adddf3vfp",
            "sqrt",
            "floor",
            "erf",
            "modf",
            "_ZN4libm4math5atan25atan217h0123456789abcdefE",
            "_ZN4libm4math5round5round17h0123456789abcdefE",
            "_ZN4libm4math3cos3cos17h0123456789abcdefE",
        ] {
            assert!(kinds(name).contains(&LinkedKind::F64), "{name} ({}) is double precision", demangle(name));
        }
    }

    #[test]
    fn single_precision_and_integer_routines_are_not() {
        for name in [
            "__aeabi_fadd",
            "__aeabi_fmul",
            "__aeabi_f2iz",
            "__aeabi_i2f",
            "__aeabi_uldivmod",
            "__aeabi_div0",
            "__aeabi_idiv",
            "__aeabi_memcpy",
            "__addsf3",
            "__floatsisf",
            "__fixsfsi",
            "__udivmoddi4",
            "_RNvNtNtCs7NhdfSRABLd_17compiler_builtins3int19specialized_div_rem11u64_div_rem",
            "sqrtf",
            "floorf",
            "fminf",
            "erff",
            "modff",
            "_ZN4libm4math5sqrtf5sqrtf17h0123456789abcdefE",
            "_ZN4libm4math6floorf6floorf17h0123456789abcdefE",
            "_ZN4libm4math6k_cosf6k_cosf17h0123456789abcdefE",
            "_ZN4libm4math9rem_pio2f9rem_pio2f17h0123456789abcdefE",
            "_ZN4libm4math9lgammaf_r9lgammaf_r17h0123456789abcdefE",
            "_ZN4libm4math7fabsf167fabsf1617h0123456789abcdefE",
            "_ZN4libm4math7generic4sqrt9RSQRT_TAB17he16595f9ed77d006E",
            "_ZN10microtrace6number5float78_$LT$impl$u20$microtrace..number..Number$u20$for$u20$f32$GT$4sqrt17h8db36369a486ff0fE",
            "microtrace_measure_start",
        ] {
            assert!(!kinds(name).contains(&LinkedKind::F64), "{name} ({}) is not double precision", demangle(name));
        }
    }

    #[test]
    fn panic_and_formatting_paths_are_found() {
        for name in [
            "_RNvNtCs7ldSeZOOJos_4core9panicking18panic_bounds_check",
            "_RNvNtCs7ldSeZOOJos_4core9panicking9panic_fmt",
            "_RNvNtNtCs7ldSeZOOJos_4core9panicking11panic_const23panic_const_div_by_zero",
            "_RNvNtNtCs7ldSeZOOJos_4core5slice5index16slice_index_fail",
        ] {
            assert_eq!(kinds(name), [LinkedKind::Panic], "{name} ({})", demangle(name));
        }
        for name in ["_RNvNvMsa_NtCs7ldSeZOOJos_4core3fmtNtB7_9Formatter12pad_integral12write_prefix", "_RNvXsd_NtNtNtCs7ldSeZOOJos_4core3fmt3num3impjNtB9_7Display3fmt"] {
            assert_eq!(kinds(name), [LinkedKind::Fmt], "{name} ({})", demangle(name));
        }
        for name in [
            "_ZN19microtrace_firmware4fail17hdfa094dc4a9d9e18E",
            "_ZN10microtrace8geometry9transform24AffineTransform$LT$N$GT$3ray17h6df4e2bada79fc99E",
            "HardFault",
        ] {
            assert!(kinds(name).is_empty(), "{name} ({}) is none of them", demangle(name));
        }
    }
}

/// One symbol in flash: its demangled name, its bytes and its area ([`area`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FlashSymbol {
    pub demangled: String,
    pub bytes: u64,
    pub area: String,
}

/// Each area's flash bytes, largest first.
pub type FlashAreas = Vec<(String, u64)>;

/// Where the flash goes, `cargo bloat`'s way: every sized symbol in a section that reaches flash
/// (code, read-only data, `.data`'s initial values), largest first (aliases of one address
/// counted once), and the bytes of each area; what no symbol covers (alignment, unnamed
/// constants) is the area `(no symbol)`.
pub fn flash_symbols(elf: &[u8]) -> Result<(Vec<FlashSymbol>, FlashAreas), String> {
    let file = object::File::parse(elf).map_err(|error| format!("not an ELF file: {error}"))?;
    let in_flash = |index: object::SectionIndex| {
        file.section_by_index(index).ok().is_some_and(|section| {
            let SectionFlags::Elf { sh_flags } = section.flags() else { return false };
            let nobits = matches!(section.kind(), object::SectionKind::UninitializedData | object::SectionKind::UninitializedTls);
            sh_flags & SHF_ALLOC != 0 && !nobits
        })
    };
    let mut seen = std::collections::BTreeSet::new();
    let mut symbols: Vec<FlashSymbol> = file
        .symbols()
        .filter(|symbol| symbol.size() > 0 && matches!(symbol.kind(), object::SymbolKind::Text | object::SymbolKind::Data))
        .filter(|symbol| symbol.section_index().is_some_and(in_flash))
        .filter(|symbol| seen.insert((symbol.section_index().map(|index| index.0), symbol.address())))
        .filter_map(|symbol| {
            let demangled = demangle(symbol.name().ok()?);
            Some(FlashSymbol { area: area(&demangled), demangled, bytes: symbol.size() })
        })
        .collect();
    symbols.sort_by(|a, b| b.bytes.cmp(&a.bytes).then_with(|| a.demangled.cmp(&b.demangled)));
    let mut areas: std::collections::BTreeMap<String, u64> = std::collections::BTreeMap::new();
    for symbol in &symbols {
        *areas.entry(symbol.area.clone()).or_default() += symbol.bytes;
    }
    let named: u64 = areas.values().sum();
    let flash = footprint(elf)?.flash_bytes();
    areas.insert("(no symbol)".to_owned(), flash.saturating_sub(named));
    let mut areas: Vec<(String, u64)> = areas.into_iter().collect();
    areas.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    Ok((symbols, areas))
}

/// The module a symbol's code or data belongs to: the core's and the firmware's to their second
/// level (`microtrace::number`, `microtrace::render`, `microtrace_firmware::scene`), anything
/// else to its crate (`compiler_builtins`, `core`, `libm`); an implementation for a type goes to
/// the type's module (`<microtrace::number::SoftFloat as core::ops::Add>::add` is
/// `microtrace::number`).
pub fn area(demangled: &str) -> String {
    let bare = |text: &str| -> String {
        let mut text = text;
        loop {
            let trimmed = text.trim_start_matches(['<', '&', '[', '(', '*']).trim_start_matches("impl ").trim_start_matches("mut ").trim_start_matches("const ");
            if trimmed == text {
                return text.to_owned();
            }
            text = trimmed;
        }
    };
    let path = bare(demangled);
    // `<f32 as microtrace::number::Number>::add`: a type without a path goes by its trait.
    let path = match path.split_once(" as ") {
        Some((own, trait_path)) if !own.contains("::") => bare(trait_path),
        _ => path,
    };
    let path = path.split([' ', '<', '>', '(', ',', ';', ']']).next().unwrap_or("");
    let segments: Vec<&str> = path.split("::").collect();
    match segments.as_slice() {
        [krate @ ("microtrace" | "microtrace_firmware"), module, _, ..] => format!("{krate}::{module}"),
        [krate, _, ..] if !krate.is_empty() => (*krate).to_owned(),
        _ => "(other)".to_owned(),
    }
}

/// `flash-by-function.txt`: the areas, then every symbol, largest first.
pub fn flash_text(symbols: &[FlashSymbol], areas: &[(String, u64)]) -> String {
    let total: u64 = areas.iter().map(|(_, bytes)| bytes).sum();
    let mut text = format!("flash: {total} bytes\n\nby area:\n");
    for (name, bytes) in areas {
        text += &format!("{bytes:>8}  {name}\n");
    }
    text += "\nby symbol:\n";
    for symbol in symbols {
        text += &format!("{:>8}  {}\n", symbol.bytes, symbol.demangled);
    }
    text
}

#[cfg(test)]
mod area_tests {
    use super::area;

    #[test]
    fn a_symbol_goes_to_its_module_or_its_crate() {
        assert_eq!(area("<microtrace::number::soft_float::SoftFloat as core::ops::arith::Add>::add"), "microtrace::number");
        assert_eq!(area("microtrace::render::direct_lighting::direct_lighting"), "microtrace::render");
        assert_eq!(area("microtrace_firmware::scene::OBJECTS"), "microtrace_firmware::scene");
        assert_eq!(area("microtrace_firmware::main"), "microtrace_firmware");
        assert_eq!(area("compiler_builtins::float::add::__addsf3"), "compiler_builtins");
        assert_eq!(area("__aeabi_fadd"), "(other)");
        assert_eq!(area("<f32 as microtrace::number::Number>::checked_div"), "microtrace::number");
        assert_eq!(area("<[T; N] as core::fmt::Debug>::fmt"), "core");
        assert_eq!(area("<(A, B) as microtrace::storage::Table<T>>::slots"), "microtrace::storage");
    }
}
