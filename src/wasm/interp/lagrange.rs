//! `lagrange(points, dim, params)` and the `LagrangeCurve` class.

use super::ParamArg;
use crate::error::Error;
use crate::geom::{check_dim, points_from_flat, Cartesian};
use crate::interp::{check_point_count, LagrangeCurve, ParamChoice};
use crate::wasm::bezier::{flatten_points, point_from};
use crate::wasm::class::check_count;
use crate::wasm::{numbers, whole};
use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;

/// A 2D or 3D Lagrange curve behind the JS class.
#[derive(Clone)]
enum Curve {
    D2(LagrangeCurve<DVec2>),
    D3(LagrangeCurve<DVec3>),
}

macro_rules! with_lagrange {
    ($curve:expr, $c:ident => $body:expr) => {
        match $curve {
            Curve::D2($c) => $body,
            Curve::D3($c) => $body,
        }
    };
}

/// The interpolating polynomial through n + 1 points at strictly increasing parameters,
/// evaluated in barycentric form; `aitken(t)` gives Aitken's triangle.
#[wasm_bindgen(js_name = LagrangeCurve)]
pub struct JsLagrangeCurve {
    inner: Curve,
    /// Where the parameters came from: a spacing is recomputed when a point moves.
    choice: ParamChoice,
}

fn build<C: Cartesian>(
    coords: &[f64],
    params: ParamArg,
) -> Result<(LagrangeCurve<C>, ParamChoice), Error> {
    let points: Vec<C> = points_from_flat(coords)?;
    check_point_count(points.len(), 2, "a Lagrange curve")?;
    let choice = params.choice()?;
    let params = choice.resolve(&points)?;
    Ok((LagrangeCurve::new(points, &params)?, choice))
}

/// Moves point i of `c`: in place for given parameters, by a rebuild (new parameters and
/// weights) when they are a spacing computed from the points. On an error `c` is unchanged.
fn move_point<C: Cartesian>(
    c: &mut LagrangeCurve<C>,
    choice: &ParamChoice,
    i: usize,
    p: C,
) -> Result<(), Error> {
    match choice {
        ParamChoice::Given(_) => c.set_point(i, p),
        ParamChoice::Spacing(_) => {
            let mut moved = c.clone();
            moved.set_point(i, p)?;
            let params = choice.resolve(moved.points())?;
            *c = LagrangeCurve::new(moved.points().to_vec(), &params)?;
            Ok(())
        }
    }
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
) -> Result<JsLagrangeCurve, JsError> {
    let points = &*numbers("points", &points)?;
    let params = ParamArg::read(&params)?;
    let dim = whole("dim", dim)?;
    let (inner, choice) = match check_dim(dim)? {
        2 => {
            let (c, choice) = build(points, params)?;
            (Curve::D2(c), choice)
        }
        _ => {
            let (c, choice) = build(points, params)?;
            (Curve::D3(c), choice)
        }
    };
    Ok(JsLagrangeCurve { inner, choice })
}

#[wasm_bindgen(js_class = LagrangeCurve)]
impl JsLagrangeCurve {
    /// Dimension: 2 or 3.
    #[wasm_bindgen(getter)]
    pub fn dim(&self) -> usize {
        match self.inner {
            Curve::D2(_) => 2,
            Curve::D3(_) => 3,
        }
    }

    /// The degree bound n (number of points − 1).
    #[wasm_bindgen(getter)]
    pub fn degree(&self) -> usize {
        with_lagrange!(&self.inner, c => c.degree())
    }

    /// The domain `[t_0, t_n]`.
    pub fn domain(&self) -> Vec<f64> {
        let (a, b) = with_lagrange!(&self.inner, c => c.domain());
        vec![a, b]
    }

    /// The parameters `t_0 … t_n`.
    pub fn params(&self) -> Vec<f64> {
        with_lagrange!(&self.inner, c => c.params().to_vec())
    }

    /// The data points, flat.
    pub fn points(&self) -> Vec<f64> {
        with_lagrange!(&self.inner, c => flatten_points(c.points()))
    }

    /// The point at t (dim numbers; exactly `p_i` at `t_i`).
    pub fn evaluate(&self, t: f64) -> Result<Vec<f64>, JsError> {
        Ok(with_lagrange!(&self.inner, c => flatten_points(&[c.evaluate(t)?])))
    }

    /// Points at every t of `ts`, flat (ts.length·dim numbers).
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] ts: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let ts = &*numbers("ts", &ts)?;
        let mut out = vec![0.0; ts.len().saturating_mul(self.dim())];
        with_lagrange!(&self.inner, c => c.sample_into(ts, &mut out))?;
        Ok(out)
    }

    /// `count` points at equally spaced t over the domain, ends included, flat.
    #[wasm_bindgen(js_name = sampleUniform)]
    pub fn sample_uniform(&self, count: f64) -> Result<Vec<f64>, JsError> {
        let count = whole("count", count)?;
        check_count(count)?;
        let mut out = vec![0.0; count * self.dim()];
        with_lagrange!(&self.inner, c => c.sample_uniform_into(count, &mut out))?;
        Ok(out)
    }

    /// Every `L_i(t)`, i = 0..n (n + 1 numbers, summing to 1).
    pub fn basis(&self, t: f64) -> Result<Vec<f64>, JsError> {
        Ok(with_lagrange!(&self.inner, c => c.basis(t))?)
    }

    /// Aitken's triangle at t, flat: level 0 the n + 1 points, then level r = 1..n with the
    /// n + 1 − r points `p_i^r`; (n+1)(n+2)/2 points, the last is P(t).
    pub fn aitken(&self, t: f64) -> Result<Vec<f64>, JsError> {
        Ok(with_lagrange!(&self.inner, c => flatten_points(&c.aitken(t)?)))
    }

    /// Moves data point i in place (the drag path); `point` has dim numbers. Parameters given
    /// as a kind or α are recomputed from the moved points.
    #[wasm_bindgen(js_name = setPoint)]
    pub fn set_point(
        &mut self,
        i: f64,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] point: JsValue,
    ) -> Result<(), JsError> {
        let point = numbers("point", &point)?;
        let i = whole("i", i)?;
        let choice = &self.choice;
        with_lagrange!(&mut self.inner, c => move_point(c, choice, i, point_from(&point)?))?;
        Ok(())
    }
}
