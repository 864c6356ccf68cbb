#!/usr/bin/env bash
# Builds softgl (Release) and runs every example program; the PNGs go to out/ and their paths are printed.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh assimp-testmodels

cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j "$(nproc)"

out="${1:-out}"
mkdir -p "$out"
for example in hello triangle cube wireframe clipped stencil_outline mirror transparency decals \
    textured_cube srgb multisample sample_shading small_formats shadow_map cascaded_shadows post_process environment_map instancing models; do
  "build/release/examples/$example" "$out"
done
