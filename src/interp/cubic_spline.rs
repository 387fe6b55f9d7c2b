//! The piecewise cubic Hermite spline [`CubicSpline`]: data points, parameters and tangents,
//! and the recipe its tangents came from, so a moved point re-solves in place.
//!
//! Piece i on `[t_i, t_{i+1}]` is the cubic Hermite interpolant of `p_i, p_{i+1}` with tangents
//! `m_i, m_{i+1}` (`C'(t_i) = m_i` with respect to the global parameter): C1 whatever the
//! tangents, C2 when they solve the spline system ([`super::end_conditions`]).

use super::end_conditions::{spline_system, EndCondition};
use super::params::{check_point_count, ParamChoice};
use super::tangents::{bessel_tangents, cardinal_tangents, catmull_rom_tangents};
use super::tridiagonal::Tridiagonal;
use crate::bspline::Parameterization;
use crate::error::InterpError;
use crate::error::{check_coordinate, check_coordinate_of, check_finite, Error, Result};
use crate::geom::check::check_point_edit;
use crate::geom::{Cartesian, Point};
use glam::DVec3;

/// What the system of [`CubicSpline::system`] is called in [`Error::SingularSystem`].
const SYSTEM_NAME: &str = "cubic-spline-system";

/// How a [`CubicSpline`]'s tangents are found from its points and parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TangentRule<C> {
    /// Given tangents (`hermiteSpline`); moving a point keeps them.
    Given,
    /// Cardinal tangents with tension c ([`cardinal_tangents`]).
    Cardinal {
        /// The tension c (0: Catmull–Rom on these parameters).
        tension: f64,
    },
    /// Barry–Goldman tangents ([`catmull_rom_tangents`]); closed curves wrap.
    CatmullRom,
    /// Bessel tangents ([`bessel_tangents`]).
    Bessel,
    /// The C2 spline with an end condition ([`spline_system`]).
    Spline(EndCondition<C>),
}

impl<C> TangentRule<C> {
    /// The JS constructor that builds a spline with this rule ("cubicSpline", …).
    pub fn constructor(&self) -> &'static str {
        match self {
            TangentRule::Given => "hermiteSpline",
            TangentRule::Cardinal { .. } => "cardinalSpline",
            TangentRule::CatmullRom => "catmullRom",
            TangentRule::Bessel => "besselSpline",
            TangentRule::Spline(_) => "cubicSpline",
        }
    }
}

/// A piecewise cubic Hermite curve through `p_0..p_n` at `t_0 < … < t_n` with tangents
/// `m_0..m_n` (w.r.t. the global parameter). A closed one (periodic spline, closed
/// Catmull–Rom) has `p_n = p_0` and `m_n = m_0`.
#[derive(Debug, Clone, PartialEq)]
pub struct CubicSpline<C: Cartesian> {
    pub(crate) points: Vec<C>,
    pub(crate) params: Vec<f64>,
    pub(crate) tangents: Vec<C>,
    rule: TangentRule<C>,
    choice: ParamChoice,
    closed: bool,
    system: Option<Tridiagonal<C>>,
}

/// Tangents (and the solved system, for a C2 spline) by `rule` for the points at `params`.
fn tangents_by<C: Cartesian>(
    rule: &TangentRule<C>,
    points: &[C],
    params: &[f64],
    closed: bool,
    given: &[C],
) -> Result<(Vec<C>, Option<Tridiagonal<C>>)> {
    let local = |rule: LocalRule| {
        let lifted: Vec<DVec3> = points.iter().map(lift).collect();
        let m = local_tangents(rule, &lifted, params, closed);
        m.iter()
            .map(|v| C::from_slice(&v.to_array()[..C::DIM]))
            .collect()
    };
    Ok(match rule {
        TangentRule::Given => (given.to_vec(), None),
        TangentRule::Cardinal { tension } => (local(LocalRule::Cardinal(*tension)), None),
        TangentRule::CatmullRom => (local(LocalRule::CatmullRom), None),
        TangentRule::Bessel => (local(LocalRule::Bessel), None),
        TangentRule::Spline(end) => {
            let system = spline_system(points, params, end);
            let mut m = system.solve(SYSTEM_NAME)?;
            if let EndCondition::Periodic = end {
                m.push(m[0]);
            }
            (m, Some(system))
        }
    })
}

