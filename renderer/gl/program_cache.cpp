// Program cache (see program_cache.h).
#include "renderer/gl/program_cache.h"

namespace npr::gl {

std::string programKey(const ProgramSource& src) {
  std::string key = src.vertexFile + "|" + src.geometryFile + "|" + src.fragmentFile + "|" + src.computeFile;
  for (const std::string& d : src.defines) key += "|" + d;
  return key;
}

Result<ShaderProgram*> ProgramCache::get(const ProgramSource& src, int& builds) {
  std::string key = programKey(src);
  auto it = programs_.find(key);
  if (it != programs_.end()) {
    it->second.lastUse = frame_;
    return &it->second.program;
  }
  Result<ShaderProgram> p = src.computeFile.empty() ? ShaderProgram::build(src.vertexFile, src.fragmentFile, src.defines, src.geometryFile)
                                                    : ShaderProgram::buildCompute(src.computeFile, src.defines);
  if (!p) return Error{p.error()};
  ++builds;
  return &programs_.emplace(std::move(key), Entry{std::move(*p), frame_}).first->second.program;
}

void ProgramCache::startFrame() {
  ++frame_;
  while (programs_.size() > capacity_) {
    auto oldest = programs_.begin();
    for (auto it = programs_.begin(); it != programs_.end(); ++it)
      if (it->second.lastUse < oldest->second.lastUse) oldest = it;
    programs_.erase(oldest);
    ++evictions_;
  }
}

}  // namespace npr::gl
