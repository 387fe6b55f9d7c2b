/**
 * Work done a task at a time. `later(fn)` runs `fn` in a task of its own, after everything
 * queued before it: a page's start becomes several short tasks instead of one long one (Total
 * Blocking Time counts each task's time beyond 50 ms, and input waits for the task it lands
 * in). Between the tasks the browser may paint and handle input. A task's continuation is
 * `scheduler.yield()`'s where the browser has it (it goes ahead of other queued tasks), else a
 * `setTimeout(0)`. An error in one function is reported (as an uncaught one) and the next still
 * runs.
 */

/** Resolves in a later task. */
const nextTask = () =>
  globalThis.scheduler?.yield
    ? globalThis.scheduler.yield()
    : new Promise((resolve) => setTimeout(resolve, 0));

const report = (err) => (globalThis.reportError ? reportError(err) : console.error(err));

/** A new queue: returns `later(fn)`. */
export function taskQueue() {
  let tail = Promise.resolve();
  return (fn) => {
    tail = tail.then(nextTask).then(fn).catch(report);
  };
}

/** Runs `fn` at once: `later` for a mount made in one task. */
export const now = (fn) => fn();
