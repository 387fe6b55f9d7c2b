/**
 * Drawing support for an adaptive mesh's parameter side (patch-subdivision): the triangles of
 * `tessellateAdaptive` drawn in the (u, v) square from their `uvs` (the quadtree of the notes'
 * "split until the net is flat"), and the size of its finest cell. Nothing here tessellates or
 * measures the surface: it reads the core's mesh.
 */
import { WIDTH, themed } from "./theme.js";

/** Side of the (u, v) inset in CSS px at scale 1, and its distance from the canvas corner. */
export const PARAMETER_INSET_PX = 150;
const INSET_MARGIN_PX = 14;
/** The inset never takes more than this fraction of the canvas width. */
const INSET_FRACTION = 0.3;

/**
 * The side of the smallest quadtree cell of an adaptive mesh on [0, 1]²: the shortest edge
 * parallel to a parameter axis (every leaf's own sides are such edges; fans only add edges as
 * long as a neighbour's side or longer). 1 for an empty mesh.
 */
export function finestCell({ uvs, indices }) {
  let h = 1;
  for (let t = 0; t + 2 < indices.length; t += 3) {
    for (let e = 0; e < 3; e++) {
      const a = 2 * indices[t + e];
      const b = 2 * indices[t + ((e + 1) % 3)];
      const du = Math.abs(uvs[a] - uvs[b]);
      const dv = Math.abs(uvs[a + 1] - uvs[b + 1]);
      if (du === 0 && dv > 0 && dv < h) h = dv;
      else if (dv === 0 && du > 0 && du < h) h = du;
    }
  }
  return h;
}

const stylesFor = themed((theme) => ({
  frame: Object.freeze({ stroke: theme.text, width: 1, fill: theme.background, alpha: 0.9 }),
  edges: Object.freeze({ stroke: "#1D5A80", width: WIDTH.helper * 0.75, strokeAlpha: 0.8 }),
  axis: Object.freeze({ fill: theme.text, size: 13, halo: theme.background }),
}));

/**
 * The triangles of `mesh` in the unit square (u to the right, v up) in the top-right corner of
 * the canvas, `side` CSS px wide at scale 1, framed, with the axes named `labels.u`, `labels.v`.
 */
export function drawParameterMesh(r, mesh, side, labels) {
  const styles = stylesFor(r.theme);
  const scale = r.scale;
  // At most INSET_FRACTION of the canvas width (a phone keeps room for the figure).
  const size = Math.min(side * scale, INSET_FRACTION * r.width);
  const x0 = r.width - INSET_MARGIN_PX * scale - size;
  const y0 = INSET_MARGIN_PX * scale;
  r.beginPath();
  r.rect(x0, y0, size, size);
  r.paint(styles.frame);
  const { uvs, indices } = mesh;
  const x = (k) => x0 + size * uvs[2 * k];
  const y = (k) => y0 + size * (1 - uvs[2 * k + 1]);
  r.beginPath();
  for (let t = 0; t + 2 < indices.length; t += 3) {
    r.moveTo(x(indices[t]), y(indices[t]));
    r.lineTo(x(indices[t + 1]), y(indices[t + 1]));
    r.lineTo(x(indices[t + 2]), y(indices[t + 2]));
    r.closePath();
  }
  r.paint(styles.edges);
  r.text(labels.u, x0 + size, y0 + size + 3 * scale, styles.axis, "right", "top");
  r.text(labels.v, x0 - 4 * scale, y0, styles.axis, "right", "top");
}
