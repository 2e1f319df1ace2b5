// The original stencil-bucket algorithm (see stencil_path.h).
#include "renderer/paths/stencil_path.h"

#include <algorithm>
#include <array>

#include "renderer/gl/pass_state.h"

namespace npr {
namespace {

// Stencil values a bucket can be marked with when every mask is drawn first: 1 to 255 (0 is
// unmarked); a palette with more non-empty buckets is drawn in runs of this many.
constexpr int kMarksPerRun = 255;

}  // namespace

Status StencilPath::draw(FrameContext& f) {
  if (f.output != gl::MeshOutput::Colour) return selection_.draw(f);
  const RenderSettings& s = f.settings;
  if (Status st = updateTriangleShading(f); !st) return st;
  if (s.stencilScissor) f.triangles.updateBounds(f.camera.projection * f.camera.view, {f.viewport.z, f.viewport.w}, f.stats);

  const gl::StrokeSource stroke = f.strokeSource();
  const bool angleBuffer = stroke == gl::StrokeSource::Field || stroke == gl::StrokeSource::Light;
  const bool objectPattern = f.pattern.mapping() == gl::PatternMapping::Object;
  Result<gl::ShaderProgram*> bgQuad = f.program(gl::QuadProgram{gl::QuadProgram::Kind::Background, f.palette->backgroundImage()});
  if (!bgQuad) return Error{bgQuad.error()};
  const gl::QuadProgram layerVariant{gl::QuadProgram::Kind::Layer, false, f.pattern.mapping(), f.palette->layerSizesDiffer(),
                                     f.palette->filtered(f.pattern), f.palette->orientBins(f.pattern), angleBuffer, f.palette->precomposited()};
  Result<gl::ShaderProgram*> layerQuad = f.program(layerVariant);
  if (!layerQuad) return Error{layerQuad.error()};
  // Layers with no stroke direction are drawn unturned, by the same quad without orientation:
  // one lookup instead of two and no read of the angle buffer.
  Result<gl::ShaderProgram*> plainQuad = layerQuad;
  if (stroke != gl::StrokeSource::None) {
    gl::QuadProgram plainVariant = layerVariant;
    plainVariant.orientBins = 0;
    plainVariant.orientBuffer = false;
    plainQuad = f.program(plainVariant);
    if (!plainQuad) return Error{plainQuad.error()};
  }

  // The surface buffers from the masks themselves, when every mask is drawn first and the
  // bound framebuffer's depth-stencil can be shared; else from passes of their own.
  const bool buffers = angleBuffer || objectPattern;
  bool buffersFromMasks = false;
  const glm::ivec4& vp = f.viewport;
  std::array<GLuint, gl::SharedDepthFramebuffer::kOutputs> maskOutputs{};
  if (buffers && s.stencilMasksFirst) {
    maskOutputs = {angleBuffer ? strokeAngles_.output(vp, f.stats) : 0, objectPattern ? patternCoordinates_.output(vp, f.stats) : 0};
    buffersFromMasks = maskTarget_.bind(maskOutputs);
    if (buffersFromMasks) maskTarget_.restore();
  }
  gl::MeshProgram maskVariant;
  maskVariant.shading = gl::MeshShading::Mask;
  if (buffersFromMasks) {
    maskVariant.stroke = angleBuffer ? stroke : gl::StrokeSource::None;
    if (objectPattern) {
      maskVariant.palette = f.paletteVariant();
      maskVariant.palette->orientBins = 0;
      maskVariant.palette->filtered = false;
    }
  }
  Result<gl::ShaderProgram*> mask = f.program(maskVariant);
  if (!mask) return Error{mask.error()};

  // Where the mesh is on screen: the buckets' rectangles together (the whole viewport when
  // they are not computed).
  glm::ivec4 meshRect(0, 0, vp.z, vp.w);
  if (s.stencilScissor) {
    meshRect = glm::ivec4(vp.z, vp.w, 0, 0);
    for (const glm::ivec4& b : f.triangles.shading().bucketBounds)
      if (b.z > b.x && b.w > b.y) meshRect = glm::ivec4(glm::min(glm::ivec2(meshRect), glm::ivec2(b)), glm::max(glm::ivec2(meshRect.z, meshRect.w), glm::ivec2(b.z, b.w)));
  }
  f.stats.surfaceBuffers += int(angleBuffer) + int(objectPattern);
  if (!buffersFromMasks) {
    f.stats.surfaceBufferPasses += int(angleBuffer) + int(objectPattern);
    if (angleBuffer)
      if (Status st = strokeAngles_.draw(f, meshRect); !st) return st;
    if (objectPattern)
      if (Status st = patternCoordinates_.draw(f, meshRect); !st) return st;
  }

  (*mask)->use();
  setMeshTransform(**mask, f.camera);
  if (buffersFromMasks && objectPattern) f.palette->bindPattern(**mask, f.pattern);
  if (buffersFromMasks && angleBuffer) f.palette->bindStrokeSource(**mask, f.pattern);
  // Layers stored over the background are drawn opaque: the background under them would be
  // covered, so it is not drawn (a draw per bucket saved, which is most of what a scene's
  // objects cost this path beyond the merged mesh: bench_scene).
  const bool layersOpaque = layerVariant.opaque;
  if (!layersOpaque) {
    (*bgQuad)->use();
    f.palette->bindBackground(**bgQuad, f.pattern);
  }
  const glm::ivec2 bufferOrigin = buffersFromMasks ? glm::ivec2(0) : glm::ivec2(vp.x, vp.y);
  auto bindLayerQuad = [&](gl::ShaderProgram& quad) {
    quad.use();
    f.palette->bindLayers(quad, f.pattern);
    f.palette->bindPattern(quad, f.pattern);
    if (objectPattern) patternCoordinates_.bind(quad, bufferOrigin);
  };
  if (*plainQuad != *layerQuad) bindLayerQuad(**plainQuad);
  bindLayerQuad(**layerQuad);  // last: still in use for the orientation's uniforms below
  if (stroke != gl::StrokeSource::None) {
    f.palette->bindOrientation(**layerQuad, f.pattern);
    if (angleBuffer) strokeAngles_.bind(**layerQuad, bufferOrigin);
    else f.palette->bindStrokeSource(**layerQuad, f.pattern);
  }

  // (1) the bucket's triangles mark the pixels where they are visible so far with `mark`
  auto drawMask = [&](int k, std::uint32_t count, int mark) {
    gl::PassState state = f.meshPass(gl::pass::kStencilMask);
    state.colorWrite = buffersFromMasks;  // outputs 1 and 2 only (output 0 goes nowhere)
    state.stencilRef = mark;
    gl::apply(state);
    (*mask)->use();
    f.gpuMesh.bindIndices(f.triangles.bucketIndices());
    f.gpuMesh.drawTriangles(f.triangles.bucketFirst(k), count);
    ++f.stats.drawCalls;
  };
  // (2) the background under the pixels marked `mark`, (3) the palette layer blended over it,
  // clearing the mark as it is drawn (the background only under layers not stored over it).
  auto drawQuads = [&](int k, std::uint32_t count, int mark) {
    glm::ivec4 rect = vp;
    if (s.stencilScissor) {
      const glm::ivec4& b = f.triangles.shading().bucketBounds[static_cast<size_t>(k)];
      rect = glm::ivec4(vp.x + b.x, vp.y + b.y, b.z - b.x, b.w - b.y);
      if (count > 0 && (rect.z <= 0 || rect.w <= 0)) return;  // entirely off screen
    }
    if (rect.z <= 0 || rect.w <= 0) return;
    glScissor(rect.x, rect.y, rect.z, rect.w);
    glBindVertexArray(f.emptyVao.id());
    if (!layersOpaque) {
      gl::PassState background = gl::pass::kStencilBackground;
      background.stencilRef = mark;
      gl::apply(background);
      (*bgQuad)->use();
      glDrawArrays(GL_TRIANGLES, 0, 3);
      ++f.stats.drawCalls;
    }
    gl::PassState layer = gl::pass::kStencilLayer;
    layer.stencilRef = mark;
    gl::apply(layer);
    const bool turned = stroke != gl::StrokeSource::None && f.palette->entryAngle(k) > -10.0f;
    gl::ShaderProgram& quad = turned ? **layerQuad : **plainQuad;
    quad.use();
    quad.set("uLayer", k);
    quad.set("uLayerSize", f.palette->layerSize(k));
    if (turned) quad.set("uLayerAngle", f.palette->entryAngle(k));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++f.stats.drawCalls;
  };

  std::vector<int> drawn;  // the buckets drawn, in palette order
  for (int k = 0; k < f.triangles.buckets(); ++k)
    if (f.triangles.bucketCount(k) > 0 || !s.stencilSkipEmpty) drawn.push_back(k);
  if (!s.stencilMasksFirst) {
    for (int k : drawn) {
      const std::uint32_t count = f.triangles.bucketCount(k);
      if (count > 0) drawMask(k, count, 1);
      drawQuads(k, count, 1);
    }
  } else {
    // Later buckets' triangles overwrite earlier marks where nearer, so each pixel ends marked
    // with the bucket it shows, and gets only that bucket's quads: the same picture.
    for (std::size_t first = 0; first < drawn.size(); first += kMarksPerRun) {
      const std::size_t last = std::min(drawn.size(), first + kMarksPerRun);
      if (buffersFromMasks && !maskTarget_.bind(maskOutputs)) return Error{"the stencil path's mask framebuffer could not be bound again"};
      for (std::size_t i = first; i < last; ++i)
        if (const std::uint32_t count = f.triangles.bucketCount(drawn[i]); count > 0) drawMask(drawn[i], count, int(i - first) + 1);
      if (buffersFromMasks) maskTarget_.restore();
      for (std::size_t i = first; i < last; ++i) drawQuads(drawn[i], f.triangles.bucketCount(drawn[i]), int(i - first) + 1);
    }
  }
  glScissor(vp.x, vp.y, vp.z, vp.w);
  return okStatus();
}

}  // namespace npr
