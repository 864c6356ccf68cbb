#!/usr/bin/env bash
# A fuzzing campaign beside the test gate: every libFuzzer target, coverage-guided, for SECONDS each (default 3600),
# one after another, over a corpus that grows from run to run and lives outside the repository.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#
# Environment: SOFTGL_FUZZ_DIR, the campaign's folder (default ~/.cache/softgl-fuzz): <target>/corpus holds the
# corpus, <target>/findings the inputs that crashed, leaked, ran out of memory or took longer than the per-input
# limit (20 s; a slow input is a finding, not noise); SOFTGL_FUZZ_JOBS, parallel fuzzing processes per target
# (default 1).
#
# Each target runs in libFuzzer's fork mode, so that a finding is saved and the campaign goes on; rendering uses
# the context's default thread count, so the worker threads are fuzzed too. Afterwards the corpus is minimized
# (-merge=1: the smallest set of inputs with the same coverage) and one line per target gives the executions, the
# coverage (edges, features), the corpus size and the findings. Replay a finding with
#   build/fuzz/tests/fuzz/<target> <finding>
# and, once fixed, copy it to tests/fuzz/corpus/<target>/regression_<name> so that the gate replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-3600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_api fuzz_pipeline fuzz_image fuzz_model)
dir=${SOFTGL_FUZZ_DIR:-$HOME/.cache/softgl-fuzz}
jobs=${SOFTGL_FUZZ_JOBS:-1}

scripts/deps.sh clang libclang-rt-14-dev
CC=clang CXX=clang++ scripts/configure.sh build/fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSOFTGL_FUZZ=ON \
  -DSOFTGL_BUILD_TESTS=OFF -DSOFTGL_BUILD_EXAMPLES=OFF -DSOFTGL_INSTALL=OFF -DSOFTGL_WERROR=ON > /dev/null
cmake --build build/fuzz -j "$(nproc)" > /dev/null

results=()
for target in "${targets[@]}"; do
  bin="build/fuzz/tests/fuzz/$target"
  corpus="$dir/$target/corpus" findings="$dir/$target/findings" log="$dir/$target/last-run.log"
  mkdir -p "$corpus" "$findings"
  before=$(find "$findings" -type f | wc -l)
  echo "== $target: ${seconds} s, corpus $corpus ($(find "$corpus" -type f | wc -l) inputs)"
  ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$PWD/tests/fuzz/lsan.supp "$bin" -fork="$jobs" \
    -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 -artifact_prefix="$findings/" \
    "$corpus" "tests/fuzz/corpus/$target" > "$log" 2>&1 || true
  last=$(grep -E "^#[0-9]+: cov:" "$log" | tail -1)
  executions=$(sed -E 's/^#([0-9]+):.*/\1/' <<< "$last")
  coverage=$(sed -E 's/.*cov: ([0-9]+) ft: ([0-9]+).*/\1 edges, \2 features/' <<< "$last")
  # Minimize: merge the corpus into an empty folder, which keeps the smallest set with the same coverage.
  merged="$dir/$target/merged"
  rm -rf "$merged" && mkdir -p "$merged"
  ASAN_OPTIONS=detect_leaks=0 "$bin" -merge=1 -timeout=20 -rss_limit_mb=4096 "$merged" "$corpus" \
    > "$dir/$target/merge.log" 2>&1 && rm -rf "$corpus" && mv "$merged" "$corpus"
  after=$(find "$findings" -type f | wc -l)
  results+=("$target: ${executions:-?} executions in ${seconds} s, ${coverage:-coverage unknown}, corpus $(find "$corpus" -type f | wc -l) inputs, $((after - before)) new findings ($after in $findings)")
done

echo
echo "== campaign (${seconds} s per target)"
printf '%s\n' "${results[@]}"
