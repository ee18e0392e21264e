//! The number types the command line offers, and dispatch from a runtime choice to the
//! generic core.

use clap::ValueEnum;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum NumberType {
    /// IEEE double precision: the reference.
    F64,
    /// IEEE single precision.
    F32,
}

impl NumberType {
    pub const ALL: &'static [NumberType] = &[NumberType::F64, NumberType::F32];

    pub fn name(self) -> &'static str {
        match self {
            NumberType::F64 => "f64",
            NumberType::F32 => "f32",
        }
    }
}

/// Runs `$body` with the type alias `$number` bound to the chosen number type.
#[macro_export]
macro_rules! with_number_type {
    ($choice:expr, $number:ident => $body:expr) => {
        match $choice {
            $crate::number_type::NumberType::F64 => {
                type $number = f64;
                $body
            }
            $crate::number_type::NumberType::F32 => {
                type $number = f32;
                $body
            }
        }
    };
}
