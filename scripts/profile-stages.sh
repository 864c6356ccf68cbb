#!/usr/bin/env bash
# Where softgl's time goes per pipeline stage, for each bench scene on one thread: samples with `perf record`
# (from linux-perf), then each sampled function is put in the stage it belongs to. The bench's own set-up
# (model loading, scene generation, llvmpipe is not run) is counted apart and left out of the percentages.
# Needs the Release build with the bench (./scripts/bench.sh builds it) and perf.
#
#   ./scripts/profile-stages.sh [SCENE ...]   (the scenes whose names contain SCENE; without one, the usual six)
set -euo pipefail
cd "$(dirname "$0")/.."
bench=${BENCH:-build/release/bench/bench}  # BENCH=path profiles another build (an older commit's, say)
[ -x "$bench" ] || { echo "build first: ./scripts/bench.sh" >&2; exit 1; }
data=$(mktemp)
trap 'rm -f "$data"' EXIT
echo "| scene | front end | binning | clears | rasterization | early depth test | fragment shader and texture sampling | fragment operations | memory copies, fills, page faults | bench set-up (% of samples, left out) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
# (a name ending in $ is matched as the end of the scene's: the engine alone, not its multisampled forms)
scenes=("model: 2CylinderEngine, Blinn-Phong$" "model: SuzanneSubdiv_252, Blinn-Phong$" "african_head" "small triangles"
        "fill rate" "overdraw" "many draws, each its own")
[ $# -gt 0 ] && scenes=("$@")  # scenes named on the command line: only those
for scene in "${scenes[@]}"; do
  frames=20
  case "$scene" in model*|african*|many*) frames=200 ;; esac  # short frames: more of them, so set-up weighs little
  perf record -q -o "$data" "$bench" --scene "$scene" --frames "$frames" --softgl-only 1 --scalar 0 --threads 1 >/dev/null 2>&1
  perf report -i "$data" --no-children --stdio --sort sym 2>/dev/null | python3 -c '
import re, sys
rules = [
  ("front end", r"FetchAttribute|FetchVertices|ShadeVertices|Vertices(Avx512|Avx2|Base)|VertexLanes|Resolve|ClipCodes|ClipTriangle|ClipLine|ToWindow|SignedArea|AssemblePrimitives|AssembleRun|RecordChunk|RecordDraw|RecordPiece|PrimitiveRunner|ReadIndices|Intersect|IsFrontFacing|IsCulled|PolygonOffset|CoversNoPixelCentre|TriangleCentreBox|DrawsNothing|WindowPositions|JudgeGroup|JudgeTriangles|ContextState::Draw|Context::Draw|Context::BindVertexArray|CheckNotMapped|CheckModes|FrameTarget|Framebuffer::Samples|SameBuffers|MakeView|Snapshot|MakeViewportTransform|WorkerPool|ShadeSmallDraw|SmallDrawApplies|JoinsPending|RecordPending|UniqueVertices|FragmentOpsState::operator=="),
  ("binning", r"BinnedBatch::Add|BinnedBatch::Note|BinnedBatch::Finish|TriangleBox|LineBox|PointBox|::Box\(|SharedBatch|NewBatches|ListLastDraw|Frame::AddDraw|Frame::List"),
  ("clears", r"RenderTarget::Clear|FillTexels"),
  ("rasterization", r"Rasterize|TriangleQuads|CoverTriangle|SetUpTriangle|SetUpGroup|RenderTile|BinnedBatch::Vertex|BinnedBatch::View|FragmentStage|RegionCoverage|FragCoord|VaryingsOfBlock|InterpolateVaryings|InterpolateFragCoords|AddSquare|AddQuad|EmitQuad|BlockSink"),
  ("early depth test", r"EarlyDepth|EarlyBlock|EarlyRange|HierarchicalDepth|HiddenTriangle|HiddenRegion"),
  ("fragment shader and texture sampling", r"ShadeBlocks|Blocks(Avx512|Avx2|Base)|BlockLanes|FragmentLanes|Textures::|SampleTexel|SampleBlock|SampleRepeat|FilterLevel|SampleFace|Fetch\(|Lambda|powf|__pow|expf|logf|sqrt"),
  ("fragment operations", r"ApplyFragmentOps|BlockOps|Unorm8Blender|ColorBuffer::|FloatToUnorm8|detail::Blend"),
  ("memory copies, fills, page faults", r"memmove|memset|memcpy|page_fault|clear_page|do_anonymous_page|handle_mm_fault"),
]
total, other = {}, 0.0
for line in sys.stdin:
    m = re.match(r"\s+([0-9.]+)%\s+\[[.k]\]\s+(.*)", line)
    if not m: continue
    pct, sym = float(m.group(1)), m.group(2)
    for name, rx in rules:
        if re.search(rx, sym):
            total[name] = total.get(name, 0) + pct
            break
    else:
        other += pct
s = sum(total.values()) or 1.0
print("| " + sys.argv[1] + " | " + " | ".join("%.0f%%" % (total.get(n, 0) / s * 100) for n, _ in rules) + " | %.0f%% |" % other)
' "$scene"
done
