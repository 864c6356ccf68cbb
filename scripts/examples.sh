#!/usr/bin/env bash
# Builds softgl (Release) and the example programs only (not the test suite), runs every example, and prints the
# paths of the PNGs it wrote to out/ (or the folder given as the first argument).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh assimp-testmodels

examples=(hello triangle cube wireframe clipped stencil_outline mirror transparency decals textured_cube compressed_textures srgb
  multisample sample_shading small_formats shadow_map cascaded_shadows post_process environment_map instancing buffer_texture picking deferred particles feedback_particles geometry_stage models tour)

scripts/configure.sh build/release -DCMAKE_BUILD_TYPE=Release
cmake --build build/release -j "$(nproc)" --target "${examples[@]}"

out="${1:-out}"
mkdir -p "$out"
for example in "${examples[@]}"; do
  "build/release/examples/$example" "$out"
done
