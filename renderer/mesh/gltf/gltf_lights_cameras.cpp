// The glTF reader: KHR_lights_punctual lights and the file's cameras, placed by the nodes that hold them.
#include "renderer/mesh/gltf/gltf_reader.h"

namespace npr::gltf {

// KHR_lights_punctual's lights (placed later by the nodes that name them); a malformed one
// is reported and left out.
Status GltfReader::readLights() {
  const auto it = m_.extensions.find("KHR_lights_punctual");
  if (it == m_.extensions.end() || !it->second.Has("lights")) return okStatus();
  const tinygltf::Value& list = it->second.Get("lights");
  if (!list.IsArray()) return fail("KHR_lights_punctual's lights is not an array");
  auto number = [](const tinygltf::Value& v, const char* key, double fallback, bool& ok) {
    if (!v.Has(key)) return fallback;
    const tinygltf::Value& n = v.Get(key);
    if (!n.IsNumber() || !std::isfinite(n.GetNumberAsDouble())) ok = false;
    return n.IsNumber() ? n.GetNumberAsDouble() : fallback;
  };
  for (std::size_t i = 0; i < list.ArrayLen(); ++i) {
    const tinygltf::Value& l = list.Get(static_cast<int>(i));
    std::optional<SceneLight> light;
    if (l.IsObject() && l.Has("type") && l.Get("type").IsString()) {
      SceneLight s;
      bool ok = true;
      const std::string type = l.Get("type").Get<std::string>();
      s.type = type == "point" ? SceneLight::Type::Point : type == "spot" ? SceneLight::Type::Spot : SceneLight::Type::Directional;
      ok = type == "point" || type == "spot" || type == "directional";
      if (l.Has("name") && l.Get("name").IsString()) s.name = l.Get("name").Get<std::string>();
      if (l.Has("color")) {
        const tinygltf::Value& c = l.Get("color");
        if (!c.IsArray() || c.ArrayLen() != 3) ok = false;
        else
          for (int k = 0; k < 3; ++k) {
            const tinygltf::Value& v = c.Get(k);
            if (v.IsNumber() && std::isfinite(v.GetNumberAsDouble())) s.colour[k] = static_cast<float>(v.GetNumberAsDouble());
            else ok = false;
          }
      }
      s.intensity = static_cast<float>(number(l, "intensity", 1.0, ok));
      s.range = static_cast<float>(number(l, "range", 0.0, ok));
      if (l.Has("spot") && l.Get("spot").IsObject()) {
        s.innerCone = static_cast<float>(number(l.Get("spot"), "innerConeAngle", 0.0, ok));
        s.outerCone = static_cast<float>(number(l.Get("spot"), "outerConeAngle", 0.7853981633974483, ok));
      }
      ok = ok && std::isfinite(s.colour.x + s.colour.y + s.colour.z) && s.intensity >= 0.0f && s.range >= 0.0f && s.innerCone >= 0.0f &&
           s.outerCone > s.innerCone && s.outerCone <= 1.5707964f;
      if (ok) light = s;
    }
    if (!light) warn_.add(name_ + ": light " + std::to_string(i) + " of KHR_lights_punctual is malformed and left out");
    lights_.push_back(light);
  }
  return okStatus();
}

// The camera of node `n` (placed at `world`), or a warning when it is malformed.
void GltfReader::addCamera(int index, const glm::dmat4& world) {
  if (index >= static_cast<int>(m_.cameras.size())) {
    warn_.add(name_ + ": a node names camera " + std::to_string(index) + ", which does not exist");
    return;
  }
  const tinygltf::Camera& c = m_.cameras[static_cast<std::size_t>(index)];
  SceneCamera s;
  s.name = c.name.empty() ? "camera " + std::to_string(index) : c.name;
  s.world = glm::mat4(world);
  bool ok = true;
  if (c.type == "perspective") {
    const tinygltf::PerspectiveCamera& p = c.perspective;
    s.yfov = static_cast<float>(p.yfov);
    s.aspect = static_cast<float>(p.aspectRatio);
    s.znear = static_cast<float>(p.znear);
    s.zfar = static_cast<float>(p.zfar);
    ok = std::isfinite(p.yfov) && p.yfov > 1e-4 && p.yfov < 3.1 && std::isfinite(p.aspectRatio) && p.aspectRatio >= 0.0 &&
         std::isfinite(p.znear) && p.znear > 0.0 && std::isfinite(p.zfar) && (p.zfar == 0.0 || p.zfar > p.znear);
  } else if (c.type == "orthographic") {
    const tinygltf::OrthographicCamera& o = c.orthographic;
    s.perspective = false;
    s.xmag = static_cast<float>(o.xmag);
    s.ymag = static_cast<float>(o.ymag);
    s.znear = static_cast<float>(o.znear);
    s.zfar = static_cast<float>(o.zfar);
    ok = std::isfinite(o.xmag) && std::isfinite(o.ymag) && o.xmag != 0.0 && o.ymag != 0.0 && std::isfinite(o.znear) && o.znear >= 0.0 &&
         std::isfinite(o.zfar) && o.zfar > o.znear;
  } else {
    ok = false;
  }
  const glm::mat4 w = s.world;
  for (int k = 0; k < 4 && ok; ++k) ok = std::isfinite(w[k].x + w[k].y + w[k].z + w[k].w);
  if (!ok) {
    warn_.add(name_ + ": camera " + std::to_string(index) + " is malformed and left out");
    return;
  }
  cameras_.push_back(s);
}

void GltfReader::placeLight(const tinygltf::Node& n, const glm::dmat4& world) {
  const auto it = n.extensions.find("KHR_lights_punctual");
  if (it == n.extensions.end() || !it->second.Has("light") || !it->second.Get("light").IsInt()) return;
  const int index = it->second.Get("light").Get<int>();
  if (index < 0 || index >= static_cast<int>(lights_.size())) {
    warn_.add(name_ + ": a node names light " + std::to_string(index) + ", which does not exist");
    return;
  }
  if (!lights_[static_cast<std::size_t>(index)]) return;  // reported as malformed already
  SceneLight l = *lights_[static_cast<std::size_t>(index)];
  l.world = glm::mat4(world);
  if (l.name.empty()) l.name = "light " + std::to_string(index);
  placedLights_.push_back(l);
}

}  // namespace npr::gltf
