#!/usr/bin/env bash
# Builds and runs the whole test suite with ctest, twice: a Release build, then a Debug build under
# AddressSanitizer + UndefinedBehaviorSanitizer, then the threading test under ThreadSanitizer, then each fuzz
# target for a fixed time. Warnings are errors throughout.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh libosmesa6-dev libgl1-mesa-dri assimp-testmodels

jobs=$(nproc)

echo "== Release build and tests"
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DSOFTGL_WERROR=ON
cmake --build build/release -j "$jobs"
ctest --test-dir build/release --output-on-failure -j "$jobs"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S . -B build/sanitize -DCMAKE_BUILD_TYPE=Debug -DSOFTGL_SANITIZE=ON -DSOFTGL_WERROR=ON
cmake --build build/sanitize -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/sanitize --output-on-failure -j "$jobs"

echo "== ThreadSanitizer: several contexts rendering on several threads at once"
cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTGL_TSAN=ON -DSOFTGL_WERROR=ON -DSOFTGL_INSTALL=OFF
cmake --build build/tsan -j "$jobs" --target softgl_tests
TSAN_OPTIONS=halt_on_error=1 ctest --test-dir build/tsan -R threads --output-on-failure
