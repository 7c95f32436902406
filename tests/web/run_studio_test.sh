#!/bin/sh
# tests/web/run_studio_test.sh — runs the studio's real-browser test (studio.test.mjs) under
# `node --test`, or skips it (exit 77, ctest's SKIP_RETURN_CODE) when what it needs is missing:
# node (20 or newer, for playwright-core), /usr/bin/chromium, the built bundle web/dist, or
# web/node_modules/playwright-core (`npm ci` in web/, which `make build` runs).
# Usage: run_studio_test.sh TESSERA_BINARY SOURCE_DIR BUILD_DIR [TEST_FILE]
tessera=$1
source_dir=$2
build_dir=$3
test_file=${4:-$source_dir/tests/web/studio.test.mjs}
skip() { echo "studio_browser: skipped: $*"; exit 77; }
command -v node >/dev/null 2>&1 || skip "node is not installed (scripts/install-deps installs it)"
major=$(node -p 'process.versions.node.split(".")[0]' 2>/dev/null || echo 0)
[ "$major" -ge 20 ] || skip "node $(node --version) is older than 20 (playwright-core needs 20)"
[ -x /usr/bin/chromium ] || skip "/usr/bin/chromium is not installed (scripts/install-deps installs it)"
[ -f "$source_dir/web/dist/app.js" ] || skip "the front end was not built (web/dist/app.js; make build builds it)"
[ -d "$source_dir/web/node_modules/playwright-core" ] || skip "web/node_modules/playwright-core is missing (npm ci in web/)"
[ -x "$tessera" ] || { echo "studio_browser: $tessera is not executable"; exit 1; }
export TESSERA_BIN="$tessera" TESSERA_SOURCE_DIR="$source_dir" TESSERA_BUILD_DIR="$build_dir"
exec node --test --test-reporter=spec "$test_file"
