/**
 * Boxes that scroll sideways (a wide table, a formula too long to fit) can be scrolled from the
 * keyboard only when they take focus (WCAG 2.1.1; axe's scrollable-region-focusable). While its
 * content overflows, such a box is a named group in the tab order (role "group", its name,
 * tabindex 0: the arrow keys then scroll it); when everything fits it is a plain box again, so a
 * page of narrow tables gains no tab stops. A group, not a region: a region is a landmark, and
 * two embeds of one demo on a page would give two landmarks of one name (axe landmark-unique).
 *
 *   scrollRegion(wrap, { labelledBy: title.id }, [table]);  // re-checked when either resizes
 *   scrollRegion(panel, { label: t("shell.formula") });     // markScrollable(panel) after changes
 */

/** Scroller per observed node (the scroller itself and the content whose size it follows). */
const watched = new WeakMap();
/** The name each scroller takes while it overflows: { label } or { labelledBy }. */
const names = new WeakMap();
let observer = null;

/** Makes `scroller` a focusable named group while its content overflows, a plain box otherwise. */
export function markScrollable(scroller) {
  const name = names.get(scroller);
  if (!name) return;
  const overflows =
    scroller.scrollWidth > scroller.clientWidth + 1 ||
    scroller.scrollHeight > scroller.clientHeight + 1;
  if (overflows === scroller.hasAttribute("tabindex")) return;
  const attributes = {
    tabindex: "0",
    role: "group",
    "aria-label": name.label,
    "aria-labelledby": name.labelledBy,
  };
  for (const [key, value] of Object.entries(attributes)) {
    if (overflows && value != null) scroller.setAttribute(key, value);
    else scroller.removeAttribute(key);
  }
}

/**
 * Watches `scroller` (and the nodes of `content`, whose size changes with what they show): it
 * becomes a named, focusable group whenever its content overflows. A scroller taken out of the
 * document is no longer watched. `name`: { label } (text) or { labelledBy } (an element's id).
 */
export function scrollRegion(scroller, name, content = []) {
  names.set(scroller, name);
  observer ??= new ResizeObserver((entries) => {
    for (const entry of entries) {
      const box = watched.get(entry.target);
      if (!box) continue;
      if (!box.isConnected) {
        observer.unobserve(entry.target);
        watched.delete(entry.target);
      } else markScrollable(box);
    }
  });
  for (const node of [scroller, ...content]) {
    watched.set(node, scroller);
    observer.observe(node);
  }
  return scroller;
}
