//! The cubic Hermite basis for JavaScript: `hermiteBasis(s)` and `hermiteBezier(…)`.

use super::flat_points;
use crate::error::{check_finite, Error};
use crate::geom::check_dim;
use crate::interp::{hermite_basis, hermite_basis_derivative, hermite_to_bezier};
use crate::wasm::ApiError;
use crate::wasm::{numbers, whole};
use glam::DVec3;
use wasm_bindgen::prelude::*;

/// `hermiteBasis(s, order = 0)`: `[H0, H1, H2, H3](s)` with `H0 = 2s³ − 3s² + 1`,
/// `H1 = −2s³ + 3s²`, `H2 = s³ − 2s² + s`, `H3 = s³ − s²` (order 1: their derivatives). Any
/// finite s (the curve piece uses [0, 1]).
#[wasm_bindgen(js_name = hermiteBasis)]
pub fn hermite_basis_js(s: f64, order: Option<f64>) -> Result<Vec<f64>, ApiError> {
    let order = order.map(|o| whole("order", o)).transpose()?.unwrap_or(0);
    check_finite("s", None, s)?;
    Ok(match order {
        0 => hermite_basis(s).to_vec(),
        1 => hermite_basis_derivative(s).to_vec(),
        _ => {
            return Err(Error::UnknownOption {
                name: "order",
                value: order.to_string(),
                expected: "0, 1",
            }
            .into())
        }
    })
}

/// The four vectors (each `dim` numbers, finite) and the Bézier points, computed in 3D (z = 0
/// for 2D: one copy of the code) and cut back to `dim`.
fn bezier_points(
    args: [(&'static str, &[f64]); 4],
    dim: usize,
    delta: f64,
) -> Result<Vec<f64>, Error> {
    let mut v = [DVec3::ZERO; 4];
    for (slot, (name, values)) in v.iter_mut().zip(args) {
        if values.len() != dim {
            return Err(Error::ArgumentLength {
                name,
                expected: dim,
                got: values.len(),
            });
        }
        crate::geom::check_all_coordinates(values, name)?;
        let mut coords = [0.0; 3];
        for (c, &x) in coords.iter_mut().zip(values) {
            *c = x;
        }
        *slot = DVec3::from_array(coords);
    }
    let [p0, m0, p1, m1] = v;
    Ok(flat_points(&hermite_to_bezier(p0, m0, p1, m1, delta), dim))
}

/// `hermiteBezier(p0, m0, p1, m1, delta = 1)`: the Bézier control points (flat, 4·dim) of the
/// Hermite piece from p0 to p1 with tangents m0, m1 over an interval of length `delta`:
/// `[p0, p0 + Δ·m0/3, p1 − Δ·m1/3, p1]`. The dimension is that of p0 (2 or 3).
#[wasm_bindgen(js_name = hermiteBezier)]
pub fn hermite_bezier(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] p0: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] m0: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] p1: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] m1: JsValue,
    delta: Option<f64>,
) -> Result<Vec<f64>, ApiError> {
    let p0 = numbers("p0", &p0)?;
    let m0 = numbers("m0", &m0)?;
    let p1 = numbers("p1", &p1)?;
    let m1 = numbers("m1", &m1)?;
    let delta = check_finite("delta", None, delta.unwrap_or(1.0))?;
    let args = [("p0", &*p0), ("m0", &*m0), ("p1", &*p1), ("m1", &*m1)];
    Ok(bezier_points(args, check_dim(p0.len())?, delta)?)
}
