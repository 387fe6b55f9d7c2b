//! `parametricCurve(pieces, parameters?)`, the `ParametricCurve` class and
//! `expressionNames(text)`: typed curves (syllabus 1).

use super::bezier::JsBezierCurve;
use super::{numbers, set_key, string_arg, type_name, whole, ApiError};
use crate::error::Error;
use crate::expr::{self, ExprError, Problem};
use crate::parametric::{ParametricCurve, PieceSource};
use js_sys::{Array, Float64Array, Object, Reflect};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A typed curve: pieces of text x(t), y(t) (z(t)) on intervals that join in t.
#[wasm_bindgen(js_name = ParametricCurve)]
pub struct JsParametricCurve {
    inner: ParametricCurve,
}

/// `object[key]`, `undefined` when it cannot be read.
fn get(object: &JsValue, key: &str) -> JsValue {
    Reflect::get(object, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
}

/// A field of a piece: a string, or a finite number (written as JavaScript writes it).
#[inline(never)]
fn field_text(piece: usize, object: &JsValue, field: &str) -> Result<Option<String>, ApiError> {
    let value = get(object, field);
    if value.is_undefined() || value.is_null() {
        return Ok(None);
    }
    if let Some(s) = value.as_string() {
        return Ok(Some(s));
    }
    if let Some(x) = value.as_f64() {
        if x.is_finite() {
            return Ok(Some(crate::platform::number_text(x)));
        }
        let mut e = ExprError::at(0, 0, Problem::NotFiniteValue { value: x });
        e.piece = Some(piece);
        e.field = Some(field.into());
        return Err(Error::from(e).into());
    }
    Err(Error::ArgumentType {
        name: "pieces",
        expected: "string",
        got: type_name(&value),
    }
    .into())
}

/// A required field, or the coded "missing-field" error placed in it.
#[inline(never)]
fn required(piece: usize, object: &JsValue, field: &str) -> Result<String, ApiError> {
    field_text(piece, object, field)?.ok_or_else(|| {
        Error::from(ExprError::at(0, 0, Problem::MissingField {}).in_field(piece, field)).into()
    })
}

/// The pieces argument: an array of `{ x, y, z?, from, to }`.
fn read_pieces(value: &JsValue) -> Result<Vec<PieceSource>, ApiError> {
    if !Array::is_array(value) {
        return Err(Error::ArgumentType {
            name: "pieces",
            expected: "array",
            got: type_name(value),
        }
        .into());
    }
    let array: &Array = value.unchecked_ref();
    let count = array.length() as usize;
    if count == 0 || count > crate::parametric::MAX_PIECES {
        return Err(Error::from(ExprError::at(
            0,
            0,
            Problem::PieceCount {
                count,
                max: crate::parametric::MAX_PIECES,
            },
        ))
        .into());
    }
    let mut pieces = Vec::with_capacity(count);
    for (i, object) in array.iter().enumerate() {
        if !object.is_object() {
            return Err(Error::ArgumentType {
                name: "pieces",
                expected: "object",
                got: type_name(&object),
            }
            .into());
        }
        pieces.push(PieceSource {
            x: required(i, &object, "x")?,
            y: required(i, &object, "y")?,
            z: field_text(i, &object, "z")?,
            from: required(i, &object, "from")?,
            to: required(i, &object, "to")?,
        });
    }
    Ok(pieces)
}

/// The parameters argument: `{ name: value, … }` (own enumerable keys, in order).
fn read_parameters(value: &JsValue) -> Result<Vec<(String, f64)>, ApiError> {
    if value.is_undefined() || value.is_null() {
        return Ok(Vec::new());
    }
    if !value.is_object() || Array::is_array(value) {
        return Err(Error::ArgumentType {
            name: "parameters",
            expected: "object",
            got: type_name(value),
        }
        .into());
    }
    let entries = Object::entries(value.unchecked_ref());
    let mut out = Vec::with_capacity(entries.length() as usize);
    for entry in entries.iter() {
        let pair: &Array = entry.unchecked_ref();
        let name = pair.get(0).as_string().unwrap_or_default();
        let Some(v) = pair.get(1).as_f64() else {
            return Err(Error::ArgumentType {
                name: "parameters",
                expected: "number",
                got: type_name(&pair.get(1)),
            }
            .into());
        };
        out.push((name, v));
    }
    Ok(out)
}

/// `parametricCurve(pieces, parameters?)`: the curve typed as text, see the README (syntax
/// table, errors with `code` and `params.{piece, field, start, end}`).
#[wasm_bindgen(js_name = parametricCurve)]
pub fn parametric_curve(
    #[wasm_bindgen(
        unchecked_param_type = "{ x: string, y: string, z?: string, from: string | number, to: string | number }[]"
    )]
    pieces: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "Record<string, number>")] parameters: JsValue,
) -> Result<JsParametricCurve, ApiError> {
    let pieces = read_pieces(&pieces)?;
    let parameters = read_parameters(&parameters)?;
    Ok(JsParametricCurve {
        inner: ParametricCurve::new(&pieces, &parameters)?,
    })
}

