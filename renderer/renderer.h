// The palette renderer's one entry point for the app and the tests: set a scene of models, a
// palette and the lighting state, then render frames. Each frame is: clear, background, the
// chosen render path over every model (paths/, one file each), lines (lines/), timers. The paths light with the shared
// lighting model (lighting/) and match with the shared PaletteMatcher (palette/); they differ
// only in where lighting is sampled and how the palette reaches the screen (screen space).
//
// The renderer draws into whatever framebuffer is bound (the window's, or an
// OffscreenTarget) and needs a current OpenGL 3.3+ core context. It never sees a window.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gpu_timer.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/control_weights.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/tone_range.h"
#include "renderer/passes/geometry_pass.h"
#include "renderer/passes/turn_resolve_pass.h"
#include "renderer/paths/path_table.h"
#include "renderer/features/feature.h"
#include "renderer/render_settings.h"
#include "renderer/scene/scene.h"

namespace npr {

// What a selection render writes instead of texels: the chosen entry (entry / 255 in red, an
// 8-bit target will do) or the smooth path's selection (entry a, entry b, weight of b as
// floats: read it from a float target; one entry is a = b, weight 0).
enum class SelectionOutput { Entry, Blend };

struct FrameContext;

// Whether a frame drawn with `settings` reads a deforming mesh's pose on the CPU: the
// per-triangle paths light its faces there, object-space lines and painterly strokes are found
// on it, the anchored pattern fits samples read on it. Else the GPU's pose serves every pass.
bool framePosesOnCpu(const RenderSettings& settings);

// Where a frame poses its deforming meshes (`--deform`). `auto` poses on the GPU, and on the
// CPU too where the frame reads the pose there; posing on both then skips the CPU copy's
// upload, which on a GPU costs more than the compute dispatch (an H100: the 871K torus's
// triangle path 22.5 ms posed on the CPU alone, 19.7 ms on both), while on a software
// rasterizer the dispatch runs on the CPU's own cores (llvmpipe: 1.34x against 1.71x the still
// frame), so there the CPU poses alone.
struct PoseTargets {
  bool gpu = false;
  bool cpu = false;
};
PoseTargets poseTargets(const RenderSettings& settings, bool softwareRasterizer);

class Renderer {
 public:
  [[nodiscard]] static Result<std::unique_ptr<Renderer>> create();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The scene (scene/scene.h): models placed by transforms, each uploaded when added and
  // owning what is derived from its mesh. The renderer keeps a pointer to each mesh: remove
  // the model (or set another scene) before the mesh is destroyed.
  ModelId addModel(const Mesh& mesh, const glm::mat4& transform = glm::mat4(1.0f));
  // A temporary would be gone before the first frame.
  ModelId addModel(Mesh&& mesh, const glm::mat4& transform = glm::mat4(1.0f)) = delete;
  void removeModel(ModelId id);
  // False when there is no such model.
  bool setModelTransform(ModelId id, const glm::mat4& transform);
  // The object's name, for line sets that select objects. False when there is no such model.
  bool setModelName(ModelId id, const std::string& name);
  // An animation's move: as setModelTransform, but the ground stays where the layout put it.
  bool setModelPose(ModelId id, const glm::mat4& transform);
  // Poses a model whose mesh deforms (Mesh::deformation): morph `weights` and skin `joints`
  // (per joint, the mesh's rest space to its posed space; animation/deformation.h). False
  // when there is no such model; a mesh that does not deform ignores it.
  bool setModelDeformation(ModelId id, const std::vector<glm::mat4>& joints, const std::vector<float>& weights);
  // A hidden model keeps everything derived from its mesh and is left out of every pass.
  bool setModelVisible(ModelId id, bool visible) { return scene_.setVisible(id, visible); }
  // The model's detail in [0, 1] (clamped; not finite: 0), which a palette with `axis detail`
  // picks its row by. False when there is no such model.
  bool setModelDetail(ModelId id, float detail) {
    Model* m = scene_.find(id);
    if (m) m->setDetail(std::isfinite(detail) ? std::clamp(detail, 0.0f, 1.0f) : 0.0f);
    return m != nullptr;
  }
  // The model's own palette, in place of the main one for its surfaces (every path; its
  // materials' palettes still win). On failure, or for no such model, nothing changes.
  [[nodiscard]] Status setModelPalette(ModelId id, const Palette& palette);
  void clearModelPalette(ModelId id);
  std::size_t modelCount() const { return scene_.size(); }
  const Model* model(ModelId id) const { return scene_.find(id); }
  // A scene of one model, untransformed (nullptr or an empty mesh: an empty scene).
  void setMesh(const Mesh* mesh);
  // An empty scene.
  void clearModels();
  // Uploads the palette; on failure the current one stays in place.
  [[nodiscard]] Status setPalette(const Palette& palette);
  // Per-material palettes: faces of the material named `material` are drawn with `palette`
  // (every path; matched with its own matcher), the rest with the main one. Kept across
  // meshes, applied to whichever has a material of that name; on failure nothing changes.
  [[nodiscard]] Status setMaterialPalette(const std::string& material, const Palette& palette);
  // Per-material detail: faces of the material named `material` take `detail` (clamped to
  // [0, 1]; not finite: 0) in place of their model's, for a palette with `axis detail` (with
  // materials on, as per-material palettes). Kept across meshes, like the palettes.
  void setMaterialDetail(const std::string& material, float detail);
  void clearMaterialPalette(const std::string& material);
  // Control-image palettes (passes/control_palette_pass.h): drawn where shadows fall or in
  // crevices, blended in by that parameter over the main palette. Matched with the main
  // palette's match mode and range scale; on failure nothing changes.
  [[nodiscard]] Status setControlPalette(ControlParameter parameter, const Palette& palette);
  void clearControlPalette(ControlParameter parameter);
  bool hasControlPalette(ControlParameter parameter) const { return controlPalette(parameter) != nullptr; }

