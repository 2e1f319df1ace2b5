// The one-pass per-triangle path (see triangle_path.h).
#include "renderer/paths/triangle_path.h"

#include "renderer/gl/pass_state.h"
#include "renderer/paths/turn_resolve_pass.h"
#include "renderer/paths/triangle_lighting_ahead.h"

namespace npr {

Status updateTriangleShading(FrameContext& f) {
  const PaletteAxis axis = f.paletteAxis();
  f.triangles.expectRows(axis.rows > 1);
  const TriangleLighting where = f.settings.triangleLighting;
  const bool gpu = where == TriangleLighting::Gpu || (where == TriangleLighting::Auto && f.shadows);
  if (gpu && !f.drawMaterials()) {
    std::vector<std::uint8_t> entries;
    const GpuTriangleLightingInputs in{f.lighting, f.camera, *f.palette, f.settings.match, f.shadows, f.sceneView, f.occlusion, f.settings.occlusionStrength};
    if (Status st = f.triangles.gpu().shade(in, f.programs, f.stats, entries); !st) return st;
    f.triangles.setEntries(std::move(entries), f.palette->size(), f.stats);
  } else {
    f.triangles.update(f.lighting, f.camera.view, *f.palette->matcher(), f.palette->matcherId(), f.stats, f.settings.materials, f.occlusion,
                       f.settings.occlusionStrength);
  }
  // A palette with rows: each triangle's row from its centroid (stencil buckets of row and entry).
  f.triangles.applyRows(axis, f.palette->axisMap(), f.palette->columns(), f.camera.view, f.stats, f.axisDetail);
  return okStatus();
}

void TrianglePath::prepareScene(FrameView& frame) { lightTrianglesAhead(frame); }

Status TrianglePath::draw(FrameContext& f) {
  if (Status st = updateTriangleShading(f); !st) return st;
  gl::MeshProgram variant;
  variant.shading = gl::MeshShading::Triangle;  // lit on the CPU: no lighting in the shader
  variant.output = f.output;
  variant.palette = f.paletteVariant();
  variant.stroke = f.strokeSource();
  TurnResolvePass* resolve = f.turnResolve && f.turnResolve->begin(f, false) ? f.turnResolve : nullptr;
  if (resolve) {
    variant.deferTurn = true;
    variant.palette->orientBins = 0;
  }
  Result<gl::ShaderProgram*> prog = f.program(variant);
  if (!prog) {
    if (resolve) resolve->cancel();
    return Error{prog.error()};
  }
  gl::ShaderProgram& p = **prog;
  gl::apply(f.meshPass(resolve ? gl::pass::kMeshMarked : gl::pass::kMesh));
  p.use();
  setMeshTransform(p, f.camera);
  f.bindPalette(p);
  f.gpuMesh.bindIndices(f.triangles.bucketIndices());
  for (int k = 0; k < f.triangles.buckets(); ++k) {
    const std::uint32_t count = f.triangles.bucketCount(k);
    if (count == 0) continue;
    p.set("uEntry", k);
    f.gpuMesh.drawTriangles(f.triangles.bucketFirst(k), count);
    ++f.stats.drawCalls;
  }
  return resolve ? resolve->resolve(f) : okStatus();
}

}  // namespace npr
