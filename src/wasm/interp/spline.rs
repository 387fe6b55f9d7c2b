//! The `CubicSpline` class: every piecewise cubic Hermite interpolant (C2 splines, Hermite,
//! cardinal, Catmull–Rom, Bessel) behind one JS class.

use super::flat_points;
use crate::bezier::CompositeCurve;
use crate::bspline::BSplineCurve;
use crate::error::Error;
use crate::error::InterpError;
use crate::interp::{bezier_points, bspline_form, CubicSpline, TangentRule};
use crate::prelude::*;
use crate::wasm::bezier::{flatten_points, point_from};
use crate::wasm::class::check_count;
use crate::wasm::ApiError;
use crate::wasm::{memory_view, numbers, whole, JsBSplineCurve, JsCompositeBezier};
use glam::{DVec2, DVec3};
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// A 2D or 3D spline behind the JS class.
#[derive(Clone)]
pub(super) enum Spline {
    D2(CubicSpline<DVec2>),
    D3(CubicSpline<DVec3>),
}

macro_rules! with_spline {
    ($spline:expr, $c:ident => $body:expr) => {
        match $spline {
            Spline::D2($c) => $body,
            Spline::D3($c) => $body,
        }
    };
}

/// A piecewise cubic Hermite curve through `p_0..p_n` at `t_0 < … < t_n`, built by
/// `cubicSpline`, `hermiteSpline`, `cardinalSpline`, `catmullRom` or `besselSpline`.
#[wasm_bindgen(js_name = CubicSpline)]
pub struct JsCubicSpline {
    inner: Spline,
    /// The buffer behind the `…View` methods' results.
    view: Vec<f64>,
}

/// `system()`'s object.
#[derive(Serialize)]
struct SystemJs {
    size: usize,
    dim: usize,
    lower: Vec<f64>,
    diagonal: Vec<f64>,
    upper: Vec<f64>,
    rhs: Vec<f64>,
    corners: Vec<f64>,
    solution: Vec<f64>,
}

impl JsCubicSpline {
    pub(super) fn wrap(inner: Spline) -> Self {
        JsCubicSpline {
            inner,
            view: Vec::new(),
        }
    }

    fn dim_of(&self) -> usize {
        match self.inner {
            Spline::D2(_) => 2,
            Spline::D3(_) => 3,
        }
    }

    /// The points and tangents in 3D (z = 0 for 2D), and the parameters: the cold conversions
    /// (`toBezier`, `toBSpline`) run on them, one copy of their code for both dimensions.
    fn lifted(&self) -> (Vec<DVec3>, Vec<DVec3>, &[f64]) {
        match &self.inner {
            Spline::D2(c) => {
                let lift = |v: &[DVec2]| v.iter().map(|p| p.extend(0.0)).collect();
                (lift(c.points()), lift(c.tangents()), c.params())
            }
            Spline::D3(c) => (c.points().to_vec(), c.tangents().to_vec(), c.params()),
        }
    }

    /// The derivative of `order` at every t of `ts` into `out` (resized).
    fn sample_into(&self, ts: &[f64], order: usize, out: &mut Vec<f64>) -> Result<(), Error> {
        let len = crate::geom::result_len("sample-ts-result", &[ts.len(), self.dim_of()])?;
        out.resize(len, 0.0);
        with_spline!(&self.inner, c => c.sample_derivatives_into(ts, order, out))
    }

    /// `count` points over the domain into `out` (resized).
    fn sample_uniform_into(&self, count: usize, out: &mut Vec<f64>) -> Result<(), Error> {
        check_count(count)?;
        let len = crate::geom::result_len("sample-uniform-result", &[count, self.dim_of()])?;
        out.resize(len, 0.0);
        with_spline!(&self.inner, c => c.sample_uniform_into(count, out))
    }
}

fn system_of<C: crate::geom::Cartesian>(c: &CubicSpline<C>) -> Result<SystemJs, Error> {
    let s = c.system().ok_or(Error::Interp(InterpError::SplineKind {
        operation: "system()",
        needs: "cubicSpline",
        got: c.rule().constructor(),
    }))?;
    let size = s.size();
    Ok(SystemJs {
        size,
        dim: C::DIM,
        lower: s.lower.clone(),
        diagonal: s.diagonal.clone(),
        upper: s.upper.clone(),
        rhs: flatten_points(&s.rhs),
        corners: s.corners.map(|k| k.to_vec()).unwrap_or_default(),
        solution: flatten_points(c.tangents().get(..size).unwrap_or_default()),
    })
}

#[wasm_bindgen(js_class = CubicSpline)]
impl JsCubicSpline {
    /// Dimension: 2 or 3.
    #[wasm_bindgen(getter)]
    pub fn dim(&self) -> usize {
        self.dim_of()
    }

    /// Number of cubic pieces n (points − 1).
    #[wasm_bindgen(getter, js_name = pieceCount)]
    pub fn piece_count(&self) -> usize {
        with_spline!(&self.inner, c => c.piece_count())
    }

