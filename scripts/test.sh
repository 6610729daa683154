#!/usr/bin/env bash
# One command from a fresh Debian 12 checkout to every test: installs the packages, builds and
# runs the GoogleTest suite in Release, then again under AddressSanitizer and
# UndefinedBehaviorSanitizer, then builds the libFuzzer targets with clang-14 and runs their short
# runs and regression inputs (scripts/fuzz.sh). Also builds the benchmarks, so that they cannot
# rot. The Release tests include the explorer in headless chromium (tests/browser).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
jobs=$(nproc)
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

echo "== Fuzz targets (libFuzzer, clang-14, ASan + UBSan): seed corpora, short fixed runs, regressions"
bash scripts/fuzz.sh
