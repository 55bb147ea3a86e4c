//! Reading decimal numbers as Rust's `str::parse` reads them. The browser's build checks the text
//! against Rust's grammar for floats and then has JavaScript's `parseFloat` convert it, so that the
//! wasm carries no decimal-to-binary tables of its own (about 12 KB gzipped); other builds use Rust's
//! reader. Both conversions are correctly rounded, so every text reads as the same f64 in both.

/// `text` as an f64, or `None` where `str::parse::<f64>` fails: an optional sign, then digits with
/// at most one decimal point and an optional exponent, or `inf`, `infinity` or `nan` in any case. No
/// spaces are allowed.
pub fn parse_f64(text: &str) -> Option<f64> {
    let (negative, body) = match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    let magnitude = if body.eq_ignore_ascii_case("inf") || body.eq_ignore_ascii_case("infinity") {
        f64::INFINITY
    } else if body.eq_ignore_ascii_case("nan") {
        f64::NAN
    } else if is_decimal(body) {
        decimal(body)
    } else {
        return None;
    };
    Some(if negative { -magnitude } else { magnitude })
}

/// `text` as an f32: the f64 it reads as, rounded to f32 (in both builds, so they agree).
pub fn parse_f32(text: &str) -> Option<f32> {
    parse_f64(text).map(|x| x as f32)
}

/// Whether `text` is unsigned digits with at most one point (a digit on at least one side) and an
/// optional exponent (`e` or `E`, an optional sign, digits).
fn is_decimal(text: &str) -> bool {
    let bytes = text.as_bytes();
    let (whole, mut at) = digits(bytes, 0);
    let mut fraction = 0;
    if bytes.get(at) == Some(&b'.') {
        (fraction, at) = digits(bytes, at + 1);
    }
    if whole + fraction == 0 {
        return false;
    }
    if matches!(bytes.get(at), Some(b'e' | b'E')) {
        at += 1;
        if matches!(bytes.get(at), Some(b'+' | b'-')) {
            at += 1;
        }
        let count;
        (count, at) = digits(bytes, at);
        if count == 0 {
            return false;
        }
    }
    at == bytes.len()
}

/// How many ASCII digits follow `start` in `bytes`, and where they end.
fn digits(bytes: &[u8], start: usize) -> (usize, usize) {
    let end = start + bytes[start.min(bytes.len())..].iter().take_while(|b| b.is_ascii_digit()).count();
    (end - start, end)
}

/// The value of text that [`is_decimal`] accepts.
#[cfg(target_arch = "wasm32")]
fn decimal(text: &str) -> f64 {
    js_sys::parse_float(text)
}

/// The value of text that [`is_decimal`] accepts.
#[cfg(not(target_arch = "wasm32"))]
fn decimal(text: &str) -> f64 {
    text.parse().unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Accepts and rejects exactly what `str::parse::<f64>` does, with the same values.
    #[test]
    fn reads_as_rust_does() {
        let texts = [
            "0",
            "-0",
            "+0",
            "1",
            "1.",
            ".5",
            "-.5",
            "+1.5e3",
            "1E-3",
            "1e+300",
            "1e400",
            "-1e-400",
            "0.1",
            "3.4028236e38",
            "007",
            "inf",
            "-Infinity",
            "+INF",
            "nan",
            "NaN",
            "-nan",
            "",
            "-",
            "+",
            ".",
            "-.",
            "e5",
            "1e",
            "1e+",
            "1.2.3",
            "1e5.5",
            " 1",
            "1 ",
            "1_000",
            "0x10",
            "1,5",
            "--1",
            "+-1",
            "infinit",
            "infinityy",
            "nana",
            "١",
            "1f",
            "1.5e-3x",
            "123456789012345678901234567890",
        ];
        for text in texts {
            let ours = parse_f64(text);
            let rust = text.parse::<f64>().ok();
            assert_eq!(ours.is_some(), rust.is_some(), "{text:?}");
            if let (Some(a), Some(b)) = (ours, rust) {
                assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()), "{text:?}: {a} vs {b}");
            }
            assert_eq!(parse_f32(text).map(f32::to_bits), ours.map(|x| (x as f32).to_bits()), "{text:?}");
        }
    }
}
