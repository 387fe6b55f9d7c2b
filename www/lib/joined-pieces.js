/**
 * Two Bézier pieces joined at a point, in wasm, kept to a continuity rule by the core: the left
 * piece P on its interval [a, b] and the right piece Q on [b, c] (a state's `left` and `right`
 * [x, y] point lists). The rule (C0: Q₀ = P_n; C1: n(P_n − P_{n−1}) = m(Q₁ − Q₀); G1: Q₁ − Q₀ =
 * λ(P_n − P_{n−1}), λ > 0; C2: C1 and the second differences too) is the core's `joinBezier`
 * (`follow`): the piece named `adjust` is replaced by the one it returns (the other copy is
 * freed at once) and its points are written into the state. `error` keeps the core's message
 * when it could not (G1 with P_{n−1} = P_n: no tangent to follow), for the demo to show.
 */
import { flatten } from "./geometry.js";
import { errorText } from "./core-errors.js";

export class JoinedPieces {
  /** `intervals`: `{ left: [a, b], right: [b, c] }`; throws what the core throws (nothing leaks). */
  constructor(sl, state, intervals) {
    this.sl = sl;
    this.left = sl.BezierCurve.withInterval(
      flatten(state.left),
      2,
      intervals.left[0],
      intervals.left[1],
    );
    try {
      this.right = sl.BezierCurve.withInterval(
        flatten(state.right),
        2,
        intervals.right[0],
        intervals.right[1],
      );
    } catch (err) {
      this.left.free();
      throw err;
    }
    this.error = null;
  }

  /** Re-establishes `state.rule` by moving the piece `adjust` ("left" or "right"); may throw. */
  follow(state, adjust) {
    const [l, r] = this.sl.joinBezier(this.left, this.right, state.rule, adjust);
    const keep = adjust === "right" ? r : l;
    (adjust === "right" ? l : r).free();
    this[adjust].free();
    this[adjust] = keep;
    const flat = keep.controlPoints();
    const points = state[adjust];
    for (let i = 0; i < points.length; i++) {
      points[i][0] = flat[2 * i];
      points[i][1] = flat[2 * i + 1];
    }
  }

  /** `follow`, keeping the core's message in `error` instead of throwing. */
  tryFollow(state, adjust) {
    try {
      this.follow(state, adjust);
    } catch (err) {
      this.error = errorText(err);
    }
  }

  free() {
    this.left.free();
    this.right.free();
  }
}
