/**
 * `import "splinelab/element"` defines the custom element `<spline-lab>`: one demo of the
 * playground in a course page (attributes: `demo`, the demo's state fields, `view`).
 */
export {};

declare global {
  /** `<spline-lab demo="de-casteljau" points="0,0 2,2 6,4 8,2" t="1/4">`. */
  interface SplineLabElement extends HTMLElement {}
  interface HTMLElementTagNameMap {
    "spline-lab": SplineLabElement;
  }
}