/// The rules whose tangent `m_i` depends only on nearby points (no system to solve).
#[derive(Clone, Copy)]
enum LocalRule {
    Cardinal(f64),
    CatmullRom,
    Bessel,
}

/// A point as a 3D one (z = 0 for a 2D point).
fn lift<C: Cartesian>(p: &C) -> DVec3 {
    let z = if C::DIM > 2 { p.coord(2) } else { 0.0 };
    DVec3::new(p.coord(0), p.coord(1), z)
}

/// The tangents of a local rule, computed in 3D for both dimensions (each coordinate on its
/// own, so a 2D spline's in the plane z = 0 are its own): one copy of the code. Not the drag
/// path of a C2 spline, whose system stays in the spline's dimension.
#[inline(never)]
fn local_tangents(rule: LocalRule, points: &[DVec3], params: &[f64], closed: bool) -> Vec<DVec3> {
    match rule {
        LocalRule::Cardinal(tension) => cardinal_tangents(points, params, tension),
        LocalRule::CatmullRom => catmull_rom_tangents(points, params, closed),
        LocalRule::Bessel => bessel_tangents(points, params),
    }
}

/// The data of a spline before its tangents: points, resolved parameters and their source.
struct Data<C> {
    points: Vec<C>,
    params: Vec<f64>,
    choice: ParamChoice,
}

/// The checks every constructor starts with, in order: at least `min` points, every coordinate
/// finite and at most [`crate::geom::MAX_COORDINATE`] in magnitude ([`Error::NotFinite`],
/// [`Error::CoordinateTooLarge`]), then the parameters (given ones checked, or a spacing
/// computed).
#[inline(never)]
fn data<C: Cartesian>(
    points: Vec<C>,
    choice: ParamChoice,
    min: usize,
    what: &'static str,
) -> Result<Data<C>> {
    check_point_count(points.len(), min, what)?;
    super::global::check_points(&points)?;
    let params = choice.resolve(&points)?;
    Ok(Data {
        points,
        params,
        choice,
    })
}

impl<C: Cartesian> CubicSpline<C> {
    /// Finds the tangents by `rule` (`given` for [`TangentRule::Given`]) and builds the spline.
    #[inline(never)]
    fn build(data: Data<C>, rule: TangentRule<C>, closed: bool, given: Vec<C>) -> Result<Self> {
        let Data {
            points,
            params,
            choice,
        } = data;
        let (tangents, system) = tangents_by(&rule, &points, &params, closed, &given)?;
        Ok(CubicSpline {
            points,
            params,
            tangents,
            rule,
            choice,
            closed,
            system,
        })
    }

