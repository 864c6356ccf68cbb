// buffer_texture — 1,200 cubes from one instanced draw, each placed by a matrix read from a buffer texture
// (TexBuffer, texelFetch by gl_InstanceID) and coloured from a palette at an integer attribute's index
// (VertexAttribIPointer). Writes buffer_texture.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "buffer_texture.png", scenes::BufferTextures(800, 500));
}
