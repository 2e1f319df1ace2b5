// Compiling, linking and uniform lookup (see shader_program.h).
#include "renderer/gl/shader_program.h"

#include <cctype>
#include <cstring>
#include <optional>

#include <glm/gtc/type_ptr.hpp>

#include "renderer/gl/gl_debug.h"
#include "renderer/gl/shader_sources.h"

namespace npr::gl {
namespace {

#ifdef NDEBUG
bool g_strict = false;
#else
bool g_strict = true;
#endif

std::string variantLabel(const std::string& files, const std::vector<std::string>& defines) {
  std::string s = files;
  for (const auto& d : defines) s += " -D" + d;
  return s;
}

std::string infoLog(GLuint object, bool isProgram) {
  GLint len = 0;
  isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<size_t>(len > 0 ? len : 1), '\0');
  isProgram ? glGetProgramInfoLog(object, len, nullptr, log.data()) : glGetShaderInfoLog(object, len, nullptr, log.data());
  return log;
}

Result<Shader> compile(GLenum type, const std::string& text, const std::string& label) {
  Shader shader(glCreateShader(type));
  const char* src = text.c_str();
  glShaderSource(shader.id(), 1, &src, nullptr);
  glCompileShader(shader.id());
  GLint ok = 0;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) return Error{"shader " + label + " failed to compile:\n" + infoLog(shader.id(), false)};
  return shader;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `name` occurs in `text` as a whole identifier.
bool mentions(const std::string& text, const char* name) {
  const size_t n = std::strlen(name);
  for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    const bool startOk = at == 0 || !isIdentifierChar(text[at - 1]);
    const bool endOk = at + n >= text.size() || !isIdentifierChar(text[at + n]);
    if (startOk && endOk) return true;
  }
  return false;
}

}  // namespace

void setStrictUniforms(bool on) { g_strict = on; }

Result<ShaderProgram> ShaderProgram::build(const std::string& vertexFile, const std::string& fragmentFile,
                                           const std::vector<std::string>& defines, const std::string& geometryFile) {
  Result<std::string> vsText = assembleShader(vertexFile, defines);
  if (!vsText) return Error{vsText.error()};
  Result<std::string> fsText = assembleShader(fragmentFile, defines);
  if (!fsText) return Error{fsText.error()};
  Result<Shader> vs = compile(GL_VERTEX_SHADER, *vsText, variantLabel(vertexFile, defines));
  if (!vs) return Error{vs.error()};
  Result<Shader> fs = compile(GL_FRAGMENT_SHADER, *fsText, variantLabel(fragmentFile, defines));
  if (!fs) return Error{fs.error()};
  std::string gsText;
  std::optional<Shader> gs;
  if (!geometryFile.empty()) {
    Result<std::string> text = assembleShader(geometryFile, defines);
    if (!text) return Error{text.error()};
    Result<Shader> compiled = compile(GL_GEOMETRY_SHADER, *text, variantLabel(geometryFile, defines));
    if (!compiled) return Error{compiled.error()};
    gsText = std::move(*text);
    gs = std::move(*compiled);
  }
  ShaderProgram p;
  p.label_ = variantLabel(vertexFile + (gs ? "+" + geometryFile : "") + "+" + fragmentFile, defines);
  p.program_ = Program(glCreateProgram());
  glAttachShader(p.program_.id(), vs->id());
  if (gs) glAttachShader(p.program_.id(), gs->id());
  glAttachShader(p.program_.id(), fs->id());
  glLinkProgram(p.program_.id());
  GLint ok = 0;
  glGetProgramiv(p.program_.id(), GL_LINK_STATUS, &ok);
  glDetachShader(p.program_.id(), vs->id());
  glDetachShader(p.program_.id(), fs->id());
  if (gs) glDetachShader(p.program_.id(), gs->id());
  if (!ok) return Error{"program " + p.label_ + " failed to link:\n" + infoLog(p.program_.id(), true)};
  p.source_ = *vsText + gsText + *fsText;
  return p;
}

Result<ShaderProgram> ShaderProgram::buildCompute(const std::string& computeFile, const std::vector<std::string>& defines) {
  Result<std::string> text = assembleShader(computeFile, defines);
  if (!text) return Error{text.error()};
  Result<Shader> cs = compile(GL_COMPUTE_SHADER, *text, variantLabel(computeFile, defines));
  if (!cs) return Error{cs.error()};
  ShaderProgram p;
  p.label_ = variantLabel(computeFile, defines);
  p.program_ = Program(glCreateProgram());
  glAttachShader(p.program_.id(), cs->id());
  glLinkProgram(p.program_.id());
  GLint ok = 0;
  glGetProgramiv(p.program_.id(), GL_LINK_STATUS, &ok);
  glDetachShader(p.program_.id(), cs->id());
  if (!ok) return Error{"program " + p.label_ + " failed to link:\n" + infoLog(p.program_.id(), true)};
  p.source_ = std::move(*text);
  return p;
}

