//! Writing floats as `{}`, `{:.N}` and `{:e}` write them, through one small path. Rust's own float
//! formatting (shortest digits by Grisu with a Dragon4 fallback, exact digits by big-number arithmetic,
//! and their tables) is about 10 KB of the browser's gzipped wasm; here the shortest digits come from
//! `zmij`, which the wasm carries anyway for writing JSON, and exact digits from 128-bit integers.
//! Everything the wasm formats goes through these types, so that the wasm holds none of core's float
//! formatting; the tests check every form against Rust's own.

use std::fmt;

/// An f32 or f64 for a message or text: `{}` of it writes exactly what `{}` of the float writes (its
/// shortest decimal that reads back as itself, never in scientific notation; `NaN`, `inf`, `-inf`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Num {
    F32(f32),
    F64(f64),
}

impl From<f32> for Num {
    fn from(x: f32) -> Self {
        Num::F32(x)
    }
}

impl From<f64> for Num {
    fn from(x: f64) -> Self {
        Num::F64(x)
    }
}

/// `x` as `{}` writes it: `num(x)` in a message instead of `x`.
pub fn num(x: impl Into<Num>) -> Num {
    x.into()
}

/// `x` with `places` digits after the point, as `{:.places$}` writes it (exactly rounded, ties to
/// even).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fixed(pub f64, pub usize);

/// `x` in scientific notation with its shortest digits, as `{:e}` writes it (`1.5e-7`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sci(pub f64);

/// The shortest decimal digits of a finite float (no leading or trailing zeros, `0` for zero) and
/// the power of ten of the point: the value is `0.DIGITS × 10^point`.
struct Digits {
    negative: bool,
    digits: Vec<u8>,
    point: i32,
}

/// The f64 that `x`'s shortest decimal (as `{}` writes it) reads as, where it can be worked out
/// without reading text: digits that fit 2⁵³ and a power of ten within 10²², so one correctly rounded
/// multiplication or division by an exact power of ten gives the correctly rounded value (Clinger's
/// fast path). `None` otherwise (and for values that are not finite).
pub fn shortest_as_f64(x: f32) -> Option<f64> {
    if !x.is_finite() {
        return None;
    }
    let digits = Num::F32(x).digits();
    let whole = digits.whole().filter(|&w| w < 1 << 53)?;
    let tens = digits.point - digits.digits.len() as i32;
    let power = *POWERS_OF_TEN.get(tens.unsigned_abs() as usize)?;
    let value = if tens >= 0 { whole as f64 * power } else { whole as f64 / power };
    Some(if digits.negative { -value } else { value })
}

/// 10⁰ to 10²², each exact in an f64.
const POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18,
    1e19, 1e20, 1e21, 1e22,
];

impl Num {
    fn as_f64(self) -> f64 {
        match self {
            Num::F32(x) => f64::from(x),
            Num::F64(x) => x,
        }
    }

    fn digits(self) -> Digits {
        let mut buffer = zmij::Buffer::new();
        let text = match self {
            Num::F32(x) => buffer.format_finite(x),
            Num::F64(x) => buffer.format_finite(x),
        };
        let mut digits = digits_of(text);
        // At an exact tie between two shortest decimals zmij may write the lower; Rust writes the
        // upper.
        if self.is_tie(&digits) {
            digits.round_up();
        }
        digits
    }

    /// Whether the value lies exactly halfway between `digits` and the decimal one unit of their last
    /// place above: 2 × value = (2 × DIGITS + 1) × 10^(point - len).
    fn is_tie(self, digits: &Digits) -> bool {
        let (mantissa, exponent) = parts(self.as_f64().abs());
        let Some(whole) = digits.whole() else { return false };
        let (mut left, mut right) = (Big::from(mantissa), Big::from(2 * whole + 1));
        let (twos, tens) = (exponent + 1, digits.point - digits.digits.len() as i32);
        for _ in 0..tens.unsigned_abs() {
            if tens > 0 { right.mul_small(10) } else { left.mul_small(10) }
        }
        if twos > 0 {
            left.shl(twos as u32)
        } else {
            right.shl(twos.unsigned_abs())
        }
        left.trimmed() == right.trimmed()
    }
}

