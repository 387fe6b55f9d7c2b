/**
 * Paths of a 3D figure's 2D layer beside draw3d.js: the control net of a flat xyz array (what a
 * surface's `controlPoints()` returns) and a segment between two space points.
 */

const a = new Float64Array(3);

/**
 * The control net of a rows × cols grid of points in a flat xyz array (what `controlPoints()`
 * returns, row-major): every row, then every column, as one path (draw3d's `netPath` takes
 * `[x, y, z]` lists).
 */
export function flatNetPath(r, view, flat, rows, cols) {
  r.beginPath();
  const to = (k, first) => {
    view.project(flat[3 * k], flat[3 * k + 1], flat[3 * k + 2], a);
    if (first) r.moveTo(a[0], a[1]);
    else r.lineTo(a[0], a[1]);
  };
  for (let i = 0; i < rows; i++) for (let j = 0; j < cols; j++) to(i * cols + j, j === 0);
  for (let j = 0; j < cols; j++) for (let i = 0; i < rows; i++) to(i * cols + j, i === 0);
}

/** The segment between two space points, as a new path. */
export function segmentPath3(r, view, x0, y0, z0, x1, y1, z1) {
  r.beginPath();
  view.project(x0, y0, z0, a);
  r.moveTo(a[0], a[1]);
  view.project(x1, y1, z1, a);
  r.lineTo(a[0], a[1]);
}
