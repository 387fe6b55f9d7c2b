//! The cubic Hermite basis for JavaScript: `hermiteBasis(s)` and `hermiteBezier(…)`.

use super::vector_arg;
use crate::error::{check_finite, Error};
use crate::geom::{check_dim, Point};
use crate::interp::{hermite_basis, hermite_basis_derivative, hermite_to_bezier};
use crate::wasm::bezier::flatten_points;
use crate::wasm::{numbers, whole};
use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;

/// `hermiteBasis(s, order = 0)`: `[H0, H1, H2, H3](s)` with `H0 = 2s³ − 3s² + 1`,
/// `H1 = −2s³ + 3s²`, `H2 = s³ − 2s² + s`, `H3 = s³ − s²` (order 1: their derivatives). Any
/// finite s (the curve piece uses [0, 1]).
#[wasm_bindgen(js_name = hermiteBasis)]
pub fn hermite_basis_js(s: f64, order: Option<f64>) -> Result<Vec<f64>, JsError> {
    let order = order.map(|o| whole("order", o)).transpose()?.unwrap_or(0);
    check_finite(|| "s".into(), s)?;
    Ok(match order {
        0 => hermite_basis(s).to_vec(),
        1 => hermite_basis_derivative(s).to_vec(),
        _ => {
            return Err(Error::UnknownOption {
                name: "order",
                value: order.to_string(),
                expected: "0 or 1",
            }
            .into())
        }
    })
}

/// The four vectors (each `P::DIM` numbers, finite) and the Bézier points.
fn bezier_points<P: Point>(
    args: [(&'static str, &[f64]); 4],
    delta: f64,
) -> Result<Vec<f64>, Error> {
    let mut v = [P::ZERO; 4];
    for (slot, (name, values)) in v.iter_mut().zip(args) {
        *slot = vector_arg::<P>(name, values)?;
        crate::geom::check_all_finite(values, name)?;
    }
    Ok(flatten_points(&hermite_to_bezier(
        v[0], v[1], v[2], v[3], delta,
    )))
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
) -> Result<Vec<f64>, JsError> {
    let p0 = numbers("p0", &p0)?;
    let m0 = numbers("m0", &m0)?;
    let p1 = numbers("p1", &p1)?;
    let m1 = numbers("m1", &m1)?;
    let delta = check_finite(|| "delta".into(), delta.unwrap_or(1.0))?;
    let args = [("p0", &*p0), ("m0", &*m0), ("p1", &*p1), ("m1", &*m1)];
    Ok(match check_dim(p0.len())? {
        2 => bezier_points::<DVec2>(args, delta)?,
        _ => bezier_points::<DVec3>(args, delta)?,
    })
}
