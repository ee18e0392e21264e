//! Integers as decimal text without `core::fmt`: formatting numbers with `{}` pulls in kilobytes
//! of flash (docs: shared/research/qemu.md, "Memory footprint"), and the report needs integers
//! only.

/// The decimal digits of `value`, in a buffer large enough for any `u64`.
pub struct Decimal {
    digits: [u8; 20],
    start: usize,
}

impl Decimal {
    pub fn new(mut value: u64) -> Self {
        let mut digits = [0u8; 20];
        let mut start = digits.len();
        // From the last digit back; 20 digits hold any u64, so the iterator never runs out.
        for digit in digits.iter_mut().rev() {
            let (quotient, remainder) = divide_by_ten(value);
            *digit = b'0' + remainder;
            start -= 1;
            value = quotient;
            if value == 0 {
                break;
            }
        }
        Self { digits, start }
    }

    /// The digits.
    pub fn as_bytes(&self) -> &[u8] {
        self.digits.get(self.start..).unwrap_or(&[])
    }

    pub fn as_str(&self) -> &str {
        // Only ASCII digits were written.
        core::str::from_utf8(self.as_bytes()).unwrap_or("?")
    }
}

/// `value` divided by ten, and the remainder, in 32-bit divisions: a 64-bit one links
/// compiler-builtins' 866-byte `u64_div_rem`. The high word first; then what it leaves, below
/// ten, over the low word in two 16-bit steps, each dividend below 10 · 2¹⁶.
fn divide_by_ten(value: u64) -> (u64, u8) {
    let (high, low) = ((value >> 32) as u32, value as u32);
    let (high_quotient, high_remainder) = (high / 10, high % 10);
    let middle = (high_remainder << 16) | (low >> 16);
    let (middle_quotient, middle_remainder) = (middle / 10, middle % 10);
    let bottom = (middle_remainder << 16) | (low & 0xFFFF);
    let (bottom_quotient, remainder) = (bottom / 10, bottom % 10);
    ((u64::from(high_quotient) << 32) | (u64::from(middle_quotient) << 16) | u64::from(bottom_quotient), remainder as u8)
}
