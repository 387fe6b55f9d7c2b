/**
 * A knot vector U = [u₀, …, u_m] as text: the values in order, repeated knots repeated (their
 * multiplicity is how often a value occurs), each as `knotText` writes it ("0, 0, 0, 1, 1.5,
 * 2"); and a readout (panel.js) that says it in a sentence and carries the list on
 * `data-knots` ("0,0,0,1,1.5,2") for tests and scripts.
 */
import { readout } from "./panel.js";
import { knotText } from "./knot-ruler.js";

/** "0, 0, 0, 1, 2" (any iterable of knots; `separator` between them). */
export function knotListText(values, separator = ", ") {
  return Array.from(values, knotText).join(separator);
}

/**
 * A readout `name` with `text(state, data)`; `knots(state, data)` → the vector on `data-knots`
 * (null: empty).
 */
export function knotVectorReadout(name, text, knots) {
  return readout(name, text, {
    data: (s, d) => {
      const values = knots(s, d);
      return { knots: values ? knotListText(values, ",") : "" };
    },
  });
}
