// example_main.h — the shared command line of the example programs: `example [OUTPUT_DIR]` (default "out").
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include <softgl/softgl.h>

namespace example {

inline std::string OutputDir(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "out";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return dir;
}

/// Writes image to dir/name and prints the path; returns the process exit status.
inline int Save(const std::string& dir, const std::string& name, const softgl::Image& image) {
  const std::string path = dir + "/" + name;
  if (!softgl::WritePng(path, image)) {
    std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
    return 1;
  }
  std::printf("%s\n", path.c_str());
  return 0;
}

}  // namespace example
