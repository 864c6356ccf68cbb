// textured_cube — writes textured_cube.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "textured_cube.png", scenes::TexturedCube(640, 480));
}
