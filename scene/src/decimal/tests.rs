//! Every form [`super`] writes, against Rust's own formatting of the same values.

use super::*;

/// A fixed sequence of 64-bit patterns (xorshift), for floats of every size and digit count.
fn patterns(count: usize) -> impl Iterator<Item = u64> {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    (0..count).map(move |_| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    })
}

fn specials() -> Vec<f64> {
    let mut xs = vec![0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 1.5, 2.5, 0.25, 0.125, 0.05, 1e15, 1e16, 1e21, 1e-7];
    xs.extend([123456.789, 0.000123, f64::MAX, f64::MIN_POSITIVE, 5e-324, f64::NAN, f64::INFINITY]);
    xs.extend([f64::NEG_INFINITY, f64::from(f32::MAX), f64::from(f32::MIN_POSITIVE), 9.995, 0.0005]);
    xs
}

#[test]
fn shortest_as_rust_writes_it() {
    for bits in patterns(200_000) {
        let x = f64::from_bits(bits);
        assert_eq!(num(x).to_string(), x.to_string(), "{bits:#x}");
        let y = f32::from_bits(bits as u32);
        assert_eq!(num(y).to_string(), y.to_string(), "{:#x}", bits as u32);
    }
    for x in specials() {
        assert_eq!(num(x).to_string(), x.to_string());
        assert_eq!(num(x as f32).to_string(), (x as f32).to_string());
    }
}

#[test]
fn scientific_as_rust_writes_it() {
    for bits in patterns(50_000) {
        let x = f64::from_bits(bits);
        assert_eq!(Sci(x).to_string(), format!("{x:e}"), "{bits:#x}");
    }
    for x in specials() {
        assert_eq!(Sci(x).to_string(), format!("{x:e}"));
    }
}

#[test]
fn fixed_as_rust_writes_it() {
    let mut xs = specials();
    // Values near every power of ten, where rounding carries, and halves of every size.
    for (i, bits) in patterns(20_000).enumerate() {
        let scale = 10f64.powi((i % 40) as i32 - 20);
        xs.push((bits >> 11) as f64 / (1u64 << 53) as f64 * scale);
        xs.push(f64::from(f32::from_bits(bits as u32)));
        xs.push(f64::from_bits(bits));
    }
    for x in xs {
        for places in 0..=6 {
            assert_eq!(Fixed(x, places).to_string(), format!("{x:.places$}"), "{x:e} at {places}");
        }
    }
}

#[test]
fn pads_as_strings_do() {
    assert_eq!(format!("[{:>6}]", num(1.5f32)), "[   1.5]");
    assert_eq!(format!("[{:<6}]", Fixed(2.0, 1)), "[2.0   ]");
}

#[test]
fn shortest_as_f64_is_what_the_shortest_decimal_reads_as() {
    let mut fast = 0;
    let settings_like = [0.15f32, 0.85, 0.6, 1.5, 45.0, -30.0, 0.3, 200.0, 1e-3, 2.5e-2, 3.4e5, -0.0, 0.0];
    let random = patterns(200_000).map(|bits| f32::from_bits(bits as u32));
    for x in settings_like.into_iter().chain(random).chain(specials().into_iter().map(|x| x as f32)) {
        let read: Option<f64> = x.to_string().parse().ok().filter(|_| x.is_finite());
        match shortest_as_f64(x) {
            Some(value) => {
                fast += 1;
                assert_eq!(Some(value.to_bits()), read.map(f64::to_bits), "{x}");
            }
            None => {
                assert!(!x.is_finite() || x.to_string().len() > 22 || x.abs() < 1e-13, "{x} has no fast path")
            }
        }
    }
    assert!(fast > 50_000, "{fast} values took the fast path");
}
