// Debian's Chromium as the browser tests, screenshots and the browser benchmark start it (see
// shared design.md: launchPersistentContext with these flags; the background-networking flags
// keep it from dialling out on this closed network, SwiftShader gives WebGL2 without a GPU).
export const CHROMIUM = process.env.CHROMIUM ?? "/usr/bin/chromium";
export const CHROMIUM_ARGS = Object.freeze([
  "--headless",
  "--no-sandbox",
  "--disable-gpu",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
  "--disable-quic",
  "--no-first-run",
  "--enable-unsafe-swiftshader",
]);
