// The frame's surfaces as depth layers, for hidden lines limited by occlusion level
// (LineSet::occlusion, Blender Line Art's occlusion levels): layer 0 is the frame's own depth,
// copied from the bound framebuffer after the surfaces; layer k the nearest surface behind
// layer k - 1 at each pixel (depth peeling; every face counts, so a closed part's near and far
// sides are two layers). A hidden line with a level-k limit is left out where layer k lies in
// front of it: more than k surfaces hide it. Built only in frames with such a set, one
// depth-only pass of the scene per level.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/texture_units.h"
#include "renderer/mesh/placed_mesh.h"

namespace npr {

inline const gl::TextureUnit kOcclusionLimitUnit = gl::claimTextureUnit();  // read by the hidden lines
inline const gl::TextureUnit kPeelUnit = gl::claimTextureUnit();            // the layer in front, while peeling

class OcclusionLayers {
 public:
  // Layers 0..levels over `viewport` (each texture's corner holds it); leaves the framebuffer
  // and viewport that were bound. `radius`: the scene's, which the depth tolerance scales with.
  [[nodiscard]] Status build(int levels, const std::vector<PlacedMesh>& meshes, float radius, const glm::ivec4& viewport, gl::ProgramCache& programs,
                             FrameStats& stats);
  GLuint limit(int level) const { return layers_[std::size_t(level)].id(); }
  // Eye units within which a line on a surface, or a surface on the layer in front, is not
  // behind it (depth precision and the differences between programs' positions).
  float tolerance() const { return tolerance_; }

 private:
  std::vector<gl::Texture> layers_;
  gl::Framebuffer fbo_;
  glm::ivec2 size_{0};
  float tolerance_ = 0.0f;
};

}  // namespace npr
