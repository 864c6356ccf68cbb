// mirror — writes mirror.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "mirror.png", scenes::Mirror(640, 480));
}