/// `expressionNames(text)`: the parameter names a text uses, in order of first appearance (so
/// a page can offer a slider per name); a syntax error throws the coded Error.
#[wasm_bindgen(js_name = expressionNames)]
pub fn expression_names(
    #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
) -> Result<Vec<String>, ApiError> {
    let text = string_arg("text", &text, None)?;
    Ok(expr::parameter_names(&text).map_err(Error::from)?)
}

/// A piece index from JavaScript, checked against the count.
fn piece_index(curve: &ParametricCurve, i: f64) -> Result<usize, ApiError> {
    let i = whole("piece", i)?;
    if i >= curve.piece_count() {
        return Err(Error::IndexOutOfRange {
            index: i,
            count: curve.piece_count(),
        }
        .into());
    }
    Ok(i)
}

fn numbers_value(values: &[f64]) -> JsValue {
    Float64Array::from(values).into()
}

#[wasm_bindgen(js_class = ParametricCurve)]
impl JsParametricCurve {
    /// Dimension: 2, or 3 with a z expression.
    #[wasm_bindgen(getter)]
    pub fn dim(&self) -> usize {
        self.inner.dim()
    }

    /// Number of pieces.
    #[wasm_bindgen(getter, js_name = pieceCount)]
    pub fn piece_count(&self) -> usize {
        self.inner.piece_count()
    }

    /// `[a, b]`: the first piece's start, the last piece's end.
    pub fn domain(&self) -> Vec<f64> {
        let (a, b) = self.inner.domain();
        vec![a, b]
    }

    /// Piece `i`'s interval `[from, to]`.
    #[wasm_bindgen(js_name = pieceDomain)]
    pub fn piece_domain(&self, i: f64) -> Result<Vec<f64>, ApiError> {
        let (a, b) = self.inner.piece_domain(piece_index(&self.inner, i)?)?;
        Ok(vec![a, b])
    }

    /// P(t) (dim numbers): the right piece at a joint, NaN where undefined.
    pub fn evaluate(&self, t: f64) -> Result<Vec<f64>, ApiError> {
        Ok(self.inner.evaluate(t)?)
    }

    /// `evaluate` into the per-call buffer; 0 on an error. Internal: `evaluateInto`.
    #[wasm_bindgen(js_name = __evaluateScratch, skip_typescript)]
    pub fn evaluate_scratch(&self, t: f64) -> u32 {
        let mut p = [0.0; 3];
        match self.inner.evaluate_into(t, &mut p) {
            Ok(()) => super::scratch::put_coords(self.inner.dim(), p),
            Err(_) => 0,
        }
    }

    /// The derivative of order `order` ≤ 8 at t (automatic differentiation).
    pub fn derivative(&self, t: f64, order: f64) -> Result<Vec<f64>, ApiError> {
        let order = whole("order", order)?;
        Ok(self.inner.derivative(t, order)?)
    }

