// Viewer state: loading with rollback, palette discovery and the light (see viewer_state.h).
#include "app/viewer_state.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/palette/palette_analysis.h"
#include "renderer/core/printable.h"
#include "app/file_lights.h"

namespace npr {
namespace fs = std::filesystem;

std::vector<std::string> discoverPalettes() {
  std::vector<std::string> out;
  std::error_code ec;
  const fs::path root = fs::path(dataDirectory()) / "palettes";
  for (const auto& dir : fs::directory_iterator(root, ec)) {
    if (!dir.is_directory()) continue;
    for (const auto& f : fs::directory_iterator(dir.path(), ec))
      if (f.path().extension() == ".palette") out.push_back(f.path().string());
  }
  std::sort(out.begin(), out.end());
  // The default palette first, so key 1 is the style the viewer opened with.
  auto it = std::find(out.begin(), out.end(), defaultPalettePath());
  if (it != out.end()) std::rotate(out.begin(), it, it + 1);
  return out;
}

void ViewerState::note(const std::string& raw) {
  const std::string message = printableMessage(raw);
  // Also on stderr: a user who started the viewer from a terminal, and the soak test's log,
  // see every load failure and warning without the overlay. A failure repeated every frame
  // (a render error) is printed once, not once per frame.
  if (echo && (messages.empty() || messages.back() != message)) std::fprintf(stderr, "npr-viewer: %s\n", message.c_str());  // escaped above
  messages.push_back(message);
  if (messages.size() > 20) messages.erase(messages.begin());
}

void ViewerState::problem(const std::string& raw) {
  note(raw);
  problems.push_back(printableMessage(raw));
  if (problems.size() > 8) problems.erase(problems.begin());
}

Status ViewerState::loadModels(const std::vector<std::string>& paths, bool add, Renderer& renderer) {
  std::vector<std::string> warnings;
  if (Status s = scene.load(paths, add, renderer, warnings); !s) return Error{"model not loaded: " + s.error()};
  for (const auto& w : warnings) note(w);
  const std::size_t lights = scene.lights().size();
  if (lights > 0 && fileLights)
    note(scene.label() + " is lit by its file's " + std::to_string(lights) + " light(s)" +
         (lights > kMaxLights ? " (the " + std::to_string(kMaxLights) + " brightest)" : std::string()) + "; --no-file-lights for the viewer's");
  fileCamera.reset();
  // A new scene plays all its animations from the start (a choice of the old one means nothing).
  playback.choice = {};
  playback.time = 0.0;
  poseScene(renderer);
  frameScene();
  renderer.resetPattern();
  for (const auto& [material, file] : materialPalettes) noteMissingMaterial(material);
  for (const auto& [material, detail] : materialDetails) noteMissingMaterial(material, "its detail");
  return okStatus();
}

void ViewerState::frameScene(bool everyYaw) {
  camera.frame(1.0f);  // the scene is fitted into the unit sphere: near and far planes, and the fallback
  camera.framePoints(scene.framingPoints(playback.choice), viewAspect, 0.9f, everyYaw);
}

void ViewerState::noteMissingMaterial(const std::string& material, const char* forWhat) {
  if (scene.empty()) return;
  std::vector<std::string> names;
  for (const ViewerObject& o : scene.objects())
    for (const MeshMaterial& m : o.mesh->materials) {
      if (m.name == material) return;
      if ((!m.fromLightingState || m.name != "(default)") && std::find(names.begin(), names.end(), m.name) == names.end() && names.size() < 16)
        names.push_back(m.name);
    }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  note("no material named '" + printable(material) + "' in " + scene.label() + " for " + forWhat +
       (list.empty() ? std::string(" (the scene has no materials)") : " (its materials: " + list + ")"));
}

Status ViewerState::setMaterialPalette(const std::string& material, const std::string& path, Renderer& renderer) {
  if (path.empty()) {
    renderer.palettes().clearMaterial(material);
    materialPalettes.erase(material);
    return okStatus();
  }
  Result<Palette> p = npr::loadPalette(path);
  if (!p) return Error{"palette for material '" + material + "' not loaded: " + p.error()};
  if (Status s = renderer.palettes().setMaterial(material, *p); !s) return Error{"palette for material '" + material + "' not loaded: " + s.error()};
  for (const auto& w : p->warnings) note(w);
  materialPalettes[material] = path;
  noteMissingMaterial(material);
  return okStatus();
}

void ViewerState::setMaterialDetail(const std::string& material, float detail, Renderer& renderer) {
  renderer.palettes().setMaterialDetail(material, detail);
  materialDetails[material] = detail;
  noteMissingMaterial(material, "its detail");
}

Status ViewerState::setControlPalette(ControlParameter parameter, const std::string& path, Renderer& renderer) {
  const char* what = parameter == ControlParameter::Shadow ? "shadow palette" : "occlusion palette";
  std::string& current = parameter == ControlParameter::Shadow ? shadowPalette : occlusionPalette;
  if (path.empty()) {
    renderer.palettes().clearControl(parameter);
    current.clear();
    return okStatus();
  }
  Result<Palette> p = npr::loadPalette(path);
  if (!p) return Error{std::string(what) + " not loaded: " + p.error()};
  if (Status s = renderer.palettes().setControl(parameter, *p); !s) {
    return Error{std::string(what) + " not loaded: " + s.error()};
  }
  for (const auto& w : p->warnings) note(w);
  current = path;
  return okStatus();
}

void ViewerState::noteIdleControlPalettes() {
  if (!shadowPalette.empty() && !settings.shadows)
    note("the shadow palette is drawn where cast shadows fall: turn shadows on (--shadows, overlay) to see it");
  if (!occlusionPalette.empty() && !settings.occlusion)
    note("the occlusion palette is drawn in crevices: turn occlusion on (--occlusion, overlay) to see it");
  if ((!shadowPalette.empty() || !occlusionPalette.empty()) && !pathInfo(settings.path).usesPalette)
    note(std::string("control palettes are not drawn by the ") + renderPathName(settings.path) + " path (it has no palette)");
}

Status ViewerState::loadPalette(const std::string& path, Renderer& renderer) { return loadPalette(path, npr::loadPalette(path), renderer); }

Status ViewerState::loadPalette(const std::string& path, Result<Palette> p, Renderer& renderer) {
  if (!p) return Error{"palette not loaded: " + p.error()};
  if (Status s = renderer.palettes().setMain(*p); !s) return Error{"palette not loaded: " + s.error()};
  palette = std::make_unique<Palette>(std::move(*p));
  if (palette->defaultMatch) settings.match = *palette->defaultMatch;
  settings.rangeScale = palette->defaultRangeScale.value_or(1.0f);
  settings.bands.clear();  // thresholds belong to the palette they were set for
  for (const auto& w : palette->warnings) note(w);
  for (const auto& w : analysePalette(*palette).suitabilityWarnings(settings.match)) note(palette->name + ": " + w);
  const auto it = std::find(palettes.begin(), palettes.end(), path);
  if (it == palettes.end()) {
    palettes.push_back(path);
    paletteIndex = static_cast<int>(palettes.size()) - 1;
  } else {
    paletteIndex = static_cast<int>(it - palettes.begin());
  }
  return okStatus();
}

Status ViewerState::selectPalette(int index, Renderer& renderer) {
  if (index < 0 || index >= static_cast<int>(palettes.size())) return Error{"no palette number " + std::to_string(index + 1)};
  return loadPalette(palettes[static_cast<size_t>(index)], renderer);
}

CameraMatrices ViewerState::view(float aspect) const {
  if (!fileCamera) return camera.matrices(aspect);
  const SceneCamera& c = *fileCamera;
  // The node's rotation without its scale; the scale (the fit of the scene, the file's own)
  // applies to the camera's distances instead.
  const glm::mat4& w = c.world;
  const float scale = std::max(glm::length(glm::vec3(w[1])), 1e-12f);
  const glm::vec3 back = glm::normalize(glm::vec3(w[2])), eye(w[3]);
  const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(w[1]), back));
  const glm::vec3 up = glm::cross(back, right);
  CameraMatrices m;
  m.view = glm::lookAt(eye, eye - back, up);
  // The scene lies inside the unit sphere about the origin: a far plane just past it, and a
  // near plane no closer than depth precision allows for that far plane.
  const float far = c.zfar > 0.0f ? c.zfar * scale : glm::length(eye) + 1.5f;
  const float near = std::max(c.znear * scale, far * 1e-5f);
  const float a = aspect > 0.0f && std::isfinite(aspect) ? aspect : 1.0f;
  if (c.perspective) {
    m.projection = glm::perspective(c.yfov, a, near, std::max(far, near * 2.0f));
  } else {
    const float h = std::abs(c.ymag) * scale;
    m.projection = glm::ortho(-h * a, h * a, -h, h, c.znear * scale, std::max(far, c.znear * scale + 1e-3f));
  }
  return m;
}

