// cascaded_shadows — writes cascaded_shadows.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "cascaded_shadows.png", scenes::CascadedShadows(960, 360));
}
