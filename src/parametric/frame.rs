//! The Frenet frame and the curvatures at t, from the jets (v = P′, a = P″, j = P‴).
//!
//! 3D: `T = v/|v|`, `B = (v × a)/|v × a|`, `N = B × T`, curvature `κ = |v × a|/|v|³`, torsion
//! `τ = (v × a)·j / |v × a|²`. 2D: `T = v/|v|`, `N` = T turned by +90° (towards the left), the
//! signed curvature `κ = (x′y″ − y′x″)/|v|³` (> 0 turning left; the centre of the osculating
//! circle is `P + N/κ`), `B = (0, 0, 1)` and `τ = 0`. Where the velocity is 0 the frame is NaN;
//! where `v × a = 0` (a straight stretch) κ = 0 and N, B (3D) and τ are NaN.

use super::curve::ParametricCurve;
use crate::error::Result;
use glam::DVec3;

/// The moving frame at one t.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// P(t) (`dim` numbers).
    pub point: Vec<f64>,
    /// Unit tangent T (`dim`).
    pub tangent: Vec<f64>,
    /// Unit principal normal N (`dim`).
    pub normal: Vec<f64>,
    /// Unit binormal B (3 numbers; 2D: (0, 0, 1)).
    pub binormal: Vec<f64>,
    /// κ (signed in 2D).
    pub curvature: f64,
    /// τ (0 in 2D).
    pub torsion: f64,
}

impl ParametricCurve {
    /// The Frenet frame, curvature and torsion at `t` (see the module's comment).
    pub fn frame(&self, t: f64) -> Result<Frame> {
        let i = self.piece_at(t)?;
        let mut d = [DVec3::ZERO; 4];
        self.piece_derivatives(i, t, 3, &mut |k, c, v| {
            if let Some(p) = d.get_mut(k) {
                p[c] = v;
            }
        })?;
        let [p, v, a, j] = d;
        let dim = self.dim;
        let take = |w: DVec3| {
            w.to_array()
                .get(..dim)
                .map(<[f64]>::to_vec)
                .unwrap_or_default()
        };
        let speed = v.length();
        let tangent = v / speed;
        let cross = v.cross(a);
        let frame = if dim == 2 {
            let normal = DVec3::new(-tangent.y, tangent.x, 0.0);
            Frame {
                point: take(p),
                tangent: take(tangent),
                normal: take(normal),
                binormal: vec![0.0, 0.0, 1.0],
                curvature: cross.z / (speed * speed * speed),
                torsion: 0.0,
            }
        } else {
            let c = cross.length();
            let binormal = cross / c;
            let normal = binormal.cross(tangent);
            Frame {
                point: take(p),
                tangent: take(tangent),
                normal: take(normal),
                binormal: binormal.to_array().to_vec(),
                curvature: if c == 0.0 {
                    0.0
                } else {
                    c / (speed * speed * speed)
                },
                torsion: cross.dot(j) / (c * c),
            }
        };
        Ok(frame)
    }
}
