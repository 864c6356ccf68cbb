#!/usr/bin/env bash
# The whole test suite, in stages: a Release build and its ctest (GCC), the same with Clang, one Clang build under
# AddressSanitizer + UndefinedBehaviorSanitizer that is also instrumented for libFuzzer, its ctest, then the
# libFuzzer targets of that build, each for a fixed number of inputs from its seed corpus with a fixed seed (the
# same commit gives the same result), the threading tests under ThreadSanitizer, and an arm64 cross-build whose
# ctest runs under qemu-aarch64-static. Warnings are errors throughout.
#
# Every stage runs, even after one has failed; each prints its name as it starts and, when it fails, the cause (the
# failing tests, the compiler's errors, or the fuzz artifact and its stack). Each stage's whole output is kept in
# build/logs/<stage>.log. The last lines are one summary line per stage; the exit status is 1 if any failed.
#
# SOFTGL_FUZZ_SCALE=N multiplies the number of fuzz inputs (default 1). For long, coverage-guided campaigns see
# scripts/fuzz.sh.
set -uo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh libosmesa6-dev libgl1-mesa-dri assimp-testmodels clang libclang-rt-14-dev \
  pybind11-dev python3-dev python3-numpy python3-pytest \
  g++-aarch64-linux-gnu qemu-user-static libassimp-dev:arm64 libjpeg62-turbo-dev:arm64 libwebp-dev:arm64 \
  libstb-dev:arm64 zlib1g-dev:arm64 || exit 1

jobs=$(nproc)
logs=build/logs
rm -rf "$logs" && mkdir -p "$logs"
summary=()
failed=0

# stage NAME COMMAND...: runs the command with its output on the terminal and in build/logs/NAME.log.
stage() {
  local name=$1
  shift
  local start=$SECONDS
  echo
  echo "== stage: $name"
  "$@" 2>&1 | tee "$logs/$name.log"
  finish "$name" "${PIPESTATUS[0]}" $((SECONDS - start))
}

