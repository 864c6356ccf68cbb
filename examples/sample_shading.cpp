// sample_shading — writes sample_shading.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "sample_shading.png", scenes::SampleShading(480, 240));
}
