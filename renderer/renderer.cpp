// The renderer facade (see renderer.h): what a frame is, in order. The work is in the passes.
#include "renderer/renderer.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "renderer/core/elapsed.h"
#include "renderer/gl/pass_state.h"
#include "renderer/lines/hardware_outline_pass.h"
#include "renderer/mesh/ground_plane.h"
#include "renderer/mesh/mesh_subset.h"
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
// Below this many pixels per front-facing triangle the triangle, vertex, pixel and smooth paths turn
// their lookups once per pixel after the mesh pass (passes/turn_resolve_pass.h). Measured with
// the viewer, headless, 1280x720, triangle path, --orient curvature, orbiting, resolved against
// in the mesh pass, three alternated runs: icosphere-7 (2 pixels a triangle) 8-14% faster,
// icosphere-6 (8) 8-11% faster, icosphere-5 (32) even (-9% to +9%), icosphere-4 (128) 11-24%
// slower, the bunny (178) 13-22% slower.
constexpr float kResolveTurnPixels = 16.0f;
}  // namespace

Result<std::unique_ptr<Renderer>> Renderer::create() {
  if (epoxy_gl_version() < 33) return Error{"the renderer needs OpenGL 3.3 or later; this context is " + std::to_string(epoxy_gl_version())};
  std::unique_ptr<Renderer> r(new Renderer());
  r->emptyVao_ = gl::createVertexArray();
  for (const PathInfo& info : renderPaths()) r->paths_.push_back(info.create());
  return r;
}

Renderer::~Renderer() = default;

void Renderer::setMesh(const Mesh* mesh) {
  mesh_ = mesh && !mesh->indices.empty() ? mesh : nullptr;
  gpuMesh_.clear();
  materials_.clear();
  triangles_.setMesh(mesh_);
  lines_.setMesh(mesh_);
  strokes_.setMesh(mesh_);
  patterns_.setMesh(mesh_);
  groups_.clear();
  groupsDirty_ = true;
  field_.reset();
  occlusion_.reset();
  ++sceneVersion_;
  groundGpu_.clear();
  groundTriangles_.setMesh(nullptr);
  ground_ = Mesh{};
  if (!mesh_) return;
  gpuMesh_.upload(*mesh_);
  materials_.upload(*mesh_);
  stats_.bufferUploads += 3;
}

Status Renderer::setMaterialPalette(const std::string& material, const Palette& palette) {
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  materialPalettes_[material] = std::move(*uploaded);
  groupsDirty_ = true;
  stats_.bufferUploads += 1;
  return okStatus();
}

