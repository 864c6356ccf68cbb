#!/usr/bin/env bash
# Builds softgl in Release with bench/ and runs it at 1 and 2 threads: softgl against Mesa's llvmpipe.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh libosmesa6-dev libgl1-mesa-dri assimp-testmodels
scripts/configure.sh build/release -DCMAKE_BUILD_TYPE=Release -DSOFTGL_BUILD_BENCH=ON
cmake --build build/release -j "$(nproc)" --target bench
for threads in 1 2; do build/release/bench/bench --threads "$threads" --frames "${BENCH_FRAMES:-5}"; done
