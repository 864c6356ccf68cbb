// stencil_outline — writes stencil_outline.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "stencil_outline.png", scenes::StencilOutline(640, 480));
}