void Renderer::clearMaterialPalette(const std::string& material) {
  if (materialPalettes_.erase(material)) groupsDirty_ = true;
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

std::vector<std::string> Renderer::materialPaletteNames() const {
  std::vector<std::string> out;
  for (const auto& [name, palette] : materialPalettes_) out.push_back(name);
  return out;
}

void Renderer::rebuildPaletteGroups() {
  groupsDirty_ = false;
  groups_.clear();
  if (!mesh_ || materialPalettes_.empty() || mesh_->faceMaterials.size() != mesh_->triangleCount()) return;
  // The palette of each material: 0 the main one, k > 0 the k-th distinct material palette.
  std::vector<const GpuPalette*> palettes{nullptr};
  std::vector<std::size_t> groupOf(mesh_->materials.size(), 0);
  for (std::size_t i = 0; i < mesh_->materials.size(); ++i) {
    auto it = materialPalettes_.find(mesh_->materials[i].name);
    if (it == materialPalettes_.end()) continue;
    auto at = std::find(palettes.begin(), palettes.end(), it->second.get());
    if (at == palettes.end()) at = palettes.insert(palettes.end(), it->second.get());
    groupOf[i] = static_cast<std::size_t>(at - palettes.begin());
  }
  if (palettes.size() == 1) return;  // no material of this mesh has its own palette
  for (std::size_t g = 0; g < palettes.size(); ++g) {
    std::vector<char> keep(mesh_->triangleCount(), 0);
    bool any = false;
    for (std::size_t f = 0; f < keep.size(); ++f) {
      keep[f] = groupOf[mesh_->faceMaterials[f]] == g;
      any = any || keep[f];
    }
    if (!any) continue;
    auto group = std::make_unique<PaletteGroup>();
    group->palette = palettes[g];
    group->mesh = meshSubset(*mesh_, keep);
    group->gpuMesh.upload(group->mesh);
    group->materials.upload(group->mesh);
    group->triangles.setMesh(&group->mesh);
    if (field_) group->gpuMesh.uploadDirections(field_->directions);  // a subset keeps every vertex
    if (occlusion_ && occlusion_->done()) group->gpuMesh.uploadOcclusion(occlusion_->values());
    stats_.bufferUploads += 3;
    groups_.push_back(std::move(group));
  }
}

Status Renderer::setPalette(const Palette& palette) {
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  palette_ = std::move(*uploaded);
  stats_.bufferUploads += 1;
  return okStatus();
}

void Renderer::collectGpuTime() {
  if (std::optional<double> ms = timer_.collect()) stats_.gpuMs = *ms;
}

Status Renderer::prepare(const RenderSettings& s) {
  if (!palette_ && pathInfo(s.path).usesPalette) return Error{"no palette loaded"};
  if (groupsDirty_) rebuildPaletteGroups();
  // Cel bands belong to the main palette (they are one fewer than its tones).
  for (auto& [name, p] : materialPalettes_)
    if (Status st = p->updateMatcher(s.match, s.rangeScale, {}, stats_); !st) return Error{"palette of material '" + name + "': " + st.error()};
  if (shadowPalette_)
    if (Status st = shadowPalette_->updateMatcher(s.match, s.rangeScale, {}, stats_); !st) return Error{"shadow palette: " + st.error()};
  if (occlusionPalette_)
    if (Status st = occlusionPalette_->updateMatcher(s.match, s.rangeScale, {}, stats_); !st) return Error{"occlusion palette: " + st.error()};
  if (palette_) return palette_->updateMatcher(s.match, s.rangeScale, s.bands, stats_);
  return okStatus();
}

void Renderer::preparePattern(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  std::optional<PatternFrame> frame;
  if (s.pattern == PatternSpace::Anchored && mesh_) {
    const PatternFit& fit = patterns_.update(camera, viewport, s.patternFollowsRotation);
    stats_.cpuPatternMs = fit.ms;
    stats_.patternSamples = fit.samplesUsed;
    frame = patterns_.frame();
  }
  const float scale = std::clamp(s.patternScale, RenderSettings::kMinPatternScale, RenderSettings::kMaxPatternScale);
  // Object units one pixel spans at eye depth 1 (the mesh's units are the eye's).
  const float pixelSize = 2.0f / (std::max(std::abs(camera.projection[1][1]), 1e-6f) * float(std::max(viewport.w, 1)));
  const glm::mat4 eyeToObject = glm::inverse(camera.view);
  // Mapped patterns are placed per vertex where the model's triangles span a few pixels each:
  // there interpolation is cheaper than mapping every pixel; on denser meshes llvmpipe shades a
  // block of pixels per triangle anyway and a varying costs each triangle's set-up more than the
  // arithmetic it saves (pattern_vertex.glsl has the figures).
  bool perVertex = true;
  pixelsPerFrontTriangle_ = std::numeric_limits<float>::infinity();
  if (mesh_ && !mesh_->indices.empty()) {
    const float frontTriangles = 0.5f * float(mesh_->indices.size() / 3);
    pixelsPerFrontTriangle_ = projectedSphereArea(camera, mesh_->radius, viewport) / frontTriangles;
    perVertex = pixelsPerFrontTriangle_ >= kPatternPerVertexPixels;
  }
  auto place = [&](GpuPalette& p) {
    p.setPatternFrame(frame, scale, s.patternLinearFilter);
    p.setObjectPattern(s.pattern == PatternSpace::Object, pixelSize, eyeToObject);
    p.setPlacement(glm::vec2(frameOffset_), viewport, perVertex);
  };
  if (palette_) place(*palette_);
  forEachExtraPalette(place);
}

void Renderer::prepareOrientation(const RenderSettings& s) {
  glm::vec4 light(0, 0, 1, 0);
  for (int i = 0; i < kMaxLights; ++i)
    if (lighting_.light(i).enabled) {
      light = lighting_.light(i).position;
      break;
    }
  bool turned = false;
  if (palette_) {
    palette_->setOrientation(s.orient, light);
    turned = palette_->oriented();
  }
  forEachExtraPalette([&](GpuPalette& p) {
    p.setOrientation(s.orient, light);
    turned = turned || p.oriented();
  });
  if (turned && s.orient.source == OrientSource::Curvature) ensureDirectionField();
}

void Renderer::ensureDirectionField() {
  if (!mesh_ || field_) return;
  field_ = computeDirectionField(*mesh_);
  stats_.cpuFieldMs = field_->ms;
  gpuMesh_.uploadDirections(field_->directions);
  for (auto& g : groups_) g->gpuMesh.uploadDirections(field_->directions);
  stats_.bufferUploads += 1;
}

void Renderer::prepareGround() {
  if (!mesh_ || !ground_.indices.empty()) return;
  ground_ = groundPlane(*mesh_);
  groundGpu_.upload(ground_);
  groundTriangles_.setMesh(&ground_);
  stats_.bufferUploads += 1;
}

Status Renderer::prepareShadows(const CameraMatrices& camera, const RenderSettings& s) {
  shadowsReady_ = false;
  if (!s.shadows || !mesh_) return okStatus();
  if (s.ground) prepareGround();
  ShadowScene scene;
  scene.casters = {&gpuMesh_};
  scene.casterRadius = mesh_->radius;
  scene.sceneRadius = s.ground ? ground_.radius : mesh_->radius;
  scene.version = sceneVersion_ * 2 + (s.ground ? 1 : 0);
  if (Status st = shadows_.update(lighting_, camera.view, scene, programs_, stats_); !st) return st;
  shadowsReady_ = shadows_.layers() > 0;
  stats_.shadowLayers = shadows_.layers();
  return okStatus();
}

const std::vector<float>* Renderer::occlusionValues(const RenderSettings& s) const {
  return s.occlusion && s.occlusionMethod == OcclusionMethod::Baked && occlusion_ && occlusion_->done() ? &occlusion_->values() : nullptr;
}

Status Renderer::prepareScreenOcclusion(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  screenOcclusionReady_ = false;
  if (!s.occlusion || s.occlusionMethod != OcclusionMethod::Screen || !mesh_) return okStatus();
  std::vector<const GpuMesh*> meshes{&gpuMesh_};
  if (s.ground) {
    prepareGround();
    meshes.push_back(&groundGpu_);
  }
  const float radius = std::clamp(s.screenOcclusionRadius, 0.01f, 10.0f) * (mesh_->radius > 0.0f ? mesh_->radius : 1.0f);
  if (Status st = screenOcclusion_.draw(meshes, camera, radius, viewport, programs_, emptyVao_, stats_); !st) return st;
  screenOcclusionReady_ = true;
  return okStatus();
}

Status Renderer::prepareOcclusion(const RenderSettings& s) {
  if (!s.occlusion || !mesh_ || s.occlusionMethod != OcclusionMethod::Baked) return okStatus();
  if (!occlusion_) {
    Result<std::unique_ptr<OcclusionBake>> bake = OcclusionBake::start(*mesh_, gpuMesh_);
    if (!bake) return Error{bake.error()};
    occlusion_ = std::move(*bake);
  }
  if (occlusion_->done()) return okStatus();
  if (occlusionBudgetMs_ <= 0.0 && progress_) {
    // To the end now, in slices, saying how far it got.
    while (!occlusion_->done()) {
      if (Status st = occlusion_->step(250.0, programs_, stats_); !st) return st;
      progress_("baking ambient occlusion", double(occlusion_->directionsDone()) / occlusion_->directions());
    }
  } else if (Status st = occlusion_->step(occlusionBudgetMs_, programs_, stats_); !st) {
    return st;
  }
  if (!occlusion_->done()) return okStatus();
  gpuMesh_.uploadOcclusion(occlusion_->values());
  for (auto& g : groups_) g->gpuMesh.uploadOcclusion(occlusion_->values());  // subsets keep every vertex
  stats_.bufferUploads += 1;
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

Status Renderer::drawPath(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport, gl::MeshOutput output) {
  if (!mesh_) return okStatus();
  // The whole mesh's, for every part: the parts hide each other's back faces.
  const bool cullBackFaces = backFacesHidden(camera, s);
  if (groups_.empty() || !s.materials) {
    if (s.materials) materials_.update(*mesh_, lighting_, stats_);
    FrameContext frame{camera, viewport, s, lighting_, gpuMesh_, *mesh_, materials_, palette_.get(), triangles_, programs_, stats_, emptyVao_, output};
    frame.occlusion = occlusionValues(s);
    frame.turnResolve = turnResolveFor(s, frame.palette, output);
    frame.cullBackFaces = cullBackFaces;
    if (Status st = drawPart(frame, s.path); !st) return st;
    return drawGround(camera, s, viewport, output);
  }
  // One draw of the path per palette, each over its part of the mesh; depth testing across
  // the parts keeps the nearest surface, whichever part is drawn first.
  for (auto& g : groups_) {
    g->materials.update(g->mesh, lighting_, stats_);
    const GpuPalette* palette = g->palette ? g->palette : palette_.get();
    FrameContext frame{camera, viewport, s, lighting_, g->gpuMesh, g->mesh, g->materials, palette, g->triangles, programs_, stats_, emptyVao_, output};
    frame.occlusion = occlusionValues(s);
    frame.turnResolve = turnResolveFor(s, palette, output);
    frame.cullBackFaces = cullBackFaces;
    if (Status st = drawPart(frame, s.path); !st) return st;
  }
  return drawGround(camera, s, viewport, output);
}

bool Renderer::backFacesHidden(const CameraMatrices& camera, const RenderSettings& s) {
  const bool hidden = s.cullHiddenBackFaces && mesh_ && mesh_->closed && sphereBeyondNearPlane(camera, mesh_->radius);
  stats_.backFacesCulled = stats_.backFacesCulled || hidden;
  return hidden;
}

Status Renderer::drawGround(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport, gl::MeshOutput output) {
  if (!s.ground || !mesh_ || !palette_) return okStatus();
  prepareGround();
  // The ground has no materials of its own: lit with the lighting state's material.
  RenderSettings plain = s;
  plain.materials = false;
  FrameContext frame{camera, viewport, plain, lighting_, groundGpu_, ground_, groundMaterials_, palette_.get(), groundTriangles_, programs_, stats_, emptyVao_, output};
  if (shadowsReady_ && s.groundShadowTexture) {
    if (Status st = groundShadows_.update(shadows_, ground_, sceneVersion_, programs_, emptyVao_, stats_); !st) return st;
    if (groundShadows_.ready()) frame.groundShadows = &groundShadows_;
  }
  return drawPart(frame, s.path);
}

TurnResolvePass* Renderer::turnResolveFor(const RenderSettings& s, const GpuPalette* palette, gl::MeshOutput output) {
  const bool meshPath = s.path == RenderPath::Triangle || s.path == RenderPath::Vertex || s.path == RenderPath::Pixel || s.path == RenderPath::Smooth;
  // The object pattern's coordinate comes from the surface, which the resolve cannot see.
  if (!meshPath || output != gl::MeshOutput::Colour || !palette || !palette->oriented() || palette->patternMapping() == gl::PatternMapping::Object)
    return nullptr;
  const TurnPlacement where = s.orient.placement;
  if (where == TurnPlacement::InMeshPass || (where == TurnPlacement::Auto && !(pixelsPerFrontTriangle_ < kResolveTurnPixels))) return nullptr;
  ++stats_.surfaceBuffers;
  return &turnResolve_;
}

Status Renderer::drawPart(FrameContext& frame, RenderPath path) {
  frame.shadows = shadowsReady_ ? &shadows_ : nullptr;
  frame.screenOcclusion = screenOcclusionReady_ ? &screenOcclusion_ : nullptr;
  if (Status st = paths_[pathIndex(path)]->draw(frame); !st) return st;
  if (!frame.settings.controlPalettes) return okStatus();
  frame.shadowPalette = shadowPalette_.get();
  frame.occlusionPalette = occlusionPalette_.get();
  return drawControlPalettes(frame, path);
}

Status Renderer::render(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  const auto frameStart = std::chrono::steady_clock::now();
  stats_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();  // minimised window: nothing to draw
  if (Status st = prepare(s); !st) return st;
  collectGpuTime();
  preparePattern(camera, s, viewport);
  prepareOrientation(s);
  Status shadowStatus = prepareShadows(camera, s);
  if (shadowStatus) shadowStatus = prepareOcclusion(s);
  timer_.begin();
  clearViewport(viewport);
  if (shadowStatus) shadowStatus = prepareScreenOcclusion(camera, s, viewport);
  Status result = shadowStatus ? drawBackground(palette_.get(), programs_, emptyVao_, stats_) : shadowStatus;
  if (result) result = drawPath(camera, s, viewport, gl::MeshOutput::Colour);
  if (result && mesh_ && s.strokes.on && palette_) {
    ensureDirectionField();
    result = strokes_.draw(camera, s.strokes, lighting_, *palette_, s.match, field_->directions, viewport, programs_, stats_);
  }
  if (result && mesh_) result = drawHardwareOutlines(gpuMesh_, camera, s.lines, palette_.get(), s.match, viewport, programs_, stats_);
  if (result && mesh_) result = imageEdges_.draw(gpuMesh_, camera, s.lines, viewport, programs_, emptyVao_, stats_);
  if (result && mesh_) result = lines_.draw(camera, s.lines, viewport, programs_, stats_);
  timer_.end();
  gl::restoreDefaults();
  stats_.cpuFrameMs = msSince(frameStart);
  return result;
}

Status Renderer::renderSelection(const CameraMatrices& camera, const RenderSettings& s, SelectionOutput output,
                                 const glm::ivec4& viewport) {
  stats_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();
  if (Status st = prepare(s); !st) return st;
  if (Status st = prepareShadows(camera, s); !st) return st;
  if (Status st = prepareOcclusion(s); !st) return st;
  clearViewport(viewport);
  if (Status st = prepareScreenOcclusion(camera, s, viewport); !st) return st;
  const Status result = drawPath(camera, s, viewport, output == SelectionOutput::Entry ? gl::MeshOutput::Entry : gl::MeshOutput::Blend);
  gl::restoreDefaults();
  return result;
}

Status Renderer::renderStrokeAngles(const CameraMatrices& camera, const RenderSettings& s, const glm::ivec4& viewport) {
  stats_.startFrame();
  if (viewport.z < 1 || viewport.w < 1 || !mesh_) return okStatus();
  if (Status st = prepare(s); !st) return st;
  if (!palette_) return Error{"no palette loaded"};
  preparePattern(camera, s, viewport);
  prepareOrientation(s);
  clearViewport(viewport);
  FrameContext frame{camera, viewport, s, lighting_, gpuMesh_, *mesh_, materials_, palette_.get(), triangles_, programs_, stats_, emptyVao_};
  const Status result = palette_->oriented() ? drawStrokeAngles(frame) : okStatus();
  gl::restoreDefaults();
  return result;
}

Status Renderer::renderGeometry(const CameraMatrices& camera, GeometryOutput output, const glm::ivec4& viewport) {
  stats_.startFrame();
  if (viewport.z < 1 || viewport.w < 1) return okStatus();
  clearViewport(viewport);
  const Status result = mesh_ ? drawGeometry(gpuMesh_, camera, output, programs_, stats_) : okStatus();
  gl::restoreDefaults();
  return result;
}

Status Renderer::drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour, float pixels,
                            const glm::ivec4& viewport) {
  return npr::drawMarker(camera, worldPosition, colour, pixels, viewport, programs_, emptyVao_, stats_);
}

}  // namespace npr