impl Digits {
    /// The digits as one whole number, where it fits a u64 (up to 19 digits).
    fn whole(&self) -> Option<u64> {
        (self.digits.len() <= 19).then(|| self.digits.iter().fold(0, |w, &d| w * 10 + u64::from(d - b'0')))
    }

    /// Adds one unit of the last place.
    fn round_up(&mut self) {
        for d in self.digits.iter_mut().rev() {
            if *d == b'9' {
                *d = b'0';
            } else {
                *d += 1;
                break;
            }
        }
        if self.digits[0] == b'0' {
            self.digits.insert(0, b'1');
            self.point += 1;
        }
        while self.digits.len() > 1 && self.digits.last() == Some(&b'0') {
            self.digits.pop();
        }
    }
}

/// A finite, non-negative f64 as `mantissa × 2^exponent`.
fn parts(x: f64) -> (u64, i32) {
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    match exponent {
        0 => (bits & ((1 << 52) - 1), -1074),
        _ => ((bits & ((1 << 52) - 1)) | (1 << 52), exponent - 1075),
    }
}

/// Reads zmij's output (`-1.25`, `1e30`, `1.5e-7`, `100.0`) into [`Digits`].
fn digits_of(text: &str) -> Digits {
    let negative = text.starts_with('-');
    let text = text.trim_start_matches('-');
    let (mantissa, exponent) = text.split_once(['e', 'E']).unwrap_or((text, "0"));
    let exponent: i32 = exponent.trim_start_matches('+').parse().unwrap_or(0);
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let mut digits: Vec<u8> = whole.bytes().chain(fraction.bytes()).collect();
    let mut point = whole.len() as i32 + exponent;
    let leading = digits.iter().take_while(|&&d| d == b'0').count();
    digits.drain(..leading);
    point -= leading as i32;
    while digits.last() == Some(&b'0') {
        digits.pop();
    }
    if digits.is_empty() {
        digits.push(b'0');
        point = 1;
    }
    Digits { negative, digits, point }
}

/// Writes the non-finite values as Rust does; `false` for a finite `x`.
fn special(x: f64, f: &mut fmt::Formatter<'_>) -> Option<fmt::Result> {
    if x.is_nan() {
        Some(f.pad("NaN"))
    } else if x.is_infinite() {
        Some(f.pad(if x < 0.0 { "-inf" } else { "inf" }))
    } else {
        None
    }
}

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(done) = special(self.as_f64(), f) {
            return done;
        }
        let Digits { negative, digits, point } = self.digits();
        let mut text = String::with_capacity(digits.len() + 8);
        if negative {
            text.push('-');
        }
        let digits = std::str::from_utf8(&digits).unwrap_or("0");
        if point <= 0 {
            text.push_str("0.");
            text.extend(std::iter::repeat_n('0', point.unsigned_abs() as usize));
            text.push_str(digits);
        } else if (point as usize) < digits.len() {
            text.push_str(&digits[..point as usize]);
            text.push('.');
            text.push_str(&digits[point as usize..]);
        } else {
            text.push_str(digits);
            text.extend(std::iter::repeat_n('0', point as usize - digits.len()));
        }
        f.pad(&text)
    }
}

impl fmt::Display for Sci {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(done) = special(self.0, f) {
            return done;
        }
        let Digits { negative, digits, point } = Num::F64(self.0).digits();
        let digits = std::str::from_utf8(&digits).unwrap_or("0");
        let sign = if negative { "-" } else { "" };
        let exponent = if digits == "0" { 0 } else { point - 1 };
        let text = match digits.split_at(1) {
            (first, "") => format!("{sign}{first}e{exponent}"),
            (first, rest) => format!("{sign}{first}.{rest}e{exponent}"),
        };
        f.pad(&text)
    }
}

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Fixed(x, places) = *self;
        if let Some(done) = special(x, f) {
            return done;
        }
        let mut digits = scaled_digits(x.abs(), places);
        if digits.len() <= places {
            let zeros = places + 1 - digits.len();
            digits.insert_str(0, &"0".repeat(zeros));
        }
        if places > 0 {
            digits.insert(digits.len() - places, '.');
        }
        if x.is_sign_negative() {
            digits.insert(0, '-');
        }
        f.pad(&digits)
    }
}

