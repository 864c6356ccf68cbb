// particles — a fountain of 1,500 point sprites in one draw (gl_PointSize, gl_PointCoord, additive blending).
// Writes particles.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "particles.png", scenes::Particles(640, 400));
}
