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
        loop {
            start -= 1;
            digits[start] = b'0' + (value % 10) as u8;
            value /= 10;
            if value == 0 {
                break;
            }
        }
        Self { digits, start }
    }

    pub fn as_bytes(&self) -> &[u8] {
        &self.digits[self.start..]
    }

    pub fn as_str(&self) -> &str {
        // Only ASCII digits were written.
        core::str::from_utf8(self.as_bytes()).unwrap_or("?")
    }
}
