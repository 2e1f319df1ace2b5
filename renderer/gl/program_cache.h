// The renderer's programs, built on first use and kept: toggling features back and forth
// costs no rebuild. Keyed by typed variants (program_variants.h).
#pragma once

#include <map>

#include "renderer/core/result.h"
#include "renderer/gl/program_variants.h"
#include "renderer/gl/shader_program.h"

namespace npr::gl {

class ProgramCache {
 public:
  // The program for `variant`; a build adds one to `builds` (the frame's shader-build counter).
  [[nodiscard]] Result<ShaderProgram*> get(const ProgramVariant& variant, int& builds);

 private:
  std::map<ProgramVariant, ShaderProgram> programs_;
};

}  // namespace npr::gl
