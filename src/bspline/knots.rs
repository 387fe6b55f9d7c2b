//! Validated knot vectors, span search and multiplicity (syllabus §3).

use crate::error::{check_finite, check_in_range, Error, Result};

/// A non-decreasing knot vector `u_0..u_m` (`m = n + p + 1`) for degree `p` and `n + 1` control
/// points, whose domain `[u_p, u_{n+1}]` is not empty and where no value repeats more than
/// `p + 1` times.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotVector {
    knots: Vec<f64>,
    degree: usize,
    /// The span [`KnotVector::span_hinted`] found last (not part of the value).
    hint: SpanHint,
}

/// The span of the last one-point query, so that the next one, usually at a nearby parameter,
/// starts there: O(1) instead of a binary search when a caller walks along the curve point by
/// point. A cache only: equal for every two knot vectors, reset by a clone's first miss.
#[derive(Debug, Clone, Default)]
struct SpanHint(std::cell::Cell<usize>);

impl PartialEq for SpanHint {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl KnotVector {
    /// Validates `knots` for `point_count` control points of degree `degree`.
    ///
    /// # Errors
    /// In this order: [`Error::KnotCount`] for a count other than `n + p + 2`,
    /// [`Error::NotFinite`], [`Error::KnotOrder`] for a decreasing pair, [`Error::EmptyDomain`],
    /// [`Error::KnotMultiplicity`] above `p + 1`; each message carries the numbers.
    pub fn new(knots: Vec<f64>, degree: usize, point_count: usize) -> Result<Self> {
        let expected = point_count + degree + 1;
        if knots.len() != expected {
            return Err(Error::KnotCount {
                expected,
                got: knots.len(),
                points: point_count,
                degree,
            });
        }
        for (i, &u) in knots.iter().enumerate() {
            check_finite("knot", Some(i), u)?;
        }
        if let Some(i) = (1..knots.len()).find(|&i| knots[i] < knots[i - 1]) {
            return Err(Error::KnotOrder {
                index: i,
                value: knots[i],
                previous: knots[i - 1],
            });
        }
        let (a, b) = (knots[degree], knots[point_count]);
        if a >= b {
            return Err(Error::EmptyDomain {
                a,
                b,
                degree,
                points: point_count,
            });
        }
        let mut i = 0;
        while i < knots.len() {
            let mut j = i;
            while j + 1 < knots.len() && knots[j + 1] == knots[i] {
                j += 1;
            }
            let r = j - i + 1;
            if r > degree + 1 {
                return Err(Error::KnotMultiplicity {
                    knot: knots[i],
                    multiplicity: r,
                    first: i,
                    last: j,
                    degree,
                });
            }
            i = j + 1;
        }
        Ok(KnotVector {
            knots,
            degree,
            hint: SpanHint::default(),
        })
    }

    /// The knot values.
    pub fn as_slice(&self) -> &[f64] {
        &self.knots
    }

    /// The degree `p` this vector was validated for.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Number of control points `n + 1` it serves.
    pub fn point_count(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// The domain `[u_p, u_{n+1}]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.point_count()])
    }

    /// Checks `u` lies in the domain (naming the range otherwise).
    pub fn check_parameter(&self, u: f64) -> Result<f64> {
        self.check_named("u", u)
    }

    /// As [`KnotVector::check_parameter`], the parameter called `name` in the error (`"v"` for a
    /// surface's second direction).
    pub fn check_named(&self, name: &'static str, u: f64) -> Result<f64> {
        check_in_range(name, u, self.domain())
    }

    /// The span index `k` with `u_k <= u < u_{k+1}` and `p <= k <= n`; at the end of the domain
    /// the last non-empty span (it is closed on the right). `u` must lie in the domain.
    /// Binary search, O(log n).
    pub fn span(&self, u: f64) -> usize {
        let (p, n) = (self.degree, self.point_count() - 1);
        if u >= self.knots[n + 1] {
            return self.last_span();
        }
        // Largest k in [p, n] with u_k <= u.
        let slice = &self.knots[p..=n];
        p + slice.partition_point(|&k| k <= u) - 1
    }

    /// As [`KnotVector::span`], starting from `hint` (the previous span when walking forward
    /// through sorted parameters: O(1) amortised).
    #[inline]
    pub fn span_from(&self, u: f64, hint: usize) -> usize {
        let (p, n) = (self.degree, self.point_count() - 1);
        let k = hint.clamp(p, n);
        if self.knots[k] <= u
            && (u < self.knots[k + 1] || (k == self.last_span() && u <= self.knots[k + 1]))
        {
            return k;
        }
        if k < n && self.knots[k + 1] <= u && u < self.knots[k + 2] {
            return k + 1;
        }
        self.span(u)
    }

    /// As [`KnotVector::span`], starting from the span the previous call found (see
    /// [`SpanHint`]): the per-point `evaluate`/`derivative` path. The same span as `span(u)`.
    #[inline]
    pub fn span_hinted(&self, u: f64) -> usize {
        let k = self.span_from(u, self.hint.0.get());
        self.hint.0.set(k);
        k
    }

