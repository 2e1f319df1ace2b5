// The renderer's programs, built on first use and kept: toggling features back and forth
// costs no rebuild. Asked for by typed variants (program_variants.h) and keyed by what each
// variant turns into (its files and #define lines), so the key can never leave out a field
// that changes the program: two variants that give the same source are the same program.
#pragma once

#include <map>
#include <string>

#include "renderer/core/result.h"
#include "renderer/gl/program_variants.h"
#include "renderer/gl/shader_program.h"

namespace npr::gl {

// The cache's key for `variant`: its files and #define lines, in order.
std::string programKey(const ProgramVariant& variant);

class ProgramCache {
 public:
  // The program for `variant`; a build adds one to `builds` (the frame's shader-build counter).
  [[nodiscard]] Result<ShaderProgram*> get(const ProgramVariant& variant, int& builds);
  std::size_t size() const { return programs_.size(); }

 private:
  std::map<std::string, ShaderProgram> programs_;
};

}  // namespace npr::gl
