// A linked GLSL program built from the embedded shader files, with its uniform locations
// cached by name and typed setters. A uniform name that appears in neither stage's source is
// a typo the driver would silently ignore: in debug and test builds it is reported as a GL
// error (gl_debug.h). A uniform that a variant compiled out, or the compiler optimised away,
// is present in the source text and is skipped quietly, as GL skips location -1.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"

namespace npr::gl {

class ShaderProgram {
 public:
  // `defines` are "NAME" or "NAME VALUE" lines prepended to every stage. A geometry stage
  // is optional (empty `geometryFile`: none).
  [[nodiscard]] static Result<ShaderProgram> build(const std::string& vertexFile, const std::string& fragmentFile,
                                                   const std::vector<std::string>& defines, const std::string& geometryFile = {});

  // A compute program (GL 4.3; the caller checks the context has compute shaders).
  [[nodiscard]] static Result<ShaderProgram> buildCompute(const std::string& computeFile, const std::vector<std::string>& defines);

  GLuint id() const { return program_.id(); }
  void use() const { glUseProgram(program_.id()); }
  // "mesh.vert+mesh.frag -DPATH_PIXEL ...": what error messages name.
  const std::string& label() const { return label_; }

  void set(const char* name, int v);
  void set(const char* name, float v);
  void set(const char* name, const glm::vec2& v);
  void set(const char* name, const glm::vec3& v);
  void set(const char* name, const glm::vec4& v);
  void set(const char* name, const glm::ivec2& v);
  void set(const char* name, const glm::mat3& v);
  void set(const char* name, const glm::mat4& v);
  void setArray(const char* name, const glm::vec4* v, int count);
  void setArray(const char* name, const glm::vec3* v, int count);
  void setArray(const char* name, const glm::vec2* v, int count);
  void setArray(const char* name, const glm::mat4* v, int count);
  void setArray(const char* name, const int* v, int count);
  void setArray(const char* name, const unsigned* v, int count);
  void setArray(const char* name, const float* v, int count);
  void setArray(const char* name, const glm::ivec2* v, int count);
  void set(const char* name, unsigned v);

 private:
  GLint location(const char* name);
  Program program_;
  std::string label_;
  std::string source_;  // both stages, for telling a typo from a compiled-out uniform
  std::unordered_map<std::string, GLint> locations_;
};

// Whether unknown uniform names are reported: on in debug builds and in the test programs.
void setStrictUniforms(bool on);

}  // namespace npr::gl
