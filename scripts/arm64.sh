#!/usr/bin/env bash
# softgl for 64-bit ARM from an x86-64 Debian 12 machine: installs the cross compiler, qemu and the :arm64 libraries
# when missing (as root), cross-builds (Release, cmake/aarch64-linux-gnu.cmake) into build/arm64, and runs the whole
# ctest suite there under qemu-aarch64-static. Arguments go to ctest (for example -R image).
#
# scripts/arm64.sh --tsan instead builds the test suite with ThreadSanitizer (build/arm64-tsan) and runs the
# threading tests under qemu; scripts/arm64.sh --sanitize builds it with AddressSanitizer and
# UndefinedBehaviorSanitizer (build/arm64-sanitize, Debug) and runs the test program's cases under qemu (leak checks
# off: LeakSanitizer does not run emulated; the softgl-render command's tests are left to the other builds). The sanitizers re-execute a program whose address layout is randomized, which an
# emulated program cannot do: the tests run with randomization off (setarch -R), and the sanitizer runtimes are
# linked statically (Debian's cross runtimes lie outside the arm64 library path).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh assimp-testmodels g++-aarch64-linux-gnu qemu-user-static libassimp-dev:arm64 \
  libjpeg62-turbo-dev:arm64 libwebp-dev:arm64 libstb-dev:arm64 zlib1g-dev:arm64
jobs=$(nproc)
if [ "${1:-}" = "--tsan" ]; then
  shift
  scripts/configure.sh build/arm64-tsan -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTGL_TSAN=ON -DSOFTGL_INSTALL=OFF -DCMAKE_EXE_LINKER_FLAGS=-static-libtsan
  # (The build lists the test cases by running the program: under setarch too.)
  setarch "$(uname -m)" -R cmake --build build/arm64-tsan -j "$jobs" --target softgl_tests
  TSAN_OPTIONS=halt_on_error=1 setarch "$(uname -m)" -R \
    ctest --test-dir build/arm64-tsan -R threads --output-on-failure "$@"
  exit
fi
if [ "${1:-}" = "--sanitize" ]; then
  shift
  scripts/configure.sh build/arm64-sanitize -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Debug \
    -DSOFTGL_SANITIZE=ON -DSOFTGL_INSTALL=OFF "-DCMAKE_EXE_LINKER_FLAGS=-static-libasan -static-libubsan"
  setarch "$(uname -m)" -R cmake --build build/arm64-sanitize -j "$jobs" --target softgl_tests
  ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    setarch "$(uname -m)" -R ctest --test-dir build/arm64-sanitize --output-on-failure -j "$jobs" \
    -E '^(cli_|docs_render_help)' "$@"
  exit
fi
scripts/configure.sh build/arm64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Release
cmake --build build/arm64 -j "$jobs"
ctest --test-dir build/arm64 --output-on-failure -j "$jobs" "$@"
