// Compiling and linking GLSL programs from the embedded shader files, with #define variants.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/gl_handle.h"
#include "renderer/core/result.h"

namespace npr::gl {

Result<Program> buildProgram(const std::string& vertexFile, const std::string& fragmentFile,
                             const std::vector<std::string>& defines);

// For GLSL written elsewhere (tests): the sources may #include the embedded files.
Result<Program> buildProgramFromText(const std::string& vertexText, const std::string& fragmentText,
                                     const std::vector<std::string>& defines);

// Uniform setters that look the location up each call: the programs are small and the
// number of uniforms set per frame is a few dozen, so a cache would not pay for itself.
void setUniform(GLuint program, const char* name, int v);
void setUniform(GLuint program, const char* name, float v);
void setUniform(GLuint program, const char* name, const glm::vec2& v);
void setUniform(GLuint program, const char* name, const glm::vec3& v);
void setUniform(GLuint program, const char* name, const glm::vec4& v);
void setUniform(GLuint program, const char* name, const glm::ivec2& v);
void setUniform(GLuint program, const char* name, const glm::mat3& v);
void setUniform(GLuint program, const char* name, const glm::mat4& v);
void setUniformArray(GLuint program, const char* name, const glm::vec4* v, int count);
void setUniformArray(GLuint program, const char* name, const glm::vec3* v, int count);
void setUniformArray(GLuint program, const char* name, const float* v, int count);
void setUniformArray(GLuint program, const char* name, const glm::ivec2* v, int count);

}  // namespace npr::gl
