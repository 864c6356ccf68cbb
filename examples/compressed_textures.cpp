// compressed_textures — writes compressed_textures.png (see scenes.h for what it shows).
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "compressed_textures.png",
                       scenes::CompressedTextures(800, 480));
}
