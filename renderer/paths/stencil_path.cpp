// The original stencil-bucket algorithm (see stencil_path.h).
#include "renderer/paths/stencil_path.h"

#include "renderer/gl/pass_state.h"

namespace npr {

Status StencilPath::draw(FrameContext& f) {
  if (f.output != gl::MeshOutput::Colour) return selection_.draw(f);
  const RenderSettings& s = f.settings;
  if (Status st = updateTriangleShading(f); !st) return st;
  if (s.stencilScissor) f.triangles.updateBounds(f.camera.projection * f.camera.view, {f.viewport.z, f.viewport.w}, f.stats);

  gl::MeshProgram maskVariant;
  maskVariant.shading = gl::MeshShading::Mask;
  Result<gl::ShaderProgram*> mask = f.program(maskVariant);
  if (!mask) return Error{mask.error()};
  Result<gl::ShaderProgram*> bgQuad = f.program(gl::QuadProgram{gl::QuadProgram::Kind::Background, f.palette->backgroundImage()});
  if (!bgQuad) return Error{bgQuad.error()};
  const gl::StrokeSource stroke = f.strokeSource();
  const bool angleBuffer = stroke == gl::StrokeSource::Field || stroke == gl::StrokeSource::Light;
  Result<gl::ShaderProgram*> layerQuad =
      f.program(gl::QuadProgram{gl::QuadProgram::Kind::Layer, false, f.palette->patternMapping(), f.palette->layerSizesDiffer(), f.palette->filtered(),
                                     f.palette->orientBins(), angleBuffer});
  if (!layerQuad) return Error{layerQuad.error()};
  // Where the mesh is on screen: the buckets' rectangles together (the whole viewport when
  // they are not computed).
  glm::ivec4 meshRect(0, 0, f.viewport.z, f.viewport.w);
  if (s.stencilScissor) {
    meshRect = glm::ivec4(f.viewport.z, f.viewport.w, 0, 0);
    for (const glm::ivec4& b : f.triangles.shading().bucketBounds)
      if (b.z > b.x && b.w > b.y) meshRect = glm::ivec4(glm::min(glm::ivec2(meshRect), glm::ivec2(b)), glm::max(glm::ivec2(meshRect.z, meshRect.w), glm::ivec2(b.z, b.w)));
  }
  if (angleBuffer)
    if (Status st = strokeAngles_.draw(f, meshRect); !st) return st;
  const bool objectPattern = f.palette->patternMapping() == gl::PatternMapping::Object;
  if (objectPattern)
    if (Status st = patternCoordinates_.draw(f, meshRect); !st) return st;

  (*mask)->use();
  setMeshTransform(**mask, f.camera);
  (*bgQuad)->use();
  f.palette->bindBackground(**bgQuad);
  (*layerQuad)->use();
  f.palette->bindLayers(**layerQuad);
  f.palette->bindPattern(**layerQuad);
  if (objectPattern) patternCoordinates_.bind(**layerQuad, f.viewport);
  if (stroke != gl::StrokeSource::None) {
    f.palette->bindOrientation(**layerQuad);
    if (angleBuffer) strokeAngles_.bind(**layerQuad, f.viewport);
    else f.palette->bindStrokeSource(**layerQuad);
  }

  const glm::ivec4& vp = f.viewport;
  for (int k = 0; k < f.palette->size(); ++k) {
    const std::uint32_t count = f.triangles.bucketCount(k);
    if (count == 0 && s.stencilSkipEmpty) continue;
    glm::ivec4 rect = vp;
    if (s.stencilScissor) {
      const glm::ivec4& b = f.triangles.shading().bucketBounds[static_cast<size_t>(k)];
      rect = glm::ivec4(vp.x + b.x, vp.y + b.y, b.z - b.x, b.w - b.y);
      // Entirely off screen: its triangles still write depth that later buckets test against.
      if (count > 0 && (rect.z <= 0 || rect.w <= 0)) rect = glm::ivec4(vp.x, vp.y, 0, 0);
    }
    // (1) mark the pixels where this bucket's triangles are visible so far
    gl::apply(gl::pass::kStencilMask);
    (*mask)->use();
    f.gpuMesh.bindIndices(f.triangles.bucketIndices());
    if (count > 0) {
      f.gpuMesh.drawTriangles(f.triangles.bucketFirst(k), count);
      ++f.stats.drawCalls;
    }
    if (rect.z <= 0 || rect.w <= 0) continue;
    glScissor(rect.x, rect.y, rect.z, rect.w);
    glBindVertexArray(f.emptyVao.id());
    // (2) the background under the marked pixels
    gl::apply(gl::pass::kStencilBackground);
    (*bgQuad)->use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // (3) the palette layer blended over it; the stencil mark is cleared as it is drawn
    gl::apply(gl::pass::kStencilLayer);
    (*layerQuad)->use();
    (*layerQuad)->set("uLayer", k);
    (*layerQuad)->set("uLayerSize", f.palette->layerSize(k));
    if (stroke != gl::StrokeSource::None) (*layerQuad)->set("uLayerAngle", f.palette->entryAngle(k));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    f.stats.drawCalls += 2;
  }
  glScissor(vp.x, vp.y, vp.z, vp.w);
  return okStatus();
}

}  // namespace npr