  // The OpenGL-like lighting state (Lightfv, Materialfv, ...).
  LightingState& lighting() { return lighting_; }
  const LightingState& lighting() const { return lighting_; }

  // Draws one frame into the bound framebuffer's `viewport` (x, y, width, height).
  [[nodiscard]] Status render(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport);

  // Whether a frame with these settings has passes that share the bound framebuffer's depth
  // and stencil (the stencil path's masks writing its surface buffers, the turn resolve): a
  // window's own framebuffer cannot be shared, so the window draws such frames offscreen. Said
  // before the frame, from the conditions those passes test.
  bool sharesFramebufferDepth(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport) const;

  // Outputs for tests and the benchmark's accuracy reference, not images. Neither draws a
  // background or lines; clear the target first.
  // The palette selection `settings.path` makes at each pixel (stencil: the triangle path's,
  // which is the same choice by construction).
  [[nodiscard]] Status renderSelection(const CameraMatrices& camera, const RenderSettings& settings, SelectionOutput output,
                                       const glm::ivec4& viewport);
  // Each pixel's hatching stroke angle on screen for `settings.orient` (radians in red, 1 in
  // green where there is one; read from a float target), through the colour frame's surfaces:
  // each model, part and the ground with its own palette's orientation. All invalid where that
  // palette has no entry with a stroke direction.
  [[nodiscard]] Status renderStrokeAngles(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport);
  // The scene's interpolated eye-space position or normal (read from a float target).
  [[nodiscard]] Status renderGeometry(const CameraMatrices& camera, GeometryOutput output, const glm::ivec4& viewport);

