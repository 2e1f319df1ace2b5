// Scene loading (see scene_loader.h): glTF through its scene reader, the rest as one object.
#include "renderer/mesh/scene_loader.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/core/elapsed.h"
#include "renderer/core/input_file.h"
#include "renderer/mesh/polygon_soup.h"
#include "renderer/core/json.h"
#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/obj_parser.h"

namespace npr {
namespace fs = std::filesystem;

glm::mat4 filePlacement(const LoadReport& report) {
  const double scale = report.original_scale > 0.0 && std::isfinite(report.original_scale) ? report.original_scale : 1.0;
  return glm::mat4(glm::translate(glm::dmat4(1.0), report.original_centre) * glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / scale)));
}

std::string sceneReportJson(const LoadedScene& scene) {
  std::string head = scene.report.toJson();
  head.pop_back();  // its closing brace: the scene's keys follow
  std::string o = head + ",\"objects\":[";
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& ob = scene.objects[i];
    const glm::vec3 at(ob.transform[3]);
    o += (i ? "," : "") + std::string("{\"name\":") + json::string(ob.name) + ",\"triangles\":" + std::to_string(ob.mesh->triangleCount()) +
         ",\"vertices\":" + std::to_string(ob.mesh->positions.size()) + ",\"materials\":" + std::to_string(ob.mesh->materials.size()) +
         ",\"origin\":[" + json::number(at.x) + "," + json::number(at.y) + "," + json::number(at.z) + "]}";
  }
  o += "],\"cameras\":[";
  for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
    const SceneCamera& c = scene.cameras[i];
    o += (i ? "," : "") + std::string("{\"name\":") + json::string(c.name) + ",\"type\":\"" + (c.perspective ? "perspective" : "orthographic") +
         "\"" + (c.perspective ? ",\"yfov\":" + json::number(c.yfov) : std::string()) + "}";
  }
  o += "],\"lights\":[";
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const SceneLight& l = scene.lights[i];
    const char* type = l.type == SceneLight::Type::Point ? "point" : l.type == SceneLight::Type::Spot ? "spot" : "directional";
    o += (i ? "," : "") + std::string("{\"name\":") + json::string(l.name) + ",\"type\":\"" + type + "\",\"intensity\":" + json::number(l.intensity) + "}";
  }
  o += "],\"animations\":[";
  for (std::size_t i = 0; i < scene.animations.size(); ++i) {
    const SceneAnimation& a = scene.animations[i];
    o += (i ? "," : "") + std::string("{\"name\":") + json::string(a.name) + ",\"start\":" + json::number(a.start) + ",\"end\":" + json::number(a.end) +
         ",\"channels\":" + std::to_string(a.channels.size()) + "}";
  }
  o += "],\"skins\":" + std::to_string(scene.skins.size()) + "}";
  return o;
}

Result<LoadedScene> loadScene(const std::string& nameOrPath, const SceneLoadOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const WarningDetail detail(options.allWarnings);
  std::string ext = fs::path(nameOrPath).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".gltf" || ext == ".glb") {
    if (Result<std::uintmax_t> f = checkInputFile(nameOrPath, InputKind::Mesh); !f) return Error{f.error()};
    Result<std::string> bytes = readInputFile(nameOrPath, InputKind::Mesh);
    if (!bytes) return Error{bytes.error()};
    if (bytes->empty()) return Error{nameOrPath + ": the file is empty"};
    Result<LoadedScene> scene = parseGltfScene(nameOrPath, std::move(*bytes));
    if (scene) scene->load_ms = scene->report.load_ms = msSince(t0);
    return scene;
  }
  if (ext == ".obj" && options.splitObjects) {
    if (Result<std::uintmax_t> f = checkInputFile(nameOrPath, InputKind::Mesh); !f) return Error{f.error()};
    Result<std::string> bytes = readInputFile(nameOrPath, InputKind::Mesh);
    if (!bytes) return Error{bytes.error()};
    Result<std::vector<ObjObject>> parts = parseObjObjects(nameOrPath, std::move(*bytes));
    if (!parts) return Error{parts.error()};
    LoadedScene scene;
    scene.file = nameOrPath;
    scene.report = parts->front().mesh.report;
    scene.report.vertices = scene.report.triangles = 0;
    for (ObjObject& o : *parts) {
      finalizeMesh(o.mesh);
      scene.report.vertices += o.mesh.positions.size();
      scene.report.triangles += o.mesh.triangleCount();
      const glm::mat4 placement = filePlacement(o.mesh.report);
      scene.objects.push_back({o.name, std::make_shared<const Mesh>(std::move(o.mesh)), placement});
    }
    scene.warnings = scene.report.warnings;
    scene.load_ms = scene.report.load_ms = msSince(t0);
    return scene;
  }
  Result<Mesh> m = loadModel(nameOrPath);
  if (!m) return Error{m.error()};
  LoadedScene scene;
  scene.file = m->report.file.empty() ? nameOrPath : m->report.file;
  scene.warnings = m->report.warnings;
  scene.report = m->report;
  scene.load_ms = msSince(t0);
  const glm::mat4 placement = filePlacement(m->report);
  scene.objects.push_back({fs::path(nameOrPath).stem().string(), std::make_shared<const Mesh>(std::move(*m)), placement});
  return scene;
}

}  // namespace npr
