// picking — object picking by an integer colour buffer: each object's id rendered into an R32UI texture, the ids
// under five clicks read back by ReadPixels(RED_INTEGER, UNSIGNED_INT), the picked objects shown in colour and the
// id buffer in false colours in a corner. Writes picking.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  return example::Save(example::OutputDir(argc, argv), "picking.png", scenes::Picking(800, 500));
}
