// What a shader program is built from: its GLSL files (shaders/) and #define lines. The
// program cache is keyed by it; the typed variants that produce it live above gl/
// (programs/program_variants.h), so this layer knows no feature, palette or line.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace npr::gl {

struct ProgramSource {
  ProgramSource(std::string vertex, std::string fragment, std::vector<std::string> defs = {}, std::string geometry = {})
      : vertexFile(std::move(vertex)), fragmentFile(std::move(fragment)), defines(std::move(defs)), geometryFile(std::move(geometry)) {}
  std::string vertexFile, fragmentFile;
  std::vector<std::string> defines;
  std::string geometryFile;  // empty: none
  std::string computeFile;   // a compute program: this alone (the others empty)
};

}  // namespace npr::gl