    /// The C2 cubic spline through `points` at `params` with the end condition `end`
    /// (syllabus §5; `cubicSpline` in JS).
    ///
    /// # Errors
    /// [`Error::TooFewDataPoints`] below `end.min_points()` (2; 3 for periodic), the parameter
    /// errors of [`ParamChoice::resolve`], [`Error::NotFinite`] for a clamped tangent,
    /// [`InterpError::NotClosed`] for periodic with `p_n ≠ p_0`, [`Error::SingularSystem`].
    ///
    /// ```
    /// use splinelab::interp::{CubicSpline, EndCondition};
    /// use splinelab::{prelude::*, DVec2};
    /// // Natural: 2m_0 + m_1 = 3s_0, m_0 + 4m_1 + m_2 = 3(s_0 + s_1), m_1 + 2m_2 = 3s_1.
    /// let p = vec![DVec2::new(0.0, 0.0), DVec2::new(1.0, 1.0), DVec2::new(2.0, 0.0)];
    /// let c = CubicSpline::interpolate(p, vec![0.0, 1.0, 2.0], EndCondition::Natural).unwrap();
    /// assert_eq!(c.evaluate(1.0).unwrap(), DVec2::new(1.0, 1.0));
    /// assert!((c.tangents()[0] - DVec2::new(1.0, 1.5)).length() < 1e-15);
    /// assert!(c.derivative(0.0, 2).unwrap().length() < 1e-15);
    /// ```
    pub fn interpolate(
        points: Vec<C>,
        params: impl Into<ParamChoice>,
        end: EndCondition<C>,
    ) -> Result<Self> {
        let data = data(points, params.into(), end.min_points(), "cubic-spline")?;
        if let EndCondition::Clamped { start, end } = end {
            check_vector("startTangent", start)?;
            check_vector("endTangent", end)?;
        }
        let n = data.points.len() - 1;
        let closed = matches!(end, EndCondition::Periodic);
        if closed && data.points[n] != data.points[0] {
            return Err(Error::Interp(InterpError::NotClosed { last: n }));
        }
        Self::build(data, TangentRule::Spline(end), closed, Vec::new())
    }

    /// The C1 piecewise Hermite curve with the given tangents `m_i = C'(t_i)` (`hermiteSpline`).
    ///
    /// # Errors
    /// [`Error::TooFewDataPoints`] below 2, the parameter errors, [`Error::ArgumentLength`]
    /// (`tangents`, counted in numbers) for other than one tangent per point,
    /// [`Error::NotFinite`] for a tangent coordinate.
    pub fn hermite(
        points: Vec<C>,
        params: impl Into<ParamChoice>,
        tangents: Vec<C>,
    ) -> Result<Self> {
        let data = data(points, params.into(), 2, "hermite-spline")?;
        if tangents.len() != data.points.len() {
            return Err(Error::ArgumentLength {
                name: "tangents",
                expected: data.points.len() * C::DIM,
                got: tangents.len() * C::DIM,
            });
        }
        for (i, m) in tangents.iter().enumerate() {
            for k in 0..C::DIM {
                check_coordinate("tangents", Some(i * C::DIM + k), m.coord(k))?;
            }
        }
        Self::build(data, TangentRule::Given, false, tangents)
    }

    /// The cardinal spline with tension c (`cardinalSpline`; see [`cardinal_tangents`]).
    ///
    /// # Errors
    /// [`Error::TooFewDataPoints`] below 2, the parameter errors, [`Error::NotFinite`] for c.
    pub fn cardinal(points: Vec<C>, params: impl Into<ParamChoice>, tension: f64) -> Result<Self> {
        let data = data(points, params.into(), 2, "cardinal-spline")?;
        check_finite("tension", None, tension)?;
        Self::build(data, TangentRule::Cardinal { tension }, false, Vec::new())
    }

    /// The Catmull–Rom spline with parameters `Σ |Δp|^α` (0 uniform, 0.5 centripetal, 1 chord)
    /// and Barry–Goldman tangents (`catmullRom`). `closed`: the points are a cycle; the spline
    /// stores them with the first repeated at the end, so it has `count + 1` points and `count`
    /// pieces, and returns to the start with the same tangent (a cycle given with its first
    /// point already repeated at the end, more than 3 points, is taken as that cycle).
    ///
    /// # Errors
    /// [`Error::TooFewDataPoints`] below 2 (3 when closed), [`InterpError::AlphaOutOfRange`],
    /// [`Error::CoincidentPoints`] for α > 0 and a repeated consecutive point (a closed curve
    /// also compares the last with the first).
    pub fn catmull_rom(mut points: Vec<C>, alpha: f64, closed: bool) -> Result<Self> {
        let min = if closed { 3 } else { 2 };
        check_point_count(points.len(), min, "catmull-rom-spline")?;
        let kind = Parameterization::from_alpha(alpha)?;
        if closed {
            if points.len() > min && points.first() == points.last() {
                // The cycle given with its first point repeated: the repeat closes it.
                points.pop();
            }
            points.push(points[0]);
        }
        let data = data(
            points,
            ParamChoice::Spacing(kind),
            min,
            "catmull-rom-spline",
        )?;
        Self::build(data, TangentRule::CatmullRom, closed, Vec::new())
    }

