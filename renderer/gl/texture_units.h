// Texture units by name: each sampler a pass uses has its own unit, so no pass rebinds a unit
// another pass's program still samples (the image-space edges used to take units 0 and 1,
// the palette's and the background's).
#pragma once

#include <epoxy/gl.h>

namespace npr::gl {

enum class TextureUnit : GLint {
  Palette = 0,     // palette layers (GL_TEXTURE_2D_ARRAY)
  Background,      // palette background image
  LutIndex,        // matcher: nearest entry per tone bin
  LutBlend,        // matcher: bracketing entries and weight per tone bin
  Lut3D,           // matcher: colours mode grid
  EdgeNormals,     // image-space edges: the frame's normals
  EdgeDepth,       // image-space edges: the frame's depth
  MaterialTable,   // the mesh's materials (GL_TEXTURE_BUFFER)
  MaterialMaps,    // their diffuse maps (GL_TEXTURE_2D_ARRAY)
  StrokeAngles,    // the stencil path's per-pixel hatching angles
  PatternCoordinates,  // the stencil path's per-pixel object-space pattern coordinates
  ShadowMaps,      // every light's shadow maps (GL_TEXTURE_2D_ARRAY, depth compare)
  Brush,           // painterly strokes' brush coverage
  ScreenOcclusion,  // screen-space ambient occlusion: the frame's (blurred) result, and its passes' inputs
  ScreenOcclusionDepth,
  ScreenOcclusionNormals,
  GroundShadows,   // the ground plane's visibility per light
  TurnBuffer,      // a mesh pass's stroke angle and entry per pixel, for the turn resolve
  LineTexture,     // a line set's stroke texture (lines/stroke_textures.h)
};

inline GLint unitIndex(TextureUnit u) { return static_cast<GLint>(u); }
// Binds `texture` to `target` on unit `u` and leaves unit 0 active, as every pass expects.
inline void bindTexture(TextureUnit u, GLenum target, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(u));
  glBindTexture(target, texture);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace npr::gl
