// Texture units handed out (see texture_units.h).
#include "renderer/gl/texture_units.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace npr::gl {

TextureUnit claimTextureUnit() {
  static std::atomic<GLint> next{1};
  const GLint unit = next++;
  if (unit >= kMaxTextureUnits) {
    std::fprintf(stderr, "npr-viewer: internal error: more than %d texture units claimed\n", kMaxTextureUnits - 1);
    std::abort();
  }
  return TextureUnit{unit};
}

}  // namespace npr::gl