    /// The spline with Bessel tangents (`besselSpline`; see [`bessel_tangents`]).
    ///
    /// # Errors
    /// [`Error::TooFewDataPoints`] below 2, the parameter errors.
    pub fn bessel(points: Vec<C>, params: impl Into<ParamChoice>) -> Result<Self> {
        let data = data(points, params.into(), 2, "bessel-spline")?;
        Self::build(data, TangentRule::Bessel, false, Vec::new())
    }

    /// The data points `p_0..p_n` (a closed spline repeats the first at the end).
    pub fn points(&self) -> &[C] {
        &self.points
    }

    /// The parameters `t_0 < … < t_n`.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// The tangents `m_i = C'(t_i)` with respect to the global parameter.
    pub fn tangents(&self) -> &[C] {
        &self.tangents
    }

    /// How the tangents were found.
    pub fn rule(&self) -> &TangentRule<C> {
        &self.rule
    }

    /// Whether the spline is closed (`p_n = p_0`, `m_n = m_0`).
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// Number of pieces n.
    pub fn piece_count(&self) -> usize {
        self.points.len() - 1
    }

    /// The domain `[t_0, t_n]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.params[0], self.params[self.params.len() - 1])
    }

    /// The tridiagonal (or cyclic) system whose solution is the tangents, for a C2 spline
    /// (`None` for other rules). Row i is the equation of `m_i`.
    pub fn system(&self) -> Option<&Tridiagonal<C>> {
        self.system.as_ref()
    }

    /// Moves data point i to `p` and recomputes what depends on it — the parameters when they
    /// were computed from the points, the tangents by the spline's rule — in place: the drag
    /// path, O(n). On a closed spline point 0 and point n are one point: moving either moves
    /// both. On an error the spline is unchanged.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`], [`Error::CoincidentPoints`] when the
    /// parameters are a spacing with α > 0, [`Error::SingularSystem`].
    pub fn set_point(&mut self, i: usize, p: C) -> Result<()> {
        check_point_edit(i, self.points.len(), p)?;
        let n = self.points.len() - 1;
        let mut points = self.points.clone();
        points[i] = p;
        if self.closed && (i == 0 || i == n) {
            points[0] = p;
            points[n] = p;
        }
        let params = match &self.choice {
            ParamChoice::Given(_) => self.params.clone(),
            ParamChoice::Spacing(_) => self.choice.resolve(&points)?,
        };
        let (tangents, system) =
            tangents_by(&self.rule, &points, &params, self.closed, &self.tangents)?;
        self.points = points;
        self.params = params;
        self.tangents = tangents;
        self.system = system;
        Ok(())
    }

    /// Sets tangent i (`C'(t_i)`) of a spline with given tangents (`hermiteSpline`), in place.
    ///
    /// # Errors
    /// [`InterpError::SplineKind`] for a spline whose tangents are computed,
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`].
    pub fn set_tangent(&mut self, i: usize, m: C) -> Result<()> {
        if self.rule != TangentRule::Given {
            return Err(Error::Interp(InterpError::SplineKind {
                operation: "setTangent",
                needs: "hermiteSpline",
                got: self.rule.constructor(),
            }));
        }
        check_point_edit(i, self.tangents.len(), m)?;
        self.tangents[i] = m;
        Ok(())
    }
}

/// Checks every coordinate of a vector argument is finite ("startTangent 1 is NaN").
#[inline(never)]
fn check_vector<P: Point>(name: &'static str, v: P) -> Result<()> {
    for k in 0..P::DIM {
        check_coordinate_of(name, k, v.coord(k))?;
    }
    Ok(())
}
