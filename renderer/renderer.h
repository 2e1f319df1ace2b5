// The palette renderer's one entry point for the app and the tests: it holds a scene of models
// (scene/scene.h), the palettes they are drawn with (palette/palette_set.h) and the lighting
// state, and renders frames of them. A frame is: the palettes and features prepared, clear,
// background, the chosen render path over every model (paths/, one file each), the features'
// passes over the surfaces (features/), timers. The paths light with the shared lighting model
// (lighting/) and match with the shared PaletteMatcher (palette/); they differ only in where
// lighting is sampled and how the palette reaches the screen (screen space).
//
// The renderer draws into whatever framebuffer is bound (the window's, or an
// OffscreenTarget) and needs a current OpenGL 3.3+ core context. It never sees a window.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/features/feature.h"
#include "renderer/frame/frame_needs.h"
#include "renderer/frame/supersample.h"
#include "renderer/frame/tone_fit.h"
#include "renderer/gl/gpu_timer.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/palette_set.h"
#include "renderer/paths/path_table.h"
#include "renderer/scene/scene.h"
#include "renderer/scene/scene_lines.h"
#include "renderer/settings/render_settings.h"
#include "renderer/surfaces/scene_surfaces.h"

namespace npr {

// What a frame writes. Colour: the picture. The others are for tests, the benchmark's accuracy
// reference and the exports, not images, and draw no background or lines (clear the target
// first): Entry, the palette entry the path picks at each pixel (entry / 255 in red, an 8-bit
// target will do; the stencil path's is the triangle path's, the same choice by construction);
// Blend, the smooth path's selection (entry a, entry b, weight of b as floats; one entry is a =
// b, weight 0); StrokeAngles, each pixel's hatching stroke angle on screen for the settings'
// orientation (radians in red, 1 in green where there is one), through the colour frame's
// surfaces, each with its own palette's orientation; EyePosition and EyeNormal, the scene's
// interpolated eye-space position or normal. Read the float ones from a float target.
enum class FrameOutput { Colour, Entry, Blend, StrokeAngles, EyePosition, EyeNormal };

// What a frame drawn with `settings` needs before it draws, as the path's table row, the
// pattern and the features' table rows declare it from the settings alone (the shared depth
// also depends on the scene: Renderer::sharesFramebufferDepth).
FrameNeeds frameNeeds(const RenderSettings& settings);

// Where a frame drawn with `settings` poses its deforming meshes (frame/frame_needs.h).
PoseTargets poseTargets(const RenderSettings& settings, bool softwareRasterizer);

class Renderer {
 public:
  [[nodiscard]] static Result<std::unique_ptr<Renderer>> create();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The models, placed by transforms, each uploaded when added and owning what is derived from
  // its mesh (and its own palette); the ground plane.
  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }
  // The main, per-material and control-image palettes.
  PaletteSet& palettes() { return palettes_; }
  const PaletteSet& palettes() const { return palettes_; }
  // The OpenGL-like lighting state (Lightfv, Materialfv, ...).
  LightingState& lighting() { return lighting_; }
  const LightingState& lighting() const { return lighting_; }

  // Draws one frame into the bound framebuffer's `viewport` (x, y, width, height).
  [[nodiscard]] Status render(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport,
                              FrameOutput output = FrameOutput::Colour);

  // What one frame hands the next, carried through a frame without drawing it, as render()
  // would: the poses, and the anchored pattern's frame following each model. A frame range's
  // frames before its first (app/headless/frame_sequence.h) pass through here.
  [[nodiscard]] Status follow(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport);

  // Whether a frame with these settings has passes that share the bound framebuffer's depth
  // and stencil (FrameNeeds::sharedDepth, with this scene's palettes and models): a window's
  // own framebuffer cannot be shared, so the window draws such frames offscreen.
  bool sharesFramebufferDepth(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport) const;

