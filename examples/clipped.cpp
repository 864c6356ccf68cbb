// clipped — a floor and a cube crossing the near plane, clipped in homogeneous space: writes clipped.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "clipped.png", scenes::Clipped(640, 480));
}
