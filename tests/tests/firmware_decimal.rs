//! The firmware's decimal digits (firmware/src/decimal.rs, compiled here for the host): the
//! report's integers and the fault messages' numbers, formatted with 32-bit divisions only,
//! against the standard library's formatting, edges and a million pseudo-random values of
//! every magnitude.

#[path = "../../firmware/src/decimal.rs"]
#[allow(dead_code)]
mod decimal;

use decimal::Decimal;

#[test]
fn the_firmwares_digits_are_the_standard_librarys() {
    let edges = [0, 1, 9, 10, 11, 99, 100, 65_535, 65_536, 655_359, 655_360, u64::from(u32::MAX), u64::from(u32::MAX) + 1, 1 << 48, (1 << 48) - 1, u64::MAX - 1, u64::MAX];
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let random = (0..1_000_000).map(|_| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state >> (state % 64)
    });
    for value in edges.into_iter().chain(random) {
        assert_eq!(Decimal::new(value).as_str(), value.to_string(), "{value}");
    }
}