namespace {
UniformTraffic g_uniformTraffic;
}  // namespace

UniformTraffic uniformTraffic() { return g_uniformTraffic; }

ShaderProgram::Uniform& ShaderProgram::uniform(const char* name) {
  auto it = uniforms_.find(name);
  if (it != uniforms_.end()) return it->second;
  const GLint loc = glGetUniformLocation(program_.id(), name);
  if (loc < 0 && g_strict && !mentions(source_, name))
    reportError("uniform '" + std::string(name) + "' is declared by no stage of program " + label_);
  Uniform& u = uniforms_[name];
  u.location = loc;
  return u;
}

GLint ShaderProgram::changed(const char* name, const void* value, std::size_t bytes) {
  Uniform& u = uniform(name);
  if (u.location < 0) return -1;
  const auto* v = static_cast<const unsigned char*>(value);
  if (u.sent.size() == bytes && std::memcmp(u.sent.data(), v, bytes) == 0) {
    ++g_uniformTraffic.unchanged;
    return -1;
  }
  u.sent.assign(v, v + bytes);
  ++g_uniformTraffic.sent;
  return u.location;
}

// Each setter sends only a changed value (changed() gives -1 otherwise; GL ignores location -1,
// but the call is skipped outright).
#define NPR_SET(DATA, BYTES, CALL)                          \
  do {                                                      \
    const GLint loc = changed(n, DATA, BYTES);              \
    if (loc >= 0) CALL;                                     \
  } while (false)

void ShaderProgram::set(const char* n, int v) { NPR_SET(&v, sizeof v, glUniform1i(loc, v)); }
void ShaderProgram::set(const char* n, unsigned v) { NPR_SET(&v, sizeof v, glUniform1ui(loc, v)); }
void ShaderProgram::set(const char* n, float v) { NPR_SET(&v, sizeof v, glUniform1f(loc, v)); }
void ShaderProgram::set(const char* n, const glm::vec2& v) { NPR_SET(&v, sizeof v, glUniform2fv(loc, 1, glm::value_ptr(v))); }
void ShaderProgram::set(const char* n, const glm::vec3& v) { NPR_SET(&v, sizeof v, glUniform3fv(loc, 1, glm::value_ptr(v))); }
void ShaderProgram::set(const char* n, const glm::vec4& v) { NPR_SET(&v, sizeof v, glUniform4fv(loc, 1, glm::value_ptr(v))); }
void ShaderProgram::set(const char* n, const glm::ivec2& v) { NPR_SET(&v, sizeof v, glUniform2iv(loc, 1, glm::value_ptr(v))); }
void ShaderProgram::set(const char* n, const glm::mat3& v) { NPR_SET(&v, sizeof v, glUniformMatrix3fv(loc, 1, GL_FALSE, glm::value_ptr(v))); }
void ShaderProgram::set(const char* n, const glm::mat4& v) { NPR_SET(&v, sizeof v, glUniformMatrix4fv(loc, 1, GL_FALSE, glm::value_ptr(v))); }
void ShaderProgram::setArray(const char* n, const glm::vec4* v, int c) { NPR_SET(v, sizeof *v * c, glUniform4fv(loc, c, glm::value_ptr(*v))); }
void ShaderProgram::setArray(const char* n, const glm::vec3* v, int c) { NPR_SET(v, sizeof *v * c, glUniform3fv(loc, c, glm::value_ptr(*v))); }
void ShaderProgram::setArray(const char* n, const glm::mat4* v, int c) { NPR_SET(v, sizeof *v * c, glUniformMatrix4fv(loc, c, GL_FALSE, glm::value_ptr(*v))); }
void ShaderProgram::setArray(const char* n, const int* v, int c) { NPR_SET(v, sizeof *v * c, glUniform1iv(loc, c, v)); }
void ShaderProgram::setArray(const char* n, const unsigned* v, int c) { NPR_SET(v, sizeof *v * c, glUniform1uiv(loc, c, v)); }
void ShaderProgram::setArray(const char* n, const glm::vec2* v, int c) { NPR_SET(v, sizeof *v * c, glUniform2fv(loc, c, glm::value_ptr(*v))); }
void ShaderProgram::setArray(const char* n, const float* v, int c) { NPR_SET(v, sizeof *v * c, glUniform1fv(loc, c, v)); }
void ShaderProgram::setArray(const char* n, const glm::ivec2* v, int c) { NPR_SET(v, sizeof *v * c, glUniform2iv(loc, c, glm::value_ptr(*v))); }

#undef NPR_SET

}  // namespace npr::gl
