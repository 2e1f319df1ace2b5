// The renderer facade (see renderer.h): what a frame is, in order. The work is in the passes,
// the features and the frame's steps (frame/); what is derived from each mesh lives with its
// model (scene/model.h).
#include "renderer/renderer.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <utility>

#include "renderer/core/elapsed.h"
#include "renderer/frame/scene_palettes.h"
#include "renderer/gl/gpu_choice.h"
#include "renderer/gl/pass_state.h"
#include "renderer/orientation/stroke_orientation.h"
#include "renderer/passes/background_pass.h"
#include "renderer/passes/geometry_pass.h"
#include "renderer/passes/marker_pass.h"
#include "renderer/paths/surface_buffer_pass.h"
#include "renderer/paths/path_table.h"

namespace npr {

Result<std::unique_ptr<Renderer>> Renderer::create() {
  if (epoxy_gl_version() < 33) return Error{"the renderer needs OpenGL 3.3 or later; this context is " + std::to_string(epoxy_gl_version())};
  std::unique_ptr<Renderer> r(new Renderer());
  gl::forgetAppliedState();  // perhaps a new context: nothing of its state is known
  r->gpu_.emptyVao = gl::createVertexArray();
  const auto* glRenderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  r->gpu_.softwareRasterizer = !glRenderer || isSoftwareRenderer(glRenderer);
  r->features_ = makeFeatures();
  return r;
}

Renderer::~Renderer() = default;

// ---------------------------------------------------------------------------------------
// What a frame needs

FrameNeeds frameNeeds(const RenderSettings& s) {
  FrameNeeds needs;
  // The per-triangle paths light the faces on the CPU; the anchored pattern fits samples read there.
  needs.cpuPose = pathInfo(s.path).perTriangle || s.pattern == PatternSpace::Anchored;
  // Each object's own pattern frame and direction field. (Its own tone range is fitted per
  // surface: a batch of one material as one.)
  needs.objectSurfaces = s.pattern != PatternSpace::Screen || s.orient.source == OrientSource::Curvature;
  featureNeeds(s, needs);
  return needs;
}

PoseTargets poseTargets(const RenderSettings& s, bool softwareRasterizer) { return poseTargets(frameNeeds(s), s.deform, softwareRasterizer); }

bool Renderer::sharesFramebufferDepth(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) const {
  if (!palettes_.main() || scene_.empty() || viewport.z < 1 || viewport.w < 1) return false;
  NeedsQuery q{s};
  q.softwareRasterizer = gpu_.softwareRasterizer;
  bool turnable = false;
  palettes_.forEach([&](const GpuPalette& p) { turnable = turnable || p.hasOrientedEntries(); });
  scene_.forEach([&](const Model& m) {
    turnable = turnable || (m.palette() && m.palette()->hasOrientedEntries());
    q.fewestPixelsPerTriangle = std::min(q.fewestPixelsPerTriangle, m.pixelsPerFrontTriangle(m.placed(camera), viewport));
  });
  q.turned = turnable && s.orient.source != OrientSource::None;
  FrameNeeds needs = frameNeeds(s);
  const RenderPass& path = surfaces_.path(s.path);
  path.needs(q, needs);
  if (path.resolvesTurns() &&
      turnResolveWanted(s, q.turned, s.pattern == PatternSpace::Object, q.softwareRasterizer, q.fewestPixelsPerTriangle))
    needs.sharedDepth = true;
  return needs.sharedDepth;
}

// ---------------------------------------------------------------------------------------
// The frame

// The scene's poses, tone range and palettes made ready for a frame of `output`.
Status Renderer::prepare(const CameraMatrices& camera, const RenderSettings& s, FrameOutput output) {
  const PoseTargets on = poseTargets(s, gpu_.softwareRasterizer);
  Status status = okStatus();
  scene_.forEachIncludingHidden([&](Model& m) {
    if (status) status = m.applyPose(on.gpu, on.cpu, gpu_.programs, stats_);
  });
  if (!status) return status;
  scene_.setBatching(s.tuning.batchObjects && !frameNeeds(s).objectSurfaces);
  // The reference path draws no palette: in the split view it need not fit the tone range a
  // second time each frame. Stroke angles read no tone.
  if (output == FrameOutput::Colour ? s.path != RenderPath::Reference : output != FrameOutput::StrokeAngles) {
    CameraMatrices whole = camera;
    if (work_.tile) whole.projection = work_.tile->wholeProjection;
    toneFit_.update(scene_, lighting_, whole, s, stats_);
  }
  if (!palettes_.main() && (pathInfo(s.path).usesPalette || output == FrameOutput::StrokeAngles)) return Error{"no palette loaded"};
  return preparePalettes(scene_, palettes_, s, toneFit_.target(), stats_);
}

FrameView Renderer::frameView(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport, bool colour) {
  return FrameView{camera,        s,      viewport,      colour,         scene_,         lighting_,         palettes_,
                   palettes_.main(), surfaces_.pattern(), gpu_.programs, stats_, gpu_.emptyVao, work_.progress, work_.budgetMs,
                   work_.tile ? work_.tile->offset : glm::ivec2(0), gpu_.softwareRasterizer};
}

// The frame's hatching orientation, and the direction field of each model where a palette
// turns its strokes along the curvature.
void Renderer::orientFrame(const RenderSettings& s) {
  PatternPlacement& pattern = surfaces_.pattern();
  orientStrokes(pattern, s.orient, lighting_);
  bool turned = false;
  palettes_.forEach([&](const GpuPalette& p) { turned = turned || p.oriented(pattern); });
  scene_.forEach([&](const Model& m) { turned = turned || (m.palette() && m.palette()->oriented(pattern)); });
  if (turned && s.orient.source == OrientSource::Curvature) scene_.forEach([&](Model& m) { (void)m.directionField(stats_); });
}

// Picks this frame's active features and runs their preparation (before the clear).
Status Renderer::prepareFeatures(FrameView& frame) {
  active_.clear();
  for (const auto& f : features_)
    if (f->active(frame)) active_.push_back(f.get());
  for (Feature* f : active_)
    if (Status st = f->prepare(frame); !st) return st;
  return okStatus();
}

// Depth and stencil cleared in the viewport only (the split view draws two).
void Renderer::clearViewport(const glm::ivec4& viewport) {
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  glScissor(viewport.x, viewport.y, viewport.z, viewport.w);
  gl::apply(gl::pass::kClearViewport);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// The frame: the scene's poses and palettes and the features prepared, the viewport cleared,
// the paper, the surfaces with the path, then the features' passes over them. Frames of the
// other outputs take the steps their output reads.
Status Renderer::render(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport, FrameOutput output) {
  if (output == FrameOutput::Colour && (supersampleFactor(s.aa) > 1 || postFiltered(s.aa)) && viewport.z > 0 && viewport.w > 0) {
    const int k = std::min(supersampleFactor(s.aa), RenderSettings::kMaxSupersample);
    return supersampler_.run(k, postFiltered(s.aa), viewport, gpu_.programs, gpu_.emptyVao, stats_, [&](int factor, const glm::ivec4& big) {
      RenderSettings scaled = pixelSizesScaled(s, float(factor));
      scaled.aa = AntiAliasing::Edges;
      // A poster's tile sits at k times its offset in the supersampled whole.
      const std::optional<Tile> tile = work_.tile;
      if (work_.tile) work_.tile->offset *= factor;
      const Status st = render(camera, scaled, big, output);
      work_.tile = tile;
      return st;
    });
  }
  const auto frameStart = std::chrono::steady_clock::now();
  stats_.startFrame();
  gpu_.programs.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();  // minimised window: nothing to draw
  if (output == FrameOutput::EyePosition || output == FrameOutput::EyeNormal) {
    clearViewport(viewport);
    const GeometryOutput geometry = output == FrameOutput::EyePosition ? GeometryOutput::EyePosition : GeometryOutput::EyeNormal;
    Status result = okStatus();
    for (const PlacedMesh& m : scene_.placed(camera))
      if (result) result = drawGeometry(m, geometry, gpu_.programs, stats_);
    gl::restoreDefaults();
    return result;
  }
  if (output == FrameOutput::StrokeAngles && scene_.empty()) return okStatus();
  if (Status st = prepare(camera, s, output); !st) return st;
  const bool colour = output == FrameOutput::Colour;
  if (colour) collectGpuTime();
  FrameView frame = frameView(camera, s, viewport, colour);
  // The frame's orientation, and the pattern placement of the first model (the paper reads it
  // too); the other models place theirs before they are drawn.
  Model* first = scene_.first();
  if (colour) surfaces_.placeFor(frame, first);
  if (output != FrameOutput::Entry && output != FrameOutput::Blend) orientFrame(s);
  Status result = output == FrameOutput::StrokeAngles ? okStatus() : prepareFeatures(frame);
  if (!colour && !result) return result;
  if (colour) surfaces_.path(s.path).prepareScene(frame);
  if (colour) gpu_.timer.begin();
  clearViewport(viewport);
  if (output != FrameOutput::StrokeAngles)
    for (Feature* f : active_)
      if (result) result = f->afterClear(frame);
  if (output == FrameOutput::StrokeAngles) {
    // The colour frame's surfaces, each part drawing its palette's stroke angles instead of its texels.
    const SceneSurfaces::PartDraw angles = [](FrameView&, const Model*, FrameContext& f) {
      return f.palette && f.palette->oriented(f.pattern) ? drawStrokeAngles(f) : okStatus();
    };
    result = surfaces_.draw(frame, active_, gl::MeshOutput::Colour, nullptr, &angles);
  } else if (!colour) {
    if (result) result = surfaces_.draw(frame, active_, output == FrameOutput::Entry ? gl::MeshOutput::Entry : gl::MeshOutput::Blend, nullptr);
  } else {
    if (result) result = drawBackground(palettes_.main(), surfaces_.pattern(), gpu_.programs, gpu_.emptyVao, stats_);
    if (result) result = surfaces_.draw(frame, active_, gl::MeshOutput::Colour, first);
    for (Feature* f : active_)
      if (result) result = f->drawOver(frame);
    gpu_.timer.end();
  }
  gl::restoreDefaults();
  if (colour) stats_.cpuFrameMs = msSince(frameStart);
  return result;
}

Status Renderer::follow(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  // What render() would see: nothing in an empty viewport, the supersampled frame's viewport
  // when the frame is supersampled. The pattern follows where render() places it: not on the
  // reference path.
  if (viewport.z < 1 || viewport.w < 1) return okStatus();
  if (supersampleFactor(s.aa) > 1 || postFiltered(s.aa)) {
    const int k = Supersampler::factorFor(std::min(supersampleFactor(s.aa), RenderSettings::kMaxSupersample), viewport);
    RenderSettings scaled = pixelSizesScaled(s, float(k));
    scaled.aa = AntiAliasing::Edges;
    const bool ours = k > 1 || postFiltered(s.aa);  // drawn into the supersampler's target
    return follow(camera, scaled, ours ? glm::ivec4(0, 0, viewport.z * k, viewport.w * k) : viewport);
  }
  const glm::ivec4& v = viewport;
  // Posed as render() poses: the close-up samples are drawn from the posed surface.
  const PoseTargets on = poseTargets(s, gpu_.softwareRasterizer);
  Status status = okStatus();
  scene_.forEachIncludingHidden([&](Model& m) {
    if (status) status = m.applyPose(on.gpu, on.cpu, gpu_.programs, stats_);
  });
  if (!status) return status;
  if (s.pattern == PatternSpace::Anchored && s.path != RenderPath::Reference)
    scene_.forEach([&](Model& m) { (void)m.patterns().update(m.placed(camera), v, s.patternFollowsRotation); });
  // The ground is built from the pose of the first frame that draws it.
  if (s.ground) (void)scene_.ground();
  FrameView frame = frameView(camera, s, v, true);
  for (const auto& f : features_)
    if (status && f->active(frame)) status = f->follow(frame);
  return status;
}

// ---------------------------------------------------------------------------------------
// What the app reads back and draws beside the frame

void Renderer::collectGpuTime() {
  if (std::optional<double> ms = gpu_.timer.collect()) stats_.gpuMs = *ms;
}

Status Renderer::drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour, float pixels,
                            const glm::ivec4& viewport) {
  return npr::drawMarker(camera, worldPosition, colour, pixels, viewport, gpu_.programs, gpu_.emptyVao, stats_);
}

}  // namespace npr
