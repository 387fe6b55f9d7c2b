# splinelab — build, serve and test. Every target installs what it lacks and is safe to re-run.
#   make serve        build the wasm package and serve www/ on http://127.0.0.1:$(PORT)
#   make dist         build, then write the static site dist/site/ for any static host (README "Deploy")
#   make serve-dist   make dist, then serve dist/site/ as a host would (precompressed, cached)
#   make test         native + doc tests, wasm-bindgen-test suites in Node, browser tests
#   make test-native  the fast loop: core tests and doctests only
#   make lint         rustfmt check, clippy with warnings denied, and lint-js
#   make lint-js      Biome (biome.json): the JS formatting and lint check, writes nothing
#   make format       Biome formats the JS and applies its safe fixes (writes)
#   make screenshots  a PNG of every demo (DPR 1 and 2) into screenshots/
#   make package      build, then write the npm package dist/splinelab-<version>.tgz (npm pack)
#   make bench        dist, then time splinelab against the peers and a JS baseline, and Lighthouse the site (BENCH_ARGS=--quick)
#   make fuzz         build, then 1 000 000 seeded random calls of the whole JS API in Node (FUZZ_ARGS)
SHELL := /bin/bash
PORT ?= 8000
TOOLS := $(CURDIR)/.tools
WASM_TARGET := wasm32-unknown-unknown
# The wasm-bindgen CLI must match the library version locked in Cargo.lock exactly.
WB_VERSION := $(shell awk '/^name = "wasm-bindgen"$$/ {getline; gsub(/version = |"/, ""); print; exit}' Cargo.lock)
WB_STAMP := $(TOOLS)/wasm-bindgen-$(WB_VERSION).stamp
WASM_OUT := target/$(WASM_TARGET)/release/splinelab.wasm
PKG := www/pkg
BIOME := node_modules/.bin/biome
# The JS Biome looks at (biome.json's files.includes narrows them: not www/pkg, www/vendor).
JS_DIRS := www tests/e2e tests/fuzz tests/package tests/i18n scripts bench

.PHONY: all build package dist serve serve-dist test test-native test-wasm test-e2e lint lint-js format screenshots bench fuzz clean tools rust-target npm-deps chromium

all: build

rust-target:
	@rustup target list --installed | grep -q '^$(WASM_TARGET)$$' || rustup target add $(WASM_TARGET)

$(WB_STAMP):
	@echo "installing wasm-bindgen-cli $(WB_VERSION) into .tools (once)"
	@# opt-level 1: installs in 2 min 33 s instead of 3 min 4 s on 2 cores; the test runner then
	@# takes ~2 s longer over the wasm suites (--debug would make it 5x slower).
	CARGO_PROFILE_RELEASE_OPT_LEVEL=1 cargo install --root $(TOOLS) wasm-bindgen-cli --version $(WB_VERSION)
	@rm -f $(TOOLS)/wasm-bindgen-*.stamp && touch $@

node_modules/.stamp: package.json
	npm ci --no-audit --no-fund
	@touch $@

npm-deps: node_modules/.stamp

chromium:
	@test -x /usr/bin/chromium || { echo "installing Debian's chromium"; \
	  (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium) >/dev/null; }

tools: rust-target $(WB_STAMP) npm-deps

build: tools
	cargo build --release --lib --target $(WASM_TARGET)
	@# Built beside www/ and swapped in at the end, so a page loading meanwhile sees whole files.
	rm -rf target/pkg-next
	$(TOOLS)/bin/wasm-bindgen --target web --out-dir target/pkg-next --out-name splinelab $(WASM_OUT)
	@# The …Into per-call methods and the freed-object checks (see the script's header).
	node scripts/glue.mjs target/pkg-next
	node_modules/.bin/wasm-opt -O target/pkg-next/splinelab_bg.wasm -o target/pkg-next/splinelab_bg.wasm
	rm -rf $(PKG) && mv target/pkg-next $(PKG)
	node scripts/vendor.mjs

package: build
	node scripts/package.mjs

serve: build
	node scripts/serve.mjs --port $(PORT)

# The posters (scripts/posters.mjs, headless Chromium), then bundled and minified JS (esbuild),
# content-hashed names under assets/, .gz and .br beside every text file and the wasm; see
# scripts/dist.mjs.
dist: build chromium
	node scripts/dist.mjs

serve-dist: dist
	node scripts/serve.mjs --port $(PORT) --root dist/site

test: tools chromium
	bash scripts/test-all.sh

test-native:
	cargo test --lib --tests
	cargo test --doc

test-wasm: tools
	cargo test --target $(WASM_TARGET) --lib --tests

test-e2e: build chromium
	node tests/e2e/run.mjs

lint: lint-js rust-target
	cargo fmt --check
	cargo clippy --all-targets -- -D warnings
	cargo clippy --lib --target $(WASM_TARGET) -- -D warnings

lint-js: npm-deps
	$(BIOME) check --error-on-warnings $(JS_DIRS)

format: npm-deps
	$(BIOME) check --write $(JS_DIRS)

screenshots: build chromium
	node scripts/screenshots.mjs

# Prints the tables and writes bench/results/latest.json and frames.json (row (l), every demo's
# frame cost in Chromium) and lighthouse.json (issue 26's page-load goals on dist/site/); see
# bench/README.md. No timing asserts.
bench: dist chromium
	node bench/bench.mjs $(BENCH_ARGS)
	node bench/frames.mjs $(BENCH_ARGS)
	node bench/lighthouse.mjs $(BENCH_ARGS)

# Every call returns or throws a plain Error; exits 1 with the seed and a reproduction otherwise.
# See tests/fuzz/run.mjs for the options (--calls, --seed, --slow-ms, --trace-from).
fuzz: build
	node tests/fuzz/run.mjs --calls 1000000 --freed-soak 100000 $(FUZZ_ARGS)

clean:
	cargo clean
	rm -rf $(PKG) www/vendor www/posters screenshots dist/site
