// shaders.cpp — the built-in shaders' vertex and fragment stages, compiled once for every program that links
// softgl::model (shaders.h declares them extern).
#include <softgl/shaders.h>

namespace softgl {

template void Shader<UnlitShader, SurfaceVaryings>::ShadeVertices(const VertexBatch&) const;
template void Shader<UnlitShader, SurfaceVaryings>::ShadeBlocks(const BlockBatch&) const;
template void Shader<PhongShader, SurfaceVaryings>::ShadeVertices(const VertexBatch&) const;
template void Shader<PhongShader, SurfaceVaryings>::ShadeBlocks(const BlockBatch&) const;
template void Shader<PbrShader, SurfaceVaryings>::ShadeVertices(const VertexBatch&) const;
template void Shader<PbrShader, SurfaceVaryings>::ShadeBlocks(const BlockBatch&) const;

}  // namespace softgl
