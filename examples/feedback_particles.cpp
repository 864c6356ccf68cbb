// feedback_particles — a fountain of 800 particles simulated on the vertex stage: each of 150 steps is recorded by
// transform feedback into the other of two buffers, with nothing rasterized; every second step is drawn as faint
// points, which leave trails. Writes feedback_particles.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "feedback_particles.png",
                       scenes::FeedbackParticles(640, 400));
}
