// Texture set-up shared by every owner of a texture: the renderer's textures are all sampled
// with texelFetch or at one texel per pixel, so they get nearest filtering and a single level.
#pragma once

#include <epoxy/gl.h>

namespace npr::gl {

// For the texture bound to `target` on the active unit.
inline void setNearestSingleLevel(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
}

}  // namespace npr::gl
