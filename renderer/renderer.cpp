// The renderer facade (see renderer.h): what a frame is, in order. The work is in the passes;
// what is derived from each mesh lives with its model (scene/model.h).
#include "renderer/renderer.h"

#include <algorithm>
#include <utility>
#include <chrono>
#include <limits>

#include "renderer/core/elapsed.h"
#include "renderer/core/parallel.h"
#include "renderer/gl/gpu_choice.h"
#include "renderer/gl/pass_state.h"
#include "renderer/lines/intersection_lines.h"
#include "renderer/mesh/ground_plane.h"
#include "renderer/passes/background_pass.h"
#include "renderer/passes/control_palette_pass.h"
#include "renderer/passes/marker_pass.h"
#include "renderer/passes/surface_buffer_pass.h"
#include "renderer/paths/render_pass.h"

namespace npr {
namespace {
// Screen pixels per front-facing triangle (the model's bounding disc over half its triangles)
// from which mapped patterns are placed per vertex. Framed at 1280x720, triangle path, anchored,
// orbiting, per vertex against per pixel: icosphere-7 (2.0 pixels) 4-9% faster, torus-500k (1.3)
// 0-5% slower; in bench_frames the 871K torus (0.75) 5-10% slower, the bunny (178) 7-9% faster.
constexpr float kPatternPerVertexPixels = 1.5f;

bool isIdentity(const glm::mat4& m) { return m == glm::mat4(1.0f); }
}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create() {
  if (epoxy_gl_version() < 33) return Error{"the renderer needs OpenGL 3.3 or later; this context is " + std::to_string(epoxy_gl_version())};
  std::unique_ptr<Renderer> r(new Renderer());
  gl::forgetAppliedState();  // perhaps a new context: nothing of its state is known
  r->emptyVao_ = gl::createVertexArray();
  const auto* glRenderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  r->softwareRasterizer_ = !glRenderer || isSoftwareRenderer(glRenderer);
  for (const PathInfo& info : renderPaths()) r->paths_.push_back(info.create());
  return r;
}

Renderer::~Renderer() = default;

// ---------------------------------------------------------------------------------------
// The scene and the palettes

ModelId Renderer::addModel(const Mesh& mesh, const glm::mat4& transform) {
  partsDirty_ = true;
  return scene_.add(mesh, transform, stats_);
}

void Renderer::removeModel(ModelId id) {
  if (const Model* m = scene_.find(id)) modelPalettes_.erase(m);
  scene_.remove(id);
}

void Renderer::clearModels() {
  modelPalettes_.clear();
  ground_.reset();
  scene_.clear();
}

Status Renderer::setModelPalette(ModelId id, const Palette& palette) {
  const Model* m = scene_.find(id);
  if (!m) return Error{"no model " + std::to_string(id) + " in the scene"};
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  modelPalettes_[m] = std::move(*uploaded);
  stats_.bufferUploads += 1;
  return okStatus();
}

void Renderer::clearModelPalette(ModelId id) {
  if (const Model* m = scene_.find(id)) modelPalettes_.erase(m);
}

bool Renderer::setModelTransform(ModelId id, const glm::mat4& transform) { return scene_.setTransform(id, transform); }
bool Renderer::setModelPose(ModelId id, const glm::mat4& transform) { return scene_.pose(id, transform); }
bool Renderer::setModelName(ModelId id, const std::string& name) {
  Model* m = scene_.find(id);
  if (m) m->setName(name);
  return m != nullptr;
}

bool Renderer::setModelDeformation(ModelId id, const std::vector<glm::mat4>& joints, const std::vector<float>& weights) {
  Model* m = scene_.find(id);
  if (!m) return false;
  m->deform(joints, weights);  // made by the next frame, where it reads it (applyPoses)
  scene_.touch();
  return true;
}

void Renderer::setMesh(const Mesh* mesh) {
  ground_.reset();
  partsDirty_ = true;
  modelPalettes_.clear();
  if (mesh && !mesh->indices.empty()) scene_.setOnly(*mesh, glm::mat4(1.0f), stats_);
  else scene_.clear();
}

Status Renderer::setPalette(const Palette& palette) {
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  palette_ = std::move(*uploaded);
  stats_.bufferUploads += 1;
  return okStatus();
}

Status Renderer::setMaterialPalette(const std::string& material, const Palette& palette) {
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  materialPalettes_[material] = std::move(*uploaded);
  partsDirty_ = true;
  stats_.bufferUploads += 1;
  return okStatus();
}

void Renderer::clearMaterialPalette(const std::string& material) {
  if (materialPalettes_.erase(material)) partsDirty_ = true;
}

void Renderer::setMaterialDetail(const std::string& material, float detail) {
  const float d = std::isfinite(detail) ? std::clamp(detail, 0.0f, 1.0f) : 0.0f;
  const auto it = materialDetails_.find(material);
  if (it != materialDetails_.end() && it->second == d) return;
  materialDetails_[material] = d;
  partsDirty_ = true;
}

Status Renderer::setControlPalette(ControlParameter parameter, const Palette& palette) {
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  (parameter == ControlParameter::Shadow ? shadowPalette_ : occlusionPalette_) = std::move(*uploaded);
  stats_.bufferUploads += 1;
  return okStatus();
}

void Renderer::clearControlPalette(ControlParameter parameter) {
  (parameter == ControlParameter::Shadow ? shadowPalette_ : occlusionPalette_).reset();
}

// ---------------------------------------------------------------------------------------
// What the frame needs before it draws

bool framePosesOnCpu(const RenderSettings& s) {
  return pathInfo(s.path).perTriangle || s.lines.drawnKinds() != 0 || s.strokes.on || s.pattern == PatternSpace::Anchored;
}

PoseTargets poseTargets(const RenderSettings& s, bool softwareRasterizer) {
  PoseTargets t;
  t.cpu = s.deform == PosePlacement::Cpu || framePosesOnCpu(s);
  t.gpu = s.deform == PosePlacement::Gpu || (s.deform == PosePlacement::Auto && (!t.cpu || !softwareRasterizer));
  return t;
}

Status Renderer::applyPoses(const RenderSettings& s) {
  const PoseTargets on = poseTargets(s, softwareRasterizer_);
  Status status = okStatus();
  scene_.forEachIncludingHidden([&](Model& m) {
    if (status) status = m.applyPose(on.gpu, on.cpu, programs_, stats_);
  });
  return status;
}

Status Renderer::prepare(const RenderSettings& s) {
  if (!palette_ && pathInfo(s.path).usesPalette) return Error{"no palette loaded"};
  if (partsDirty_) {
    partsDirty_ = false;
    auto paletteOf = [&](const std::string& material) -> const GpuPalette* {
      const auto it = materialPalettes_.find(material);
      return it == materialPalettes_.end() ? nullptr : it->second.get();
    };
    auto detailOf = [&](const std::string& material) -> std::optional<float> {
      const auto it = materialDetails_.find(material);
      return it == materialDetails_.end() ? std::nullopt : std::optional<float>(it->second);
    };
    scene_.forEachIncludingHidden([&](Model& m) { m.splitByMaterial(paletteOf, detailOf, stats_); });
  }
  // A depth axis counts in scene radii, so a palette with rows suits any model's units.
  const float sceneRadius = scene_.empty() ? 1.0f : scene_.bounds().w;
  if (palette_) palette_->setAxisScale(sceneRadius);
  forEachExtraPalette([&](GpuPalette& p) { p.setAxisScale(sceneRadius); });
  const std::optional<glm::vec2> target = toneTarget_;
  for (auto& [model, p] : modelPalettes_)
    if (Status st = p->updateMatcher(s.match, s.rangeScale, {}, stats_, target); !st) return Error{"an object's palette: " + st.error()};
  // Cel bands belong to the main palette (they are one fewer than its tones).
  for (auto& [name, p] : materialPalettes_)
    if (Status st = p->updateMatcher(s.match, s.rangeScale, {}, stats_, target); !st) return Error{"palette of material '" + name + "': " + st.error()};
  if (shadowPalette_)
    if (Status st = shadowPalette_->updateMatcher(s.match, s.rangeScale, {}, stats_, target); !st) return Error{"shadow palette: " + st.error()};
  if (occlusionPalette_)
    if (Status st = occlusionPalette_->updateMatcher(s.match, s.rangeScale, {}, stats_, target); !st) return Error{"occlusion palette: " + st.error()};
  if (palette_)
    if (Status st = palette_->updateMatcher(s.match, s.rangeScale, s.bands, stats_, s.bands.empty() ? target : std::nullopt); !st) return st;
  // Each object fitted to its own tones: its palettes get a matcher for its range, in its slot.
  Status status = okStatus();
  scene_.forEach([&](Model& m) {
    if (!status || m.toneSlot == 0) return;
    const auto fit = [&](GpuPalette& p) {
      if (status) status = p.updateMatcher(s.match, s.rangeScale, {}, stats_, m.toneTarget, m.toneSlot);
    };
    if (GpuPalette* p = mainPaletteOf(m)) fit(*p);
    for (auto& [name, p] : materialPalettes_) fit(*p);
  });
  return status;
}

void Renderer::selectToneSlot(int slot) const {
  if (palette_) palette_->useMatcher(slot);
  forEachExtraPalette([&](GpuPalette& p) { p.useMatcher(slot); });
}

void Renderer::updateToneRange(const CameraMatrices& camera, const RenderSettings& s) {
  const bool perObject = s.toneRange == ToneRange::PerObject && s.bands.empty();
  if (!perObject)
    scene_.forEachIncludingHidden([](Model& m) {
      m.toneTracker().reset();
      m.toneTarget.reset();
      m.toneSlot = 0;
    });
  if (s.toneRange == ToneRange::Fixed || !s.bands.empty()) {
    toneRange_.reset();
    toneTarget_.reset();
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  // About 1024 triangles over the whole scene for one range: enough for stable percentiles
  // (the spider orbiting moves it at most 2 quanta a frame, as 4096 did), a tenth of a
  // millisecond on the CPU. Each object's own range needs more, about 4096 over the scene
  // (with 1024 the dark object of test_gl_tone_range moved 8 quanta a frame), at least 64 each
  // (a scene of many parts keeps about the same total).
  std::size_t models = 0;
  scene_.forEach([&](const Model&) { ++models; });
  const std::size_t budget = perObject ? std::max<std::size_t>(64, 4096 / std::max<std::size_t>(models, 1)) : std::max<std::size_t>(256, 1024 / std::max<std::size_t>(models, 1));
  toneSamples_.clear();
  int slot = 0;
  scene_.forEach([&](Model& m) {
    const std::size_t first = toneSamples_.size();
    m.poseToneSamples(toneSampleStride(m.mesh().triangleCount(), budget));  // a pose only the GPU made
    sampleTones(m.mesh(), lighting_, camera.view * m.transform(), camera.projection, s.materials, s.match, budget, toneSamples_);
    if (!perObject) return;
    // Its own tones, fitted and smoothed as the scene's are (slots from 1, in scene order).
    std::vector<ToneSample> own(toneSamples_.begin() + std::ptrdiff_t(first), toneSamples_.end());
    m.toneTarget = m.toneTracker().update(percentileRange(own, 2.0f, 98.0f, 0.15f), 0.25f);
    m.toneSlot = ++slot;
  });
  // A quarter of the way to each new estimate per frame: settles in about ten frames and
  // follows an orbit without pumping.
  toneTarget_ = toneRange_.update(percentileRange(toneSamples_, 2.0f, 98.0f, 0.15f), 0.25f);
  stats_.cpuToneMs = msSince(t0);
}

void Renderer::preparePattern(Model* model, const CameraMatrices& placed, const RenderSettings& s, const glm::ivec4& viewport) {
  std::optional<PatternFrame> frame;
  if (s.pattern == PatternSpace::Anchored && model) {
    // The reference path draws no pattern: following its frame too would fit the split view's
    // two viewports as motion, back and forth every frame, and the fits' float error would make
    // the pattern creep over a still model.
    if (s.path != RenderPath::Reference) {
      const PatternFit& fit = model->patterns().update(placed, viewport, s.patternFollowsRotation);
      stats_.cpuPatternMs = fit.ms;
      stats_.patternSamples = fit.samplesUsed;
    }
    frame = model->patterns().frame();
  }
  const float scale = std::clamp(s.patternScale, RenderSettings::kMinPatternScale, RenderSettings::kMaxPatternScale);
  // Object units one pixel spans at eye depth 1 (the model's units are the eye's).
  const float pixelSize = 2.0f / (std::max(std::abs(placed.projection[1][1]), 1e-6f) * float(std::max(viewport.w, 1)));
  const glm::mat4 eyeToObject = glm::inverse(placed.view);
  // Mapped patterns are placed per vertex where the model's triangles span a few pixels each:
  // there interpolation is cheaper than mapping every pixel; on denser meshes llvmpipe shades a
  // block of pixels per triangle anyway and a varying costs each triangle's set-up more than the
  // arithmetic it saves (pattern_vertex.glsl has the figures).
  bool perVertex = true;
  pixelsPerFrontTriangle_ = std::numeric_limits<float>::infinity();
  if (model) {
    pixelsPerFrontTriangle_ = model->pixelsPerFrontTriangle(placed, viewport);
    perVertex = pixelsPerFrontTriangle_ >= kPatternPerVertexPixels;
  }
  pattern_.frame = frame;
  pattern_.scale = scale;
  pattern_.linearFilter = s.patternLinearFilter;
  pattern_.object = s.pattern == PatternSpace::Object;
  pattern_.pixelSize = pixelSize;
  pattern_.eyeToObject = eyeToObject;
  pattern_.frameOffset = glm::vec2(frameOffset_);
  pattern_.viewport = viewport;
  pattern_.perVertex = perVertex;
}

void Renderer::prepareOrientation(const RenderSettings& s) {
  glm::vec4 light(0, 0, 1, 0);
  for (int i = 0; i < kMaxLights; ++i)
    if (lighting_.light(i).enabled) {
      light = lighting_.light(i).position;
      break;
    }
  pattern_.orient = s.orient;
  pattern_.orient.bins = std::clamp(s.orient.bins, OrientSettings::kMinBins, OrientSettings::kMaxBins);
  pattern_.light = light;
  bool turned = palette_ && palette_->oriented(pattern_);
  forEachExtraPalette([&](const GpuPalette& p) { turned = turned || p.oriented(pattern_); });
  if (turned && s.orient.source == OrientSource::Curvature) scene_.forEach([&](Model& m) { (void)m.directionField(stats_); });
}

// The per-triangle paths light each model's triangles on the CPU when it draws. A large model's
// lighting is split over the cores (parallel.h); a scene's small models would each light on
// one core, one after another: here they light side by side, a share of the models per core,
// before the frame draws them, and each cache then finds its lighting done and only uploads
// (bench_scene: 16 objects against one merged mesh). Only where the draw will ask for exactly
// this lighting: CPU-lit (no shadows, which Auto lights on the GPU), no baked occlusion, one tone
// range for the scene, no per-material parts; elsewhere the draw lights as before.
void Renderer::prepareTriangleShading(const CameraMatrices& camera, const RenderSettings& s) {
  if ((s.path != RenderPath::Stencil && s.path != RenderPath::Triangle) || s.triangleLighting == TriangleLighting::Gpu || s.shadows ||
      s.occlusion)
    return;
  std::vector<Model*> models;
  scene_.forEach([&](Model& m) {
    if (m.toneSlot == 0 && (m.parts().empty() || !s.materials) && mainPaletteOf(m)) models.push_back(&m);
  });
  if (models.size() < 2) return;
  std::vector<FrameStats> counted(models.size());
  parallelChunks(
      models.size(), workerCount(),
      [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) {
          Model& m = *models[i];
          const GpuPalette& p = *mainPaletteOf(m);
          m.triangles().expectRows(s.paletteAxis && p.axis().rows > 1);
          m.triangles().prepare(lighting_, m.placed(camera).view, *p.matcher(), p.matcherId(), counted[i], s.materials, nullptr,
                                s.occlusionStrength);
        }
      },
      1);
  for (const FrameStats& c : counted) {
    stats_.cpuShadingMs += c.cpuShadingMs;
    stats_.lightingRecomputes += c.lightingRecomputes;
    stats_.modelsLitAhead += c.lightingRecomputes;
  }
}

Model* Renderer::prepareGround() {
  if (scene_.empty()) return nullptr;
  if (ground_ && groundVersion_ == scene_.layoutVersion()) return ground_.get();
  // Under the scene's lowest point, about the origin, holding every model.
  float lowest = std::numeric_limits<float>::infinity();
  scene_.forEach([&](const Model& m) {
    if (isIdentity(m.transform())) {
      for (const glm::vec3& p : m.mesh().positions) lowest = std::min(lowest, p.y);
    } else {
      for (const glm::vec3& p : m.mesh().positions) lowest = std::min(lowest, (m.transform() * glm::vec4(p, 1.0f)).y);
    }
  });
  const glm::vec4 bounds = scene_.bounds();
  groundMesh_ = groundPlane(std::isfinite(lowest) ? lowest : -1.0f, glm::length(glm::vec3(bounds)) + bounds.w);
  ground_ = std::make_unique<Model>(groundMesh_, glm::mat4(1.0f), stats_, false);
  groundVersion_ = scene_.layoutVersion();
  return ground_.get();
}

FrameView Renderer::frameView(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport, bool colour) {
  return FrameView{camera,     s,       viewport,   colour,          scene_,   lighting_, palette_.get(), pattern_, programs_, stats_,
                   emptyVao_, [this] { return prepareGround(); }, progress_, occlusionBudgetMs_};
}

Status Renderer::prepareFeatures(FrameView& frame) {
  if (features_.empty()) features_ = makeFeatures();
  active_.clear();
  for (const auto& f : features_)
    if (f->active(frame)) active_.push_back(f.get());
  for (Feature* f : active_)
    if (Status st = f->prepare(frame); !st) return st;
  return okStatus();
}

void Renderer::clearViewport(const glm::ivec4& viewport) {
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  glScissor(viewport.x, viewport.y, viewport.z, viewport.w);
  gl::apply(gl::pass::kClearViewport);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// ---------------------------------------------------------------------------------------
// The surfaces

Status Renderer::drawScene(FrameView& frame, gl::MeshOutput output, const Model* prepared, const PartDraw* draw) {
  // The path may draw several objects' work together at the end (the stencil path's quads).
  RenderPass* path = draw ? nullptr : paths_[pathIndex(frame.settings.path)].get();
  if (path) path->beginScene();
  Status status = okStatus();
  scene_.forEach([&](Model& m) {
    if (status) status = drawModel(frame, m, output, &m != prepared, draw);
  });
  if (status && !scene_.empty()) status = drawGround(frame, output, draw);
  if (path)
    if (Status st = path->endScene(); status && !st) status = st;
  return status;
}

Status Renderer::drawModel(FrameView& view, Model& model, gl::MeshOutput output, bool placePattern, const PartDraw* draw) {
  const RenderSettings& s = view.settings;
  const CameraMatrices placed = model.placed(view.camera);
  if (output == gl::MeshOutput::Colour && placePattern) preparePattern(&model, placed, s, view.viewport);
  // The whole model's, for every part: the parts hide each other's back faces.
  const bool cullBackFaces = backFacesHidden(model, placed, s);
  // The model's materials, once for every part (a part keeps every material: the same rows).
  GpuMaterials& materials = model.materials();
  if (s.materials || materials.coverage()) materials.update(model.mesh(), lighting_, stats_);
  auto drawOne = [&](GpuMesh& gpu, TriangleShadingCache& triangles, const GpuPalette* palette, float detail) {
    FrameContext frame{placed, view.viewport, s, lighting_, gpu, model.mesh(), materials, palette, pattern_, triangles, programs_, stats_, emptyVao_, output};
    frame.sceneView = view.camera.view;
    frame.turnResolve = turnResolveFor(s, palette, output);
    frame.cullBackFaces = cullBackFaces;
    frame.axisDetail = detail;
    return draw ? (*draw)(view, &model, frame) : drawPart(view, &model, frame, s.path);
  };
  GpuPalette* main = mainPaletteOf(model);
  // Its own tone range's matchers while it draws (per-object fitting; slot 0 otherwise).
  struct ToneSlot {
    const Renderer& r;
    ToneSlot(const Renderer& renderer, int slot) : r(renderer) { r.selectToneSlot(slot); }
    ~ToneSlot() { r.selectToneSlot(0); }
  } toneSlot(*this, model.toneSlot);
  if (model.parts().empty() || !s.materials) return drawOne(model.gpu(), model.triangles(), main, model.detail());
  // One draw of the path per palette, each over its part of the model; depth testing across
  // the parts keeps the nearest surface, whichever part is drawn first.
  for (auto& part : model.parts())
    if (Status st = drawOne(part->gpu, part->triangles, part->palette ? part->palette : main, part->detail.value_or(model.detail()));
        !st)
      return st;
  return okStatus();
}

Status Renderer::drawGround(FrameView& view, gl::MeshOutput output, const PartDraw* draw) {
  if (!view.settings.ground || !palette_) return okStatus();
  Model* ground = prepareGround();
  if (!ground) return okStatus();
  // The ground has no materials of its own: lit with the lighting state's material.
  RenderSettings plain = view.settings;
  plain.materials = false;
  FrameContext frame{view.camera, view.viewport, plain, lighting_, ground->gpu(), ground->mesh(), ground->materials(), palette_.get(), pattern_,
                     ground->triangles(), programs_, stats_, emptyVao_, output};
  frame.sceneView = view.camera.view;
  return draw ? (*draw)(view, nullptr, frame) : drawPart(view, nullptr, frame, plain.path);
}

bool Renderer::backFacesHidden(const Model& model, const CameraMatrices& placed, const RenderSettings& s) {
  const bool hidden = s.tuning.cullHiddenBackFaces && model.mesh().closed && !model.mesh().seeThrough && glm::determinant(glm::mat3(model.transform())) > 0.0f &&
                      sphereBeyondNearPlane(placed, model.sceneRadius());
  stats_.backFacesCulled = stats_.backFacesCulled || hidden;
  return hidden;
}

TurnResolvePass* Renderer::turnResolveFor(const RenderSettings& s, const GpuPalette* palette, gl::MeshOutput output) {
  const bool meshPath = s.path == RenderPath::Triangle || s.path == RenderPath::Vertex || s.path == RenderPath::Pixel || s.path == RenderPath::Smooth;
  // The object pattern's coordinate comes from the surface, which the resolve cannot see.
  if (!meshPath || output != gl::MeshOutput::Colour || !palette || !palette->oriented(pattern_) || pattern_.mapping() == gl::PatternMapping::Object)
    return nullptr;
  const TurnPlacement where = s.tuning.turnPlacement;
  if (where == TurnPlacement::InMeshPass || (where == TurnPlacement::Auto && !resolveTurnAutomatically(softwareRasterizer_, pixelsPerFrontTriangle_))) return nullptr;
  ++stats_.surfaceBuffers;
  return &turnResolve_;
}

Status Renderer::drawPart(FrameView& view, const Model* model, FrameContext& frame, RenderPath path) {
  for (Feature* f : active_) f->shade(view, model, frame);
  // Set before the path draws: a path that defers its work to the scene's end (the stencil
  // path) must not, where these are drawn over each surface as it is drawn.
  if (frame.settings.controlPalettes) {
    frame.shadowPalette = shadowPalette_.get();
    frame.occlusionPalette = occlusionPalette_.get();
  }
  if (Status st = paths_[pathIndex(path)]->draw(frame); !st) return st;
  return frame.settings.controlPalettes ? drawControlPalettes(frame, path) : okStatus();
}

// ---------------------------------------------------------------------------------------
// Frames

// The frame: the scene's palettes and features prepared, the viewport cleared, the paper, the
// surfaces with the path, then the features' passes over them.
Status Renderer::render(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  const auto frameStart = std::chrono::steady_clock::now();
  stats_.startFrame();
  programs_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();  // minimised window: nothing to draw
  if (Status st = applyPoses(s); !st) return st;
  // The reference path draws no palette; in the split view it must not smooth the tone range
  // a second time each frame.
  if (s.path != RenderPath::Reference) updateToneRange(camera, s);
  if (Status st = prepare(s); !st) return st;
  collectGpuTime();
  FrameView frame = frameView(camera, s, viewport, true);
  // The frame's orientation, and the pattern placement of the first model (the paper reads it
  // too); the other models place theirs before they are drawn.
  Model* first = scene_.first();
  preparePattern(first, first ? first->placed(camera) : camera, s, viewport);
  prepareOrientation(s);
  Status result = prepareFeatures(frame);
  prepareTriangleShading(camera, s);
  timer_.begin();
  clearViewport(viewport);
  for (Feature* f : active_)
    if (result) result = f->afterClear(frame);
  if (result) result = drawBackground(palette_.get(), pattern_, programs_, emptyVao_, stats_);
  if (result) result = drawScene(frame, gl::MeshOutput::Colour, first);
  for (Feature* f : active_)
    if (result) result = f->drawOver(frame);
  timer_.end();
  gl::restoreDefaults();
  stats_.cpuFrameMs = msSince(frameStart);
  return result;
}

Status Renderer::renderSelection(const CameraMatrices& camera, const RenderSettings& s, SelectionOutput output,
                                 const glm::ivec4& viewport) {
  stats_.startFrame();
  programs_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();
  if (Status st = applyPoses(s); !st) return st;
  updateToneRange(camera, s);
  if (Status st = prepare(s); !st) return st;
  FrameView frame = frameView(camera, s, viewport, false);
  if (Status st = prepareFeatures(frame); !st) return st;
  clearViewport(viewport);
  for (Feature* f : active_)
    if (Status st = f->afterClear(frame); !st) return st;
  const Status result = drawScene(frame, output == SelectionOutput::Entry ? gl::MeshOutput::Entry : gl::MeshOutput::Blend, nullptr);
  gl::restoreDefaults();
  return result;
}

Status Renderer::renderStrokeAngles(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  stats_.startFrame();
  programs_.startFrame();
  if (viewport.z < 1 || viewport.w < 1 || scene_.empty()) return okStatus();
  if (Status st = applyPoses(s); !st) return st;
  if (Status st = prepare(s); !st) return st;
  if (!palette_) return Error{"no palette loaded"};
  FrameView frame = frameView(camera, s, viewport, false);
  prepareOrientation(s);
  clearViewport(viewport);
  // The colour frame's surfaces, each part drawing its palette's stroke angles instead of its texels.
  const PartDraw angles = [](FrameView&, const Model*, FrameContext& f) {
    return f.palette && f.palette->oriented(f.pattern) ? drawStrokeAngles(f) : okStatus();
  };
  const Status result = drawScene(frame, gl::MeshOutput::Colour, nullptr, &angles);
  gl::restoreDefaults();
  return result;
}

Status Renderer::renderGeometry(const CameraMatrices& camera, GeometryOutput output, const glm::ivec4& viewport) {
  stats_.startFrame();
  programs_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();
  clearViewport(viewport);
  Status result = okStatus();
  for (const PlacedMesh& m : scene_.placed(camera))
    if (result) result = drawGeometry(m, output, programs_, stats_);
  gl::restoreDefaults();
  return result;
}

bool Renderer::sharesFramebufferDepth(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) const {
  if (!palette_ || scene_.empty() || viewport.z < 1 || viewport.w < 1) return false;
  bool turnable = palette_->hasOrientedEntries();
  forEachExtraPalette([&](const GpuPalette& p) { turnable = turnable || p.hasOrientedEntries(); });
  const bool turned = turnable && s.orient.source != OrientSource::None;
  const bool object = s.pattern == PatternSpace::Object;
  // The stencil path's surface buffers: the stroke angle (field or light) and the object pattern.
  if (s.path == RenderPath::Stencil)
    return object || (turned && (s.orient.source == OrientSource::Curvature || s.orient.source == OrientSource::Light));
  // The turn resolve (turnResolveFor), by each model's density as preparePattern measures it.
  const bool meshPath = s.path == RenderPath::Triangle || s.path == RenderPath::Vertex || s.path == RenderPath::Pixel || s.path == RenderPath::Smooth;
  if (!meshPath || !turned || object || s.tuning.turnPlacement == TurnPlacement::InMeshPass) return false;
  if (s.tuning.turnPlacement == TurnPlacement::Resolved) return true;
  bool dense = false;
  scene_.forEach([&](const Model& m) {
    dense = dense || resolveTurnAutomatically(softwareRasterizer_, m.pixelsPerFrontTriangle(m.placed(camera), viewport));
  });
  return dense;
}

// ---------------------------------------------------------------------------------------
// What the app and the tests read back

void Renderer::collectGpuTime() {
  if (std::optional<double> ms = timer_.collect()) stats_.gpuMs = *ms;
}

Status Renderer::drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour, float pixels,
                            const glm::ivec4& viewport) {
  return npr::drawMarker(camera, worldPosition, colour, pixels, viewport, programs_, emptyVao_, stats_);
}

std::vector<FeatureLine> Renderer::featureLines(const CameraMatrices& camera, const RenderSettings& settings,
                                                const std::function<std::uint8_t(const std::string* object)>& kindsFor, const LineSet* set) {
  std::vector<FeatureLine> out;
  // Lines are found on the CPU's pose.
  FrameStats exportStats;
  scene_.forEachIncludingHidden([&](Model& m) { (void)m.applyPose(false, true, programs_, exportStats); });
  auto keep = [&](std::vector<FeatureLine>& lines, const std::string* object) {
    const std::uint8_t kinds = kindsFor ? kindsFor(object) : settings.lines.drawnKinds();
    lines.erase(std::remove_if(lines.begin(), lines.end(), [&](const FeatureLine& l) { return !((kinds >> int(l.kind + 0.5f)) & 1u); }), lines.end());
  };
  scene_.forEach([&](Model& m) {
    std::vector<FeatureLine> lines = m.lines().lines(m.placed(camera), settings.lines);
    keep(lines, &m.name());
    if (set && !set->materials.empty()) {
      const std::vector<MeshMaterial>& materials = m.mesh().materials;
      const auto taken = [&](std::uint16_t i) { return i < materials.size() && set->takesMaterial(materials[i].name); };
      lines.erase(std::remove_if(lines.begin(), lines.end(), [&](const FeatureLine& l) { return !taken(l.attributes.materials.x) && !taken(l.attributes.materials.y); }),
                  lines.end());
    }
    if (!isIdentity(m.transform())) {
      const glm::mat3 normals = glm::transpose(glm::inverse(glm::mat3(m.transform())));
      for (FeatureLine& l : lines) {
        l.a = glm::vec3(m.transform() * glm::vec4(l.a, 1.0f));
        l.b = glm::vec3(m.transform() * glm::vec4(l.b, 1.0f));
        const glm::vec3 n = normals * l.attributes.normal;
        l.attributes.normal = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f);
      }
    }
    out.insert(out.end(), lines.begin(), lines.end());
  });
  if (settings.lines.drawnKinds() & 16u) {
    std::vector<FeatureLine> crossings = sceneIntersectionLines(scene_);
    keep(crossings, nullptr);
    out.insert(out.end(), crossings.begin(), crossings.end());
  }
  return out;
}

const PatternTracker& Renderer::patternTracker() const {
  static const PatternTracker none;
  return scene_.first() ? scene_.first()->patterns() : none;
}

const TriangleShading& Renderer::triangleShading() const {
  static const TriangleShading none;
  return scene_.first() ? const_cast<Model*>(scene_.first())->triangles().shading() : none;
}

std::size_t Renderer::strokeCount() const {
  std::size_t n = 0;
  scene_.forEach([&](const Model& m) { n += const_cast<Model&>(m).strokes().strokes(); });
  return n;
}

double Renderer::strokeSeedMs() const {
  double ms = 0.0;
  scene_.forEach([&](const Model& m) { ms += const_cast<Model&>(m).strokes().seedMs(); });
  return ms;
}

}  // namespace npr
