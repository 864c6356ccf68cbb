// shadow_map — writes shadow_map.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "shadow_map.png", scenes::ShadowMap(640, 480));
}
