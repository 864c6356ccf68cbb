// post_process — writes post_process.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "post_process.png", scenes::PostProcess(640, 480));
}
