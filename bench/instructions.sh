#!/usr/bin/env bash
# instructions.sh — what one draw call costs, in instructions: the bench's softgl frames of a scene run under
# valgrind's callgrind, counting only inside the context's calls (Draw*, BindVertexArray: recording; Clear, Finish:
# rendering), divided by the draws the timed and warm-up frames made.
#
#   bench/instructions.sh BENCH SCENE DRAWS_PER_FRAME [FRAMES]
#   bench/instructions.sh build/release/bench/bench "many draws, each its own vertex array" 10000
#
# Instruction counts do not drift with a shared machine's load as times do. Under valgrind the CPU reports no
# AVX-512, so the AVX2 forms of the wide code run (what a machine without AVX-512 runs). Needs valgrind
# (Debian's package `valgrind`).
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 BENCH SCENE DRAWS_PER_FRAME [FRAMES]" >&2
  exit 2
fi
bench=$1 scene=$2 per_frame=$3 frames=${4:-3}
command -v valgrind > /dev/null || { echo "instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
valgrind --tool=callgrind --callgrind-out-file="$out" \
  --toggle-collect='softgl::Context::Draw*' --toggle-collect='softgl::Context::BindVertexArray*' \
  --toggle-collect='softgl::Context::Clear*' --toggle-collect='softgl::Context::Finish*' \
  "$bench" --threads 1 --frames "$frames" --scalar 0 --softgl-only 1 --scene "$scene" > /dev/null 2>&1
# The bench draws two warm-up frames before the timed ones.
draws=$((per_frame * (frames + 2)))
callgrind_annotate --inclusive=yes --threshold=100 "$out" 2> /dev/null | awk -v draws="$draws" -v scene="$scene" '
  /:softgl::Context::(Draw|BindVertexArray)/ { gsub(",", "", $1); record += $1 }
  /:softgl::Context::(Clear|Finish)\(/ { gsub(",", "", $1); render += $1 }
  END {
    printf "%s: %d draws; instructions per draw: %.0f recording (Draw*, BindVertexArray), %.0f rendering (Clear, Finish), %.0f in all\n",
      scene, draws, record / draws, render / draws, (record + render) / draws
  }'
