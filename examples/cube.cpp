// cube — a lit cube turning through eight frames: writes cube_0.png ... cube_7.png.
#include <string>

#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  const std::string dir = example::OutputDir(argc, argv);
  constexpr int kFrames = 8;
  for (int i = 0; i < kFrames; ++i) {
    const float angle = 2.0f * 3.14159265f * float(i) / float(kFrames * 4);  // a quarter turn in all
    if (int rc = example::Save(dir, "cube_" + std::to_string(i) + ".png", scenes::Cube(480, 480, angle))) return rc;
  }
  return 0;
}
