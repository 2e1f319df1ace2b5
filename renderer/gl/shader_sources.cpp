// Resolves embedded shader files into compilable sources (see shader_sources.h).
#include "renderer/gl/shader_sources.h"

#include <sstream>

namespace npr {
namespace {

const char* findShader(const std::string& name) {
  for (const ShaderSource& s : embeddedShaders())
    if (name == s.name) return s.text;
  return nullptr;
}

Result<std::string> expandText(const std::string& name, const char* text, int depth);

Result<std::string> expandIncludes(const std::string& name, int depth) {
  if (depth > 8) return Error{"shader include depth exceeded at " + name};
  const char* text = findShader(name);
  if (!text) return Error{"no embedded shader named '" + name + "'"};
  return expandText(name, text, depth);
}

Result<std::string> expandText(const std::string& name, const char* text, int depth) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    const auto pos = line.find("#include");
    if (pos != std::string::npos && line.find_first_not_of(" \t") == pos) {
      const auto a = line.find('"'), b = line.rfind('"');
      if (a == std::string::npos || b <= a) return Error{name + ": malformed #include line: " + line};
      Result<std::string> inc = expandIncludes(line.substr(a + 1, b - a - 1), depth + 1);
      if (!inc) return inc;
      out += *inc;
    } else if (line.rfind("#version", 0) != 0) {
      out += line;
      out += '\n';
    }
  }
  return out;
}

}  // namespace

namespace {
// Every stage is GLSL 3.30 (the context the viewer asks for); compute needs 4.30, and is only
// built where the context has it (gpu_deformation.h).
Result<std::string> withHeader(Result<std::string> body, const std::vector<std::string>& defines, bool compute) {
  if (!body) return body;
  std::string src = compute ? "#version 430 core\n" : "#version 330 core\n";
  for (const std::string& d : defines) src += "#define " + d + "\n";
  src += "#line 1\n";
  src += *body;
  return src;
}
}  // namespace

Result<std::string> assembleShader(const std::string& name, const std::vector<std::string>& defines) {
  const bool compute = name.size() > 5 && name.compare(name.size() - 5, 5, ".comp") == 0;
  return withHeader(expandIncludes(name, 0), defines, compute);
}

}  // namespace npr