  // The anchored pattern starts again from the screen's frame at the next frame: call on view
  // jumps (frame the model, reset the view). A new model does it too.
  void resetPattern() {
    scene_.forEach([](Model& m) { m.patterns().reset(); });
  }
  // Where the viewport's pixels sit in the whole frame, for a poster drawn in tiles: palette
  // patterns continue across the tiles' seams. (0, 0) for an ordinary frame.
  void setFrameOffset(const glm::ivec2& offset) { frameOffset_ = offset; }
  // The feature lines the frame shows for this camera, every model's in scene space, for
  // vector export.
  // `kindsFor(object)` (null: the scene's intersection lines; empty function: every kind drawn)
  // chooses the kinds kept for each object by name (bit EdgeKind); `set`, when it selects
  // materials, keeps the lines on a face of one of them (LineSet::materials).
  std::vector<FeatureLine> featureLines(const CameraMatrices& camera, const RenderSettings& settings,
                                        const std::function<std::uint8_t(const std::string* object)>& kindsFor = {}, const LineSet* set = nullptr);
  // The first shown model's (tests and the overlay).
  const PatternTracker& patternTracker() const;
  // The main palette as the last frame drew it (null before one is set).
  const GpuPalette* palette() const { return palette_.get(); }
  // How the palettes' textures lay on the model drawn last (patterns/pattern_placement.h).
  const PatternPlacement& patternPlacement() const { return pattern_; }
  // The first model's ambient occlusion bake: started the first time a frame asks for
  // occlusion, run for at most `occlusionBudgetMs` per frame (0: to the end in one frame, as
  // headless runs and tests want), uploaded when done. Null before it starts.
  const OcclusionBake* occlusionBake() const { return scene_.first() ? scene_.first()->occlusionBake() : nullptr; }
  void setOcclusionBudget(double ms) { occlusionBudgetMs_ = ms; }
  // Told how far long work inside a frame has got (the occlusion bake when it bakes to the end
  // at once), so a terminal can show it; empty: nothing told.
  void setProgress(std::function<void(const std::string& what, double fraction)> progress) { progress_ = std::move(progress); }
  // The first model's hatching direction field: computed the first time a frame orients
  // strokes along the curvature, kept with the model (null until then).
  const DirectionField* directionField() const { return scene_.first() ? scene_.first()->directionFieldIfComputed() : nullptr; }
  // The painterly strokes seeded on the scene's models (0 until a frame draws them).
  std::size_t strokeCount() const;
  double strokeSeedMs() const;

  // Reads finished GPU timer queries into stats().gpuMs (render() does this first). Call it
  // after the GPU work is finished to attribute a frame's time to that frame.
  void collectGpuTime();
  // A small screen-facing disc at `worldPosition` (the light marker).
  [[nodiscard]] Status drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour,
                                  float pixels, const glm::ivec4& viewport);

  const FrameStats& stats() const { return stats_; }
  // The automatic tone range the last frame fitted the palettes onto (query axis, 0..3), or
  // none (--tone-range fixed).
  std::optional<glm::vec2> toneRange() const { return toneTarget_; }
  // The matcher of the last frame (for tests and the benchmark's accuracy reference).
  const PaletteMatcher* matcher() const { return palette_ ? palette_->matcher() : nullptr; }
  // The first model's per-triangle shading (tests).
  const TriangleShading& triangleShading() const;

 private:
  Renderer() = default;
  // Makes the poses given since the last frame, on the GPU or the CPU as the frame reads them
  // (RenderSettings::deform; framePosesOnCpu).
  Status applyPoses(const RenderSettings& settings);
  // Checks that `settings` can be drawn and brings the matchers and the models' parts up to date.
  Status prepare(const RenderSettings& settings);
  // Every palette's matchers from `slot` on (GpuPalette::useMatcher): a model fitted to its own tones.
  void selectToneSlot(int slot) const;
  // The automatic tone range for this view (settings.toneRange), into toneTarget_ (and each
  // model's own, per object).
  void updateToneRange(const CameraMatrices& camera, const RenderSettings& settings);
  ToneRangeTracker toneRange_;
  std::optional<glm::vec2> toneTarget_;
  std::vector<ToneSample> toneSamples_;
  // What the features see of this frame.
  FrameView frameView(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport, bool colour);
  // Picks this frame's active features and runs their preparation (before the clear).
  Status prepareFeatures(FrameView& frame);
  // Depth and stencil cleared in the viewport only (the split view draws two).
  void clearViewport(const glm::ivec4& viewport);
  // What each part of the scene is drawn with; drawPart (the path) unless a frame of another
  // kind says otherwise (renderStrokeAngles).
  using PartDraw = std::function<Status(FrameView&, const Model*, FrameContext&)>;
  // The scene's surfaces with the path (or `draw`): every model's parts, then the ground. Colour
  // frames place each model's pattern first, but for `prepared`'s (done).
  Status drawScene(FrameView& frame, gl::MeshOutput output, const Model* prepared, const PartDraw* draw = nullptr);
  // One model's parts (or the whole model) with the path (or `draw`).
  Status drawModel(FrameView& frame, Model& model, gl::MeshOutput output, bool placePattern, const PartDraw* draw);
  // The ground plane with the path's own pass (or `draw`), after the models (--ground).
  Status drawGround(FrameView& frame, gl::MeshOutput output, const PartDraw* draw);
  // One part of the scene (a model, a per-material part, the ground) with the active
  // features' share: the path, then the control-image palettes over it.
  Status drawPart(FrameView& view, const Model* model, FrameContext& frame, RenderPath path);
  // The turn resolve, where a frame of the model's with this palette leaves its turned lookups
  // to it (TurnPlacement), else null.
  TurnResolvePass* turnResolveFor(const RenderSettings& settings, const GpuPalette* palette, gl::MeshOutput output);
  // Whether this model's mesh passes may drop back faces (FrameContext::cullBackFaces); noted in
  // the frame's stats.
  bool backFacesHidden(const Model& model, const CameraMatrices& placed, const RenderSettings& settings);

