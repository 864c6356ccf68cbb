// multisample — writes multisample.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "multisample.png", scenes::Multisample(640, 320));
}
