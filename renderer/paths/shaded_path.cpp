// Single-pass GPU-lit paths (see shaded_path.h).
#include "renderer/paths/shaded_path.h"

#include "renderer/gl/pass_state.h"
#include "renderer/paths/lit_mesh_program.h"
#include "renderer/paths/turn_resolve_pass.h"

namespace npr {

Status ShadedPath::draw(FrameContext& f) {
  gl::MeshShading shading = gl::MeshShading::Pixel;
  switch (kind_) {
    case Kind::Vertex: shading = gl::MeshShading::Vertex; break;
    case Kind::Pixel: shading = gl::MeshShading::Pixel; break;
    case Kind::Smooth: shading = gl::MeshShading::Smooth; break;
    case Kind::LitTextured: shading = gl::MeshShading::LitTextured; break;
    case Kind::Reference: shading = f.settings.referenceGouraud ? gl::MeshShading::Gouraud : gl::MeshShading::Phong; break;
  }
  const GpuPalette* palette = kind_ != Kind::Reference ? f.palette : nullptr;
  gl::MeshProgram variant = litMeshProgram(f, shading, palette);
  // The palette paths' turns can wait for the resolve (the smooth path's two entries too).
  // A palette with rows blends the smooth path's rows too, which the resolve's buffer does not
  // hold: there the turns stay in place.
  const bool blend = kind_ == Kind::Smooth;
  const bool turns = kind_ == Kind::Vertex || kind_ == Kind::Pixel || (blend && !(palette && f.paletteAxis(palette).rows > 1));
  TurnResolvePass* resolve = turns && f.turnResolve && f.turnResolve->begin(f, blend) ? f.turnResolve : nullptr;
  if (resolve) {
    variant.deferTurn = true;
    variant.palette->orientBins = 0;
  }
  // Tone edges smoothed where one pass shows whole entries per pixel (the smooth path blends
  // anyway; a deferred turn shows its entry in the resolve, unsmoothed).
  variant.toneEdges = !resolve && palette && f.output == gl::MeshOutput::Colour && (kind_ == Kind::Vertex || kind_ == Kind::Pixel) &&
                      toneEdgesSmoothed(f.settings.aa);
  gl::apply(f.meshPass(resolve ? gl::pass::kMeshMarked : gl::pass::kMesh));
  if (!variant.materials || f.gpuMesh.materialRuns().empty()) {
    Result<gl::ShaderProgram*> prog = f.program(variant);
    if (!prog) {
      if (resolve) resolve->cancel();
      return Error{prog.error()};
    }
    bindLitMesh(f, **prog, variant, palette);
    f.gpuMesh.drawAll();
    ++f.stats.drawCalls;
    return resolve ? resolve->resolve(f) : okStatus();
  }
  // Material by material, each from uniforms, with the diffuse maps only where it has one: a
  // per-pixel table fetch and map lookup cost llvmpipe 11-14% of the 871K mesh's frame.
  variant.materialUniform = true;
  const bool anyMaps = variant.materialMaps;
  gl::ShaderProgram* bound[2] = {nullptr, nullptr};  // without, with maps
  for (const MaterialRun& run : f.gpuMesh.materialRuns()) {
    const bool mapped = anyMaps && f.materials.mapped(run.material);
    variant.materialMaps = mapped;
    gl::ShaderProgram*& p = bound[mapped ? 1 : 0];
    if (!p) {
      Result<gl::ShaderProgram*> prog = f.program(variant);
      if (!prog) {
        if (resolve) resolve->cancel();
        return Error{prog.error()};
      }
      p = *prog;
      bindLitMesh(f, *p, variant, palette);
    }
    p->use();
    f.materials.setMaterial(*p, run.material);
    f.gpuMesh.drawRun(run);
    ++f.stats.drawCalls;
  }
  return resolve ? resolve->resolve(f) : okStatus();
}

}  // namespace npr
