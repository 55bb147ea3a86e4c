//! Four `f32` lanes for the CPU's field loops: 128-bit SIMD in the browser's build (`simd128`, where
//! the compiler leaves these loops mostly scalar on its own), plain arrays elsewhere (which the
//! compiler vectorises). Each operation is the IEEE operation on each lane, so a lane computes exactly
//! what the same scalar expression computes.

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod imp {
    use core::arch::wasm32::*;

    /// Four lanes.
    #[derive(Clone, Copy)]
    pub struct F32x4(v128);

    impl F32x4 {
        #[inline(always)]
        pub fn splat(x: f32) -> Self {
            Self(f32x4_splat(x))
        }

        #[inline(always)]
        pub fn from_array(a: [f32; 4]) -> Self {
            Self(f32x4(a[0], a[1], a[2], a[3]))
        }

        #[inline(always)]
        pub fn to_array(self) -> [f32; 4] {
            let v = self.0;
            [
                f32x4_extract_lane::<0>(v),
                f32x4_extract_lane::<1>(v),
                f32x4_extract_lane::<2>(v),
                f32x4_extract_lane::<3>(v),
            ]
        }

        /// `if x < floor { floor } else { x }` in each lane.
        #[inline(always)]
        pub fn at_least(self, floor: Self) -> Self {
            Self(f32x4_pmax(self.0, floor.0))
        }
    }

    macro_rules! operator {
        ($trait:ident, $method:ident, $op:ident) => {
            impl std::ops::$trait for F32x4 {
                type Output = Self;
                #[inline(always)]
                fn $method(self, o: Self) -> Self {
                    Self($op(self.0, o.0))
                }
            }
        };
    }
    operator!(Add, add, f32x4_add);
    operator!(Sub, sub, f32x4_sub);
    operator!(Mul, mul, f32x4_mul);
    operator!(Div, div, f32x4_div);
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
mod imp {
    /// Four lanes.
    #[derive(Clone, Copy)]
    pub struct F32x4([f32; 4]);

    impl F32x4 {
        #[inline(always)]
        pub fn splat(x: f32) -> Self {
            Self([x; 4])
        }

        #[inline(always)]
        pub fn from_array(a: [f32; 4]) -> Self {
            Self(a)
        }

        #[inline(always)]
        pub fn to_array(self) -> [f32; 4] {
            self.0
        }

        #[inline(always)]
        fn zip(self, o: Self, f: impl Fn(f32, f32) -> f32) -> Self {
            Self(std::array::from_fn(|l| f(self.0[l], o.0[l])))
        }

        /// `if x < floor { floor } else { x }` in each lane.
        #[inline(always)]
        pub fn at_least(self, floor: Self) -> Self {
            self.zip(floor, |x, floor| if x < floor { floor } else { x })
        }
    }

    macro_rules! operator {
        ($trait:ident, $method:ident, $op:tt) => {
            impl std::ops::$trait for F32x4 {
                type Output = Self;
                #[inline(always)]
                fn $method(self, o: Self) -> Self {
                    self.zip(o, |a, b| a $op b)
                }
            }
        };
    }
    operator!(Add, add, +);
    operator!(Sub, sub, -);
    operator!(Mul, mul, *);
    operator!(Div, div, /);
}

pub use imp::F32x4;

/// Lanes per chunk of points or spheres: two vectors, so that two independent chains of work
/// overlap.
pub const LANES: usize = 8;

/// A chunk of `LANES` values as two vectors.
pub type Chunk = [F32x4; 2];

/// `xs` from `start` on as a chunk, padded with its last value, and how many are `xs`'.
#[inline(always)]
pub fn load(xs: &[f32], start: usize) -> (Chunk, usize) {
    if let Some(xs) = xs.get(start..start + LANES) {
        let at = |h: usize| F32x4::from_array([xs[h], xs[h + 1], xs[h + 2], xs[h + 3]]);
        return ([at(0), at(4)], LANES);
    }
    load_end(xs, start)
}

/// [`load`] at the end of `xs`, where fewer than `LANES` values are left (once per run: out of line).
#[cold]
#[inline(never)]
fn load_end(xs: &[f32], start: usize) -> (Chunk, usize) {
    let last = xs.len() - 1;
    let at = |l: usize| xs[(start + l).min(last)];
    let chunk =
        [F32x4::from_array([at(0), at(1), at(2), at(3)]), F32x4::from_array([at(4), at(5), at(6), at(7)])];
    (chunk, (xs.len() - start).min(LANES))
}

/// Writes the first `len` values of `chunk` to `out` from `start` on.
#[inline(always)]
pub fn store(out: &mut [f32], start: usize, chunk: Chunk, len: usize) {
    if len == LANES {
        let [a, b] = chunk.map(F32x4::to_array);
        out[start..start + LANES].copy_from_slice(&[a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]]);
    } else {
        store_end(out, start, chunk, len);
    }
}

/// [`store`] of fewer than `LANES` values (once per run: out of line).
#[cold]
#[inline(never)]
fn store_end(out: &mut [f32], start: usize, chunk: Chunk, len: usize) {
    let [a, b] = chunk.map(F32x4::to_array);
    let values = [a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]];
    out[start..start + len].copy_from_slice(&values[..len]);
}
