//! The point traits that let one implementation of de Casteljau, de Boor and knot insertion
//! serve 2D, 3D and homogeneous (rational) points, and the derivative quantities built on them.

use super::MAX_DERIVATIVE_ORDER;
use glam::{DVec2, DVec3, DVec4};
use std::ops::{Add, Mul, Sub};

/// A point (or vector) in an affine space over `f64`: what the curve algorithms need.
///
/// Implemented for [`DVec2`], [`DVec3`], [`DVec4`] and `f64` (1D, for scalar Bézier functions). Homogeneous points of 2D and 3D curves are
/// `DVec3` and `DVec4` (`(w·x, w·y, w)`, `(w·x, w·y, w·z, w)`).
pub trait Point:
    Copy
    + PartialEq
    + std::fmt::Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<f64, Output = Self>
{
    /// Number of coordinates.
    const DIM: usize;
    /// The zero vector.
    const ZERO: Self;
    /// `(1 - t)·self + t·other`; `t = 0` gives `self`, `t = 1` gives `other` exactly.
    fn lerp_to(self, other: Self, t: f64) -> Self;
    /// Coordinate `i` (`0 <= i < DIM`).
    fn coord(&self, i: usize) -> f64;
    /// Builds a point from the first `DIM` values of `c`.
    fn from_slice(c: &[f64]) -> Self;
    /// Writes the `DIM` coordinates into `out[..DIM]`.
    fn write_to(&self, out: &mut [f64]);
    /// Component-wise minimum.
    fn min_by_coord(self, other: Self) -> Self;
    /// Component-wise maximum.
    fn max_by_coord(self, other: Self) -> Self;
    /// Dot product.
    fn dot_with(self, other: Self) -> f64;
    /// Euclidean length.
    fn norm(self) -> f64 {
        self.dot_with(self).sqrt()
    }
}

/// `min_by_coord` and `max_by_coord` as the type's own `min` and `max` (per coordinate for the
/// glam vectors, plain for `f64`).
macro_rules! min_max_by_coord {
    () => {
        #[inline]
        fn min_by_coord(self, other: Self) -> Self {
            self.min(other)
        }
        #[inline]
        fn max_by_coord(self, other: Self) -> Self {
            self.max(other)
        }
    };
}

macro_rules! impl_point {
    ($t:ty, $dim:expr) => {
        impl Point for $t {
            const DIM: usize = $dim;
            const ZERO: Self = <$t>::ZERO;
            #[inline]
            fn lerp_to(self, other: Self, t: f64) -> Self {
                // Written as (1-t)a + tb rather than a + t(b-a) so both ends are exact.
                self * (1.0 - t) + other * t
            }
            #[inline]
            fn coord(&self, i: usize) -> f64 {
                self.to_array()[i]
            }
            #[inline]
            fn from_slice(c: &[f64]) -> Self {
                <$t>::from_slice(c)
            }
            #[inline]
            fn write_to(&self, out: &mut [f64]) {
                self.write_to_slice(&mut out[..$dim]);
            }
            min_max_by_coord!();
            #[inline]
            fn dot_with(self, other: Self) -> f64 {
                self.dot(other)
            }
        }
    };
}
impl_point!(DVec2, 2);
impl_point!(DVec3, 3);
impl_point!(DVec4, 4);

impl Point for f64 {
    const DIM: usize = 1;
    const ZERO: Self = 0.0;
    #[inline]
    fn lerp_to(self, other: Self, t: f64) -> Self {
        self * (1.0 - t) + other * t
    }
    #[inline]
    fn coord(&self, _i: usize) -> f64 {
        *self
    }
    #[inline]
    fn from_slice(c: &[f64]) -> Self {
        c[0]
    }
    #[inline]
    fn write_to(&self, out: &mut [f64]) {
        out[0] = *self;
    }
    min_max_by_coord!();
    #[inline]
    fn dot_with(self, other: Self) -> f64 {
        self * other
    }
}

