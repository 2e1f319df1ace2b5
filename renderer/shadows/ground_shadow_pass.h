// The ground plane's shadows as a texture: each enabled light's visibility (up to four, one per
// channel) over the ground's square, computed from the shadow maps whenever they are redrawn.
// The ground is flat and fixed to the model, so what falls on it changes only with the maps;
// reading one filtered texel per pixel instead of filtering every light's map per pixel is
// what makes shadows affordable when the ground fills half the frame on a software rasterizer.
// The per-pixel shadings read it for the ground (lighting.glsl's GROUND_SHADOW_MAP).
#pragma once

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gl/texture_target.h"
#include "renderer/mesh/mesh.h"
#include "renderer/shadows/shadow_maps.h"

namespace npr {

class GroundShadowPass {
 public:
  static constexpr int kSize = 1024;
  static constexpr int kMaxLights = 4;

  // Brings the texture up to date with `maps` for the ground `ground` (groundPlane's square at
  // one height); false in `ready()` when there are more lights than channels.
  [[nodiscard]] Status update(const ShadowMaps& maps, const Mesh& ground, unsigned groundVersion, gl::ProgramCache& programs,
                              const gl::VertexArray& emptyVao, FrameStats& stats);
  bool ready() const { return ready_; }
  // Binds the texture and where it lies for a program compiled with GROUND_SHADOW_MAP.
  void bind(gl::ShaderProgram& program) const;

 private:
  gl::TextureTarget target_;  // drawn into
  // What the ground samples: a copy of target_'s colour made after each redraw. On llvmpipe the
  // ground's draw, sampling target_ itself, waited every frame for everything drawn before it
  // (render() blocked 14 ms per bunny frame with shadows and the ground: bench_frames --shadows
  // --static-light, CPU ms); sampling a texture that never was a render target does not wait.
  gl::Texture sampled_;
  glm::vec4 rect_{0.0f};  // x0, z0, x1, z1 of the ground's square, model space
  unsigned mapsGeneration_ = ~0u, groundVersion_ = ~0u;
  bool ready_ = false;
};

}  // namespace npr
