// Shadow maps for every enabled light (`--shadows`): one depth layer per directional light
// (orthographic, fitted to the casters' bounding sphere), per spot light (perspective over its
// cone) and per point light outside the casters (perspective over the cone that holds them),
// six for a point light among them (one per axis direction), all in one depth-compare texture
// array that shaders/shadows.glsl reads. Maps live in model space, so they are redrawn only
// when a light moves relative to the model or the scene changes, not when the camera moves
// (a light that follows the camera moves every time the camera does).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/materials/gpu_materials.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/gl/texture_units.h"

namespace npr {

// The texture unit every light's shadow maps are bound on (gl/texture_units.h).
inline const gl::TextureUnit kShadowMapsUnit = gl::claimTextureUnit();

// A mesh that casts shadows, placed by its model's transform (model to scene space).
struct ShadowCaster {
  const GpuMesh* mesh;
  glm::mat4 transform{1.0f};
  // A see-through caster's materials (GpuMaterials::coverage): its cut-outs and screen doors
  // let light through as they let the eye (null: opaque).
  const GpuMaterials* materials = nullptr;
};

struct ShadowScene {
  std::vector<ShadowCaster> casters;
  glm::vec3 centre{0.0f};
  float casterRadius = 1.0f;  // a sphere about `centre` holding every caster
  float sceneRadius = 1.0f;   // ... and every receiver (the ground plane)
  unsigned version = 0;       // changes whenever the casters do
};

class ShadowMaps {
 public:
  static constexpr int kSize = 2048;       // directional and spot maps
  static constexpr int kPointSize = 1024;  // when some light is a point light (six layers each)

  // Redraws the maps that changed for the lights of `lighting` (eye space of `view`).
  [[nodiscard]] Status update(const LightingState& lighting, const glm::mat4& view, const ShadowScene& scene,
                              gl::ProgramCache& programs, FrameStats& stats);
  void clear();
  // Layers in use (0: no enabled light has a map): what programs are compiled for.
  int layers() const { return layerCount_; }
  // shadows.glsl's uniforms and the depth array, for a frame seen through `view` (identity:
  // shadows.glsl then works in model space).
  void bind(gl::ShaderProgram& program, const glm::mat4& view) const;
  // Counts redraws: what results computed from the maps are keyed by.
  unsigned generation() const { return generation_; }
  // The enabled lights in the shader's order, in model space: (direction, 0) or (position, 1).
  std::vector<glm::vec4> lightKeys() const {
    std::vector<glm::vec4> keys;
    for (const LightMap& m : maps_) keys.push_back(m.key);
    return keys;
  }

 private:
  struct LightMap {
    int firstLayer = -1;
    bool point = false, perspective = false;
    float texelSize = 0.0f;        // model units per texel (at distance 1 when perspective)
    glm::vec3 positionModel{0.0f};
    std::array<glm::mat4, 6> viewProjection{};  // model -> light clip, per layer
    glm::vec4 key{0.0f};           // position (or direction) in model space
    glm::vec4 spotKey{0.0f};       // spot direction and cutoff
  };
  std::vector<LightMap> maps_;     // per enabled light, in order (the shader's light index)
  gl::Texture depth_;              // GL_TEXTURE_2D_ARRAY, depth compare
  gl::Framebuffer fbo_;
  int size_ = 0, layerCount_ = 0, allocatedLayers_ = 0;
  unsigned sceneVersion_ = ~0u;
  unsigned generation_ = 0;
};

}  // namespace npr
