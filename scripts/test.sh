#!/usr/bin/env bash
# One command from a fresh Debian 12 checkout to every test: installs the packages, builds and
# runs the GoogleTest suite in Release, then again under AddressSanitizer and
# UndefinedBehaviorSanitizer. Also builds the benchmarks, so that they cannot rot. The Release
# tests include the explorer in headless chromium (tests/browser).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
jobs=$(nproc)
# playwright-core for the browser test, exactly as locked; it never downloads a browser (the
# test runs Debian's chromium). It is not a Debian package: where npm's registry cannot be
# reached, the browser test is left out (CMakeLists.txt says so) and every other test runs.
if [ ! -d tests/browser/node_modules/playwright-core ]; then
  if ! (cd tests/browser && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --silent --no-audit --no-fund); then
    echo "scripts/test.sh: could not install playwright-core with npm; the browser test is left out" >&2
  fi
fi

echo "== Release build and tests"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DQUATERNIA_BUILD_TESTS=ON \
  -DQUATERNIA_BUILD_BENCH=ON >/dev/null
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DQUATERNIA_SANITIZE=ON -DQUATERNIA_BUILD_TESTS=ON -DQUATERNIA_BUILD_BENCH=OFF >/dev/null
cmake --build build-sanitize -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
