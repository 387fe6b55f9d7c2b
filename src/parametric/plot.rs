//! The certified plot: a polyline that never joins two points across a pole, a jump or an
//! undefined gap, and that stays within the tolerance of the curve inside each run.
//!
//! Each piece's interval is cut into [`START_SEGMENTS`] pieces, then refined in passes: every
//! undecided t-interval `[a, b]` is looked at with interval arithmetic on the coordinates'
//! tapes (their values, first and second derivatives over the whole `[a, b]`):
//! - nowhere defined, or (with a box) its enclosure outside the box → left out (the run
//!   breaks);
//! - proven defined and continuous, and the chord within the tolerance — either the
//!   enclosure's diagonal is ≤ tolerance (the curve and the chord both lie in that box), or
//!   proven C² with `(b − a)²/8 · |x″|max ≤ tolerance` (the linear interpolant's error bound,
//!   per coordinate, combined as a vector) → a chord of the run, its ends evaluated on the curve;
//! - otherwise → split in two for the next pass, until the interval is shorter than
//!   [`MIN_RELATIVE_WIDTH`] of its piece (a discontinuity or a non-smooth point lives there:
//!   the run breaks) or the work budget [`MAX_INTERVALS`] is spent (the run breaks, the plot is
//!   marked incomplete).
//!
//! Passes refine every undecided interval once, so the budget is spread evenly across t:
//! `x = t, y = sin(1/t)` ends with a correct plot except close to 0.

use super::curve::ParametricCurve;
use super::eval::Interval;
use crate::error::{check_tolerance, Result};

/// Segments each piece starts from.
const START_SEGMENTS: usize = 16;

/// Interval evaluations one plot may make (each costs a few evaluations of the tapes).
pub const MAX_INTERVALS: usize = 50_000;

/// Intervals shorter than this fraction of their piece are not split again.
const MIN_RELATIVE_WIDTH: f64 = 1.0 / (1u64 << 36) as f64;

/// The vertices of a plot and their parameters.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Plot {
    /// Flat vertices, `dim` numbers each; runs separated by one vertex of NaNs.
    pub points: Vec<f64>,
    /// The t of every vertex (NaN at a separator).
    pub ts: Vec<f64>,
    /// False when the work budget ended refinement before every interval was decided.
    pub complete: bool,
}

#[derive(Clone, Copy, PartialEq)]
enum State {
    /// To split into this many equal parts (≥ 2) in the next pass; 0: not judged yet.
    Undecided(u8),
    Chord,
    Gap,
}

/// Most parts one interval is split into at once.
const MAX_SPLIT: f64 = 32.0;

impl ParametricCurve {
    /// The certified plot of the curve (see the module's comment): within `tolerance` (model
    /// units, > 0) of the curve inside each run, refined only where the curve is visible in
    /// `bbox = [xmin, ymin, xmax, ymax]` (on x and y) when given.
    pub fn plot(&self, tolerance: f64, bbox: Option<[f64; 4]>) -> Result<Plot> {
        check_tolerance(tolerance)?;
        if let Some(b) = bbox {
            for v in b {
                crate::error::check_finite("box", None, v)?;
            }
        }
        let mut plot = Plot {
            complete: true,
            ..Plot::default()
        };
        let mut budget = MAX_INTERVALS;
        let mut out = Writer::new(self.dim);
        for i in 0..self.pieces.len() {
            let segments = self.refine(i, tolerance, bbox, &mut budget, &mut plot.complete);
            out.piece(self, i, &segments);
        }
        (plot.points, plot.ts) = out.finish();
        Ok(plot)
    }