    /// `derivative` into the per-call buffer; 0 on an error. Internal: `derivativeInto`.
    #[wasm_bindgen(js_name = __derivativeScratch, skip_typescript)]
    pub fn derivative_scratch(&self, t: f64, order: f64) -> u32 {
        let Ok(order) = whole("order", order) else {
            return 0;
        };
        let mut p = [0.0; 3];
        match self.inner.derivative_into(t, order, &mut p) {
            Ok(()) => super::scratch::put_coords(self.inner.dim(), p),
            Err(_) => 0,
        }
    }

    /// Points at every t of `ts`, flat.
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
    ) -> Result<Vec<f64>, ApiError> {
        let ts = numbers("ts", &ts)?;
        Ok(self.inner.sample(&ts)?)
    }

    /// `count` points at equally spaced t over the domain, ends included, flat.
    #[wasm_bindgen(js_name = sampleUniform)]
    pub fn sample_uniform(&self, count: f64) -> Result<Vec<f64>, ApiError> {
        let count = whole("count", count)?;
        Ok(self.inner.sample_uniform(count)?)
    }

    /// The certified plot: `{ points, ts, complete }`, runs separated by a NaN vertex; `box`
    /// `[xmin, ymin, xmax, ymax]` limits refinement to what is visible.
    #[wasm_bindgen(
        unchecked_return_type = "{ points: Float64Array; ts: Float64Array; complete: boolean }"
    )]
    pub fn plot(
        &self,
        tolerance: f64,
        #[wasm_bindgen(js_name = box, unchecked_optional_param_type = "Float64Array | number[]")]
        bbox: JsValue,
    ) -> Result<JsValue, ApiError> {
        let bbox = match super::optional_numbers("box", &bbox)? {
            None => None,
            Some(b) => {
                Some(
                    <[f64; 4]>::try_from(b.as_slice()).map_err(|_| Error::ArgumentLength {
                        name: "box",
                        expected: 4,
                        got: b.len(),
                    })?,
                )
            }
        };
        let plot = self.inner.plot(tolerance, bbox)?;
        let out = Object::new();
        set_key(&out, "points", &numbers_value(&plot.points));
        set_key(&out, "ts", &numbers_value(&plot.ts));
        set_key(&out, "complete", &JsValue::from_bool(plot.complete));
        Ok(out.into())
    }

    /// The verdict at every joint: `[{ t, c, g, exact, disjoint, order?, left?, right? }]`.
    #[wasm_bindgen(
        unchecked_return_type = "{ t: number; c: number; g: number; exact: boolean; disjoint: boolean; order?: number; left?: Float64Array; right?: Float64Array }[]"
    )]
    pub fn joints(&self) -> Result<Array, ApiError> {
        let out = Array::new();
        for j in self.inner.joints() {
            let o = Object::new();
            set_key(&o, "t", &JsValue::from_f64(j.t));
            set_key(&o, "c", &JsValue::from_f64(j.c));
            set_key(&o, "g", &JsValue::from_f64(j.g));
            set_key(&o, "exact", &JsValue::from_bool(j.exact));
            set_key(&o, "disjoint", &JsValue::from_bool(j.disjoint));
            if let Some(k) = j.order {
                set_key(&o, "order", &JsValue::from_f64(k as f64));
            }
            if let Some(l) = &j.left {
                set_key(&o, "left", &numbers_value(l));
            }
            if let Some(r) = &j.right {
                set_key(&o, "right", &numbers_value(r));
            }
            out.push(&o);
        }
        Ok(out)
    }

    /// Sets a parameter in place (the slider path); an Error keeps the old value.
    #[wasm_bindgen(js_name = setParameter)]
    pub fn set_parameter(
        &mut self,
        #[wasm_bindgen(unchecked_param_type = "string")] name: JsValue,
        value: f64,
    ) -> Result<(), ApiError> {
        let name = string_arg("name", &name, None)?;
        Ok(self.inner.set_parameter(&name, value)?)
    }

    /// The parameters' names, in the order given.
    #[wasm_bindgen(js_name = parameterNames)]
    pub fn parameter_names(&self) -> Vec<String> {
        self.inner.parameter_names().to_vec()
    }

    /// The parameters' values.
    #[wasm_bindgen(js_name = parameterValues)]
    pub fn parameter_values(&self) -> Vec<f64> {
        self.inner.parameter_values().to_vec()
    }

    /// Whether piece `i` is a polynomial in t.
    #[wasm_bindgen(js_name = isPolynomial)]
    pub fn is_polynomial(&self, i: f64) -> Result<bool, ApiError> {
        Ok(self.inner.is_polynomial(piece_index(&self.inner, i)?)?)
    }

    /// Piece `i` as a `BezierCurve` on its interval `[from, to]` (a polynomial piece only).
    #[wasm_bindgen(js_name = toBezier)]
    pub fn to_bezier(&self, i: f64) -> Result<JsBezierCurve, ApiError> {
        let form = self.inner.to_bezier(piece_index(&self.inner, i)?)?;
        Ok(JsBezierCurve::from_parametric(&form, self.inner.dim())?)
    }

    /// Piece `i`'s Bézier control coordinates as exact fractions ("-271/50"), flat; `null`
    /// when they are not all rational (a parameter, π, e).
    #[wasm_bindgen(js_name = bezierFractions)]
    pub fn bezier_fractions(&self, i: f64) -> Result<Option<Vec<String>>, ApiError> {
        let form = self.inner.to_bezier(piece_index(&self.inner, i)?)?;
        Ok(form
            .exact
            .map(|e| e.iter().map(ToString::to_string).collect()))
    }

    /// The Frenet frame at t: `{ point, tangent, normal, binormal, curvature, torsion }`.
    #[wasm_bindgen(
        unchecked_return_type = "{ point: Float64Array; tangent: Float64Array; normal: Float64Array; binormal: Float64Array; curvature: number; torsion: number }"
    )]
    pub fn frame(&self, t: f64) -> Result<JsValue, ApiError> {
        let f = self.inner.frame(t)?;
        let out = Object::new();
        set_key(&out, "point", &numbers_value(&f.point));
        set_key(&out, "tangent", &numbers_value(&f.tangent));
        set_key(&out, "normal", &numbers_value(&f.normal));
        set_key(&out, "binormal", &numbers_value(&f.binormal));
        set_key(&out, "curvature", &JsValue::from_f64(f.curvature));
        set_key(&out, "torsion", &JsValue::from_f64(f.torsion));
        Ok(out.into())
    }

    /// Piece `i` as TeX: `{ x: { expr, d1, d2 }, y, z?, from, to }` (d1, d2 null when too large).
    #[wasm_bindgen(
        unchecked_return_type = "{ x: { expr: string; d1: string | null; d2: string | null }; y: { expr: string; d1: string | null; d2: string | null }; z?: { expr: string; d1: string | null; d2: string | null }; from: string; to: string }"
    )]
    pub fn tex(&self, i: f64) -> Result<JsValue, ApiError> {
        let tex = self.inner.tex(piece_index(&self.inner, i)?)?;
        let out = Object::new();
        for (name, c) in ["x", "y", "z"].iter().zip(&tex.coords) {
            let o = Object::new();
            set_key(&o, "expr", &JsValue::from_str(&c.expr));
            let text = |s: &Option<String>| s.as_deref().map_or(JsValue::NULL, JsValue::from_str);
            set_key(&o, "d1", &text(&c.d1));
            set_key(&o, "d2", &text(&c.d2));
            set_key(&out, name, &o.into());
        }
        set_key(&out, "from", &JsValue::from_str(&tex.from));
        set_key(&out, "to", &JsValue::from_str(&tex.to));
        Ok(out.into())
    }
}
