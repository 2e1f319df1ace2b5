// Texture units, handed out: each sampler a pass uses claims a unit of its own once, at
// start-up, beside the code that binds it (`const gl::TextureUnit kFooUnit =
// gl::claimTextureUnit();`), so no pass rebinds a unit another pass's program still samples
// (the image-space edges used to take units 0 and 1, the palette's and the background's) and
// no list here names the passes. Unit 0 is never handed out: uploads bind there.
#pragma once

#include <epoxy/gl.h>

namespace npr::gl {

struct TextureUnit {
  GLint index;
};

// Fewer than GL's least GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS (48 in OpenGL 3.3): a unit's index
// may go up to that, while each program stage samples at most 16 of them at once.
inline constexpr GLint kMaxTextureUnits = 48;

// The next unit no one has claimed (from 1). Claiming more than kMaxTextureUnits - 1 is a
// programmer error: it aborts with a message.
TextureUnit claimTextureUnit();

inline GLint unitIndex(TextureUnit u) { return u.index; }
// Binds `texture` to `target` on unit `u` and leaves unit 0 active, as every pass expects.
inline void bindTexture(TextureUnit u, GLenum target, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(u.index));
  glBindTexture(target, texture);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace npr::gl
