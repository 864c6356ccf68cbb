// small_formats — writes small_formats.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "small_formats.png", scenes::SmallFormats(800, 240));
}