  std::map<std::string, std::unique_ptr<GpuPalette>> materialPalettes_;
  std::map<std::string, float> materialDetails_;
  std::map<const Model*, std::unique_ptr<GpuPalette>> modelPalettes_;
  // The palette a model's surfaces are drawn with where no material palette applies.
  GpuPalette* mainPaletteOf(const Model& model) const {
    const auto it = modelPalettes_.find(&model);
    return it == modelPalettes_.end() ? palette_.get() : it->second.get();
  }
  std::unique_ptr<GpuPalette> shadowPalette_, occlusionPalette_;
  GpuPalette* controlPalette(ControlParameter parameter) const {
    return parameter == ControlParameter::Shadow ? shadowPalette_.get() : occlusionPalette_.get();
  }
  // Calls fn(GpuPalette&) for every palette loaded besides the main one: per-object,
  // per-material, then control palettes.
  template <class Fn>
  void forEachExtraPalette(Fn&& fn) const {
    for (const auto& [model, p] : modelPalettes_) fn(*p);
    for (const auto& [name, p] : materialPalettes_) fn(*p);
    if (shadowPalette_) fn(*shadowPalette_);
    if (occlusionPalette_) fn(*occlusionPalette_);
  }
  bool partsDirty_ = false;  // the material palettes or details changed since the models were split

  LightingState lighting_;
  FrameStats stats_;
  Scene scene_;
  std::unique_ptr<GpuPalette> palette_;
  gl::ProgramCache programs_;
  gl::GpuTimer timer_;
  gl::VertexArray emptyVao_;  // full-screen passes make their vertices in the shader
  std::vector<std::unique_ptr<RenderPass>> paths_;  // by pathIndex()
  std::vector<std::unique_ptr<Feature>> features_;  // the feature table (features/feature.h)
  std::vector<Feature*> active_;                    // this frame's
  TurnResolvePass turnResolve_;
  float pixelsPerFrontTriangle_ = 0.0f;  // the model being drawn, from its bounding disc (preparePattern)
  bool softwareRasterizer_ = true;       // GL_RENDERER names llvmpipe or the like: choices tuned for it apply
  // How the model drawn next lays every palette's textures (patterns/pattern_placement.h),
  // handed to its passes with the frame (FrameContext::pattern).
  PatternPlacement pattern_;
  // The pattern_ of this model: its frame (anchored) or none (screen) and where it is drawn (the
  // viewport, a poster tile's offset, per-vertex or per-pixel placement).
  void preparePattern(Model* model, const CameraMatrices& placed, const RenderSettings& settings, const glm::ivec4& viewport);
  // This frame's hatching orientation in pattern_, once per frame (the same for every model);
  // computes the direction field of every model when a palette turns along the curvature and a
  // model has none yet.
  void prepareOrientation(const RenderSettings& settings);
  // The per-triangle paths' CPU lighting of a scene's models, side by side (see renderer.cpp).
  void prepareTriangleShading(const CameraMatrices& camera, const RenderSettings& settings);
  double occlusionBudgetMs_ = 0.0;
  glm::ivec2 frameOffset_{0};
  std::function<void(const std::string&, double)> progress_;
  // The ground plane under the scene (--ground), drawn like one more model; built the first
  // time a frame asks for it, again when the scene changes.
  Model* prepareGround();
  Mesh groundMesh_;
  std::unique_ptr<Model> ground_;
  unsigned groundVersion_ = 0;  // the scene's version it was built for
};

}  // namespace npr
