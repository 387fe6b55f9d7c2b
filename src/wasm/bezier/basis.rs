//! `bernstein(n, i, t)` and `bernsteinBasis(n, count)`: the Bernstein polynomials for plots.

use super::whole;
use crate::bezier;
use crate::wasm::ApiError;
use wasm_bindgen::prelude::*;

/// `bernstein(n, i, t)`: `B_i^n(t) = C(n,i) t^i (1−t)^(n−i)` for `0 <= i <= n`, t ∈ [0, 1].
#[wasm_bindgen]
pub fn bernstein(n: f64, i: f64, t: f64) -> Result<f64, ApiError> {
    Ok(bezier::try_bernstein(whole("n", n)?, whole("i", i)?, t)?)
}

/// `bernsteinBasis(n, count)`: every `B_i^n` at `count` equally spaced t in [0, 1], i-major:
/// value `k` of function `i` at index `i·count + k` ((n+1)·count numbers, for plotting).
#[wasm_bindgen(js_name = bernsteinBasis)]
pub fn bernstein_basis(n: f64, count: f64) -> Result<Vec<f64>, ApiError> {
    Ok(bezier::bernstein_basis(
        whole("n", n)?,
        whole("count", count)?,
    )?)
}