  // The feature lines the frame shows for this camera, in scene space, for vector export
  // (scene/scene_lines.h says what `kindsFor` and `set` choose).
  std::vector<FeatureLine> featureLines(const CameraMatrices& camera, const RenderSettings& settings,
                                        const std::function<std::uint8_t(const std::string* object)>& kindsFor = {},
                                        const LineSet* set = nullptr) {
    return sceneFeatureLines(scene_, camera, settings, kindsFor, set, gpu_.programs);
  }

  // The files' own points and lines in scene space, for vector export.
  SceneMarks marks() const { return sceneMarks(scene_); }

  // The anchored pattern starts again from the screen's frame at the next frame: call on view
  // jumps (frame the model, reset the view). A new model does it too.
  void resetPattern() {
    scene_.forEach([](Model& m) { m.patterns().reset(); });
  }
  // A poster drawn in tiles: where the viewport's pixels sit in the whole frame (palette
  // patterns continue across the tiles' seams) and the whole frame's projection (the tone range
  // is fitted to what the whole frame shows, not the tile). None: an ordinary frame.
  struct Tile {
    glm::ivec2 offset{0};
    glm::mat4 wholeProjection{1.0f};
  };
  void setTile(const std::optional<Tile>& tile) { work_.tile = tile; }
  // Long work inside a frame (the occlusion bake) runs for at most `ms` per frame (0: to the
  // end in one frame, as headless runs and tests want).
  void setOcclusionBudget(double ms) { work_.budgetMs = ms; }
  // Told how far such work has got when it runs to the end at once, so a terminal can show
  // it; empty: nothing told.
  void setProgress(std::function<void(const std::string& what, double fraction)> progress) { work_.progress = std::move(progress); }

  // How the palettes' textures lay on the model drawn last (patterns/pattern_placement.h).
  const PatternPlacement& patternPlacement() const { return surfaces_.pattern(); }
  // The automatic tone range the last frame fitted the palettes onto (query axis, 0..3), or
  // none (--tone-range fixed).
  std::optional<glm::vec2> toneRange() const { return toneFit_.target(); }
  const FrameStats& stats() const { return stats_; }
  // Reads finished GPU timer queries into stats().gpuMs (render() does this first). Call it
  // after the GPU work is finished to attribute a frame's time to that frame.
  void collectGpuTime();
  // A small screen-facing disc at `worldPosition` (the light marker).
  [[nodiscard]] Status drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour,
                                  float pixels, const glm::ivec4& viewport);

 private:
  Renderer() = default;
  // The frame's steps, in the order render() calls them (renderer.cpp).
  Status prepare(const CameraMatrices& camera, const RenderSettings& settings, FrameOutput output);
  FrameView frameView(const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec4& viewport, bool colour);
  void orientFrame(const RenderSettings& settings);
  Status prepareFeatures(FrameView& frame);
  void clearViewport(const glm::ivec4& viewport);

  // The shared GPU resources every pass of a frame may use.
  struct GpuResources {
    gl::ProgramCache programs;
    gl::GpuTimer timer;
    gl::VertexArray emptyVao;  // full-screen passes make their vertices in the shader
    bool softwareRasterizer = true;  // GL_RENDERER names llvmpipe or the like: choices tuned for it apply
  };
  // Long work inside frames, and where a poster's tile sits.
  struct WorkOptions {
    double budgetMs = 0.0;
    std::function<void(const std::string&, double)> progress;
    std::optional<Tile> tile;
  };

  FrameStats stats_;
  Scene scene_{stats_};
  PaletteSet palettes_{stats_};
  LightingState lighting_;
  GpuResources gpu_;
  SceneSurfaces surfaces_;                          // the paths, drawing every part of the scene
  std::vector<std::unique_ptr<Feature>> features_;  // the feature table's (features/feature.h)
  std::vector<Feature*> active_;                    // this frame's
  ToneFit toneFit_;
  Supersampler supersampler_;
  WorkOptions work_;
};

}  // namespace npr
