//! `lagrange(points, dim, params)` and the `LagrangeCurve` class.

use super::{flat_points, lift_point, lift_points, narrow, ParamArg};
use crate::error::Error;
use crate::geom::check_dim;
use crate::interp::{check_point_count, LagrangeCurve};
use crate::wasm::class::check_count;
use crate::wasm::ApiError;
use crate::wasm::{numbers, whole};
use glam::DVec3;
use wasm_bindgen::prelude::*;

/// The interpolating polynomial through n + 1 points at strictly increasing parameters,
/// evaluated in barycentric form; `aitken(t)` gives Aitken's triangle. A 2D curve is kept as
/// the 3D one in the plane z = 0 (the arithmetic of x and y is the same; one copy of the code
/// for both dimensions); what leaves it is cut back to `dim` coordinates.
#[wasm_bindgen(js_name = LagrangeCurve)]
pub struct JsLagrangeCurve {
    inner: LagrangeCurve<DVec3>,
    /// 2 or 3.
    dim: usize,
}

/// The curve, its inputs checked in the documented order: points, their number, then params
/// (whose kind or α is read only after the count).
fn build(coords: &[f64], dim: usize, params: ParamArg) -> Result<LagrangeCurve<DVec3>, Error> {
    let points = lift_points(coords, dim)?;
    check_point_count(points.len(), 2, "lagrange-curve")?;
    LagrangeCurve::with_params(points, params.choice()?)
}

/// `lagrange(points, dim, params)`: the polynomial of degree ≤ n through the n + 1 points at
/// `params` (strictly increasing, one per point; a kind string or α number computes them as
/// `parameterize` does). At most 65 points (degree 64).
#[wasm_bindgen]
pub fn lagrange(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    dim: f64,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | string | number")]
    params: JsValue,
) -> Result<JsLagrangeCurve, ApiError> {
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let dim = check_dim(whole("dim", dim)?)?;
    let inner = build(points, dim, params)?;
    Ok(JsLagrangeCurve { inner, dim })
}

#[wasm_bindgen(js_class = LagrangeCurve)]
impl JsLagrangeCurve {
    /// Dimension: 2 or 3.
    #[wasm_bindgen(getter)]
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The degree bound n (number of points − 1).
    #[wasm_bindgen(getter)]
    pub fn degree(&self) -> usize {
        self.inner.degree()
    }

    /// The domain `[t_0, t_n]`.
    pub fn domain(&self) -> Vec<f64> {
        let (a, b) = self.inner.domain();
        vec![a, b]
    }

    /// The parameters `t_0 … t_n`.
    pub fn params(&self) -> Vec<f64> {
        self.inner.params().to_vec()
    }

    /// The data points, flat.
    pub fn points(&self) -> Vec<f64> {
        flat_points(self.inner.points(), self.dim)
    }

    /// The point at t (dim numbers; exactly `p_i` at `t_i`).
    pub fn evaluate(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(flat_points(&[self.inner.evaluate(t)?], self.dim))
    }

    /// `evaluate` into the per-call buffer (see `wasm::scratch`): its index, 0 on an error.
    /// Internal: `evaluateInto(t, out)` (added by `scripts/glue.mjs`) calls it.
    #[wasm_bindgen(js_name = __evaluateScratch, skip_typescript)]
    pub fn evaluate_scratch(&self, t: f64) -> u32 {
        match self.inner.evaluate(t) {
            Ok(p) => crate::wasm::scratch::put_coords(self.dim, p.to_array()),
            Err(_) => 0,
        }
    }

    /// Points at every t of `ts`, flat (ts.length·dim numbers).
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
    ) -> Result<Vec<f64>, ApiError> {
        let ts = &*numbers("ts", &ts)?;
        let len = crate::geom::result_len("sample-ts-result", &[ts.len(), 3])?;
        let mut out = vec![0.0; len];
        self.inner.sample_into(ts, &mut out)?;
        Ok(narrow(out, self.dim))
    }

    /// `count` points at equally spaced t over the domain, ends included, flat.
    #[wasm_bindgen(js_name = sampleUniform)]
    pub fn sample_uniform(&self, count: f64) -> Result<Vec<f64>, ApiError> {
        let count = whole("count", count)?;
        check_count(count)?;
        let len = crate::geom::result_len("sample-uniform-result", &[count, 3])?;
        let mut out = vec![0.0; len];
        self.inner.sample_uniform_into(count, &mut out)?;
        Ok(narrow(out, self.dim))
    }

    /// Every `L_i(t)`, i = 0..n (n + 1 numbers, summing to 1).
    pub fn basis(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(self.inner.basis(t)?)
    }

    /// Every `L_i` at `count` equally spaced t over the domain (the t of `sampleUniform`),
    /// i-major: `(n + 1)·count` numbers, value k of function i at `i·count + k`.
    #[wasm_bindgen(js_name = basisCurves)]
    pub fn basis_curves(&self, count: f64) -> Result<Vec<f64>, ApiError> {
        let count = whole("count", count)?;
        Ok(self.inner.basis_curves(count)?)
    }

    /// Aitken's triangle at t, flat: level 0 the n + 1 points, then level r = 1..n with the
    /// n + 1 − r points `p_i^r`; (n+1)(n+2)/2 points, the last is P(t).
    pub fn aitken(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(flat_points(&self.inner.aitken(t)?, self.dim))
    }

    /// Moves data point i in place (the drag path); `point` has dim numbers. Parameters given
    /// as a kind or α are recomputed from the moved points.
    #[wasm_bindgen(js_name = setPoint)]
    pub fn set_point(
        &mut self,
        i: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] point: JsValue,
    ) -> Result<(), ApiError> {
        let point = numbers("point", &point)?;
        let i = whole("i", i)?;
        let p = lift_point(&point, self.dim)?;
        self.inner.set_point(i, p)?;
        Ok(())
    }
}
