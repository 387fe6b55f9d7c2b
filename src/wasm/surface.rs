//! `BSplineSurface` for JavaScript.

use super::bezier::point_from;
use super::{memory_view, numbers, optional_numbers, whole};
use crate::surface::{BSplineSurface, Mesh};
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

    /// The same surface with the knot u inserted `times` times (default 1): a new row of
    /// control points each time (Boehm's algorithm on every column).
    #[wasm_bindgen(js_name = insertKnotU)]
    pub fn insert_knot_u(&self, u: f64, times: Option<f64>) -> Result<JsBSplineSurface, JsError> {
        let times = whole("times", times.unwrap_or(1.0))?;
        Ok(JsBSplineSurface::wrap(self.inner.insert_knot_u(u, times)?))
    }

    /// The same surface with the knot v inserted `times` times (default 1): a new column each
    /// time (Boehm's algorithm on every row).
    #[wasm_bindgen(js_name = insertKnotV)]
    pub fn insert_knot_v(&self, v: f64, times: Option<f64>) -> Result<JsBSplineSurface, JsError> {
        let times = whole("times", times.unwrap_or(1.0))?;
        Ok(JsBSplineSurface::wrap(self.inner.insert_knot_v(v, times)?))
    }
}

impl JsBSplineSurface {
    fn wrap(inner: BSplineSurface) -> Self {
        JsBSplineSurface {
            inner,
            view: Vec::new(),
        }
    }
}

/// A tensor-product Bézier patch `P(u, v) = Σ Σ B_i^m(u) B_j^n(v) P_ij` (rational with weights)
/// on `[0, 1]²`, degrees m = rows − 1 and n = cols − 1.
#[wasm_bindgen(js_name = BezierSurface)]
#[derive(Clone)]
pub struct JsBezierSurface {
    inner: BSplineSurface,
    /// The buffer behind `sampleGridView`'s result.
    view: Vec<f64>,
}

#[wasm_bindgen(js_class = BezierSurface)]
impl JsBezierSurface {
    /// `new BezierSurface(points, rows, cols, weights?)`: rows·cols points (xyz, flat,
    /// row-major, i along u), at least 2 × 2, optional weights (> 0).
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
        rows: f64,
        cols: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "Float64Array | number[]")] weights: JsValue,
    ) -> Result<JsBezierSurface, JsError> {
        let weights = optional_numbers("weights", &weights)?;
        let points = &*numbers("points", &points)?;
        let inner = BSplineSurface::bezier(
            points,
            whole("rows", rows)?,
            whole("cols", cols)?,
            weights.as_deref(),
        )?;
        Ok(JsBezierSurface {
            inner,
            view: Vec::new(),
        })
    }

    /// The four patches of a split at (u, v), each on [0, 1]²: `[u ≤ u0 & v ≤ v0, u ≤ u0 &
    /// v ≥ v0, u ≥ u0 & v ≤ v0, u ≥ u0 & v ≥ v0]` (de Casteljau on every row, then every column).
    pub fn split(&self, u: f64, v: f64) -> Result<Vec<JsBezierSurface>, JsError> {
        Ok(self
            .inner
            .split_bezier(u, v)?
            .into_iter()
            .map(|inner| JsBezierSurface {
                inner,
                view: Vec::new(),
            })
            .collect())
    }
}

/// `{ positions, normals, indices }` as typed arrays.
fn mesh_to_js(mesh: &Mesh) -> Result<JsValue, JsError> {
    let object = js_sys::Object::new();
    let set = |key: &str, value: &JsValue| {
        js_sys::Reflect::set(&object, &JsValue::from_str(key), value)
            .map(|_| ())
            .map_err(|_| JsError::new("could not build the mesh object"))
    };
    set(
        "positions",
        &js_sys::Float32Array::from(&mesh.positions[..]).into(),
    )?;
    set(
        "normals",
        &js_sys::Float32Array::from(&mesh.normals[..]).into(),
    )?;
    set(
        "indices",
        &js_sys::Uint32Array::from(&mesh.indices[..]).into(),
    )?;
    Ok(object.into())
}

/// The methods both surface classes share, on their `inner: BSplineSurface` and `view`.
macro_rules! surface_methods {
    ($class:ident, $js:ident) => {
        #[wasm_bindgen(js_class = $js)]
        impl $class {
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
            pub fn derivative(
                &self,
                u: f64,
                v: f64,
                du: f64,
                dv: f64,
            ) -> Result<Vec<f64>, JsError> {
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

            /// Moves control point (i, j) to `point` (3 numbers) in place, keeping its weight:
            /// the drag path (no new object).
            #[wasm_bindgen(js_name = setControlPoint)]
            pub fn set_control_point(
                &mut self,
                i: f64,
                j: f64,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] point: JsValue,
            ) -> Result<(), JsError> {
                let point = numbers("point", &point)?;
                let point = point_from::<glam::DVec3>(&point)?;
                Ok(self
                    .inner
                    .set_control_point(whole("i", i)?, whole("j", j)?, point)?)
            }

            /// Sets the weight (> 0) of control point (i, j) in place.
            #[wasm_bindgen(js_name = setWeight)]
            pub fn set_weight(&mut self, i: f64, j: f64, w: f64) -> Result<(), JsError> {
                Ok(self.inner.set_weight(whole("i", i)?, whole("j", j)?, w)?)
            }

            /// A triangle mesh for WebGL: `{ positions: Float32Array, normals: Float32Array, indices:
            /// Uint32Array }` with (nu + 1)(nv + 1) vertices at equally spaced (u, v) over the domain
            /// (vertex a·(nv + 1) + b), unit normals, and 2·nu·nv triangles counter-clockwise seen from
            /// the side the normals point to.
            #[wasm_bindgen(unchecked_return_type = "{ positions: Float32Array; normals: Float32Array; indices: Uint32Array }")]
            pub fn tessellate(&self, nu: f64, nv: f64) -> Result<JsValue, JsError> {
                let mesh = self.inner.tessellate(whole("nu", nu)?, whole("nv", nv)?)?;
                mesh_to_js(&mesh)
            }
        }
    };
}

surface_methods!(JsBSplineSurface, BSplineSurface);
surface_methods!(JsBezierSurface, BezierSurface);