Status ViewerState::useFileCamera(int number) {
  const std::vector<SceneCamera> cameras = scene.cameras();
  if (number < 1 || number > static_cast<int>(cameras.size()))
    return Error{"no camera " + std::to_string(number) + " in " + scene.label() +
                 (cameras.empty() ? std::string(" (it has none)") : " (it has " + std::to_string(cameras.size()) + ")")};
  fileCamera = cameras[static_cast<std::size_t>(number - 1)];
  return okStatus();
}

glm::vec3 ViewerState::lightWorldPosition(const CameraMatrices& camera) const {
  if (!lightFollowsCamera) return light;
  return glm::vec3(glm::inverse(camera.view) * glm::vec4(light, 1.0f));
}

Status ViewerState::applyLight(Renderer& renderer, const CameraMatrices& camera) const {
  LightingState& l = renderer.lighting();
  if (litByFileLights()) {
    fileLightsApplied_ = true;
    return applyFileLights(scene.lights(), scene.fileUnits(), camera, l);
  }
  if (fileLightsApplied_) {
    restoreViewerLight(l);
    fileLightsApplied_ = false;
  }
  const float pos[4] = {light.x, light.y, light.z, 1.0f};
  l.setModelView(lightFollowsCamera ? glm::mat4(1.0f) : camera.view);
  Status st = l.Lightfv(GL_LIGHT0, GL_POSITION, pos);
  l.setModelView(camera.view);
  return st;
}

}  // namespace npr
