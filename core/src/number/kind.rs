//! The number types by name: the one switch from a name (`f64`, `f32`, `fixed`, `fixed16`,
//! `f32-micromath`, `soft32`) to a type, shared by the command line, the firmware's build
//! script and xtask.

/// One of the number types a build can render in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum NumberKind {
    /// IEEE double precision: the reference.
    F64,
    /// IEEE single precision.
    F32,
    /// Q32.32 fixed point (64-bit integers): the recommended type for FPU-less targets.
    Fixed,
    /// Q16.16 fixed point (32-bit integers): cheaper, less accurate.
    Fixed16,
    /// f32 with micromath's fast approximate square root.
    F32Micromath,
    /// Software floating point for FPU-less cores: 28-bit mantissa, binary exponent.
    Soft32,
}

impl NumberKind {
    /// Every kind, the reference first.
    pub const ALL: [NumberKind; 6] = [NumberKind::F64, NumberKind::F32, NumberKind::Fixed, NumberKind::Fixed16, NumberKind::F32Micromath, NumberKind::Soft32];

    /// The name: the command line's `--number`, the firmware's `MICROTRACE_NUMBER`, and the
    /// type's `Number::NAME`.
    pub const fn name(self) -> &'static str {
        match self {
            NumberKind::F64 => "f64",
            NumberKind::F32 => "f32",
            NumberKind::Fixed => "fixed",
            NumberKind::Fixed16 => "fixed16",
            NumberKind::F32Micromath => "f32-micromath",
            NumberKind::Soft32 => "soft32",
        }
    }

    /// The kind of this name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|kind| kind.name() == name)
    }

    /// One line on what it is (the command line's help).
    pub const fn summary(self) -> &'static str {
        match self {
            NumberKind::F64 => "IEEE double precision: the reference",
            NumberKind::F32 => "IEEE single precision",
            NumberKind::Fixed => "Q32.32 fixed point (64-bit integers): the recommended type for FPU-less targets",
            NumberKind::Fixed16 => "Q16.16 fixed point (32-bit integers): cheaper, less accurate",
            NumberKind::F32Micromath => "f32 with micromath's fast approximate square root",
            NumberKind::Soft32 => "software floating point for FPU-less cores: 28-bit mantissa, binary exponent",
        }
    }

    /// The type's path, for code a build script writes (`microtrace::number::Fixed`).
    pub const fn type_path(self) -> &'static str {
        match self {
            NumberKind::F64 => "f64",
            NumberKind::F32 => "f32",
            NumberKind::Fixed => "microtrace::number::Fixed",
            NumberKind::Fixed16 => "microtrace::number::Fixed16",
            NumberKind::F32Micromath => "microtrace::number::F32Micro",
            NumberKind::Soft32 => "microtrace::number::SoftFloat",
        }
    }

    /// The cargo feature of this crate (and of the firmware) that compiles the type in.
    pub const fn feature(self) -> Option<&'static str> {
        match self {
            NumberKind::F64 | NumberKind::F32 => None,
            NumberKind::Fixed | NumberKind::Fixed16 => Some("fixed-point"),
            NumberKind::F32Micromath => Some("micromath"),
            NumberKind::Soft32 => Some("soft-float"),
        }
    }
}

/// Runs `$body` with the type alias `$number` bound to the type of the [`NumberKind`]
/// `$kind`: `with_number_kind!(kind, N => render::<N>(...))`. Every number type must be
/// compiled in (the crate's default features).
#[macro_export]
macro_rules! with_number_kind {
    ($kind:expr, $number:ident => $body:expr) => {
        match $kind {
            $crate::number::NumberKind::F64 => {
                type $number = f64;
                $body
            }
            $crate::number::NumberKind::F32 => {
                type $number = f32;
                $body
            }
            $crate::number::NumberKind::Fixed => {
                type $number = $crate::number::Fixed;
                $body
            }
            $crate::number::NumberKind::Fixed16 => {
                type $number = $crate::number::Fixed16;
                $body
            }
            $crate::number::NumberKind::F32Micromath => {
                type $number = $crate::number::F32Micro;
                $body
            }
            $crate::number::NumberKind::Soft32 => {
                type $number = $crate::number::SoftFloat;
                $body
            }
        }
    };
}

#[cfg(all(test, feature = "fixed-point", feature = "micromath", feature = "soft-float"))]
mod tests {
    use super::NumberKind;
    use crate::number::Number;

    #[test]
    fn each_name_is_its_types_name_and_leads_back_to_it() {
        for kind in NumberKind::ALL {
            let name = crate::with_number_kind!(kind, N => <N as Number>::NAME);
            assert_eq!(name, kind.name());
            assert_eq!(NumberKind::from_name(kind.name()), Some(kind));
        }
        assert_eq!(NumberKind::from_name("f16"), None);
    }
}
