// Access to the GLSL files of shaders/, embedded into the binary at build time, and the
// small preprocessor that resolves their #include lines and prepends #define variants.
#pragma once

#include <string>
#include <vector>

#include "renderer/core/result.h"

namespace npr {

struct ShaderSource {
  const char* name;
  const char* text;
};

const std::vector<ShaderSource>& embeddedShaders();

// Returns the named shader with #version first, then `defines` (each "NAME" or "NAME VALUE"),
// then the text with every `#include "file.glsl"` replaced by that embedded file.
Result<std::string> assembleShader(const std::string& name, const std::vector<std::string>& defines);

}  // namespace npr
