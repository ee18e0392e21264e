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
            *digit = b'0' + (value % 10) as u8;
            start -= 1;
            value /= 10;
            if value == 0 {
                break;
            }
        }
        Self { digits, start }
    }

    pub fn as_bytes(&self) -> &[u8] {
        self.digits.get(self.start..).unwrap_or(&[])
    }

    pub fn as_str(&self) -> &str {
        // Only ASCII digits were written.
        core::str::from_utf8(self.as_bytes()).unwrap_or("?")
    }
}
