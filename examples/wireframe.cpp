// wireframe — a torus with PolygonMode(LINE) edges and PolygonMode(POINT) vertices: writes wireframe.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "wireframe.png", scenes::Wireframe(640, 480));
}
