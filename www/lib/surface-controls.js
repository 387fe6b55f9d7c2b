/**
 * Controls and scene data the surface demos (section 6) share: the "Show" group of checkboxes,
 * the Shading choice (lit, zebra, Gaussian, mean; shading3d.js `SHADINGS`) and the core's
 * curvatures a curvature shading colours the mesh by. Labels are strings.js keys under the
 * demo's prefix: `<prefix>.control.show`, `<prefix>.control.<field>`, `<prefix>.control.shading`,
 * `<prefix>.shading.<value>`.
 */
import { checkbox, choice, group } from "./panel.js";
import { SHADINGS } from "./shading3d.js";

/** The "Show" group: one checkbox per boolean field, in order, labelled `<prefix>.control.<field>`. */
export const showGroup = (prefix, fields) =>
  group(
    `${prefix}.control.show`,
    ...fields.map((name) => checkbox(name, { label: `${prefix}.control.${name}` })),
  );

/** The Shading group: a choice bound to the field `shading`, one option per shading. */
export const shadingChoice = (prefix) =>
  group(
    `${prefix}.control.shading`,
    choice("shading", {
      options: SHADINGS.map((value) => ({ value, label: `${prefix}.shading.${value}` })),
    }),
  );

/** Whether a shading colours the mesh by curvature (and so needs the core's curvatures). */
export const isCurvatureShading = (shading) => shading === "gaussian" || shading === "mean";

/**
 * `[K0, H0, K1, H1, …]` at the mesh's vertices from the core (`surface.curvatures(mesh.uvs)`),
 * only while a curvature shading shows them (else null): a `compute` cell's value, so the scene
 * refills its colours only when the surface or the shading changes.
 */
export const shadingCurvatures = (surface, mesh, shading) =>
  isCurvatureShading(shading) ? surface.curvatures(mesh.uvs) : null;
