//! The number grammar of the scene format, checked by hand before `str::parse::<f64>` so that
//! Rust's extra spellings (`inf`, `nan`, `.5`, `5.`) are not accepted, plus an exact test of
//! whether a decimal has a fractional part. Everything here is one pass over the token.

/// The parts of a well-formed number: `[sign] int [. frac] [(e|E) [sign] exp]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Decimal<'a> {
    pub int: &'a [u8],
    pub frac: &'a [u8],
    pub exp_negative: bool,
    pub exp: &'a [u8],
}

/// Splits `bytes` at the end of its leading run of ASCII digits.
fn digits(bytes: &[u8]) -> (&[u8], &[u8]) {
    let end = bytes.iter().position(|b| !b.is_ascii_digit()).unwrap_or(bytes.len());
    bytes.split_at(end)
}

/// Strips one leading `+` or `-`; returns whether it was `-`.
fn sign(bytes: &[u8]) -> (bool, &[u8]) {
    match bytes.split_first() {
        Some((b'-', rest)) => (true, rest),
        Some((b'+', rest)) => (false, rest),
        _ => (false, bytes),
    }
}

/// Checks the grammar: optional sign, at least one digit, optionally `.` and at least one
/// digit, optionally `e`/`E`, an optional sign and at least one digit; nothing else.
pub(crate) fn split(token: &str) -> Option<Decimal<'_>> {
    let (_, rest) = sign(token.as_bytes());
    let (int, rest) = digits(rest);
    if int.is_empty() {
        return None;
    }
    let (frac, rest) = match rest.split_first() {
        Some((b'.', after)) => {
            let (frac, rest) = digits(after);
            if frac.is_empty() {
                return None;
            }
            (frac, rest)
        }
        _ => (&[][..], rest),
    };
    let (exp_negative, exp, rest) = match rest.split_first() {
        Some((b'e' | b'E', after)) => {
            let (negative, after) = sign(after);
            let (exp, rest) = digits(after);
            if exp.is_empty() {
                return None;
            }
            (negative, exp, rest)
        }
        _ => (false, &[][..], rest),
    };
    if !rest.is_empty() {
        return None;
    }
    Some(Decimal { int, frac, exp_negative, exp })
}

impl Decimal<'_> {
    /// Whether the decimal's exact value is a whole number (so `1e2` and `1.50e1` are, and
    /// `1.0000000000000000001` and `1e-400` are not), independent of float rounding.
    pub fn is_integral(&self) -> bool {
        let all = self.int.iter().chain(self.frac);
        if all.clone().all(|&b| b == b'0') {
            return true;
        }
        // value = D · 10^(exp − |frac|); strip D's trailing zeros into the exponent.
        let trailing_zeros = self.int.iter().chain(self.frac).rev().take_while(|&&b| b == b'0').count();
        let length = |n: usize| i64::try_from(n).unwrap_or(i64::MAX);
        let mut exp: i64 = 0;
        for &b in self.exp {
            exp = exp.saturating_mul(10).saturating_add(i64::from(b.saturating_sub(b'0')));
        }
        if self.exp_negative {
            exp = -exp;
        }
        exp.saturating_sub(length(self.frac.len())).saturating_add(length(trailing_zeros)) >= 0
    }
}
