#!/usr/bin/env bash
# Installs the Debian 12 packages Quaternia needs to build, test and benchmark. Idempotent and
# quiet: it does nothing (and prints nothing) when everything is already installed.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libpng-dev zlib1g-dev libtomlplusplus-dev libcli11-dev libhwy-dev
  libgtest-dev libbenchmark-dev
  nlohmann-json3-dev
  libopenexr-dev openexr
  ffmpeg
  admesh
  openmpi-bin libopenmpi-dev
  libcpp-httplib-dev
  python3 chromium chromium-driver python3-selenium
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib
  clang-14 libclang-rt-14-dev
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing Debian packages: ${missing[*]}" >&2
as_root=()
if [ "$(id -u)" -ne 0 ]; then as_root=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq >/dev/null
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
