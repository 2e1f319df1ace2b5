// The glTF reader: glTF materials onto the OpenGL lighting model (gltf_container.cpp has the mapping), their
// base colour maps decoded by OpenImageIO, with KHR_texture_transform.
#include "renderer/mesh/gltf/gltf_reader.h"

namespace npr::gltf {

// The file's materials, mapped onto GL's (the formula atop this file), and the images their
// base colour maps use, decoded once; each mesh copies the ones it uses (localMaterial).
Status GltfReader::readMaterials() {
  for (std::size_t i = 0; i < m_.materials.size(); ++i) {
    const tinygltf::Material& g = m_.materials[i];
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
    MeshMaterial mat;
    mat.name = g.name.empty() ? "material " + std::to_string(i) : g.name;
    if (pbr.baseColorFactor.size() != 4 || !finite(pbr.baseColorFactor) || g.emissiveFactor.size() != 3 || !finite(g.emissiveFactor) ||
        !std::isfinite(pbr.metallicFactor) || !std::isfinite(pbr.roughnessFactor))
      return fail("material " + std::to_string(i) + " has a non-finite or malformed factor");
    const glm::vec3 base = glm::clamp(glm::vec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]), 0.0f, 1.0f);
    const float metallic = std::clamp(static_cast<float>(pbr.metallicFactor), 0.0f, 1.0f);
    const float roughness = std::clamp(static_cast<float>(pbr.roughnessFactor), 0.0f, 1.0f);
    mat.diffuse = base * (1.0f - 0.75f * metallic);
    mat.ambient = mat.diffuse;
    mat.specular = glm::mix(glm::vec3(0.04f), base, metallic) * (1.0f - roughness);
    const float a = std::max(roughness * roughness, 1e-3f);
    mat.shininess = std::clamp(2.0f / (a * a) - 2.0f, 0.0f, 128.0f);
    if (mat.shininess < 1.0f) mat.specular = glm::vec3(0.0f);  // GL would light the whole side
    mat.emission = glm::clamp(glm::vec3(g.emissiveFactor[0], g.emissiveFactor[1], g.emissiveFactor[2]), 0.0f, 1.0f);
    mat.opacity = std::clamp(static_cast<float>(pbr.baseColorFactor[3]), 0.0f, 1.0f);
    if (g.extensions.count("KHR_materials_unlit")) mat.illum = 0;
    if (pbr.baseColorTexture.index >= 0) {
      if (pbr.baseColorTexture.texCoord != 0)
        warn_.add(name_ + ": material " + std::to_string(i) + "'s base colour uses texture coordinates " +
                  std::to_string(pbr.baseColorTexture.texCoord) + "; only set 0 is read");
      mat.diffuseMap = texture(pbr.baseColorTexture.index);
      transforms_.push_back(textureTransform(pbr.baseColorTexture.extensions));
    } else {
      transforms_.push_back(glm::mat3(1.0f));
    }
    if (g.alphaMode == "MASK") {
      if (!std::isfinite(g.alphaCutoff)) return fail("material " + std::to_string(i) + " has a non-finite alphaCutoff");
      mat.alpha = MeshMaterial::Alpha::Mask;
      mat.alphaCutoff = std::clamp(static_cast<float>(g.alphaCutoff), 0.0f, 1.0f);
    } else if (g.alphaMode == "BLEND") {
      mat.alpha = MeshMaterial::Alpha::Blend;
    } else if (g.alphaMode != "OPAQUE") {
      warn_.add(name_ + ": material '" + printable(mat.name) + "' has an unknown alphaMode '" + printable(g.alphaMode) + "'; drawn opaque");
    }
    materials_.push_back(std::move(mat));
  }
  // The default material for primitives that name none, last.
  MeshMaterial fallback;
  fallback.name = "(default)";
  fallback.fromLightingState = true;
  materials_.push_back(fallback);
  transforms_.push_back(glm::mat3(1.0f));
  report_.materials = m_.materials.size();
  return okStatus();
}

// The mesh's index of the file's material `g` (the default: the last), copied in with its
// image the first time the mesh uses it.
int GltfReader::localMaterial(Target& t, int g) {
  if (const auto it = t.material.find(g); it != t.material.end()) return it->second;
  MeshMaterial mat = materials_[static_cast<std::size_t>(g)];
  if (mat.diffuseMap >= 0) {
    const int file = mat.diffuseMap;
    auto [it, added] = t.image.emplace(file, static_cast<int>(t.soup.textures.size()));
    if (added) {
      t.soup.textures.push_back(images_[static_cast<std::size_t>(file)]);
      t.report.textures_loaded.push_back(images_[static_cast<std::size_t>(file)].path);
    }
    mat.diffuseMap = it->second;
  }
  const int local = static_cast<int>(t.soup.materials.size());
  t.soup.materials.push_back(std::move(mat));
  ++t.report.materials;
  t.material.emplace(g, local);
  // Before the first triangle: a mesh of one material keeps it too.
  if (!t.soup.tracksMaterials) t.soup.trackMaterials();
  return local;
}

