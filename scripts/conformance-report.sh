#!/usr/bin/env bash
# Prints the conformance table of docs/conformance.md: every scene drawn by softgl and by Mesa (llvmpipe, then
# softpipe), with the differences. Needs the Release build of ./scripts/test.sh (build/release).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/release/tests/softgl_conformance
[ -x "$bin" ] || { echo "build first: ./scripts/test.sh" >&2; exit 1; }
echo "| scene | renderer | check | differing pixels | largest channel difference | beyond tolerance | coverage differing | depth beyond 2^-22 | stencil differing | verdict |"
echo "|---|---|---|---|---|---|---|---|---|---|"
GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=0 "$bin" --report
GALLIUM_DRIVER=softpipe "$bin" --report
