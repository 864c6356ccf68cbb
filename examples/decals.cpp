// decals — writes decals.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "decals.png", scenes::Decals(640, 480));
}
