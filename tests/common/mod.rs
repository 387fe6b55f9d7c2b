//! Shared test helpers: approximate asserts that print both values, a seeded generator, and
//! an independent Bernstein-sum evaluator (not the de Casteljau code under test).
#![allow(dead_code)]

use splinelab::{DVec2, DVec3};

/// How error messages print infinity: as JavaScript's `String(Infinity)`, on every target (see
/// `splinelab::error` on numbers in messages).
pub const INFINITY_TEXT: &str = "Infinity";

/// The JS `Error` a wasm export threw (panics if it returned `Ok` or threw something else).
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
pub fn js_error<T, E: Into<wasm_bindgen::JsValue>>(r: Result<T, E>) -> js_sys::Error {
    use wasm_bindgen::JsCast;
    match r {
        Ok(_) => panic!("expected an error"),
        Err(e) => e.into().dyn_into::<js_sys::Error>().expect("a JS Error"),
    }
}

/// The message of the JS `Error` a wasm export threw (panics if it returned `Ok`).
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
pub fn js_message<T, E: Into<wasm_bindgen::JsValue>>(r: Result<T, E>) -> String {
    js_error(r).message().into()
}

/// `object[key]`, a `Float64Array` a wasm export returned inside an object, as numbers (panics,
/// naming the key, when it is anything else).
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
pub fn float64_field(object: &wasm_bindgen::JsValue, key: &str) -> Vec<f64> {
    use wasm_bindgen::JsCast;
    js_sys::Reflect::get(object, &key.into())
        .unwrap()
        .dyn_into::<js_sys::Float64Array>()
        .unwrap_or_else(|_| panic!("{key} is a Float64Array"))
        .to_vec()
}

/// Asserts `|a − b| <= tol`, printing both values and the difference.
#[track_caller]
pub fn assert_close(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol,
        "{what}: got {a:e}, expected {b:e}, difference {:e} > {tol:e}",
        (a - b).abs()
    );
}

/// Asserts two 2D points are within `tol` (Euclidean).
#[track_caller]
pub fn assert_close2(a: DVec2, b: DVec2, tol: f64, what: &str) {
    assert!(
        (a - b).length() <= tol,
        "{what}: got {a}, expected {b}, distance {:e} > {tol:e}",
        (a - b).length()
    );
}

/// Asserts two 3D points are within `tol` (Euclidean).
#[track_caller]
pub fn assert_close3(a: DVec3, b: DVec3, tol: f64, what: &str) {
    assert!(
        (a - b).length() <= tol,
        "{what}: got {a}, expected {b}, distance {:e} > {tol:e}",
        (a - b).length()
    );
}

/// A small deterministic generator (xorshift64*): the same seed gives the same cases on
/// every platform, so a failure prints a seed that reproduces it.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed.max(1))
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }
    pub fn point2(&mut self, size: f64) -> DVec2 {
        DVec2::new(self.range(-size, size), self.range(-size, size))
    }
    pub fn point3(&mut self, size: f64) -> DVec3 {
        DVec3::new(
            self.range(-size, size),
            self.range(-size, size),
            self.range(-size, size),
        )
    }
}

/// `C(n, k)` by the multiplicative formula, for the independent evaluator.
fn choose(n: usize, k: usize) -> f64 {
    (0..k).fold(1.0, |c, j| c * (n - j) as f64 / (j + 1) as f64)
}

/// `Σ C(n,i) s^i (1−s)^(n−i) w_i P_i / Σ … w_i` by the explicit Bernstein sum: an evaluator
/// independent of the de Casteljau code under test.
pub fn bernstein_sum2(points: &[DVec2], weights: Option<&[f64]>, s: f64) -> DVec2 {
    let n = points.len() - 1;
    let (mut num, mut den) = (DVec2::ZERO, 0.0);
    for (i, &p) in points.iter().enumerate() {
        let w = weights.map_or(1.0, |w| w[i]);
        let b = choose(n, i) * s.powi(i as i32) * (1.0 - s).powi((n - i) as i32) * w;
        num += p * b;
        den += b;
    }
    num / den
}

/// Distance from `p` to the polyline through `vertices`.
pub fn distance_to_polyline(p: DVec2, vertices: &[DVec2]) -> f64 {
    vertices
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let ab = b - a;
            let u = if ab.length_squared() > 0.0 {
                ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (p - (a + ab * u)).length()
        })
        .fold(f64::INFINITY, f64::min)
}

pub fn pts2(xy: &[(f64, f64)]) -> Vec<DVec2> {
    xy.iter().map(|&(x, y)| DVec2::new(x, y)).collect()
}

/// The 9-point NURBS unit circle (NURBS Book ex. 7.1): control points on the square's corners
/// and edge midpoints, corner weights √2/2, knots `0,0,0,¼,¼,½,½,¾,¾,1,1,1`, degree 2.
pub const CIRCLE_POINTS: [(f64, f64); 9] = [
    (1.0, 0.0),
    (1.0, 1.0),
    (0.0, 1.0),
    (-1.0, 1.0),
    (-1.0, 0.0),
    (-1.0, -1.0),
    (0.0, -1.0),
    (1.0, -1.0),
    (1.0, 0.0),
];
/// Knots of [`CIRCLE_POINTS`].
pub const CIRCLE_KNOTS: [f64; 12] = [
    0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0,
];

/// Weight `i` of [`CIRCLE_POINTS`]: √2/2 at the corners (odd `i`), 1 elsewhere.
pub fn circle_weight(i: usize) -> f64 {
    if i % 2 == 1 {
        std::f64::consts::FRAC_1_SQRT_2
    } else {
        1.0
    }
}
