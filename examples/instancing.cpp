// instancing — a field of 10,000 cubes from one instanced draw (gl_InstanceID and attribute divisors). Writes
// instancing.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "instancing.png", scenes::Instancing(800, 500));
}
