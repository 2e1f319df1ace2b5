// The original stencil-bucket algorithm (see stencil_path.h).
#include "renderer/paths/stencil_path.h"

#include <algorithm>
#include <array>

#include "renderer/gl/pass_state.h"
#include "renderer/paths/triangle_lighting_ahead.h"

namespace npr {
namespace {

// Stencil values a bucket can be marked with when every mask is drawn first: 1 to 255 (0 is
// unmarked); a palette with more non-empty buckets is drawn in runs of this many.
constexpr int kMarksPerRun = 255;

// The smallest rectangle (x0, y0, x1, y1) holding both; an empty one (x1 <= x0) adds nothing.
glm::ivec4 uniteRects(const glm::ivec4& a, const glm::ivec4& b) {
  if (b.z <= b.x || b.w <= b.y) return a;
  return glm::ivec4(glm::min(glm::ivec2(a), glm::ivec2(b)), glm::max(glm::ivec2(a.z, a.w), glm::ivec2(b.z, b.w)));
}

}  // namespace

bool StencilPath::canShare(const FrameContext& f) const {
  // Objects share a bucket's quads where the quads are the same for all of them: one palette, a
  // screen-space pattern (the anchored and object patterns are placed per object), no buffers
  // read per pixel (their passes are per object), one row of the palette (a detail row is per
  // object), and nothing drawn over each object's surface as it is drawn (control palettes).
  if (!sceneOpen_ || f.output != gl::MeshOutput::Colour || f.shadowPalette || f.occlusionPalette || f.settings.pattern != PatternSpace::Screen)
    return false;
  if (f.paletteAxis().rows > 1) return false;
  const gl::StrokeSource stroke = f.strokeSource();
  if (stroke == gl::StrokeSource::Field || stroke == gl::StrokeSource::Light) return false;
  return shared_.empty() || f.palette == shared_.front().palette;
}

void StencilPath::beginScene() {
  sceneOpen_ = true;
  shared_.clear();
}

void StencilPath::needs(const NeedsQuery& q, FrameNeeds& needs) const {
  const OrientSource source = q.settings.orient.source;
  const bool angleBuffer = q.turned && (source == OrientSource::Curvature || source == OrientSource::Light);
  needs.sharedDepth = needs.sharedDepth || q.settings.pattern == PatternSpace::Object || angleBuffer;
}

void StencilPath::prepareScene(FrameView& frame) { lightTrianglesAhead(frame); }

Status StencilPath::draw(FrameContext& f) {
  if (f.output != gl::MeshOutput::Colour) return selection_.draw(f);
  if (Status st = updateTriangleShading(f); !st) return st;
  if (f.settings.stencilScissor) f.triangles.updateBounds(f.camera.projection * f.camera.view, {f.viewport.z, f.viewport.w}, f.stats);
  if (canShare(f)) {
    shared_.push_back(Shared{f.camera, f.viewport, &f.settings, &f.lighting, &f.gpuMesh, &f.mesh, &f.materials, f.palette, f.pattern,
                             &f.triangles, &f.programs, &f.stats, &f.emptyVao, f.cullBackFaces});
    return okStatus();
  }
  return drawBuckets({&f});
}

Status StencilPath::endScene() {
  sceneOpen_ = false;
  if (shared_.empty()) return okStatus();
  std::vector<FrameContext> frames;
  frames.reserve(shared_.size());
  std::vector<FrameContext*> objects;
  for (Shared& o : shared_) {
    frames.push_back(FrameContext{o.camera, o.viewport, *o.settings, *o.lighting, *o.gpuMesh, *o.mesh, *o.materials, o.palette, o.pattern,
                                  *o.triangles, *o.programs, *o.stats, *o.emptyVao});
    frames.back().cullBackFaces = o.cullBackFaces;
    objects.push_back(&frames.back());  // stable: reserved above
  }
  const Status st = drawBuckets(objects);
  shared_.clear();
  return st;
}

Status StencilPath::drawBuckets(const std::vector<FrameContext*>& objects) {
  FrameContext& f = *objects[0];  // the frame-wide state (palette, pattern, settings) is the same for all
  const RenderSettings& s = f.settings;

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
    for (const FrameContext* o : objects)
      for (const glm::ivec4& b : o->triangles.shading().bucketBounds) meshRect = uniteRects(meshRect, b);
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

  // (1) each object's triangles of the bucket mark the pixels where they are visible so far
  // with `mark` (the program is each object's: a see-through mesh binds its coverage to it)
  auto drawMasks = [&](int k, int mark) -> Status {
    for (FrameContext* o : objects) {
      const std::uint32_t count = k < o->triangles.buckets() ? o->triangles.bucketCount(k) : 0;
      if (count == 0) continue;
      gl::PassState state = o->meshPass(gl::pass::kStencilMask);
      state.colorWrite = buffersFromMasks;  // outputs 1 and 2 only (output 0 goes nowhere)
      state.stencilRef = mark;
      gl::apply(state);
      // Fetched for every mask: a see-through object binds its own coverage maps to it.
      Result<gl::ShaderProgram*> p = o->program(maskVariant);
      if (!p) return Error{p.error()};
      (*p)->use();
      setMeshTransform(**p, o->camera);
      o->gpuMesh.bindIndices(o->triangles.bucketIndices());
      o->gpuMesh.drawTriangles(o->triangles.bucketFirst(k), count);
      ++f.stats.drawCalls;
    }
    return okStatus();
  };
  // A bucket's triangles over all objects, and the screen rectangle they cover.
  auto bucketCount = [&](int k) {
    std::uint32_t n = 0;
    for (const FrameContext* o : objects) n += k < o->triangles.buckets() ? o->triangles.bucketCount(k) : 0;
    return n;
  };
  auto bucketRect = [&](int k) {
    glm::ivec4 r(vp.z, vp.w, 0, 0);
    for (const FrameContext* o : objects)
      if (k < o->triangles.buckets()) r = uniteRects(r, o->triangles.shading().bucketBounds[static_cast<size_t>(k)]);
    return r;
  };
  // (2) the background under the pixels marked `mark`, (3) the palette layer blended over it,
  // clearing the mark as it is drawn (the background only under layers not stored over it).
  auto drawQuads = [&](int k, std::uint32_t count, int mark) {
    glm::ivec4 rect = vp;
    if (s.stencilScissor) {
      const glm::ivec4 b = bucketRect(k);
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

  // The buckets drawn, in palette order (every object's are the palette's entries).
  int buckets = 0;
  for (const FrameContext* o : objects) buckets = std::max(buckets, o->triangles.buckets());
  std::vector<int> drawn;
  for (int k = 0; k < buckets; ++k)
    if (bucketCount(k) > 0 || !s.stencilSkipEmpty) drawn.push_back(k);
  // Objects drawn together behave as one mesh: a nearer object's mask overwrites a farther one's
  // mark, a farther one fails the depth test, so each pixel shows the nearest surface's bucket.
  if (!s.stencilMasksFirst) {
    for (int k : drawn) {
      if (Status st = drawMasks(k, 1); !st) return st;
      drawQuads(k, bucketCount(k), 1);
    }
  } else {
    // Later buckets' triangles overwrite earlier marks where nearer, so each pixel ends marked
    // with the bucket it shows, and gets only that bucket's quads: the same picture.
    for (std::size_t first = 0; first < drawn.size(); first += kMarksPerRun) {
      const std::size_t last = std::min(drawn.size(), first + kMarksPerRun);
      if (buffersFromMasks && !maskTarget_.bind(maskOutputs)) return Error{"the stencil path's mask framebuffer could not be bound again"};
      for (std::size_t i = first; i < last; ++i)
        if (Status st = drawMasks(drawn[i], int(i - first) + 1); !st) return st;
      if (buffersFromMasks) maskTarget_.restore();
      for (std::size_t i = first; i < last; ++i) drawQuads(drawn[i], bucketCount(drawn[i]), int(i - first) + 1);
    }
  }
  glScissor(vp.x, vp.y, vp.z, vp.w);
  return okStatus();
}

}  // namespace npr
