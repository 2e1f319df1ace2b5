// A linked GLSL program built from the embedded shader files, with its uniform locations
// cached by name and typed setters. A uniform name that appears in neither stage's source is
// a typo the driver would silently ignore: in debug and test builds it is reported as a GL
// error (gl_debug.h). A uniform that a variant compiled out, or the compiler optimised away,
// is present in the source text and is skipped quietly, as GL skips location -1.
//
// A program keeps its uniforms' values between draws, so each setter remembers what it last
// sent and sends a value again only when it differs: a scene's objects share the lights, the
// palette's uniforms and the features', and only their transforms change from one object to
// the next. Every uniform of a program is set through these setters (no raw glUniform
// elsewhere), with the program in use, so what is remembered is what the program holds.
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
  struct Uniform {
    GLint location = -1;
    std::vector<unsigned char> sent;  // the bytes last sent; empty before the first
  };
  Uniform& uniform(const char* name);
  // The location to send `bytes` to, or -1 where the uniform is compiled out or already holds them.
  GLint changed(const char* name, const void* value, std::size_t bytes);
  Program program_;
  std::string label_;
  std::string source_;  // both stages, for telling a typo from a compiled-out uniform
  std::unordered_map<std::string, Uniform> uniforms_;
};

// How many uniform values the setters sent to GL and how many they found unchanged, since the
// process started (all programs): what the benchmarks and tests read.
struct UniformTraffic {
  long long sent = 0;
  long long unchanged = 0;
};
UniformTraffic uniformTraffic();

// Whether unknown uniform names are reported: on in debug builds and in the test programs.
void setStrictUniforms(bool on);

}  // namespace npr::gl