# fuzz_lanes "TARGET RUNS TARGET RUNS ..." ...: each argument is a lane of fuzz stages (see fuzz below) run one after
# another, the lanes side by side (each on one core), every stage's output in its log only; once all have ended,
# each log is printed whole, lane by lane, and each stage recorded as stage() records it.
fuzz_lanes() {
  local lane pids=() order=()
  for lane in "$@"; do
    read -r -a pairs <<<"$lane"
    local i
    for ((i = 0; i < ${#pairs[@]}; i += 2)); do
      echo "== stage: ${pairs[i]} (in a lane beside others; its output follows when all have ended)"
      order+=("${pairs[i]}")
    done
    (
      for ((i = 0; i < ${#pairs[@]}; i += 2)); do
        start=$SECONDS
        fuzz "${pairs[i]}" "${pairs[i + 1]}" 1 >"$logs/${pairs[i]}.log" 2>&1
        echo "$? $((SECONDS - start))" >"$logs/${pairs[i]}.status"
      done
    ) &
    pids+=($!)
  done
  wait "${pids[@]}"
  local name code took
  for name in "${order[@]}"; do
    echo
    echo "== stage: $name (output)"
    cat "$logs/$name.log"
    read -r code took <"$logs/$name.status"
    finish "$name" "$code" "$took"
  done
}

# finish NAME STATUS SECONDS: records a stage's result for the summary and, when it failed, prints the cause.
finish() {
  local name=$1 status=$2 took=$3 log="$logs/$1.log"
  if [ "$status" -eq 0 ]; then
    summary+=("passed  $name (${took} s)")
  else
    failed=1
    echo "== stage $name FAILED (exit $status); whole output in $log"
    cause "$log"
    summary+=("FAILED  $name (${took} s): $(first_cause "$log"); log: $log")
  fi
  return "$status"
}

# The cause of a failure, from a stage's log: compiler errors, failed tests, sanitizer or fuzzer reports.
cause() {
  local log=$1
  grep -E "error:|The following tests FAILED|^[[:space:]]+[0-9]+ - .*\((Failed|Timeout|SEGFAULT|Subprocess aborted|Exception)" "$log" | head -30
  if grep -q "^==[0-9]*==ERROR\|^SUMMARY:" "$log"; then
    echo "-- report:"
    sed -n '/^==[0-9]*==ERROR/,/^SUMMARY:/p' "$log" | grep -E "ERROR|SUMMARY|^ *#[0-9]+ " | head -40
  fi
  grep -E "^(artifact_prefix|Test unit written to)" "$log" | head -5
}
first_cause() {
  local log=$1 line pattern
  for pattern in "^SUMMARY:" "^[[:space:]]+[0-9]+ - " "error:"; do
    line=$(grep -m1 -E "$pattern" "$log" | sed 's/^[[:space:]]*//')
    [ -n "$line" ] && break
  done
  echo "${line:-see the log}"
}

# The Release and Clang stages build the Python module too (SOFTGL_BUILD_PYTHON) and run its pytest suite in ctest.
release() {
  scripts/configure.sh build/release -DCMAKE_BUILD_TYPE=Release -DSOFTGL_WERROR=ON -DSOFTGL_BUILD_PYTHON=ON &&
    cmake --build build/release -j "$jobs" &&
    ctest --test-dir build/release --output-on-failure -j "$jobs"
}

# The same build and tests with Clang (libstdc++), its own warnings as errors, and Clang's check of every float to
# integer conversion (GCC's UBSan has none): a value out of the integer's range stops the program. It traps (an
# illegal instruction) rather than calling the UBSan runtime, so that programs linking the library need nothing more;
# rebuild with -fsanitize=float-cast-overflow alone for the message. (consumer_subdirectory, which builds the library
# once more inside another project, runs in the Release stage only.)
clang_release() {
  CC=clang CXX=clang++ scripts/configure.sh build/clang -DCMAKE_BUILD_TYPE=Release -DSOFTGL_WERROR=ON \
      -DSOFTGL_BUILD_PYTHON=ON "-DCMAKE_CXX_FLAGS=-fsanitize=float-cast-overflow -fsanitize-trap=float-cast-overflow" &&
    cmake --build build/clang -j "$jobs" &&
    ctest --test-dir build/clang --output-on-failure -j "$jobs" -E '^consumer_subdirectory$'
}

# One build for the sanitizers and the fuzzers: Clang's AddressSanitizer and UndefinedBehaviorSanitizer (whose
# -fsanitize=undefined also checks float-to-integer conversions), every target instrumented for libFuzzer too
# (SOFTGL_FUZZ), optimized (-O2 -g). The whole ctest suite runs on it, then the fuzz stages run its fuzz targets.
sanitize_build() {
  CC=clang CXX=clang++ scripts/configure.sh build/fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTGL_FUZZ=ON \
      -DSOFTGL_SANITIZE=ON -DSOFTGL_BUILD_TESTS=ON -DSOFTGL_BUILD_EXAMPLES=ON -DSOFTGL_INSTALL=OFF \
      -DSOFTGL_WERROR=ON &&
    cmake --build build/fuzz -j "$jobs"
}
sanitizers() {
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build/fuzz --output-on-failure -j "$jobs"
}

# The tile renderer on 1 to 8 threads, and several contexts rendering at once.
tsan() {
  scripts/configure.sh build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTGL_TSAN=ON -DSOFTGL_WERROR=ON \
      -DSOFTGL_INSTALL=OFF &&
    cmake --build build/tsan -j "$jobs" --target softgl_thread_tests &&
    TSAN_OPTIONS=halt_on_error=1 ctest --test-dir build/tsan -R threads --output-on-failure --no-tests=error
}

# 64-bit ARM: cross-built with Debian's aarch64 compiler and :arm64 libraries (cmake/aarch64-linux-gnu.cmake), every
# test program run under qemu-aarch64-static at the default thread count, golden images included. (No conformance
# suite there: Mesa's llvmpipe would itself run emulated. The consumer projects and the documentation's programs
# are host packaging tests.)
arm64() {
  scripts/configure.sh build/arm64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Release \
      -DSOFTGL_WERROR=ON &&
    cmake --build build/arm64 -j "$jobs" &&
    ctest --test-dir build/arm64 --output-on-failure -j "$jobs"
}

# One fuzz target, RUNS inputs from its seed corpus, reproducibly: a fixed seed, no corpus reloads (libFuzzer
# rereads its corpus folder once a second, which makes what it runs depend on the clock), one rendering thread
# (coverage gathered on worker threads depends on the scheduler), and, where the system allows it, no address
# randomization (a branch in libstdc++'s shared_ptr depends on addresses). Threads are fuzzed by scripts/fuzz.sh
# and tested under ThreadSanitizer.
norandom=()
if setarch "$(uname -m)" -R true 2>/dev/null; then norandom=(setarch "$(uname -m)" -R); fi
fuzz() {
  local target=$1 runs=$2 leaks=$3
  local work="build/fuzz/work/$target"
  rm -rf "$work" && mkdir -p "$work"
  [ ${#norandom[@]} -gt 0 ] || echo "note: address randomization cannot be switched off here; the run may differ"
  SOFTGL_THREADS=1 ASAN_OPTIONS=detect_leaks=$leaks LSAN_OPTIONS=suppressions=tests/fuzz/lsan.supp \
    "${norandom[@]}" "build/fuzz/tests/fuzz/$target" -seed=1 \
    -runs="$runs" -reload=0 -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="build/fuzz/$target-" "$work" "tests/fuzz/corpus/$target"
}

scale=${SOFTGL_FUZZ_SCALE:-1}
stage release release
stage clang clang_release
if stage sanitize_build sanitize_build; then
  stage sanitizers sanitizers
  # Two lanes, one core each, of about 6 and 5 minutes here (each target runs about a fifth slower beside another). fuzz_model imports within limits (5 s, 2 GiB), each input
  # first in a child process: forking the sanitized process makes it the slowest target (about 30 inputs a second
  # here), hence its smaller count.
  fuzz_lanes "fuzz_pipeline $((200000 * scale)) fuzz_model $((2000 * scale))" \
    "fuzz_image $((40000 * scale)) fuzz_api $((150000 * scale))"
fi
stage tsan tsan
stage arm64 arm64

echo
echo "== summary"
printf '%s\n' "${summary[@]}"
exit "$failed"
