#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages), configures and builds ncc into ./build.
# Usage: utils/bootstrap.sh [ninja targets...]   (default: everything)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake ninja-build g++ ccache python3 llvm-19-dev llvm-19-tools
          libboost-program-options-dev libfmt-dev libgtest-dev libtomlplusplus-dev
          libpolyclipping-dev)
utils/install-missing.sh "${packages[@]}"

if [ ! -f build/build.ninja ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
ninja -C build -j2 "$@"
