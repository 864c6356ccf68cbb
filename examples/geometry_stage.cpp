// geometry_stage — the geometry stage: a torus shaded with its wireframe in one pass, and a torus with its face
// normals drawn as lines that a geometry stage makes of its triangles. Writes geometry_stage.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "geometry_stage.png", scenes::GeometryStage(640, 360));
}
