//! Sines, cosines, tangents, powers and logarithms. The browser's build asks JavaScript's `Math` (in
//! f64, then rounded), so that the wasm carries no libm of its own (about 10 KB of code, 4 KB of it for
//! reducing huge angles); other builds use the platform's. Both are as close as an f32 holds, give or
//! take its last bit, as two platforms' libms are.

#[cfg(target_arch = "wasm32")]
mod platform {
    use js_sys::Math;

    pub fn sin(x: f32) -> f32 {
        Math::sin(f64::from(x)) as f32
    }

    pub fn cos(x: f32) -> f32 {
        Math::cos(f64::from(x)) as f32
    }

    pub fn tan(x: f32) -> f32 {
        Math::tan(f64::from(x)) as f32
    }

    pub fn powf(x: f32, y: f32) -> f32 {
        Math::pow(f64::from(x), f64::from(y)) as f32
    }

    pub fn ln(x: f64) -> f64 {
        Math::log(x)
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod platform {
    pub fn sin(x: f32) -> f32 {
        x.sin()
    }

    pub fn cos(x: f32) -> f32 {
        x.cos()
    }

    pub fn tan(x: f32) -> f32 {
        x.tan()
    }

    pub fn powf(x: f32, y: f32) -> f32 {
        x.powf(y)
    }

    pub fn ln(x: f64) -> f64 {
        x.ln()
    }
}

/// The sine of `x` radians.
pub fn sin(x: f32) -> f32 {
    platform::sin(x)
}

/// The cosine of `x` radians.
pub fn cos(x: f32) -> f32 {
    platform::cos(x)
}

/// The tangent of `x` radians.
pub fn tan(x: f32) -> f32 {
    platform::tan(x)
}

/// `x` to the power `y`.
pub fn powf(x: f32, y: f32) -> f32 {
    platform::powf(x, y)
}

/// The natural logarithm of `x`.
pub fn ln(x: f64) -> f64 {
    platform::ln(x)
}
