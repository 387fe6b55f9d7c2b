//! What the JS curve classes share: the `Curve` enum behind a class (2D or 3D core curve) and
//! its macros, the [`ClassCurve`] trait, the sampling and editing bodies, and
//! [`class_curve_methods!`], the JS methods `BezierCurve` and `BSplineCurve` have in common.

use crate::error::Error;
use crate::wasm::ApiError;
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

/// Runs `$body` with `$c` bound to the curve of either dimension of a `Curve` enum (`D2`,
/// `D3`; see [`curve_enum!`]).
macro_rules! with_curve {
    ($curve:expr, $c:ident => $body:expr) => {
        match $curve {
            Curve::D2($c) => $body,
            Curve::D3($c) => $body,
        }
    };
}

/// Maps a curve of either dimension to a curve of the same dimension.
macro_rules! map_curve {
    ($curve:expr, $c:ident => $body:expr) => {
        match $curve {
            Curve::D2($c) => Curve::D2($body),
            Curve::D3($c) => Curve::D3($body),
        }
    };
}

/// Defines `enum Curve { D2(Ty<DVec2>), D3(Ty<DVec3>) }`, the 2D or 3D core curve behind one JS
/// class, and implements [`ClassCurve`] for it.
macro_rules! curve_enum {
    ($ty:ident) => {
        /// A 2D or 3D curve behind one JS class.
        #[derive(Clone)]
        enum Curve {
            D2($ty<DVec2>),
            D3($ty<DVec3>),
        }

        impl_class_curve!();
    };
}

/// Implements [`ClassCurve`] for the `Curve` enum (`D2`, `D3`) of the module it is invoked in.
macro_rules! impl_class_curve {
    () => {
        impl $crate::wasm::class::ClassCurve for Curve {
            fn dim(&self) -> usize {
                match self {
                    Curve::D2(_) => 2,
                    Curve::D3(_) => 3,
                }
            }

            fn sample_into(&self, params: &[f64], out: &mut [f64]) -> Result<(), Error> {
                with_curve!(self, c => c.sample_into(params, out))
            }

            fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<(), Error> {
                with_curve!(self, c => c.sample_uniform_into(count, out))
            }

            fn set_control_point(&mut self, i: usize, coords: &[f64]) -> Result<(), Error> {
                with_curve!(self, c => c.set_control_point(i, $crate::wasm::bezier::point_from(coords)?))
            }

            fn set_weight(&mut self, i: usize, w: f64) -> Result<(), Error> {
                with_curve!(self, c => c.set_weight(i, w))
            }
        }
    };
}

