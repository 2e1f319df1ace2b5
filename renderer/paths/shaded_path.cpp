// Single-pass GPU-lit paths (see shaded_path.h).
#include "renderer/paths/shaded_path.h"

#include "renderer/gl/pass_state.h"
#include "renderer/paths/lit_mesh_program.h"

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
  const gl::MeshProgram variant = litMeshProgram(f, shading, palette);
  Result<gl::ShaderProgram*> prog = f.program(variant);
  if (!prog) return Error{prog.error()};
  gl::apply(gl::pass::kMesh);
  bindLitMesh(f, **prog, variant, palette);
  f.gpuMesh.drawAll();
  ++f.stats.drawCalls;
  return okStatus();
}

}  // namespace npr
