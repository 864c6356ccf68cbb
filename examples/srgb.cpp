// srgb — writes srgb.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "srgb.png", scenes::Srgb(640, 480));
}
