//! `BSplineSurface` for JavaScript.

use super::{memory_view, numbers, optional_numbers, whole};
use crate::surface::BSplineSurface;
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

/// A polynomial or rational (NURBS) tensor-product B-spline surface in 3D on its domain
/// `[u_p, u_rows] × [v_q, v_cols]`.
#[wasm_bindgen(js_name = BSplineSurface)]
#[derive(Clone)]
pub struct JsBSplineSurface {
    inner: BSplineSurface,
    /// The buffer behind `sampleGridView`'s result.
    view: Vec<f64>,
}

#[wasm_bindgen(js_class = BSplineSurface)]
impl JsBSplineSurface {
    /// `new BSplineSurface(points, rows, cols, degreeU, degreeV, knotsU, knotsV, weights?)`:
    /// rows·cols points (xyz, flat, row-major: point (i, j) at index i·cols + j, i along u),
    /// rows + p + 1 and cols + q + 1 non-decreasing knots, optional weights (> 0) for a NURBS.
    #[wasm_bindgen(constructor)]
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
        rows: f64,
        cols: f64,
        #[wasm_bindgen(js_name = degreeU)] degree_u: f64,
        #[wasm_bindgen(js_name = degreeV)] degree_v: f64,
        #[wasm_bindgen(js_name = knotsU, unchecked_param_type = "Float64Array | number[]")] knots_u: JsValue,
        #[wasm_bindgen(js_name = knotsV, unchecked_param_type = "Float64Array | number[]")] knots_v: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] weights: JsValue,
    ) -> Result<JsBSplineSurface, JsError> {
        let weights = optional_numbers("weights", &weights)?;
        let points = &*numbers("points", &points)?;
        let knots_u = numbers("knotsU", &knots_u)?;
        let knots_v = numbers("knotsV", &knots_v)?;
        let inner = BSplineSurface::from_flat(
            points,
            whole("rows", rows)?,
            whole("cols", cols)?,
            whole("degreeU", degree_u)?,
            whole("degreeV", degree_v)?,
            knots_u,
            knots_v,
            weights.as_deref(),
        )?;
        Ok(JsBSplineSurface {
            inner,
            view: Vec::new(),
        })
    }

    /// Rows of the control net (points along u).
    #[wasm_bindgen(getter)]
    pub fn rows(&self) -> usize {
        self.inner.rows()
    }

    /// Columns of the control net (points along v).
    #[wasm_bindgen(getter)]
    pub fn cols(&self) -> usize {
        self.inner.cols()
    }

    /// Degree p along u.
    #[wasm_bindgen(getter, js_name = degreeU)]
    pub fn degree_u(&self) -> usize {
        self.inner.degree_u()
    }

    /// Degree q along v.
    #[wasm_bindgen(getter, js_name = degreeV)]
    pub fn degree_v(&self) -> usize {
        self.inner.degree_v()
    }

    /// Whether some weight differs from 1.
    #[wasm_bindgen(getter)]
    pub fn rational(&self) -> bool {
        self.inner.is_rational()
    }

    /// `[u_p, u_rows]`.
    #[wasm_bindgen(js_name = domainU)]
    pub fn domain_u(&self) -> Vec<f64> {
        let (a, b) = self.inner.knots_u().domain();
        vec![a, b]
    }

    /// `[v_q, v_cols]`.
    #[wasm_bindgen(js_name = domainV)]
    pub fn domain_v(&self) -> Vec<f64> {
        let (a, b) = self.inner.knots_v().domain();
        vec![a, b]
    }

    /// The knot vector along u.
    #[wasm_bindgen(js_name = knotsU)]
    pub fn knots_u(&self) -> Vec<f64> {
        self.inner.knots_u().as_slice().to_vec()
    }

    /// The knot vector along v.
    #[wasm_bindgen(js_name = knotsV)]
    pub fn knots_v(&self) -> Vec<f64> {
        self.inner.knots_v().as_slice().to_vec()
    }

    /// The control points, flat xyz, row-major.
    #[wasm_bindgen(js_name = controlPoints)]
    pub fn control_points(&self) -> Vec<f64> {
        self.inner
            .control_points()
            .iter()
            .flat_map(|p| p.to_array())
            .collect()
    }

    /// The weights, row-major (all 1 for a polynomial surface).
    pub fn weights(&self) -> Vec<f64> {
        self.inner.weights()
    }

    /// `S(u, v)`: Float64Array(3).
    pub fn evaluate(&self, u: f64, v: f64) -> Result<Vec<f64>, JsError> {
        Ok(self.inner.evaluate(u, v)?.to_array().to_vec())
    }

    /// `∂^(du+dv) S / ∂u^du ∂v^dv` at (u, v): Float64Array(3).
    pub fn derivative(&self, u: f64, v: f64, du: f64, dv: f64) -> Result<Vec<f64>, JsError> {
        let (du, dv) = (whole("du", du)?, whole("dv", dv)?);
        Ok(self.inner.derivative(u, v, du, dv)?.to_array().to_vec())
    }

    /// The unit normal `S_u × S_v / |S_u × S_v|` at (u, v): Float64Array(3). At a collapsed
    /// edge or pole, the limit from inside the domain; throws where there is none.
    pub fn normal(&self, u: f64, v: f64) -> Result<Vec<f64>, JsError> {
        Ok(self.inner.normal(u, v)?.to_array().to_vec())
    }

    /// `S(u_a, v_b)` for every u of `us` and v of `vs`, u-major: Float64Array(us.length ·
    /// vs.length · 3), point a·vs.length + b.
    #[wasm_bindgen(js_name = sampleGrid)]
    pub fn sample_grid(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] us: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] vs: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let (us, vs) = (numbers("us", &us)?, numbers("vs", &vs)?);
        let mut out = Vec::new();
        self.inner.sample_grid_into(&us, &vs, &mut out)?;
        Ok(out)
    }

    /// `sampleGrid(us, vs)` into this surface's own buffer, returned as a view of the wasm
    /// memory (no copy; valid until the next `…View` call, `free()`, or a call that grows the
    /// memory — copy it with `.slice()` to keep it).
    #[wasm_bindgen(js_name = sampleGridView)]
    pub fn sample_grid_view(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] us: JsValue,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] vs: JsValue,
    ) -> Result<Float64Array, JsError> {
        let (us, vs) = (numbers("us", &us)?, numbers("vs", &vs)?);
        self.inner.sample_grid_into(&us, &vs, &mut self.view)?;
        memory_view(&self.view)
    }
}
