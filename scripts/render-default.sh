#!/usr/bin/env bash
# One command from a fresh Debian 12 checkout to a picture: installs the packages, builds
# Quaternia (Release) and renders the embedded default scene to quaternia.png.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DQUATERNIA_BUILD_TESTS=OFF \
  -DQUATERNIA_BUILD_BENCH=OFF >/dev/null
cmake --build build --target quaternia
./build/quaternia render -o quaternia.png "$@"
