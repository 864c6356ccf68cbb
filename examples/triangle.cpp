// triangle — a colour-interpolated triangle: writes triangle.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "triangle.png", scenes::Triangle(640, 480));
}
