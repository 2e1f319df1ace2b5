// Shader compilation with readable errors that name the file and the variant.
#include "renderer/gl/gl_program.h"

#include <glm/gtc/type_ptr.hpp>

#include "renderer/gl/shader_sources.h"

namespace npr::gl {
namespace {

std::string variantName(const std::string& file, const std::vector<std::string>& defines) {
  std::string s = file;
  for (const auto& d : defines) s += " -D" + d;
  return s;
}

Result<Shader> compileSource(GLenum type, const std::string& file, const Result<std::string>& src,
                             const std::vector<std::string>& defines) {
  if (!src) return Error{src.error()};
  Shader shader(glCreateShader(type));
  const char* text = src->c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = 0;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetShaderInfoLog(shader.id(), len, nullptr, log.data());
    return Error{"shader " + variantName(file, defines) + " failed to compile:\n" + log};
  }
  return shader;
}

Result<Program> link(Result<Shader> vs, Result<Shader> fs, const std::string& vertexFile, const std::string& fragmentFile,
                     const std::vector<std::string>& defines) {
  if (!vs) return Error{vs.error()};
  if (!fs) return Error{fs.error()};
  Program program(glCreateProgram());
  glAttachShader(program.id(), vs->id());
  glAttachShader(program.id(), fs->id());
  glLinkProgram(program.id());
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  glDetachShader(program.id(), vs->id());
  glDetachShader(program.id(), fs->id());
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
    glGetProgramInfoLog(program.id(), len, nullptr, log.data());
    return Error{"program " + variantName(vertexFile + "+" + fragmentFile, defines) + " failed to link:\n" + log};
  }
  return program;
}

}  // namespace

Result<Program> buildProgram(const std::string& vertexFile, const std::string& fragmentFile,
                             const std::vector<std::string>& defines) {
  return link(compileSource(GL_VERTEX_SHADER, vertexFile, assembleShader(vertexFile, defines), defines),
              compileSource(GL_FRAGMENT_SHADER, fragmentFile, assembleShader(fragmentFile, defines), defines), vertexFile,
              fragmentFile, defines);
}

Result<Program> buildProgramFromText(const std::string& vertexText, const std::string& fragmentText,
                                     const std::vector<std::string>& defines) {
  return link(compileSource(GL_VERTEX_SHADER, "(vertex text)", assembleShaderText("(vertex text)", vertexText, defines), defines),
              compileSource(GL_FRAGMENT_SHADER, "(fragment text)", assembleShaderText("(fragment text)", fragmentText, defines), defines),
              "(vertex text)", "(fragment text)", defines);
}

void setUniform(GLuint p, const char* n, int v) { glUniform1i(glGetUniformLocation(p, n), v); }
void setUniform(GLuint p, const char* n, float v) { glUniform1f(glGetUniformLocation(p, n), v); }
void setUniform(GLuint p, const char* n, const glm::vec2& v) { glUniform2fv(glGetUniformLocation(p, n), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* n, const glm::vec3& v) { glUniform3fv(glGetUniformLocation(p, n), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* n, const glm::vec4& v) { glUniform4fv(glGetUniformLocation(p, n), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* n, const glm::ivec2& v) { glUniform2iv(glGetUniformLocation(p, n), 1, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* n, const glm::mat3& v) { glUniformMatrix3fv(glGetUniformLocation(p, n), 1, GL_FALSE, glm::value_ptr(v)); }
void setUniform(GLuint p, const char* n, const glm::mat4& v) { glUniformMatrix4fv(glGetUniformLocation(p, n), 1, GL_FALSE, glm::value_ptr(v)); }
void setUniformArray(GLuint p, const char* n, const glm::vec4* v, int c) { glUniform4fv(glGetUniformLocation(p, n), c, glm::value_ptr(*v)); }
void setUniformArray(GLuint p, const char* n, const glm::vec3* v, int c) { glUniform3fv(glGetUniformLocation(p, n), c, glm::value_ptr(*v)); }
void setUniformArray(GLuint p, const char* n, const float* v, int c) { glUniform1fv(glGetUniformLocation(p, n), c, v); }
void setUniformArray(GLuint p, const char* n, const glm::ivec2* v, int c) { glUniform2iv(glGetUniformLocation(p, n), c, glm::value_ptr(*v)); }

}  // namespace npr::gl