// KHR_texture_transform as a 3x3 matrix on (u, v, 1): translation * rotation * scale.
glm::mat3 GltfReader::textureTransform(const tinygltf::ExtensionMap& ext) {
  const auto it = ext.find("KHR_texture_transform");
  if (it == ext.end() || !it->second.IsObject()) return glm::mat3(1.0f);
  const tinygltf::Value& t = it->second;
  auto number = [](const tinygltf::Value& v, double fallback) { return v.IsNumber() && std::isfinite(v.GetNumberAsDouble()) ? v.GetNumberAsDouble() : fallback; };
  auto pair = [&](const char* key, double fallback) {
    glm::dvec2 out(fallback);
    if (t.Has(key) && t.Get(key).IsArray() && t.Get(key).ArrayLen() == 2)
      out = {number(t.Get(key).Get(0), fallback), number(t.Get(key).Get(1), fallback)};
    return out;
  };
  const glm::dvec2 offset = pair("offset", 0.0), scale = pair("scale", 1.0);
  const double r = t.Has("rotation") ? number(t.Get("rotation"), 0.0) : 0.0;
  const glm::mat3 T(1, 0, 0, 0, 1, 0, float(offset.x), float(offset.y), 1);
  const glm::mat3 R(float(std::cos(r)), float(-std::sin(r)), 0, float(std::sin(r)), float(std::cos(r)), 0, 0, 0, 1);
  const glm::mat3 S(float(scale.x), 0, 0, 0, float(scale.y), 0, 0, 0, 1);
  return T * R * S;
}

// The decoded image of texture `index` in images_, or -1 (reported missing).
int GltfReader::texture(int index) {
  if (index < 0 || index >= static_cast<int>(m_.textures.size())) {
    warn_.add(name_ + ": texture " + std::to_string(index) + " does not exist");
    return -1;
  }
  const int source = m_.textures[static_cast<std::size_t>(index)].source;
  if (const auto it = decoded_.find(source); it != decoded_.end()) return it->second;
  int& slot = decoded_[source];
  slot = -1;
  if (source < 0 || source >= static_cast<int>(m_.images.size())) {
    warn_.add(name_ + ": texture " + std::to_string(index) + " names image " + std::to_string(source) + ", which does not exist");
    return -1;
  }
  const tinygltf::Image& img = m_.images[static_cast<std::size_t>(source)];
  const std::string label = img.uri.empty() || img.uri.rfind("data:", 0) == 0 ? "image " + std::to_string(source) : img.uri;
  if (images_.size() >= kMaxModelTextures) {
    warn_.add(name_ + ": more than " + std::to_string(kMaxModelTextures) + " images; '" + printable(label) + "' is not used");
    return -1;
  }
  if (img.image.empty()) {
    report_.textures_missing.push_back(label);
    warn_.add(name_ + ": image '" + printable(label) + "' could not be read");
    return -1;
  }
  // OpenImageIO reads files: the bytes go to a private temporary file with the extension
  // their type implies, then through the same image path as every palette and texture.
  const std::string ext = img.mimeType == "image/jpeg" || label.find(".jp") != std::string::npos ? ".jpg" : ".png";
  const std::string temp = (fs::temp_directory_path() / ("npr-gltf-" + std::to_string(::getpid()) + "-" + std::to_string(source) + ext)).string();
  Result<ImageRGBA8> decoded = Error{"cannot write a temporary file"};
  if (std::FILE* f = std::fopen(temp.c_str(), "wb")) {
    const bool written = std::fwrite(img.image.data(), 1, img.image.size(), f) == img.image.size();
    std::fclose(f);
    if (written) decoded = loadImage(temp, {kMaxModelTextureSide, kMaxModelTextureSide});
    std::remove(temp.c_str());
  }
  if (!decoded) {
    report_.textures_missing.push_back(label);
    warn_.add(name_ + ": image '" + printable(label) + "' cannot be decoded; its material is drawn without it");
    return -1;
  }
  slot = static_cast<int>(images_.size());
  images_.push_back({label, std::move(*decoded)});
  report_.textures_loaded.push_back(label);
  return slot;
}

}  // namespace npr::gltf