    /// Whether the spline is closed (periodic, or a closed Catmull–Rom): `p_n = p_0`.
    #[wasm_bindgen(getter)]
    pub fn closed(&self) -> bool {
        with_spline!(&self.inner, c => c.is_closed())
    }

    /// The function that built it: "cubicSpline" | "hermiteSpline" | "cardinalSpline" |
    /// "catmullRom" | "besselSpline".
    #[wasm_bindgen(getter)]
    pub fn kind(&self) -> String {
        with_spline!(&self.inner, c => c.rule().constructor().into())
    }

    /// The domain `[t_0, t_n]`.
    pub fn domain(&self) -> Vec<f64> {
        let (a, b) = with_spline!(&self.inner, c => c.domain());
        vec![a, b]
    }

    /// The parameters `t_0 … t_n` (n + 1 numbers).
    pub fn params(&self) -> Vec<f64> {
        with_spline!(&self.inner, c => c.params().to_vec())
    }

    /// The data points, flat ((n+1)·dim; a closed spline repeats the first at the end).
    pub fn points(&self) -> Vec<f64> {
        with_spline!(&self.inner, c => flatten_points(c.points()))
    }

    /// The tangents `C'(t_i)` with respect to the global parameter, flat ((n+1)·dim).
    pub fn tangents(&self) -> Vec<f64> {
        with_spline!(&self.inner, c => flatten_points(c.tangents()))
    }

