// extract_snippets — turns the code blocks of Markdown files into a CMake project that compiles every one of them
// against the installed softgl package, so that the documentation cannot drift from the API.
//
//   extract_snippets OUT_DIR INCLUDE_DIR FILE.md...
//
// Every ```cpp block is one of three kinds, told by its text or by an HTML comment on the line before the fence
// (invisible when the Markdown is rendered):
//   a block with `int main(`          a complete program: built and, by tests/docs/run.cmake, run
//   <!-- snippet: declarations -->    declarations at namespace scope: compiled
//   <!-- snippet: statements -->      statements: compiled inside a function that has `softgl::Context& gl`
// A ```cpp block of none of these kinds is an error, so that no block goes unchecked. Every ```cmake block is
// written, in order, into the project after `add_executable(app ...)` of the first program: they are the lines a
// user adds to their own project, and they must link it. Besides, every header in INCLUDE_DIR/softgl is compiled on
// its own (included first in a translation unit of its own).
//
// Writes OUT_DIR/CMakeLists.txt, the sources, and OUT_DIR/programs.txt (the programs to run, one per line).
// Exit status 1 with a message naming the file and line on any problem.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Block {
  std::string file;
  int line = 0;  // of the opening fence
  std::string lang, kind, text;
};

bool StartsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

bool Read(const std::string& path, std::vector<Block>& blocks) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << path << ": cannot read\n";
    return false;
  }
  std::string line, previous;
  int number = 0;
  Block* open = nullptr;
  Block current;
  while (std::getline(in, line)) {
    ++number;
    const std::string t = Trim(line);
    if (open) {
      if (t == "```") {
        blocks.push_back(current);
        open = nullptr;
      } else {
        current.text += line + "\n";
      }
      continue;
    }
    if (StartsWith(t, "```")) {
      current = Block{path, number, t.substr(3), "", ""};
      const std::string p = Trim(previous);
      if (StartsWith(p, "<!-- snippet:") && p.size() > 17) current.kind = Trim(p.substr(13, p.size() - 13 - 3));
      open = &current;
    }
    if (!t.empty()) previous = t;
  }
  if (open) {
    std::cerr << path << ":" << current.line << ": code block not closed\n";
    return false;
  }
  return true;
}

bool Write(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  return bool(out);
}

const char* kPrelude =
    "#include <cstdint>\n#include <cstdio>\n#include <cstring>\n#include <string>\n#include <vector>\n\n#include <softgl/model.h>\n"
    "#include <softgl/shaders.h>\n#include <softgl/softgl.h>\n\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: extract_snippets OUT_DIR INCLUDE_DIR FILE.md...\n";
    return 2;
  }
  const fs::path out = argv[1], include = argv[2];
  std::vector<Block> blocks;
  for (int i = 3; i < argc; ++i)
    if (!Read(argv[i], blocks)) return 1;

  fs::create_directories(out);
  std::vector<std::string> programs, fragments, cmake_blocks;
  int n = 0;
  for (const Block& b : blocks) {
    const std::string where = b.file + ":" + std::to_string(b.line);
    if (b.lang == "cmake") {
      cmake_blocks.push_back("# " + where + "\n" + b.text);
      continue;
    }
    if (b.lang != "cpp") continue;
    const std::string name = "snippet_" + std::to_string(++n);
    std::string source = "// " + where + "\n";
    if (b.text.find("int main(") != std::string::npos && b.kind.empty()) {
      source += b.text;
      programs.push_back(name);
    } else if (b.kind == "declarations") {
      source += kPrelude + b.text;
      fragments.push_back(name);
    } else if (b.kind == "statements") {
      source += std::string(kPrelude) + "int " + name + "(softgl::Context& gl) {\n  (void)gl;\n  {\n" + b.text +
                "  }\n  return 0;\n}\n";
      fragments.push_back(name);
    } else {
      std::cerr << where << ": a ```cpp block needs int main() or <!-- snippet: declarations|statements --> before"
                << " it (kind '" << b.kind << "')\n";
      return 1;
    }
    if (!Write(out / (name + ".cpp"), source)) return 1;
  }
  if (programs.empty()) {
    std::cerr << "no complete program among the blocks: the CMake lines need one to link\n";
    return 1;
  }

  std::vector<std::string> headers;
  for (const auto& entry : fs::directory_iterator(include / "softgl"))
    if (entry.path().extension() == ".h") headers.push_back(entry.path().filename().string());
  if (headers.empty()) {
    std::cerr << include.string() << "/softgl: no headers\n";
    return 1;
  }

  std::ostringstream cm;
  cm << "# Generated by extract_snippets from the documentation's code blocks.\n"
        "cmake_minimum_required(VERSION 3.25)\nproject(softgl_docs LANGUAGES CXX)\n"
        "add_compile_options(-Wall -Wextra -Wpedantic -Werror)\n"
        "add_executable(app " << programs[0] << ".cpp)\n";
  for (const std::string& c : cmake_blocks) cm << c;
  for (std::size_t i = 1; i < programs.size(); ++i)
    cm << "add_executable(" << programs[i] << " " << programs[i] << ".cpp)\ntarget_link_libraries(" << programs[i]
       << " PRIVATE softgl::softgl softgl::model)\n";
  cm << "add_library(fragments OBJECT";
  for (const std::string& f : fragments) cm << " " << f << ".cpp";
  cm << ")\ntarget_link_libraries(fragments PRIVATE softgl::softgl softgl::model)\n";
  cm << "add_library(headers OBJECT";
  for (const std::string& h : headers) {
    const std::string stem = fs::path(h).stem().string();
    if (!Write(out / ("header_" + stem + ".cpp"), "#include <softgl/" + h + ">\n")) return 1;
    cm << " header_" << stem << ".cpp";
  }
  cm << ")\ntarget_link_libraries(headers PRIVATE softgl::softgl softgl::model)\n";
  if (!Write(out / "CMakeLists.txt", cm.str())) return 1;

  std::string list = "app\n";
  for (std::size_t i = 1; i < programs.size(); ++i) list += programs[i] + "\n";
  if (!Write(out / "programs.txt", list)) return 1;
  std::printf("extract_snippets: %zu programs, %zu fragments, %zu CMake blocks, %zu headers\n", programs.size(),
              fragments.size(), cmake_blocks.size(), headers.size());
  return 0;
}
