// tour — the pictures of docs/tour.md, the life of a draw call stage by stage: writes tour_*.png.
#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  const std::string dir = example::OutputDir(argc, argv);
  struct Picture {
    const char* name;
    softgl::Image (*draw)(int, int);
    int width, height;
  };
  const Picture pictures[] = {
      {"tour_clipping.png", scenes::TourClipping, 640, 320},      {"tour_coverage.png", scenes::TourCoverage, 640, 320},
      {"tour_viewport.png", scenes::TourViewport, 640, 320},
      {"tour_barycentric.png", scenes::TourBarycentric, 640, 320}, {"tour_depth.png", scenes::TourDepth, 960, 320},
      {"tour_perspective.png", scenes::TourPerspective, 640, 320}, {"tour_culling.png", scenes::TourCulling, 640, 320},
      {"tour_tiles.png", scenes::TourTiles, 640, 384},            {"tour_mipmaps.png", scenes::TourMipmapLevels, 960, 320},
      {"tour_lines.png", scenes::TourLines, 640, 320},            {"tour_multisample.png", scenes::TourMultisample, 640, 320},
  };
  int status = 0;
  for (const Picture& p : pictures) status |= example::Save(dir, p.name, p.draw(p.width, p.height));
  return status;
}