/// The methods `BezierCurve` and `BSplineCurve` share, in one `#[wasm_bindgen]` impl block of
/// `$ty` exported as `$js`: the getters, evaluation, the sampling family and the in-place edits;
/// then the Rust-side constructors (`wrap`, `from_2d`, `from_3d`) and `curve_2d` over the core
/// curve type `$core`. The parameter names (`t`/`ts` or `u`/`us`, named in the argument errors) are given per class.
macro_rules! class_curve_methods {
    (
        $js:ident for $ty:ident over $core:ident, parameter $t:ident, parameters $ts:ident
    ) => {
        #[wasm_bindgen(js_class = $js)]
        impl $ty {
            /// The degree: n (number of control points − 1) of a Bézier curve, p of a B-spline.
            #[wasm_bindgen(getter)]
            pub fn degree(&self) -> usize {
                with_curve!(&self.inner, c => c.degree())
            }

            /// Dimension: 2 or 3.
            #[wasm_bindgen(getter)]
            pub fn dim(&self) -> usize {
                $crate::wasm::class::ClassCurve::dim(&self.inner)
            }

            /// True when some weight differs from 1.
            #[wasm_bindgen(getter)]
            pub fn rational(&self) -> bool {
                with_curve!(&self.inner, c => c.is_rational())
            }

            /// The control points, flat.
            #[wasm_bindgen(js_name = controlPoints)]
            pub fn control_points(&self) -> Vec<f64> {
                with_curve!(&self.inner, c => $crate::wasm::bezier::flatten_points(&c.control_points()))
            }

            /// The weights (all 1 for a polynomial curve).
            pub fn weights(&self) -> Vec<f64> {
                with_curve!(&self.inner, c => c.weights())
            }

            /// The homogeneous control points `(w·P, w)`, flat with dim + 1 numbers per point.
            #[wasm_bindgen(js_name = homogeneousPoints)]
            pub fn homogeneous_points(&self) -> Vec<f64> {
                with_curve!(&self.inner, c => $crate::wasm::bezier::flatten_points(c.homogeneous_points()))
            }

            /// The point at the parameter (t of a Bézier curve, u of a B-spline): dim numbers.
            pub fn evaluate(&self, $t: f64) -> Result<Vec<f64>, ApiError> {
                Ok(with_curve!(&self.inner, c => $crate::wasm::bezier::flatten_points(&[c.evaluate($t)?])))
            }

            /// The derivative of the given order at the parameter (order 0 = the point; above the
            /// degree of a polynomial curve, the zero vector).
            pub fn derivative(&self, $t: f64, order: f64) -> Result<Vec<f64>, ApiError> {
                let order = $crate::wasm::whole("order", order)?;
                Ok(with_curve!(&self.inner, c => $crate::wasm::bezier::flatten_points(&[c.derivative($t, order)?])))
            }

            /// `evaluate` into the per-call buffer (see `wasm::scratch`): its index, 0 on an error.
            /// Internal: `evaluateInto(t, out)` (added by `scripts/glue.mjs`) calls it.
            #[wasm_bindgen(js_name = __evaluateScratch, skip_typescript)]
            pub fn evaluate_scratch(&self, $t: f64) -> u32 {
                with_curve!(&self.inner, c => $crate::wasm::scratch::put(c.evaluate($t)))
            }

            /// `derivative` into the per-call buffer: its index, 0 on an error (a bad order too).
            /// Internal: `derivativeInto(t, order, out)` calls it.
            #[wasm_bindgen(js_name = __derivativeScratch, skip_typescript)]
            pub fn derivative_scratch(&self, $t: f64, order: f64) -> u32 {
                let Ok(order) = $crate::wasm::whole("order", order) else {
                    return 0;
                };
                with_curve!(&self.inner, c => $crate::wasm::scratch::put(c.derivative($t, order)))
            }

            /// Points at every parameter of the array (`ts` or `us`), flat (length·dim numbers), in one
            /// pass (a B-spline walks its spans once for sorted input).
            pub fn sample(
                &self,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] $ts: JsValue,
            ) -> Result<Vec<f64>, ApiError> {
                let $ts = &*$crate::wasm::numbers(stringify!($ts), &$ts)?;
                $crate::wasm::class::sample(&self.inner, $ts)
            }

            /// `count` points at equally spaced parameters over the whole domain, ends included.
            #[wasm_bindgen(js_name = sampleUniform)]
            pub fn sample_uniform(&self, count: f64) -> Result<Vec<f64>, ApiError> {
                let count = $crate::wasm::whole("count", count)?;
                $crate::wasm::class::sample_uniform(&self.inner, count)
            }

            /// `sampleUniform(count)` written into a buffer this curve keeps in the wasm memory and
            /// returned as a `Float64Array` view of it: no copy and no new array per call, for
            /// redrawing many points every frame. The view is overwritten by the next `…View` call
            /// on this curve and detached (length 0) when the wasm memory grows; read it at once,
            /// or `slice()` it to keep it.
            #[wasm_bindgen(js_name = sampleUniformView)]
            pub fn sample_uniform_view(&mut self, count: f64) -> Result<js_sys::Float64Array, ApiError> {
                let count = $crate::wasm::whole("count", count)?;
                $crate::wasm::class::sample_uniform_view(&self.inner, &mut self.view, count)
            }

            /// `sample(ts)` or `sample(us)` into this curve's view buffer (see `sampleUniformView`).
            #[wasm_bindgen(js_name = sampleView)]
            pub fn sample_view(
                &mut self,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] $ts: JsValue,
            ) -> Result<js_sys::Float64Array, ApiError> {
                let $ts = &*$crate::wasm::numbers(stringify!($ts), &$ts)?;
                $crate::wasm::class::sample_view(&self.inner, &mut self.view, $ts)
            }

            /// Moves control point i in place (the drag path; a closed B-spline's repeated copy
            /// follows); `point` has dim numbers.
            #[wasm_bindgen(js_name = setControlPoint)]
            pub fn set_control_point(
                &mut self,
                i: f64,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] point: JsValue,
            ) -> Result<(), ApiError> {
                $crate::wasm::class::set_control_point(&mut self.inner, i, &point)
            }

            /// Sets weight i (> 0) in place.
            #[wasm_bindgen(js_name = setWeight)]
            pub fn set_weight(&mut self, i: f64, w: f64) -> Result<(), ApiError> {
                $crate::wasm::class::set_weight(&mut self.inner, i, w)
            }

            /// Curvature at the parameter: signed in 2D (positive turning left), ≥ 0 in 3D; Infinity
            /// at a cusp.
            pub fn curvature(&self, $t: f64) -> Result<f64, ApiError> {
                Ok(with_curve!(&self.inner, c => c.curvature($t))?)
            }

            /// A copy of this curve (a new wasm object; free it too).
            #[wasm_bindgen(js_name = clone)]
            pub fn clone_curve(&self) -> $ty {
                $ty::wrap(self.inner.clone())
            }
        }

        impl $ty {
            fn wrap(inner: Curve) -> Self {
                $ty {
                    inner,
                    view: Vec::new(),
                }
            }

            /// Wraps a core 2D curve.
            pub(crate) fn from_2d(c: $core<DVec2>) -> Self {
                $ty::wrap(Curve::D2(c))
            }

            /// Wraps a core 3D curve.
            pub(crate) fn from_3d(c: $core<DVec3>) -> Self {
                $ty::wrap(Curve::D3(c))
            }

            /// The 2D curve, or an error naming the operation.
            pub(crate) fn curve_2d(&self, operation: &'static str) -> Result<&$core<DVec2>, Error> {
                match &self.inner {
                    Curve::D2(c) => Ok(c),
                    Curve::D3(_) => Err(Error::Needs2D { operation, dim: 3 }),
                }
            }
        }
    };
}

