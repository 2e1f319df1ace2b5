// A mesh's own appearance on the GPU, for the GPU-lit paths with --materials on: the material
// table (a buffer texture, one RGBA32UI texel per material, colours in 8 bits a channel; see
// shaders/material.glsl), the diffuse maps as one mipmapped texture array (every map resized
// to a common size). The mesh's vertex colours, texture coordinates, material indices and
// map averages are vertex attributes (gpu_mesh.h).
//
// A see-through mesh (Mesh::seeThrough: glTF's MASK and BLEND) keeps its table and maps bound
// in every mesh pass, lit on the GPU or not: each fragment's coverage is its material's alpha
// (its row's fourth byte) times its map's, and fragments not covered are discarded
// (shaders/material.glsl). A mask cuts at its cutoff. A blend is drawn as screen-door
// transparency: covered where the alpha exceeds a 4x4 ordered-dither threshold. That needs no
// sorting and no second pass, works alike in the stencil path's buckets, the per-triangle
// paths and the GPU-lit ones, and reads as a halftone beside the palettes' own screens; its
// cost is the dither's grain, where a sorted blend would be smooth.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/programs/program_variants.h"
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
  // Whether some fragments are discarded by their material's alpha (Mesh::seeThrough).
  bool coverage() const { return coverage_; }
  // A mesh program drawing this mesh, with its coverage when it is see-through (the maps read
  // where the program does not already choose them by material); bind() then gives it the
  // table and maps.
  void addCoverage(gl::MeshProgram& variant) const {
    if (!coverage_) return;
    variant.alphaCoverage = true;
    if (!variant.materials && !variant.materialUniform) variant.materialMaps = hasMaps();
  }

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
  void uploadMaps(const Mesh& mesh);

  bool active_ = false;
  bool coverage_ = false;
  gl::Buffer tableBuffer_;
  gl::Texture table_, maps_;
  int mapSide_ = 0;
  std::vector<glm::uvec4> rows_;
};

}  // namespace npr
