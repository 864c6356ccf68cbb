// geometry_stage.cpp — the geometry stage: input primitives into lanes, the program's Geometry() over them, and
// what it emits gathered into vertices and primitives for clipping.
#include "geometry_stage.h"

#include <algorithm>
#include <cstring>

#include "simd.h"

namespace softgl::detail {

std::size_t GeometryGroup(const GeometryLayout& layout) {
  const std::size_t per = std::size_t(layout.max_vertices) * std::size_t(layout.invocations);
  return std::max<std::size_t>(1, kGeometryVertexBudget / per);
}

void RunGeometry(const Program& program, const GeometryInput& in, std::size_t begin, std::size_t end, bool layers,
                 WorkerPool& pool, GeometryScratch& s, ShadedVertices& out, Primitives& out_prims) {
  const GeometryLayout& layout = *in.layout;
  const int per = layout.InputVertices();
  const std::size_t n = end - begin;  // input primitives
  const int invocations = layout.invocations, max = layout.max_vertices;
  const int nvar = program.VaryingFloats();
  const bool ids = program.ReadsPrimitiveId();  // the last two varyings: gl_PrimitiveID, from the record's head
  const int own = nvar - (ids ? 2 : 0);          // the varyings of the fragment stage's struct
  const int stride = shader_detail::kGeometryHead + own;
  const std::size_t slots = n * std::size_t(invocations);  // (invocation, primitive), invocation-major

  // Each primitive's shaded vertices, its gl_PrimitiveIDIn and gl_InstanceID.
  s.vertex_index.resize(n * std::size_t(per));
  s.primitive_ids.resize(n);
  s.instance_ids.resize(n);
  const std::vector<std::uint32_t>& idx = in.prims->indices;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = begin + i;
    const std::size_t q = p % in.per_instance, g = p / in.per_instance;
    const std::uint32_t shift = std::uint32_t(g) * in.unique;
    for (int k = 0; k < per; ++k)
      s.vertex_index[i * std::size_t(per) + std::size_t(k)] = in.map[idx[q * std::size_t(per) + std::size_t(k)]] + shift;
    s.primitive_ids[i] = std::int32_t(in.primitive_base + std::uint32_t(q));
    s.instance_ids[i] = std::int32_t(in.first_instance + std::uint32_t(g));
  }
  s.records.resize(slots * std::size_t(max) * std::size_t(stride));
  s.emitted.resize(slots);

  // The stage, in jobs of up to 64 primitives of one invocation.
  constexpr std::size_t kJob = 64;
  const std::size_t jobs_per_invocation = (n + kJob - 1) / kJob;
  const int simd = int(CpuSimdLevel());
  pool.Run(int(jobs_per_invocation * std::size_t(invocations)), [&](int job, int) {
    const int invocation = int(std::size_t(job) / jobs_per_invocation);
    const std::size_t first = std::size_t(job) % jobs_per_invocation * kJob;
    const std::size_t slot = std::size_t(invocation) * n + first;
    GeometryBatch batch;
    batch.count = int(std::min(kJob, n - first));
    batch.vertices = per;
    batch.vertex_index = s.vertex_index.data() + first * std::size_t(per);
    batch.positions = in.vertices->position.data();
    batch.point_sizes = in.vertices->point_size.data();
    batch.varyings = in.vertices->varyings.data();
    batch.primitive_ids = s.primitive_ids.data() + first;
    batch.instance_ids = s.instance_ids.data() + first;
    batch.invocation = invocation;
    batch.textures = in.textures;
    batch.simd = simd;
    batch.records = s.records.data() + slot * std::size_t(max) * std::size_t(stride);
    batch.stride = stride;
    batch.max_vertices = max;
    batch.emitted = s.emitted.data() + slot;
    program.ShadeGeometry(batch);
  });

  // What was emitted, in order: primitive by primitive, each primitive's invocations in order.
  std::size_t total = 0;
  for (int e : s.emitted) total += std::size_t(e);
  out.count = int(total);
  out.nvar = nvar;
  out.position.resize(total);
  out.point_size.resize(total);
  out.varyings.resize(total * std::size_t(nvar));
  if (layers) out.layer.resize(total);
  out_prims.vertices_per_primitive = layout.output == POINTS ? 1 : layout.output == LINE_STRIP ? 2 : 3;
  out_prims.indices.clear();
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int inv = 0; inv < invocations; ++inv) {
      const std::size_t slot = std::size_t(inv) * n + i;
      const float* rec = s.records.data() + slot * std::size_t(max) * std::size_t(stride);
      std::uint32_t strip = v;  // where the current strip began
      for (int k = 0; k < s.emitted[slot]; ++k, rec += stride, ++v) {
        if (k > 0 && rec[6] != 0.0f) {  // EndPrimitive() came before this vertex
          AppendPrimitives(layout.output, strip, int(v - strip), out_prims.indices, in.provoking_first);
          strip = v;
        }
        std::memcpy(&out.position[v].x, rec, sizeof(float) * 4);
        out.point_size[v] = rec[4];
        if (layers) std::memcpy(&out.layer[v], rec + 5, sizeof(int));
        float* var = out.varyings.data() + std::size_t(v) * std::size_t(nvar);
        if (own > 0) std::memcpy(var, rec + shader_detail::kGeometryHead, sizeof(float) * std::size_t(own));
        if (ids) {
          std::uint32_t id;
          std::memcpy(&id, rec + 7, sizeof id);
          PrimitiveIdFloats(id, var + own);
        }
      }
      AppendPrimitives(layout.output, strip, int(v - strip), out_prims.indices, in.provoking_first);
    }
}

}  // namespace softgl::detail
