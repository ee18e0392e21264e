//! The number types the command line offers, and dispatch from a runtime choice to the
//! generic core.

use clap::ValueEnum;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum NumberType {
    /// IEEE double precision: the reference.
    F64,
    /// IEEE single precision.
    F32,
    /// Q32.32 fixed point (64-bit integers): the recommended type for FPU-less targets.
    Fixed,
    /// Q16.16 fixed point (32-bit integers): cheaper, less accurate.
    Fixed16,
    /// f32 with micromath's fast approximate square root.
    #[value(name = "f32-micromath")]
    F32Micromath,
    /// Software floating point for FPU-less cores: 28-bit mantissa, binary exponent.
    #[value(name = "soft32")]
    Soft32,
}

impl NumberType {
    pub const ALL: &'static [NumberType] =
        &[NumberType::F64, NumberType::F32, NumberType::Fixed, NumberType::Fixed16, NumberType::F32Micromath, NumberType::Soft32];

    /// The command-line name, which is also the core type's `Number::NAME`.
    pub fn name(self) -> &'static str {
        use microtrace::number::{Fixed, Fixed16, F32Micro, Number, SoftFloat};
        match self {
            NumberType::F64 => <f64 as Number>::NAME,
            NumberType::F32 => <f32 as Number>::NAME,
            NumberType::Fixed => Fixed::NAME,
            NumberType::Fixed16 => Fixed16::NAME,
            NumberType::F32Micromath => F32Micro::NAME,
            NumberType::Soft32 => SoftFloat::NAME,
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
            $crate::number_type::NumberType::Fixed => {
                type $number = microtrace::number::Fixed;
                $body
            }
            $crate::number_type::NumberType::Fixed16 => {
                type $number = microtrace::number::Fixed16;
                $body
            }
            $crate::number_type::NumberType::F32Micromath => {
                type $number = microtrace::number::F32Micro;
                $body
            }
            $crate::number_type::NumberType::Soft32 => {
                type $number = microtrace::number::SoftFloat;
                $body
            }
        }
    };
}

#[cfg(test)]
mod tests {
    use super::NumberType;
    use clap::ValueEnum;

    #[test]
    fn command_line_names_are_the_core_type_names() {
        for number in NumberType::ALL {
            let value = number.to_possible_value().expect("every type is offered");
            assert_eq!(value.get_name(), number.name());
        }
        let names: Vec<&str> = NumberType::ALL.iter().map(|n| n.name()).collect();
        assert_eq!(names, ["f64", "f32", "fixed", "fixed16", "f32-micromath", "soft32"]);
        assert_eq!(NumberType::value_variants().len(), NumberType::ALL.len());
    }
}
