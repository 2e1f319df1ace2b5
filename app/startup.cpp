// First-scene set-up from the command line (see startup.h).
#include "app/startup.h"

#include <algorithm>
#include <future>

#include "app/settings/style_file.h"
#include "renderer/core/printable.h"

namespace npr {
namespace {

// The objects --object-palette or --object-detail name: by name, or by number from 1.
Result<std::vector<std::size_t>> namedObjects(const ViewerState& state, const std::string& option, const std::string& object) {
  const auto& objects = state.scene.objects();
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (objects[i].name == object) chosen.push_back(i);
  if (chosen.empty() && !object.empty() && object.find_first_not_of("0123456789") == std::string::npos && object.size() < 9) {
    const std::size_t n = std::stoul(object);
    if (n >= 1 && n <= objects.size()) chosen.push_back(n - 1);
  }
  if (chosen.empty()) {
    std::string names;
    for (std::size_t i = 0; i < objects.size() && i < 12; ++i) names += (i ? ", " : "") + objects[i].name;
    return Error{option + ": no object named '" + printable(object) + "' in " + state.scene.label() + " (its objects: " + names +
                 (objects.size() > 12 ? ", ..." : "") + "; or give a number from 1 to " + std::to_string(objects.size()) + ")"};
  }
  return chosen;
}

Status setObjectPalette(ViewerState& state, Renderer& renderer, const std::string& object, const std::string& file) {
  Result<std::vector<std::size_t>> chosen = namedObjects(state, "--object-palette", object);
  if (!chosen) return Error{chosen.error()};
  for (std::size_t i : *chosen)
    if (Status s = state.scene.setPalette(i, file, renderer); !s) return Error{"--object-palette " + object + ": " + s.error()};
  return okStatus();
}

}  // namespace

Status startScene(const Options& o, ViewerState& state, Renderer& renderer) {
  applyDefaultMaterial(renderer.lighting());
  state.scene.setLayout(o.layout, renderer);
  state.scene.setSplitObjects(o.splitObjects);
  state.scene.setAllWarnings(o.verbose);
  const std::vector<std::string> models = o.models.empty() ? std::vector<std::string>{defaultModelPath()} : o.models;
  // The first palette is read (decoded and analysed, no GL) on another thread while the models
  // load: both are CPU work the first frame waits for, and a model's file is mostly read by
  // one thread (docs/performance-history.md, "Start-up").
  const std::string first = o.palettes.empty() ? defaultPalettePath() : o.palettes.front();
  std::future<Result<Palette>> firstPalette = std::async(std::launch::async, [first] { return npr::loadPalette(first); });
  if (Status s = state.loadModels(models, false, renderer); !s) return s;
  for (const auto& [object, file] : o.objectPalettes)
    if (Status s = setObjectPalette(state, renderer, object, file); !s) return s;
  for (const auto& [object, detail] : o.objectDetails) {
    Result<std::vector<std::size_t>> chosen = namedObjects(state, "--object-detail", object);
    if (!chosen) return Error{chosen.error()};
    for (std::size_t i : *chosen) state.scene.setDetail(i, detail, renderer);
  }
  state.palettes = discoverPalettes();
  for (const auto& p : o.palettes)
    if (std::find(state.palettes.begin(), state.palettes.end(), p) == state.palettes.end()) state.palettes.push_back(p);
  if (Status s = state.loadPalette(first, firstPalette.get(), renderer); !s) return s;
  // A style sets the look; what the command line names beside it wins.
  if (!o.style.empty()) {
    Result<std::string> file = findStyle(o.style);
    if (!file) return Error{"--style: " + file.error()};
    Result<Style> style = loadStyle(*file);
    if (!style) return Error{style.error()};
    if (!o.palettes.empty()) style->palette.reset();
    if (Status s = applyStyle(*style, state, renderer); !s) return s;
  }
  for (const auto& [material, file] : o.materialPalettes)
    if (Status s = state.setMaterialPalette(material, file, renderer); !s) return s;
  for (const auto& [material, detail] : o.materialDetails) state.setMaterialDetail(material, detail, renderer);
  if (Status s = applySettings(o.settings, false, state, renderer); !s) return s;
  state.fileLights = o.fileLights;
  if (!o.playAnimation.empty()) {
    Result<AnimationChoice> choice = parseAnimationChoice(o.playAnimation, state.scene.animationNames());
    if (!choice) return Error{choice.error()};
    state.playback.choice = *choice;
  }
  state.playback.time = o.time;
  state.playback.playing = o.play;
  state.poseScene(renderer);
  if (o.cameraFromFile > 0)
    if (Status s = state.useFileCamera(o.cameraFromFile); !s) return Error{"--camera-from-file: " + s.error()};
  // Framed for the frame's shape, from every yaw where the camera turns about the scene; a
  // camera given on the command line orbits the scene's centre at the distance it says.
  if (o.size.x > 0 && o.size.y > 0) state.viewAspect = float(o.size.x) / float(o.size.y);
  if (o.camera) state.camera.frame(1.0f);
  else state.frameScene(o.turntable > 0 || o.animation.orbitDegrees != 0.0f);
  if (o.camera) state.camera.setYawPitchDistance(o.camera->x, o.camera->y, o.camera->z * state.camera.modelRadius());
  state.noteIdleControlPalettes();
  if (!o.saveStyle.empty())
    if (Status s = saveStyle(state, renderer, o.style.empty() ? "Saved style" : o.style, o.saveStyle); !s) return s;
  return okStatus();
}

}  // namespace npr