/// The decimal digits of `x × 10^places` rounded to an integer, ties to even (`x` finite, not
/// negative).
fn scaled_digits(x: f64, places: usize) -> String {
    let (mantissa, exponent) = parts(x);
    // x × 10^places = mantissa × 5^places × 2^(exponent + places).
    let mut big = Big::from(mantissa);
    for _ in 0..places {
        big.mul_small(5);
    }
    let shift = exponent + places as i32;
    if shift >= 0 {
        big.shl(shift as u32);
    } else {
        big.shr_round_even(shift.unsigned_abs());
    }
    big.into_decimal()
}

/// A natural number as base-2^32 limbs, least significant first: enough arithmetic for exact decimal
/// digits of any f64.
struct Big(Vec<u32>);

impl Big {
    fn from(n: u64) -> Big {
        Big(vec![n as u32, (n >> 32) as u32])
    }

    fn mul_small(&mut self, m: u32) {
        let mut carry = 0u64;
        for limb in &mut self.0 {
            let v = u64::from(*limb) * u64::from(m) + carry;
            *limb = v as u32;
            carry = v >> 32;
        }
        if carry > 0 {
            self.0.push(carry as u32);
        }
    }

    fn shl(&mut self, bits: u32) {
        for _ in 0..bits / 32 {
            self.0.insert(0, 0);
        }
        let bits = bits % 32;
        if bits > 0 {
            let mut carry = 0u32;
            for limb in &mut self.0 {
                let v = (u64::from(*limb) << bits) | u64::from(carry);
                *limb = v as u32;
                carry = (v >> 32) as u32;
            }
            self.0.push(carry);
        }
    }

    /// Divides by 2^bits, rounding to the nearest integer and ties to even.
    fn shr_round_even(&mut self, bits: u32) {
        let bit = |b: &Big, i: u32| b.0.get((i / 32) as usize).is_some_and(|l| l >> (i % 32) & 1 == 1);
        let half = bits > 0 && bit(self, bits - 1);
        let below_half = (0..bits.saturating_sub(1)).any(|i| bit(self, i));
        let limbs = (bits / 32) as usize;
        self.0.drain(..limbs.min(self.0.len()));
        let bits = bits % 32;
        if bits > 0 {
            for i in 0..self.0.len() {
                let high = self.0.get(i + 1).copied().unwrap_or(0);
                self.0[i] = (self.0[i] >> bits) | (high << (32 - bits));
            }
        }
        let odd = self.0.first().is_some_and(|l| l & 1 == 1);
        if half && (below_half || odd) {
            self.add_one();
        }
    }

    fn add_one(&mut self) {
        for limb in &mut self.0 {
            let (v, overflow) = limb.overflowing_add(1);
            *limb = v;
            if !overflow {
                return;
            }
        }
        self.0.push(1);
    }

    /// The limbs without the zero limbs above the highest non-zero one.
    fn trimmed(&self) -> &[u32] {
        let len = self.0.iter().rposition(|&l| l != 0).map_or(0, |i| i + 1);
        &self.0[..len]
    }

    /// The number in decimal, without leading zeros (`0` for zero).
    fn into_decimal(mut self) -> String {
        let mut chunks = Vec::new();
        while self.0.iter().any(|&l| l != 0) {
            let mut remainder = 0u64;
            for limb in self.0.iter_mut().rev() {
                let v = (remainder << 32) | u64::from(*limb);
                *limb = (v / 1_000_000_000) as u32;
                remainder = v % 1_000_000_000;
            }
            chunks.push(remainder as u32);
        }
        let mut text = chunks.pop().map_or_else(|| "0".to_string(), |c| c.to_string());
        for chunk in chunks.iter().rev() {
            let chunk = chunk.to_string();
            text.push_str(&"0".repeat(9 - chunk.len()));
            text.push_str(&chunk);
        }
        text
    }
}

#[cfg(test)]
mod tests;
