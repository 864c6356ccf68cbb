#!/usr/bin/env bash
# softgl for 64-bit ARM from an x86-64 Debian 12 machine: installs the cross compiler, qemu and the :arm64 libraries
# when missing (as root), cross-builds (Release, cmake/aarch64-linux-gnu.cmake) into build/arm64, and runs the whole
# ctest suite there under qemu-aarch64-static. Arguments go to ctest (for example -R image).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh assimp-testmodels g++-aarch64-linux-gnu qemu-user-static libassimp-dev:arm64 \
  libjpeg62-turbo-dev:arm64 libwebp-dev:arm64 libstb-dev:arm64 zlib1g-dev:arm64
jobs=$(nproc)
cmake -S . -B build/arm64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Release
cmake --build build/arm64 -j "$jobs"
ctest --test-dir build/arm64 --output-on-failure -j "$jobs" "$@"
