// models — models from Debian's assimp-testmodels with each built-in shader, then two files of points and lines
// alone (written here: a PLY point cloud and an OBJ polyline), drawn unlit: writes model_*.png.
#include <cstdio>
#include <string>

#include "example_main.h"
#include "scenes.h"

int main(int argc, char** argv) {
  const std::string dir = example::OutputDir(argc, argv);
  struct Shot {
    const char* file;
    const char* shader;
    const char* name;
    float azimuth, elevation;
  };
  const Shot shots[] = {
      {"Collada/duck.dae", "phong", "model_duck_phong.png", 30.0f, 20.0f},
      {"OBJ/spider.obj", "phong", "model_spider_phong.png", 40.0f, 30.0f},
      {"OBJ/spider.obj", "unlit", "model_spider_unlit.png", 40.0f, 30.0f},
      {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "pbr", "model_box_pbr.png", 35.0f, 25.0f},
      {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "pbr", "model_engine_pbr.png", 30.0f, 20.0f},
      {"PLY/Wuson.ply", "phong", "model_wuson_phong.png", 150.0f, 15.0f},
  };
  for (const Shot& s : shots) {
    std::string error;
    const softgl::Image image =
        scenes::ModelView(std::string(scenes::kTestModels) + "/" + s.file, s.shader, 640, 480, s.azimuth, s.elevation,
                          &error);
    if (image.rgba.empty()) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return 1;
    }
    if (int rc = example::Save(dir, s.name, image)) return rc;
  }
  // Files without surfaces: their meshes are kept as points and lines and drawn in their colours.
  const std::string cloud = dir + "/galaxy_points.ply", knot = dir + "/torus_knot_lines.obj";
  if (!scenes::WritePointCloudPly(cloud) || !scenes::WriteTorusKnotObj(knot)) {
    std::fprintf(stderr, "error: cannot write %s or %s\n", cloud.c_str(), knot.c_str());
    return 1;
  }
  struct Wire {
    std::string file;
    const char* name;
    float azimuth, elevation, point_size;
  };
  const Wire wires[] = {{cloud, "model_point_cloud.png", 20.0f, 35.0f, 2.0f},
                        {knot, "model_wireframe_lines.png", 0.0f, 60.0f, 1.0f}};
  for (const Wire& w : wires) {
    std::string error;
    const softgl::Image image = scenes::ModelView(w.file, "phong", 640, 480, w.azimuth, w.elevation, &error, w.point_size);
    if (image.rgba.empty()) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return 1;
    }
    if (int rc = example::Save(dir, w.name, image)) return rc;
  }
  return 0;
}
