//! `CompositeBezier` and the joint helpers `jointContinuity`, `joinBezier` for JavaScript.

use super::{flatten_points, Curve, JsBezierCurve};
use crate::bezier::{self, CompositeCurve, Continuity, JoinRule, DEFAULT_CONTINUITY_TOLERANCE};
use crate::error::Error;
use crate::geom::check_dim;
use crate::prelude::*;
use crate::wasm::ApiError;
use crate::wasm::{numbers, optional_numbers, scratch, string_arg, whole, whole_at};
use glam::{DVec2, DVec3};
use serde::Serialize;
use wasm_bindgen::prelude::*;

#[derive(Serialize)]
struct ContinuityJs {
    c: f64,
    g: f64,
}

impl From<Continuity> for ContinuityJs {
    fn from(k: Continuity) -> Self {
        let order = |k: i32| {
            if k == Continuity::INFINITE {
                f64::INFINITY
            } else {
                k as f64
            }
        };
        ContinuityJs {
            c: order(k.c),
            g: order(k.g),
        }
    }
}

/// `jointContinuity(left, right, tolerance = 1e-9)`: `{ c, g }`, the largest k with C^k and
/// G^k at the joint of left's end and right's start (−1: the pieces do not meet; Infinity:
/// one polynomial). G is checked up to 2.
#[wasm_bindgen(js_name = jointContinuity, unchecked_return_type = "{ c: number; g: number }")]
pub fn joint_continuity(
    left: &JsBezierCurve,
    right: &JsBezierCurve,
    tolerance: Option<f64>,
) -> Result<JsValue, ApiError> {
    let tol = tolerance.unwrap_or(DEFAULT_CONTINUITY_TOLERANCE);
    let k = match (&left.inner, &right.inner) {
        (Curve::D2(l), Curve::D2(r)) => bezier::check_continuity(l, r, tol)?,
        (Curve::D3(l), Curve::D3(r)) => bezier::check_continuity(l, r, tol)?,
        _ => return Err(dim_mismatch(left, right).into()),
    };
    Ok(serde_wasm_bindgen::to_value(&ContinuityJs::from(k))?)
}

/// `joinBezier(left, right, rule, adjust = "right")`: `[left, right]` with the constrained
/// points of one piece moved so the joint obeys rule "C0" | "C1" | "C2" | "G1".
#[wasm_bindgen(js_name = joinBezier)]
pub fn join_bezier(
    left: &JsBezierCurve,
    right: &JsBezierCurve,
    #[wasm_bindgen(unchecked_param_type = "string")] rule: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "string")] adjust: JsValue,
) -> Result<Vec<JsBezierCurve>, ApiError> {
    let rule = &*string_arg("rule", &rule, None)?;
    let rule = JoinRule::parse(rule)?;
    let adjust_right = match string_arg("adjust", &adjust, Some("right"))?.as_str() {
        "right" => true,
        "left" => false,
        other => {
            return Err(Error::UnknownOption {
                name: "adjust",
                value: other.into(),
                expected: "\"left\", \"right\"",
            }
            .into())
        }
    };
    let (l, r) = match (&left.inner, &right.inner) {
        (Curve::D2(l), Curve::D2(r)) => {
            let (l, r) = bezier::join(l, r, rule, adjust_right)?;
            (Curve::D2(l), Curve::D2(r))
        }
        (Curve::D3(l), Curve::D3(r)) => {
            let (l, r) = bezier::join(l, r, rule, adjust_right)?;
            (Curve::D3(l), Curve::D3(r))
        }
        _ => return Err(dim_mismatch(left, right).into()),
    };
    Ok(vec![JsBezierCurve::wrap(l), JsBezierCurve::wrap(r)])
}

fn dim_mismatch(left: &JsBezierCurve, right: &JsBezierCurve) -> Error {
    Error::DimensionMismatch {
        left: left.dim(),
        right: right.dim(),
    }
}

/// A 2D or 3D composite curve behind one JS class.
enum Composite {
    D2(bezier::CompositeCurve<DVec2>),
    D3(bezier::CompositeCurve<DVec3>),
}

