// Checks of a TikZ export (www/lib/tikz.js) that need no TeX: the document's shape, balanced
// braces and brackets, every colour defined before use, finite numbers; and, when pdflatex is
// installed, a real compile into a one-page PDF.
import { spawnSync } from "node:child_process";
import { existsSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

/** Problems found in `tex` without TeX (empty when none), and its path and node counts. */
export function inspectTikz(tex) {
  const problems = [];
  for (const part of ["\\documentclass{article}", "\\begin{tikzpicture}", "\\end{document}"]) {
    if (!tex.includes(part)) problems.push(`missing ${part}`);
  }
  // Labels may hold brackets and escaped braces: balance is checked outside their text.
  const body = tex
    .replace(/^%.*$/gm, "")
    .replace(/\\[{}%$&#_]/g, "")
    .replace(/^(\\node\[.*\] at \([^)]*\) )\{.*\};$/gm, "$1{};");
  for (const [open, close] of ["{}", "[]"]) {
    let depth = 0;
    for (const ch of body) {
      if (ch === open) depth++;
      else if (ch === close && --depth < 0) break;
    }
    if (depth !== 0) problems.push(`unbalanced ${open}${close}`);
  }
  if (/NaN|Infinity|undefined/.test(body)) problems.push("a NaN, Infinity or undefined");
  const defined = new Set(
    [...tex.matchAll(/\\definecolor\{(\w+)\}\{HTML\}\{[0-9A-F]{6}\}/g)].map((m) => m[1]),
  );
  for (const m of tex.matchAll(/(?:fill|draw|text)=(\w+)/g)) {
    if (!defined.has(m[1])) problems.push(`colour ${m[1]} used but not defined`);
  }
  return {
    problems,
    paths: (tex.match(/^\\path\[/gm) ?? []).length,
    nodes: (tex.match(/^\\node\[/gm) ?? []).length,
  };
}

const pdflatex = ["/usr/bin/pdflatex", "/usr/local/bin/pdflatex"].find((p) => existsSync(p));

/** Whether `compileTikz` can run here. */
export const hasPdflatex = Boolean(pdflatex);

/**
 * Compiles `tex` with pdflatex (non-stop, in a temporary folder); returns { ok, pages, log }
 * where `log` holds the error lines when it fails.
 */
export function compileTikz(tex) {
  const dir = mkdtempSync(join(tmpdir(), "splinelab-tikz-"));
  try {
    writeFileSync(join(dir, "figure.tex"), tex);
    const run = spawnSync(pdflatex, ["-interaction=nonstopmode", "-halt-on-error", "figure.tex"], {
      cwd: dir,
      encoding: "utf8",
      timeout: 60_000,
    });
    const pdf = join(dir, "figure.pdf");
    const ok = run.status === 0 && existsSync(pdf);
    // pdfTeX's last words: "Output written on figure.pdf (1 page, 12345 bytes)."
    const written = /Output written on figure\.pdf \((\d+) pages?/.exec(run.stdout ?? "");
    const pages = ok && written ? Number(written[1]) : 0;
    const log = (run.stdout ?? "")
      .split("\n")
      .filter((l) => /^!|^l\.\d+/.test(l))
      .join("\n");
    return { ok, pages, log };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}
