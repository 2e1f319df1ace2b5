// The geometry pass (see geometry_pass.h).
#include "renderer/passes/geometry_pass.h"

#include "renderer/gl/pass_state.h"
#include "renderer/materials/gpu_materials.h"
#include "renderer/programs/program_variants.h"

namespace npr {

Status drawGeometry(const PlacedMesh& m, GeometryOutput output, gl::ProgramCache& programs, FrameStats& stats) {
  gl::MeshProgram variant;
  variant.shading = output == GeometryOutput::EyePosition ? gl::MeshShading::EyePosition : gl::MeshShading::EyeNormal;
  if (m.materials) m.materials->addCoverage(variant);
  Result<gl::ShaderProgram*> prog = programs.get(variant, stats.shaderBuilds);
  if (!prog) return Error{prog.error()};
  gl::apply(gl::pass::kMesh);
  (*prog)->use();
  if (variant.alphaCoverage) m.materials->bind(**prog);
  setMeshTransform(**prog, m.camera);
  m.mesh->drawAll();
  ++stats.drawCalls;
  return okStatus();
}

}  // namespace npr