/// A Cartesian point type of a curve (2D or 3D) and its homogeneous counterpart.
///
/// A rational curve with weights `w_i` is the projection of the polynomial curve with
/// homogeneous control points `P^w_i = (w_i·P_i, w_i)` (syllabus §4).
pub trait Cartesian: Point {
    /// The homogeneous point type: one more coordinate, the weight last.
    type Homogeneous: Point;
    /// `(w·self, w)`.
    fn to_homogeneous(self, w: f64) -> Self::Homogeneous;
    /// The first `DIM` coordinates of `h`, not divided (the numerator of a rational point).
    fn numerator(h: Self::Homogeneous) -> Self;
    /// The weight (last coordinate) of `h`.
    fn weight_of(h: Self::Homogeneous) -> f64;
    /// Central projection onto `w = 1`: `numerator(h) / weight_of(h)`.
    fn project(h: Self::Homogeneous) -> Self {
        Self::numerator(h) * (1.0 / Self::weight_of(h))
    }
    /// Distance from `self` to the segment `[a, b]`.
    fn distance_to_segment(self, a: Self, b: Self) -> f64 {
        let ab = b - a;
        let len2 = ab.dot_with(ab);
        let u = if len2 > 0.0 {
            ((self - a).dot_with(ab) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (self - (a + ab * u)).norm()
    }
    /// The 2D cross product `a.x·b.y − a.y·b.x` for 2D points, the length of `a × b` for 3D.
    fn cross_norm(a: Self, b: Self) -> f64;
}

/// [`Cartesian`] for the glam vector `$t` with homogeneous type `$h` (the weight in its field
/// `$w`); `|a, b| cross` is `cross_norm`.
macro_rules! impl_cartesian {
    ($t:ty, $h:ty, $w:ident, |$a:ident, $b:ident| $cross:expr) => {
        impl Cartesian for $t {
            type Homogeneous = $h;
            #[inline]
            fn to_homogeneous(self, w: f64) -> $h {
                (self * w).extend(w)
            }
            #[inline]
            fn numerator(h: $h) -> $t {
                h.truncate()
            }
            #[inline]
            fn weight_of(h: $h) -> f64 {
                h.$w
            }
            #[inline]
            fn cross_norm($a: $t, $b: $t) -> f64 {
                $cross
            }
        }
    };
}
impl_cartesian!(DVec2, DVec3, z, |a, b| a.perp_dot(b));
impl_cartesian!(DVec3, DVec4, w, |a, b| a.cross(b).length());

/// The `k`-th derivative of a rational curve from the derivatives `A^(0..=k)` of its homogeneous
/// curve (`k = homogeneous_derivs.len() − 1`), by the quotient rule
/// `C^(k) = (A^(k) − Σ_{i=1..k} C(k,i) w^(i) C^(k−i)) / w` (NURBS Book eq. 4.8), where `A` is
/// split into the numerator and the weight `w`. `homogeneous_derivs` must not be empty; orders
/// above [`MAX_DERIVATIVE_ORDER`] are not computed.
pub fn rational_derivative<C: Cartesian>(homogeneous_derivs: &[C::Homogeneous]) -> C {
    let order = (homogeneous_derivs.len() - 1).min(MAX_DERIVATIVE_ORDER);
    let w0 = C::weight_of(homogeneous_derivs[0]);
    if order == 1 {
        // The common case without the table (whose zeroing costs more than the sum):
        // C' = (A'_num − w' C)/w with C = A_num/w.
        let (a0, a1) = (homogeneous_derivs[0], homogeneous_derivs[1]);
        let c0 = C::numerator(a0) * (1.0 / w0);
        return (C::numerator(a1) - c0 * C::weight_of(a1)) * (1.0 / w0);
    }
    // Lower orders on the stack: dense sampling calls this once per point.
    let mut cs = [C::ZERO; MAX_DERIVATIVE_ORDER + 1];
    for k in 0..=order {
        let mut v = C::numerator(homogeneous_derivs[k]);
        let mut binom = 1.0;
        for i in 1..=k {
            binom = binom * (k + 1 - i) as f64 / i as f64;
            v = v - cs[k - i] * (binom * C::weight_of(homogeneous_derivs[i]));
        }
        cs[k] = v * (1.0 / w0);
    }
    cs[order]
}

/// Curvature from the first two derivatives: in 2D the signed `(x'y'' − y'x'') / |P'|³`
/// (positive turning counter-clockwise), in 3D `|P' × P''| / |P'|³`; `+∞` where `P' = 0`.
pub fn curvature<C: Cartesian>(d1: C, d2: C) -> f64 {
    let speed = d1.norm();
    if speed == 0.0 {
        return f64::INFINITY;
    }
    C::cross_norm(d1, d2) / (speed * speed * speed)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;
    use glam::DVec2;

    #[test]
    fn lerp_is_exact_at_both_ends() {
        let a = DVec2::new(0.1, 0.7);
        let b = DVec2::new(0.3, -2.9);
        assert_eq!(a.lerp_to(b, 0.0), a);
        assert_eq!(a.lerp_to(b, 1.0), b);
    }
}
