// What a surface pass is handed for one part of the scene (a model, a per-material part, the
// ground): its camera, mesh, palette, pattern placement and the frame's shared resources, and
// the features' shares of its program (SurfaceInput). The render paths (paths/render_pass.h),
// the passes they share (passes/) and the features (features/) all read it.
#pragma once

#include <array>
#include <cstddef>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/pass_state.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/materials/gpu_materials.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/settings/render_settings.h"
#include "renderer/shading/triangle_shading_cache.h"
#include "renderer/shadows/shadow_maps.h"

namespace npr {

class TurnResolvePass;
struct FrameContext;

// A feature's share of the GPU-lit surface programs (paths/lit_mesh_program.h): what it adds to
// a pass's variant (a typed field, whose define selects its GLSL: a file of its own that
// mesh.frag includes) and what it binds. A feature hands it to each surface pass it reads into
// (Feature::shade, FrameContext::addInput), so the passes keep no field for it. Inputs add in
// the feature table's order: a later one may override an earlier one's choice (screen-space
// occlusion replaces the bake).
class SurfaceInput {
 public:
  virtual void addTo(gl::MeshProgram& variant, const FrameContext& frame) const = 0;
  virtual void bind(gl::ShaderProgram& program, const gl::MeshProgram& variant, const FrameContext& frame) const = 0;

 protected:
  ~SurfaceInput() = default;
};

struct FrameContext {
  const CameraMatrices& camera;  // placed by the model's transform (the scene's view times it)
  glm::ivec4 viewport;  // x, y, width, height in the bound framebuffer
  const RenderSettings& settings;
  const LightingState& lighting;
  const GpuMesh& gpuMesh;
  const Mesh& mesh;
  const GpuMaterials& materials;      // active when the mesh has an appearance
  const GpuPalette* palette;         // set whenever the path uses a palette
  const PatternPlacement& pattern;   // how every palette's textures lie on this model, this frame
  TriangleShadingCache& triangles;   // shared by the per-triangle paths
  gl::ProgramCache& programs;
  FrameStats& stats;
  const gl::VertexArray& emptyVao;   // for full-screen triangles (vertices made in the shader)
  // Palette paths write their texels, or the selection behind them (tests, the benchmark).
  gl::MeshOutput output = gl::MeshOutput::Colour;
  // This frame's shadow maps, when shadows are on and some light has one, and the baked ambient
  // occlusion per vertex of this mesh, when on and baked: what the per-triangle paths light with
  // (on the CPU or the GPU); the GPU-lit programs take theirs as inputs. Maps are bound with the
  // scene's view (eye to scene space), not the model's.
  const ShadowMaps* shadows = nullptr;
  glm::mat4 sceneView{1.0f};
  const std::vector<float>* occlusion = nullptr;
  // The features' inputs to this pass's GPU-lit programs (SurfaceInput), in table order.
  static constexpr std::size_t kMaxInputs = 8;
  std::array<const SurfaceInput*, kMaxInputs> inputs{};
  std::size_t inputCount = 0;
  void addInput(const SurfaceInput* input) {
    if (inputCount < kMaxInputs) inputs[inputCount++] = input;
  }
  // Control-image palettes (passes/control_palette_pass.h), when loaded.
  const GpuPalette* shadowPalette = nullptr;
  const GpuPalette* occlusionPalette = nullptr;
  // Set where this frame's triangle, vertex, pixel or smooth pass leaves its turned lookups to one
  // pass per pixel after it (passes/turn_resolve_pass.h).
  TurnResolvePass* turnResolve = nullptr;
  // The model's detail (a palette with `axis detail` picks its row by it).
  float axisDetail = 0.0f;
  // Set where no back face can show (a closed mesh wholly beyond the near plane, Mesh::closed):
  // the mesh passes drop them in the rasterizer. Drawn first in an unsorted order, they would
  // pass the depth test and be shaded, then be covered (on the 871K torus, about a third of
  // the stencil path's frame).
  bool cullBackFaces = false;
  // A mesh pass's preset with that culling.
  gl::PassState meshPass(gl::PassState preset) const {
    if (cullBackFaces) preset.cull = GL_BACK;
    return preset;
  }

  // A palette's program variant for this output (the frame's palette, or another drawn in the
  // same frame: a control palette); selections are the same turned or not, so they ignore the
  // orientation.
  gl::PaletteVariant paletteVariant(const GpuPalette* p = nullptr) const {
    gl::PaletteVariant v = (p ? p : palette)->variant(settings.match, pattern);
    if (output != gl::MeshOutput::Colour) v.orientBins = 0;
    v.patternRest = v.pattern == gl::PatternMapping::Object && gpuMesh.deforms();
    if (paletteAxis(p).rows < 2) v.rows = 1;  // a palette with rows drawn with its first only
    // Crisp tone: where the palette has thresholds, with intensity matching (its blend's first
    // entry is the darker level, which palette.glsl's toneBetween relies on).
    v.toneThreshold = output == gl::MeshOutput::Colour && settings.toneBlend == ToneBlend::Threshold && settings.match == MatchMode::Intensity &&
                      (p ? p : palette)->hasToneThresholds();
    return v;
  }
  // The palette's second axis as this frame draws it: none when --no-palette-axis.
  PaletteAxis paletteAxis(const GpuPalette* p = nullptr) const { return settings.paletteAxis ? (p ? p : palette)->axis() : PaletteAxis{}; }
  // Where a mesh pass with the palette takes each pixel's stroke angle from.
  gl::StrokeSource strokeSource(const GpuPalette* p = nullptr) const {
    return output == gl::MeshOutput::Colour ? (p ? p : palette)->strokeSource(pattern) : gl::StrokeSource::None;
  }
  void bindPalette(gl::ShaderProgram& program, const GpuPalette* p = nullptr) const {
    (p ? p : palette)->bind(program, pattern, output == gl::MeshOutput::Colour);
    if ((p ? p : palette)->axis().kind == PaletteAxisKind::Detail) program.set("uAxisDetail", axisDetail);
  }

  // Whether this frame lights with the mesh's own materials.
  bool drawMaterials() const { return settings.materials && materials.active(); }

  [[nodiscard]] Result<gl::ShaderProgram*> program(const gl::ProgramVariant& variant) {
    return programs.get(variant, stats.shaderBuilds);
  }
  // A mesh pass's program: on a see-through mesh with its coverage (every pass drawing the
  // surface leaves out the same fragments), the material table and maps bound to it.
  [[nodiscard]] Result<gl::ShaderProgram*> program(gl::MeshProgram variant) {
    materials.addCoverage(variant);
    Result<gl::ShaderProgram*> p = programs.get(variant, stats.shaderBuilds);
    if (p && variant.alphaCoverage) {
      (*p)->use();
      materials.bind(**p);
    }
    return p;
  }
};

}  // namespace npr