/// A curve of either dimension behind a JS class: what the method bodies shared by
/// `BezierCurve` and `BSplineCurve` need (sampling and the in-place edits of a drag).
pub(crate) trait ClassCurve {
    /// 2 or 3.
    fn dim(&self) -> usize;
    /// The points at `params`, flat, into `out` (`params.len() · dim` numbers).
    fn sample_into(&self, params: &[f64], out: &mut [f64]) -> Result<(), Error>;
    /// `count` points at equally spaced parameters over the domain, flat, into `out`.
    fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<(), Error>;
    /// Moves control point i to the point with coordinates `coords` (dim numbers), in place.
    fn set_control_point(&mut self, i: usize, coords: &[f64]) -> Result<(), Error>;
    /// Sets weight i (> 0) in place.
    fn set_weight(&mut self, i: usize, w: f64) -> Result<(), Error>;
}

/// `setControlPoint(i, point)`: the drag path, in place.
pub(crate) fn set_control_point(
    curve: &mut impl ClassCurve,
    i: f64,
    point: &JsValue,
) -> Result<(), ApiError> {
    let point = super::numbers("point", point)?;
    curve.set_control_point(super::whole("i", i)?, &point)?;
    Ok(())
}

/// `setWeight(i, w)`, in place.
pub(crate) fn set_weight(curve: &mut impl ClassCurve, i: f64, w: f64) -> Result<(), ApiError> {
    curve.set_weight(super::whole("i", i)?, w)?;
    Ok(())
}

/// `sample(params)`: a new array of `params.length · dim` numbers.
pub(crate) fn sample(curve: &impl ClassCurve, params: &[f64]) -> Result<Vec<f64>, ApiError> {
    let len = crate::geom::result_len("sample-params-result", &[params.len(), curve.dim()])?;
    let mut out = vec![0.0; len];
    curve.sample_into(params, &mut out)?;
    Ok(out)
}

/// `sampleUniform(count)`: a new array of `count · dim` numbers.
pub(crate) fn sample_uniform(curve: &impl ClassCurve, count: usize) -> Result<Vec<f64>, ApiError> {
    check_count(count)?;
    let len = crate::geom::result_len("sample-uniform-result", &[count, curve.dim()])?;
    let mut out = vec![0.0; len];
    curve.sample_uniform_into(count, &mut out)?;
    Ok(out)
}

/// `sampleView(params)`: `sample(params)` written into `buffer` (the curve's own) and returned
/// as a view of it (see [`super::memory_view`]). On an error the buffer keeps its allocation.
pub(crate) fn sample_view(
    curve: &impl ClassCurve,
    buffer: &mut Vec<f64>,
    params: &[f64],
) -> Result<Float64Array, ApiError> {
    let len = crate::geom::result_len("sample-view-result", &[params.len(), curve.dim()])?;
    buffer.resize(len, 0.0);
    curve.sample_into(params, buffer)?;
    super::memory_view(buffer)
}

/// `sampleUniformView(count)`: `sampleUniform(count)` into `buffer`, as [`sample_view`].
pub(crate) fn sample_uniform_view(
    curve: &impl ClassCurve,
    buffer: &mut Vec<f64>,
    count: usize,
) -> Result<Float64Array, ApiError> {
    check_count(count)?;
    let len = crate::geom::result_len("sample-uniform-view-result", &[count, curve.dim()])?;
    buffer.resize(len, 0.0);
    curve.sample_uniform_into(count, buffer)?;
    super::memory_view(buffer)
}

/// Rejects a sample count above [`crate::geom::MAX_SAMPLES`].
pub(crate) fn check_count(count: usize) -> Result<(), Error> {
    if count > crate::geom::MAX_SAMPLES {
        return Err(Error::TooLarge {
            what: "count",
            value: count,
            max: crate::geom::MAX_SAMPLES,
        });
    }
    Ok(())
}