macro_rules! with_composite {
    ($composite:expr, $c:ident => $body:expr) => {
        match $composite {
            Composite::D2($c) => $body,
            Composite::D3($c) => $body,
        }
    };
}

/// A piecewise Bézier curve: `new CompositeBezier(points, dim, degrees, breaks?)` where
/// `points` holds every piece's n + 1 control points one piece after the other, `degrees` the
/// degree of each piece and `breaks` the k + 1 breakpoints (default 0, 1, …, k): piece i lives
/// on `[breaks[i], breaks[i+1]]`.
#[wasm_bindgen(js_name = CompositeBezier)]
pub struct JsCompositeBezier {
    inner: Composite,
}

impl JsCompositeBezier {
    /// Wraps a core 2D composite curve.
    pub(crate) fn from_2d(c: CompositeCurve<DVec2>) -> Self {
        JsCompositeBezier {
            inner: Composite::D2(c),
        }
    }

    /// Wraps a core 3D composite curve.
    pub(crate) fn from_3d(c: CompositeCurve<DVec3>) -> Self {
        JsCompositeBezier {
            inner: Composite::D3(c),
        }
    }

    /// The core curve when it is 2D.
    pub(crate) fn as_2d(&self) -> Option<&CompositeCurve<DVec2>> {
        match &self.inner {
            Composite::D2(c) => Some(c),
            Composite::D3(_) => None,
        }
    }

    /// The core curve when it is 3D.
    pub(crate) fn as_3d(&self) -> Option<&CompositeCurve<DVec3>> {
        match &self.inner {
            Composite::D3(c) => Some(c),
            Composite::D2(_) => None,
        }
    }
}

