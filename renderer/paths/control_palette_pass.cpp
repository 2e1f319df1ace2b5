// Control-image palette layers over a path's surface (see control_palette_pass.h).
#include "renderer/paths/control_palette_pass.h"

#include "renderer/gl/pass_state.h"
#include "renderer/paths/lit_mesh_program.h"

namespace npr {
namespace {

// The shading a layer over `path` uses: the path's own where it lights on the GPU, per pixel
// over the per-triangle paths; none over paths without a palette.
std::optional<gl::MeshShading> layerShading(RenderPath path) {
  switch (path) {
    case RenderPath::Vertex: return gl::MeshShading::Vertex;
    case RenderPath::Smooth: return gl::MeshShading::Smooth;
    case RenderPath::Stencil:
    case RenderPath::Triangle:
    case RenderPath::Pixel: return gl::MeshShading::Pixel;
    case RenderPath::Reference:
    case RenderPath::LitTextured: break;
  }
  return std::nullopt;
}

}  // namespace

Status drawControlPalettes(FrameContext& f, RenderPath path) {
  if (f.output != gl::MeshOutput::Colour || (!f.shadowPalette && !f.occlusionPalette)) return okStatus();
  const std::optional<gl::MeshShading> shading = layerShading(path);
  if (!shading) return okStatus();
  // Occlusion first, shadow over it: alphas o then s give the weights (1-s)(1-o), o(1-s), s.
  const struct {
    const GpuPalette* palette;
    gl::MeshControl control;
  } layers[] = {{f.occlusionPalette, gl::MeshControl::Occlusion}, {f.shadowPalette, gl::MeshControl::Shadow}};
  for (const auto& layer : layers) {
    if (!layer.palette) continue;
    gl::MeshProgram variant = litMeshProgram(f, *shading, layer.palette);
    if (layer.control == gl::MeshControl::Shadow && variant.shadowLayers == 0) continue;
    if (layer.control == gl::MeshControl::Occlusion && !variant.occlusion && !variant.screenOcclusion) continue;
    variant.control = layer.control;
    Result<gl::ShaderProgram*> prog = f.program(variant);
    if (!prog) return Error{prog.error()};
    gl::apply(gl::pass::kControlPalette);
    bindLitMesh(f, **prog, variant, layer.palette);
    f.gpuMesh.drawAll();
    ++f.stats.drawCalls;
  }
  return okStatus();
}

}  // namespace npr
