#!/usr/bin/env bash
# Runs every suite (native core + doctests, wasm in Node, browser), keeps going after a
# failure, and ends with one line "N passed, N failed" summed over all suites.
set -uo pipefail
cd "$(dirname "$0")/.."
logs=target/test-logs
mkdir -p "$logs"
status=0
run() { # name, command...
  local name=$1; shift
  echo "==> $name: $*"
  "$@" 2>&1 | tee "$logs/$name.log"
  local rc=${PIPESTATUS[0]}
  [ "$rc" -eq 0 ] || { echo "!! $name exited with $rc"; status=1; }
}
run native cargo test --lib --tests
run doc cargo test --doc
run wasm cargo test --target wasm32-unknown-unknown --lib --tests
run build make --no-print-directory build
run memory node --expose-gc tests/e2e/memory.mjs
run fuzz node tests/fuzz/run.mjs --calls 30000 --seed 1 --budgets warn
run e2e node tests/e2e/run.mjs
run package node tests/package/check.mjs
run i18n node tests/i18n/check.mjs
run i18n-errors node tests/i18n/core-errors.mjs
run numbers node tests/i18n/numbers.mjs
# cargo/wasm-bindgen-test: "test result: ok. 12 passed; 0 failed"; the others end with a line
# "<suite>: 5 passed, 0 failed" (the API fuzz, make fuzz shortened: "fuzz: 1 passed, 0 failed")
read -r passed failed < <(cat "$logs"/{native,doc,wasm,memory,fuzz,e2e,package,i18n,i18n-errors,numbers}.log 2>/dev/null | awk '
  /test result:/ { for (i = 1; i <= NF; i++) { if ($(i+1) ~ /^passed/) p += $i; if ($(i+1) ~ /^failed/) f += $i } }
  /^(e2e|memory|fuzz|package|i18n|numbers): [0-9]+ passed, [0-9]+ failed$/ { p += $2; f += $4 }
  END { print p + 0, f + 0 }')
[ "$failed" -eq 0 ] || status=1
[ "$passed" -gt 0 ] || { echo "!! no test ran"; status=1; }
echo "$passed passed, $failed failed"
exit $status