    /// The decided segments of piece `i`, in t order.
    fn refine(
        &self,
        i: usize,
        tolerance: f64,
        bbox: Option<[f64; 4]>,
        budget: &mut usize,
        complete: &mut bool,
    ) -> Vec<(f64, f64, State)> {
        let Some(piece) = self.pieces.get(i) else {
            return Vec::new();
        };
        let (a, b) = (piece.from.value, piece.to.value);
        let min_width = (b - a) * MIN_RELATIVE_WIDTH;
        let mut segments: Vec<(f64, f64, State)> = (0..START_SEGMENTS)
            .map(|k| {
                let lo = a + (b - a) * k as f64 / START_SEGMENTS as f64;
                let hi = if k + 1 == START_SEGMENTS {
                    b
                } else {
                    a + (b - a) * (k + 1) as f64 / START_SEGMENTS as f64
                };
                (lo, hi, State::Undecided(0))
            })
            .collect();
        let mut enclosure = [Interval::point(0.0); 3];
        loop {
            let mut undecided = false;
            for s in segments.iter_mut().filter(|s| s.2 == State::Undecided(0)) {
                if *budget == 0 {
                    s.2 = State::Gap;
                    *complete = false;
                    continue;
                }
                *budget -= 1;
                s.2 = self.judge(i, s.0, s.1, tolerance, bbox, &mut enclosure);
                if let State::Undecided(_) = s.2 {
                    if s.1 - s.0 <= min_width {
                        s.2 = State::Gap;
                    } else {
                        undecided = true;
                    }
                }
            }
            if !undecided {
                return segments;
            }
            let mut next = Vec::with_capacity(segments.len() * 2);
            for s in segments {
                match s.2 {
                    State::Undecided(parts) => {
                        let parts = usize::from(parts.max(2));
                        for k in 0..parts {
                            let lo = s.0 + (s.1 - s.0) * k as f64 / parts as f64;
                            let hi = if k + 1 == parts {
                                s.1
                            } else {
                                s.0 + (s.1 - s.0) * (k + 1) as f64 / parts as f64
                            };
                            next.push((lo, hi, State::Undecided(0)));
                        }
                    }
                    _ => next.push(s),
                }
            }
            segments = next;
        }
    }

    /// What `[lo, hi]` of piece `i` is: a chord, a gap, or undecided (to split: in two, or
    /// where the second-derivative bound is finite into the `k` parts that bound says may
    /// suffice, `k = ⌈√(bound/tolerance)⌉ ≤ 32`, which skips the levels bisection would
    /// reject on the way).
    fn judge(
        &self,
        i: usize,
        lo: f64,
        hi: f64,
        tolerance: f64,
        bbox: Option<[f64; 4]>,
        jet: &mut [Interval; 3],
    ) -> State {
        let Some(piece) = self.pieces.get(i) else {
            return State::Gap;
        };
        let mut continuous = true;
        let mut smooth = true;
        let mut diagonal2 = 0.0f64;
        let mut second2 = 0.0f64;
        let mut outside = false;
        for (c, coord) in piece.coords.iter().enumerate() {
            let flags = coord.interval_jet(lo, hi, 2, &self.values, jet);
            if flags.nowhere {
                return State::Gap;
            }
            continuous &= flags.continuous;
            smooth &= flags.smooth;
            let [value, _, second] = *jet;
            if let Some(b) = bbox {
                if c < 2 && (value.hi < b[c] - tolerance || value.lo > b[c + 2] + tolerance) {
                    outside = true;
                }
            }
            let w = value.hi - value.lo;
            diagonal2 += w * w;
            let m = second.mag();
            second2 += m * m;
        }
        if outside {
            return State::Gap;
        }
        if !continuous {
            return State::Undecided(2);
        }
        let h = hi - lo;
        let bound = h * h / 8.0 * second2.sqrt();
        if diagonal2.sqrt() <= tolerance || (smooth && bound <= tolerance) {
            State::Chord
        } else if smooth && bound.is_finite() {
            State::Undecided((bound / tolerance).sqrt().ceil().clamp(2.0, MAX_SPLIT) as u8)
        } else {
            State::Undecided(2)
        }
    }
}

/// Builds the flat output: runs of chord ends, NaN separators, no duplicate vertices.
struct Writer {
    dim: usize,
    points: Vec<f64>,
    ts: Vec<f64>,
    /// The last vertex written belongs to an open run.
    open: bool,
    scratch: Vec<f64>,
}

