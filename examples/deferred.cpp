// deferred — deferred shading through a G-buffer of three targets, each cleared to its own value (ClearBufferfv),
// a decal written into one target alone (ColorMaski), and a lighting pass reading them by texelFetch. Writes
// deferred.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "deferred.png", scenes::Deferred(800, 500));
}
