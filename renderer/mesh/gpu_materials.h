// A mesh's own appearance on the GPU, for the GPU-lit paths with --materials on: the material
// table (a buffer texture, one RGBA32UI texel per material, colours in 8 bits a channel; see
// shaders/material.glsl), the diffuse maps as one mipmapped texture array (every map resized
// to a common size). The mesh's vertex colours, texture coordinates, material indices and
// map averages are vertex attributes (gpu_mesh.h).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/shader_program.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh.h"

namespace npr {

class GpuMaterials {
 public:
  // Uploads the table and the maps; nothing when the mesh has no appearance.
  void upload(const Mesh& mesh);
  void clear();
  bool active() const { return active_; }
  bool hasMaps() const { return maps_.id() != 0; }
  int mapSide() const { return mapSide_; }

  // Rewrites the table where it changed (the default material follows the lighting state).
  void update(const Mesh& mesh, const LightingState& lighting, FrameStats& stats);
  // Binds the table and the maps and points the program's samplers at them.
  void bind(gl::ShaderProgram& program) const;
  // For a program drawing one material (MATERIAL_UNIFORM): its table row as uniforms, the
  // same values the table gives.
  void setMaterial(gl::ShaderProgram& program, std::size_t material) const;
  // Whether `material`'s row names a diffuse map.
  bool mapped(std::size_t material) const;

 private:
  bool active_ = false;
  gl::Buffer tableBuffer_;
  gl::Texture table_, maps_;
  int mapSide_ = 0;
  std::vector<glm::uvec4> rows_;
};

}  // namespace npr
