// What the viewer is showing: objects, palette list, render settings, camera and light. Shared
// by the window, --headless and --benchmark, so all three render a scene the same way.
// Loads are all-or-nothing: a file that fails to load leaves the current one in place, and the
// failure comes back as the Status, with what did not load, for the caller to report once
// (the command line exits with it, the window shows it in its message bar).
#pragma once

#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "app/data_directory.h"
#include "app/scene_objects.h"
#include "app/viewer_defaults.h"
#include "renderer/core/camera.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/palette.h"
#include "renderer/renderer.h"

namespace npr {

// The .palette files under palettes/, sorted by folder name.
std::vector<std::string> discoverPalettes();

struct ViewerState {
  SceneObjects scene;
  std::unique_ptr<Palette> palette;
  std::vector<std::string> palettes;  // what 1-9 and [ ] cycle through
  int paletteIndex = -1;
  RenderSettings settings = viewerDefaultSettings();
  OrbitCamera camera{30.0f, 20.0f, 3.0f};
  // The frame's width over its height (the window's, or the headless size): what framing fits.
  float viewAspect = 16.0f / 9.0f;
  // A scene file's camera in the viewer's space, looked through instead of the orbit camera
  // until the view is moved (--camera-from-file, the overlay).
  std::optional<SceneCamera> fileCamera;
  // The scene files' lights in place of the viewer's (KHR_lights_punctual; --no-file-lights).
  bool fileLights = true;
  glm::vec3 light{2.0f, 2.5f, 3.0f};  // scene space (model radius 1), or eye space when following
  bool lightFollowsCamera = false;
  bool splitView = false;  // reference on the left, the chosen path on the right
  // The scene's clock: which animations play and when (--animation, --time, --play, space).
  Playback playback;
  std::vector<std::string> messages;  // load errors and warnings, newest last, shown in the overlay
  // Failures the user must see (a failed open, a refused palette or style, a failed export):
  // the window's message bar shows them until dismissed. Also in `messages` and on stderr.
  std::vector<std::string> problems;
  // Notes go to stderr too; off for a look drawn aside (the style menu's pictures), whose
  // notes ("style applied") are not the user's doing.
  bool echo = true;
  std::string styleName;  // the style applied last (what Ctrl+S offers to save as); empty: none

  // Shows the files' objects in place of the scene (or beside it, `add`); the camera frames
  // the new scene. A file that fails leaves the scene as it was.
  Status loadModels(const std::vector<std::string>& paths, bool add, Renderer& renderer);
  // The camera frames the shown objects from its direction: their larger screen extent fills
  // 90% of a frame of viewAspect (from every yaw of a turntable, `everyYaw`).
  void frameScene(bool everyYaw = false);
  Status loadModel(const std::string& path, Renderer& renderer) { return loadModels({path}, false, renderer); }
  // Loads and selects a palette; the palette's own defaults (match mode, range scale) apply.
  Status loadPalette(const std::string& path, Renderer& renderer);
  // The same with the file already read (npr::loadPalette's result, made elsewhere: start-up
  // reads the first palette while the models load).
  Status loadPalette(const std::string& path, Result<Palette> read, Renderer& renderer);
  Status selectPalette(int index, Renderer& renderer);
  // Per-material palettes: draws the model's material `material` with the palette at `path`
  // (kept when the model changes; a model without that material is told so). An empty path
  // returns the material to the main palette. A palette that fails to load changes nothing.
  Status setMaterialPalette(const std::string& material, const std::string& path, Renderer& renderer);
  std::map<std::string, std::string> materialPalettes;  // material name -> palette file
  // Per-material detail (Renderer::setMaterialDetail), kept when the model changes; a model
  // without that material is told so.
  void setMaterialDetail(const std::string& material, float detail, Renderer& renderer);
  std::map<std::string, float> materialDetails;
  // Control-image palettes (drawn where shadows fall / in crevices); an empty path removes
  // it. A palette that fails to load changes nothing.
  Status setControlPalette(ControlParameter parameter, const std::string& path, Renderer& renderer);
  std::string shadowPalette, occlusionPalette;  // their files; empty: none
  // Says when a control palette is loaded but this frame's settings give it nothing to show.
  void noteIdleControlPalettes();
  void note(const std::string& message);
  void problem(const std::string& message);
  void noteMissingMaterial(const std::string& material, const char* forWhat = "its palette");

  // The view this frame is drawn from: the file's camera when one is chosen, else the orbit's.
  CameraMatrices view(float aspect) const;
  // Poses the scene at the clock's time (cheap when neither the time nor the choice changed).
  void poseScene(Renderer& renderer) { scene.pose(playback.choice, playback.time, renderer); }
  // The scene time the clock loops over (0: nothing plays).
  double animationLength() const { return scene.animationLength(playback.choice); }
  // Looks through the scene's camera `number` (from 1, as --info lists them).
  Status useFileCamera(int number);

  // Whether the frame is lit by the scene files' lights (there are some, and they are wanted).
  bool litByFileLights() const { return fileLights && !scene.files().empty() && !scene.lights().empty(); }
  // Sets the light for this frame's view (OpenGL semantics: the position is transformed by
  // the modelview current when it is set). Fails, leaving the light where it was, when the
  // position is not finite.
  [[nodiscard]] Status applyLight(Renderer& renderer, const CameraMatrices& camera) const;
  glm::vec3 lightWorldPosition(const CameraMatrices& camera) const;

 private:
  mutable bool fileLightsApplied_ = false;  // the lighting state holds the files' lights
};

}  // namespace npr