    /// The point at t (dim numbers; exactly `p_i` at `t_i`).
    pub fn evaluate(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_spline!(&self.inner, c => flatten_points(&[c.evaluate(t)?])))
    }

    /// The derivative of the given order at t (0 the point; above 3 the zero vector). At an
    /// interior `t_i` the right piece's.
    pub fn derivative(&self, t: f64, order: f64) -> Result<Vec<f64>, ApiError> {
        let order = whole("order", order)?;
        Ok(with_spline!(&self.inner, c => flatten_points(&[c.derivative_at(t, order)?])))
    }

    /// `evaluate` into the per-call buffer (see `wasm::scratch`): its index, 0 on an error.
    /// Internal: `evaluateInto(t, out)` (added by `scripts/glue.mjs`) calls it.
    #[wasm_bindgen(js_name = __evaluateScratch, skip_typescript)]
    pub fn evaluate_scratch(&self, t: f64) -> u32 {
        with_spline!(&self.inner, c => crate::wasm::scratch::put(c.evaluate(t)))
    }

    /// `derivative` into the per-call buffer: its index, 0 on an error.
    #[wasm_bindgen(js_name = __derivativeScratch, skip_typescript)]
    pub fn derivative_scratch(&self, t: f64, order: f64) -> u32 {
        let Ok(order) = whole("order", order) else {
            return 0;
        };
        with_spline!(&self.inner, c => crate::wasm::scratch::put(c.derivative_at(t, order)))
    }

    /// Points at every t of `ts`, flat (ts.length·dim), walking the pieces once for sorted ts.
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
    ) -> Result<Vec<f64>, ApiError> {
        let ts = &*numbers("ts", &ts)?;
        let mut out = Vec::new();
        self.sample_into(ts, 0, &mut out)?;
        Ok(out)
    }

    /// The derivative of the given order at every t of `ts`, flat (ts.length·dim).
    #[wasm_bindgen(js_name = sampleDerivatives)]
    pub fn sample_derivatives(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
        order: f64,
    ) -> Result<Vec<f64>, ApiError> {
        let ts = &*numbers("ts", &ts)?;
        let order = whole("order", order)?;
        let mut out = Vec::new();
        self.sample_into(ts, order, &mut out)?;
        Ok(out)
    }

    /// `count` points at equally spaced t over the domain, ends included, flat.
    #[wasm_bindgen(js_name = sampleUniform)]
    pub fn sample_uniform(&self, count: f64) -> Result<Vec<f64>, ApiError> {
        let count = whole("count", count)?;
        let mut out = Vec::new();
        self.sample_uniform_into(count, &mut out)?;
        Ok(out)
    }

    /// `sampleUniform(count)` into a buffer this spline keeps, returned as a `Float64Array`
    /// view of the wasm memory (no copy; overwritten by the next `…View` call, detached when
    /// the memory grows: read it at once or `slice()` it).
    #[wasm_bindgen(js_name = sampleUniformView)]
    pub fn sample_uniform_view(&mut self, count: f64) -> Result<js_sys::Float64Array, ApiError> {
        let count = whole("count", count)?;
        let mut buffer = std::mem::take(&mut self.view);
        let result = self.sample_uniform_into(count, &mut buffer);
        self.view = buffer;
        result?;
        memory_view(&self.view)
    }

    /// `sample(ts)` into this spline's view buffer (see `sampleUniformView`).
    #[wasm_bindgen(js_name = sampleView)]
    pub fn sample_view(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
    ) -> Result<js_sys::Float64Array, ApiError> {
        let ts = &*numbers("ts", &ts)?;
        let mut buffer = std::mem::take(&mut self.view);
        let result = self.sample_into(ts, 0, &mut buffer);
        self.view = buffer;
        result?;
        memory_view(&self.view)
    }

    /// The Bézier form: one cubic per interval, `[p_i, p_i + Δ_i m_i/3, p_{i+1} − Δ_i m_{i+1}/3,
    /// p_{i+1}]`, breaks = params.
    #[wasm_bindgen(js_name = toBezier)]
    pub fn to_bezier(&self) -> Result<JsCompositeBezier, ApiError> {
        let (points, tangents, params) = self.lifted();
        let q = flat_points(&bezier_points(&points, &tangents, params), self.dim_of());
        let degrees = vec![3; points.len() - 1];
        let breaks = Some(params);
        Ok(if self.dim_of() == 2 {
            JsCompositeBezier::from_2d(CompositeCurve::from_flat(&q, &degrees, breaks)?)
        } else {
            JsCompositeBezier::from_3d(CompositeCurve::from_flat(&q, &degrees, breaks)?)
        })
    }

    /// The same curve as a clamped cubic B-spline: a cubicSpline (C2) has single interior
    /// knots at `t_1..t_{n−1}` and n + 3 control points; the others (C1) double interior knots
    /// and 2n + 2 control points.
    #[wasm_bindgen(js_name = toBSpline)]
    pub fn to_bspline(&self) -> Result<JsBSplineCurve, ApiError> {
        let (points, tangents, params) = self.lifted();
        let c2 = with_spline!(&self.inner, c => matches!(c.rule(), TangentRule::Spline(_)));
        let (control, knots) = bspline_form(&points, &tangents, params, c2);
        let control = flat_points(&control, self.dim_of());
        Ok(if self.dim_of() == 2 {
            JsBSplineCurve::from_2d(BSplineCurve::from_flat(&control, 3, knots, None)?)
        } else {
            JsBSplineCurve::from_3d(BSplineCurve::from_flat(&control, 3, knots, None)?)
        })
    }

    /// The tangent system a cubicSpline solved: `{ size, dim, lower, diagonal, upper, rhs,
    /// corners, solution }`. Row i is the equation of `m_i` (i = 0..size−1; size = n + 1, or n
    /// for periodic, whose unknowns are m_0..m_{n−1}); `lower[i]` is the entry (i+1, i),
    /// `upper[i]` the entry (i, i+1) (size − 1 each), `rhs` and `solution` size·dim numbers
    /// row by row, `corners` `[top-right (0, size−1), bottom-left (size−1, 0)]` for the cyclic
    /// system of "periodic" (with size 2 they add to upper[0] and lower[0]), else `[]`.
    #[wasm_bindgen(
        unchecked_return_type = "{ size: number; dim: number; lower: number[]; diagonal: number[]; upper: number[]; rhs: number[]; corners: number[]; solution: number[] }"
    )]
    pub fn system(&self) -> Result<JsValue, ApiError> {
        let system = with_spline!(&self.inner, c => system_of(c))?;
        Ok(serde_wasm_bindgen::to_value(&system)?)
    }

    /// Moves data point i (dim numbers) and re-solves in place: the drag path, no rebuild.
    /// Parameters computed from the points (catmullRom, or params given as a kind) are
    /// recomputed; on a closed spline points 0 and n move together.
    #[wasm_bindgen(js_name = setPoint)]
    pub fn set_point(
        &mut self,
        i: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] point: JsValue,
    ) -> Result<(), ApiError> {
        let point = numbers("point", &point)?;
        let i = whole("i", i)?;
        with_spline!(&mut self.inner, c => c.set_point(i, point_from(&point)?))?;
        Ok(())
    }

    /// Sets tangent i (`C'(t_i)`, dim numbers) in place: hermiteSpline only.
    #[wasm_bindgen(js_name = setTangent)]
    pub fn set_tangent(
        &mut self,
        i: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] vector: JsValue,
    ) -> Result<(), ApiError> {
        let vector = numbers("vector", &vector)?;
        let i = whole("i", i)?;
        with_spline!(&mut self.inner, c => c.set_tangent(i, point_from(&vector)?))?;
        Ok(())
    }

    /// Curvature at t (signed in 2D, ≥ 0 in 3D; Infinity where the velocity vanishes).
    pub fn curvature(&self, t: f64) -> Result<f64, ApiError> {
        Ok(with_spline!(&self.inner, c => c.curvature(t))?)
    }

    /// A copy of this spline (a new wasm object; free it too).
    #[wasm_bindgen(js_name = clone)]
    pub fn clone_spline(&self) -> JsCubicSpline {
        JsCubicSpline::wrap(self.inner.clone())
    }
}
