// environment_map — writes environment_map.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "environment_map.png", scenes::EnvironmentMap(640, 480));
}
