//! The errors of joining Bézier pieces and of composite curves ([`super::Error::Join`]).

use std::fmt;

/// What can go wrong when pieces are joined or a composite curve is built: the variants of
/// [`super::Error::Join`].
#[derive(Debug, Clone, PartialEq)]
// In the wasm build the fields become a thrown Error's `params` (camelCase), as `Error`'s do.
#[cfg_attr(
    all(target_arch = "wasm32", target_os = "unknown"),
    derive(serde::Serialize),
    serde(untagged, rename_all_fields = "camelCase")
)]
pub enum JoinError {
    /// Joining rules are for polynomial pieces: `join(&rational, &right, JoinRule::C1, true)`.
    RationalJoin {},
    /// Pieces of too low degree for a joining rule: `join(&line, &line, JoinRule::C2, true)`.
    JoinDegree {
        /// The rule.
        #[cfg_attr(
            all(target_arch = "wasm32", target_os = "unknown"),
            serde(serialize_with = "crate::error::serialize::debug")
        )]
        rule: crate::bezier::JoinRule,
        /// Degree `n` of the left piece.
        left: usize,
        /// Degree `m` of the right piece.
        right: usize,
        /// The degree each piece needs (= points of the right piece the rule fixes).
        needed: usize,
    },
    /// G1 needs a tangent at the joint: `join(&left, &right, JoinRule::G1, true)` where the left
    /// piece's last two points coincide.
    NoJointTangent {},
    /// A composite curve with a wrong number of breakpoints:
    /// `CompositeCurve::new(two_pieces, &[0.0, 1.0])`.
    BreakpointCount {
        /// Number of pieces (the breakpoints needed are one more).
        pieces: usize,
        /// Number of breakpoints given.
        got: usize,
    },
    /// Piece degrees that do not add up to the control points given:
    /// `compositeBezier([0, 0, 1, 1], [3], …)` from JavaScript.
    PiecePointCount {
        /// The degree of each piece.
        degrees: Vec<usize>,
        /// Control points the degrees need, `Σ (n_i + 1)`.
        needed: usize,
        /// Control points given.
        got: usize,
    },
}

impl JoinError {
    /// The variant's stable kebab-case code ([`super::Error::code`]).
    pub fn code(&self) -> &'static str {
        match self {
            JoinError::RationalJoin { .. } => "rational-join",
            JoinError::JoinDegree { .. } => "join-degree",
            JoinError::NoJointTangent { .. } => "no-joint-tangent",
            JoinError::BreakpointCount { .. } => "breakpoint-count",
            JoinError::PiecePointCount { .. } => "piece-point-count",
        }
    }
}

impl fmt::Display for JoinError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            JoinError::RationalJoin {} => f.write_str(
                "the joining rules are for polynomial Bézier pieces; these have weights",
            ),
            JoinError::JoinDegree {
                rule,
                left,
                right,
                needed,
            } => write!(
                f,
                "rule {rule:?} fixes {needed} point(s) of the right piece; degrees {left} and {right} are too low (each piece needs degree >= {needed})"
            ),
            JoinError::NoJointTangent {} => f.write_str(
                "G1 needs a tangent at the joint, but the left piece's last two points coincide",
            ),
            JoinError::BreakpointCount { pieces, got } => write!(
                f,
                "{pieces} pieces need {} breakpoints, got {got}",
                pieces + 1
            ),
            JoinError::PiecePointCount {
                degrees,
                needed,
                got,
            } => write!(
                f,
                "degrees {degrees:?} need {needed} control points in all (n + 1 per piece), got {got}"
            ),
        }
    }
}