impl Writer {
    fn new(dim: usize) -> Self {
        Writer {
            dim,
            points: Vec::new(),
            ts: Vec::new(),
            open: false,
            scratch: vec![0.0; dim],
        }
    }

    fn vertex(&mut self, curve: &ParametricCurve, piece: usize, t: f64) {
        if let Some(p) = curve.pieces.get(piece) {
            for (o, c) in self.scratch.iter_mut().zip(&p.coords) {
                *o = c.value(t, &curve.values);
            }
        }
        if self.scratch.iter().all(|v| v.is_finite()) {
            self.points.extend_from_slice(&self.scratch);
            self.ts.push(t);
            self.open = true;
        } else {
            self.close();
        }
    }

    fn close(&mut self) {
        if self.open {
            self.points.extend(std::iter::repeat_n(f64::NAN, self.dim));
            self.ts.push(f64::NAN);
            self.open = false;
        }
    }

    /// Piece `i`'s segments. Its first vertex continues the previous piece's run when the two
    /// pieces meet there (same point within rounding), else a new run starts.
    fn piece(&mut self, curve: &ParametricCurve, i: usize, segments: &[(f64, f64, State)]) {
        let mut previous_end: Option<f64> = None;
        for &(a, b, state) in segments {
            if state != State::Chord {
                self.close();
                previous_end = None;
                continue;
            }
            if previous_end != Some(a) {
                if self.open && previous_end.is_none() && self.continues(curve, i, a) {
                    // The previous piece's last vertex is this piece's start: keep the run.
                } else {
                    self.close();
                    self.vertex(curve, i, a);
                }
            }
            self.end_vertex(curve, i, b);
            previous_end = Some(b);
        }
    }

    /// The vertex at a chord's end `b`. At a joint (piece `i`'s end, another piece after it)
    /// the curve's value is the next piece's: written when the pieces meet there, else piece
    /// `i`'s point at the f64 just below the joint (on the curve, and the run ends).
    fn end_vertex(&mut self, curve: &ParametricCurve, i: usize, b: f64) {
        let at_joint =
            i + 1 < curve.pieces.len() && curve.pieces.get(i).is_some_and(|p| p.to.value == b);
        if !at_joint {
            self.vertex(curve, i, b);
            return;
        }
        let mut left = vec![0.0; self.dim];
        if let Some(p) = curve.pieces.get(i) {
            for (o, c) in left.iter_mut().zip(&p.coords) {
                *o = c.value(b, &curve.values);
            }
        }
        if self.same_point(curve, i + 1, b, &left) {
            self.vertex(curve, i + 1, b);
        } else {
            self.vertex(curve, i, b.next_down());
        }
    }

    /// Whether piece `i`'s point at `t` equals `point` to within rounding.
    fn same_point(&mut self, curve: &ParametricCurve, i: usize, t: f64, point: &[f64]) -> bool {
        if let Some(p) = curve.pieces.get(i) {
            for (o, c) in self.scratch.iter_mut().zip(&p.coords) {
                *o = c.value(t, &curve.values);
            }
        }
        let scale = point.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        point
            .iter()
            .zip(&self.scratch)
            .all(|(a, b)| a.is_finite() && (a - b).abs() <= 1e-12 * scale)
    }

    /// Whether the open run ends at piece `i`'s point at `t` (a joint where the pieces meet):
    /// the last vertex written equals it to within rounding.
    fn continues(&mut self, curve: &ParametricCurve, i: usize, t: f64) -> bool {
        let n = self.points.len();
        if n < self.dim || self.ts.last() != Some(&t) {
            return false;
        }
        let last = self.points.get(n - self.dim..).unwrap_or_default().to_vec();
        self.same_point(curve, i, t, &last)
    }

    fn finish(mut self) -> (Vec<f64>, Vec<f64>) {
        // No trailing separator.
        if !self.open && self.ts.last().is_some_and(|t| t.is_nan()) {
            self.points.truncate(self.points.len() - self.dim);
            self.ts.pop();
        }
        (self.points, self.ts)
    }
}
