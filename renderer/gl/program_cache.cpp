// Program cache (see program_cache.h).
#include "renderer/gl/program_cache.h"

namespace npr::gl {

Result<ShaderProgram*> ProgramCache::get(const ProgramVariant& variant, int& builds) {
  auto it = programs_.find(variant);
  if (it != programs_.end()) return &it->second;
  const ProgramSource src = programSource(variant);
  Result<ShaderProgram> p = ShaderProgram::build(src.vertexFile, src.fragmentFile, src.defines, src.geometryFile);
  if (!p) return Error{p.error()};
  ++builds;
  return &programs_.emplace(variant, std::move(*p)).first->second;
}

}  // namespace npr::gl