    /// The last span with `u_k < u_{k+1}` (`k <= n`): the one that owns the domain's end.
    pub fn last_span(&self) -> usize {
        let n = self.point_count() - 1;
        (self.degree..=n)
            .rev()
            .find(|&k| self.knots[k] < self.knots[k + 1])
            .unwrap_or(n)
    }

    /// How many knots equal `u` (two binary searches: the knots are sorted).
    pub fn multiplicity(&self, u: f64) -> usize {
        let first = self.knots.partition_point(|&k| k < u);
        let end = self.knots.partition_point(|&k| k <= u);
        end - first
    }

    /// The non-empty spans of the domain, in order: indices `k` in `p..=n` with `u_k < u_{k+1}`.
    pub fn spans(&self) -> impl Iterator<Item = usize> + '_ {
        (self.degree..self.point_count()).filter(|&k| self.knots[k] < self.knots[k + 1])
    }

    /// The distinct knot values strictly inside the domain, each with its multiplicity.
    pub fn interior_breaks(&self) -> Vec<(f64, usize)> {
        let (a, b) = self.domain();
        let mut out: Vec<(f64, usize)> = Vec::new();
        for &u in self.knots.iter().filter(|&&u| u > a && u < b) {
            match out.last_mut() {
                Some((v, r)) if *v == u => *r += 1,
                _ => out.push((u, 1)),
            }
        }
        out
    }

    /// The knots to insert, sorted, so that every distinct knot of the domain `[u_p, u_{n+1}]`
    /// (its ends included) reaches multiplicity `p`: Bézier extraction as one refinement
    /// (NURBS Book §5.4), each value `u` listed `p − s` times where it has multiplicity `s < p`.
    pub(crate) fn extraction_knots(&self) -> Vec<f64> {
        let (a, b) = self.domain();
        let p = self.degree;
        let mut out = Vec::new();
        for run in self.knots.chunk_by(|x, y| x == y) {
            let u = run[0];
            if (a..=b).contains(&u) && run.len() < p {
                out.extend(std::iter::repeat_n(u, p - run.len()));
            }
        }
        out
    }

    /// The knot vector with `u` inserted `times` times (after the equal ones).
    pub(crate) fn with_inserted(&self, u: f64, times: usize) -> Vec<f64> {
        let at = self.knots.partition_point(|&k| k <= u);
        let mut out = Vec::with_capacity(self.knots.len() + times);
        out.extend_from_slice(&self.knots[..at]);
        out.extend(std::iter::repeat_n(u, times));
        out.extend_from_slice(&self.knots[at..]);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    fn example() -> KnotVector {
        KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0], 2, 6).unwrap()
    }

    #[test]
    fn span_search_at_edges() {
        let k = example();
        assert_eq!(k.domain(), (0.0, 4.0));
        assert_eq!(k.span(0.0), 2);
        assert_eq!(k.span(0.999), 2);
        assert_eq!(
            k.span(1.0),
            3,
            "right-continuous: a knot belongs to the span it starts"
        );
        assert_eq!(k.span(3.5), 5);
        assert_eq!(k.span(4.0), 5, "the last span is closed");
        for (u, hint) in [(0.0, 0), (1.0, 2), (2.5, 3), (4.0, 5), (0.5, 5)] {
            assert_eq!(k.span_from(u, hint), k.span(u), "u = {u}, hint {hint}");
        }
        assert_eq!(k.spans().collect::<Vec<_>>(), vec![2, 3, 4, 5]);
        assert_eq!(k.interior_breaks(), vec![(1.0, 1), (2.0, 1), (3.0, 1)]);
    }

    #[test]
    fn break_of_multiplicity_p_plus_one_is_right_continuous() {
        let k = KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0], 2, 6).unwrap();
        assert_eq!(k.span(1.0), 5);
        assert_eq!(k.span(0.5), 2);
        assert_eq!(k.spans().collect::<Vec<_>>(), vec![2, 5]);
    }

    #[test]
    fn validation_messages_carry_the_numbers() {
        let e = KnotVector::new(vec![0.0; 8], 2, 6).unwrap_err().to_string();
        assert_eq!(
            e,
            "knot vector must have n+p+2 = 5 + 2 + 2 = 9 values, got 8"
        );
        let e = KnotVector::new(vec![0.0, 0.0, 0.0, 2.0, 1.0, 3.0, 4.0, 4.0, 4.0], 2, 6)
            .unwrap_err()
            .to_string();
        assert!(e.contains("u_4 = 1 comes after u_3 = 2"), "{e}");
        let e = KnotVector::new(vec![0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0], 2, 6)
            .unwrap_err()
            .to_string();
        assert!(e.contains("knot 1 appears 4 times"), "{e}");
        let e = KnotVector::new(vec![1.0; 9], 2, 6).unwrap_err().to_string();
        assert!(e.contains("is empty"), "{e}");
        let e = KnotVector::new(vec![0.0, 0.0, 0.0, f64::NAN, 2.0, 3.0, 4.0, 4.0, 4.0], 2, 6)
            .unwrap_err()
            .to_string();
        assert!(e.contains("knot 3 is NaN"), "{e}");
    }
}