#[wasm_bindgen(js_class = CompositeBezier)]
impl JsCompositeBezier {
    /// See the class documentation.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
        dim: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] degrees: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] breaks: JsValue,
    ) -> Result<JsCompositeBezier, ApiError> {
        let breaks = optional_numbers("breaks", &breaks)?;
        let points = &*numbers("points", &points)?;
        let degrees = &*numbers("degrees", &degrees)?;
        let dim = whole("dim", dim)?;
        let degrees = degrees
            .iter()
            .enumerate()
            .map(|(i, &d)| whole_at("degrees", Some(i), d))
            .collect::<Result<Vec<usize>, ApiError>>()?;
        let breaks = breaks.as_deref();
        let inner = match check_dim(dim)? {
            2 => Composite::D2(CompositeCurve::from_flat(points, &degrees, breaks)?),
            _ => Composite::D3(CompositeCurve::from_flat(points, &degrees, breaks)?),
        };
        Ok(JsCompositeBezier { inner })
    }

    /// Number of pieces.
    #[wasm_bindgen(getter, js_name = pieceCount)]
    pub fn piece_count(&self) -> usize {
        with_composite!(&self.inner, c => c.pieces().len())
    }

    /// 2 or 3.
    #[wasm_bindgen(getter)]
    pub fn dim(&self) -> usize {
        match &self.inner {
            Composite::D2(_) => 2,
            Composite::D3(_) => 3,
        }
    }

    /// Every piece's control points back to back, flat (`n_i + 1` points of piece `i`).
    #[wasm_bindgen(js_name = controlPoints)]
    pub fn control_points(&self) -> Vec<f64> {
        with_composite!(&self.inner, c => {
            let points: Vec<_> = c.pieces().iter().flat_map(|p| p.control_points()).collect();
            flatten_points(&points)
        })
    }

    /// The degree of each piece.
    pub fn degrees(&self) -> Vec<u32> {
        with_composite!(&self.inner, c => c.pieces().iter().map(|p| p.degree() as u32).collect())
    }

    /// Moves control point `i` of piece `piece` to `point` (dim numbers), in place — the drag
    /// path: no rebuild. The neighbouring piece does not follow; move its shared point too.
    #[wasm_bindgen(js_name = setControlPoint)]
    pub fn set_control_point(
        &mut self,
        piece: f64,
        i: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] point: JsValue,
    ) -> Result<(), ApiError> {
        let piece = whole("piece", piece)?;
        let i = whole("i", i)?;
        let coords = numbers("point", &point)?;
        match &mut self.inner {
            Composite::D2(c) => c.set_control_point(piece, i, super::point_from(&coords)?)?,
            Composite::D3(c) => c.set_control_point(piece, i, super::point_from(&coords)?)?,
        }
        Ok(())
    }

    /// `count` points at equally spaced parameters over the whole domain, ends included.
    #[wasm_bindgen(js_name = sampleUniform)]
    pub fn sample_uniform(&self, count: f64) -> Result<Vec<f64>, ApiError> {
        let count = whole("count", count)?;
        let len = crate::geom::result_len("sample-uniform-result", &[count, self.dim()])?;
        let mut out = vec![0.0; len];
        with_composite!(&self.inner, c => c.sample_uniform_into(count, &mut out))?;
        Ok(out)
    }

    /// The global domain `[t_0, t_k]`.
    pub fn domain(&self) -> Vec<f64> {
        let (a, b) = with_composite!(&self.inner, c => c.domain());
        vec![a, b]
    }

    /// Piece i as a `BezierCurve` on its own interval (a copy).
    pub fn piece(&self, i: f64) -> Result<JsBezierCurve, ApiError> {
        let i = whole("i", i)?;
        let count = self.piece_count();
        let inner = match &self.inner {
            Composite::D2(c) => c.pieces().get(i).cloned().map(Curve::D2),
            Composite::D3(c) => c.pieces().get(i).cloned().map(Curve::D3),
        };
        inner
            .map(JsBezierCurve::wrap)
            .ok_or_else(|| Error::IndexOutOfRange { index: i, count }.into())
    }

    /// The point at the global parameter t (the right piece at a joint).
    pub fn evaluate(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(with_composite!(&self.inner, c => flatten_points(&[c.evaluate(t)?])))
    }

    /// The derivative of the given order at t (the right piece's at a joint).
    pub fn derivative(&self, t: f64, order: f64) -> Result<Vec<f64>, ApiError> {
        let order = whole("order", order)?;
        Ok(with_composite!(&self.inner, c => flatten_points(&[c.derivative(t, order)?])))
    }

    /// `evaluate` into the per-call buffer (see `wasm::scratch`): its index, 0 on an error.
    /// Internal: `evaluateInto(t, out)` (added by `scripts/glue.mjs`) calls it.
    #[wasm_bindgen(js_name = __evaluateScratch, skip_typescript)]
    pub fn evaluate_scratch(&self, t: f64) -> u32 {
        with_composite!(&self.inner, c => scratch::put(c.evaluate(t)))
    }

    /// `derivative` into the per-call buffer: its index, 0 on an error.
    #[wasm_bindgen(js_name = __derivativeScratch, skip_typescript)]
    pub fn derivative_scratch(&self, t: f64, order: f64) -> u32 {
        let Ok(order) = whole("order", order) else {
            return 0;
        };
        with_composite!(&self.inner, c => scratch::put(c.derivative(t, order)))
    }

    /// Points at every t of `ts`, flat.
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
    ) -> Result<Vec<f64>, ApiError> {
        let ts = &*numbers("ts", &ts)?;
        let len = crate::geom::result_len("sample-ts-result", &[ts.len(), self.dim()])?;
        let mut out = vec![0.0; len];
        with_composite!(&self.inner, c => c.sample_into(ts, &mut out))?;
        Ok(out)
    }

    /// `[{ c, g }, …]`: the continuity at each joint (see `jointContinuity`).
    #[wasm_bindgen(unchecked_return_type = "{ c: number; g: number }[]")]
    pub fn continuity(&self, tolerance: Option<f64>) -> Result<JsValue, ApiError> {
        let ks = with_composite!(&self.inner, c => c.continuity(tolerance.unwrap_or(DEFAULT_CONTINUITY_TOLERANCE))?);
        let out: Vec<ContinuityJs> = ks.into_iter().map(ContinuityJs::from).collect();
        Ok(serde_wasm_bindgen::to_value(&out)?)
    }
}
