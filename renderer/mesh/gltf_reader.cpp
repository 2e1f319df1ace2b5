// The glTF 2.0 reader (.gltf with external or embedded buffers, .glb): see mesh_formats.h.
// tinygltf (Debian's libtinygltf) parses the JSON and the GLB container; everything it hands
// back is checked here before use (its validation is not trusted): every accessor and buffer
// view against its buffer, every index against its vertex count, every node against cycles,
// every number for finiteness. Files it asks for (buffers, images) pass the same input gate as
// any model, through our file callbacks (never its path expansion), and images are decoded by
// OpenImageIO (image_io.h), never by the loader's own decoder.
//
// The file's default scene is read either flattened into one mesh (parseGltf: each node's
// meshes with the node's world transform applied) or as objects (parseGltfScene: one per node
// with a mesh, each glTF mesh built once in its own space, with the scene's cameras and
// KHR_lights_punctual lights). Materials are mapped onto the OpenGL lighting model:
//   ambient = diffuse = baseColorFactor.rgb * (1 - 0.75 metallic)   (a metal keeps some tone)
//   specular = mix(0.04, baseColorFactor.rgb, metallic) * (1 - roughness)
//   shininess = 2 / a^2 - 2 with a = roughness^2, clamped to GL's 0..128 (Phong's exponent
//               for the same highlight width as a Beckmann lobe of that roughness)
//   emission = emissiveFactor; baseColorTexture is the diffuse map (with KHR_texture_transform
//   applied to the coordinates); KHR_materials_unlit emits the base colour (illum 0);
//   alphaMode MASK and BLEND with alphaCutoff and the base colour's alpha (MeshMaterial::alpha:
//   cut-outs, and screen-door transparency for blending); every surface is drawn two-sided.
#include <tiny_gltf.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "renderer/core/image_io.h"
#include "renderer/core/input_file.h"
#include "renderer/core/json.h"
#include "renderer/core/printable.h"
#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/polygon_soup.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

// Bounds on what one file may make, whatever its counts say: instancing one mesh from many
// nodes multiplies it, so the flattened scene is bounded, not only each accessor.
constexpr std::uint64_t kMaxSceneTriangles = 50'000'000;
constexpr int kMaxNodeDepth = 256;
// Keyframe values over every channel (each copies its sampler's, and samplers may be shared).
constexpr std::uint64_t kMaxAnimationKeys = 4'000'000;
constexpr std::size_t kMaxMorphTargets = 64;
constexpr std::size_t kMaxJoints = 4096;

// tinygltf's file callbacks: files go through our input gate; paths are joined, never
// expanded by a shell (tinygltf's own expansion used wordexp, CVE-2022-3008).
bool fileExists(const std::string& path, void*) { return static_cast<bool>(checkInputFile(path, InputKind::Mesh)); }
std::string expandFilePath(const std::string& path, void*) { return path; }
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  Result<std::string> bytes = readInputFile(path, InputKind::Mesh);
  if (!bytes) {
    if (err) *err += bytes.error() + "\n";
    return false;
  }
  out->assign(bytes->begin(), bytes->end());
  return true;
}
bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not allowed\n";
  return false;
}
// Images are kept as the file's bytes and decoded later by OpenImageIO. For an image in a
// buffer view tinygltf hands over &buffer[byteOffset] with byteLength unchecked (found by
// fuzz_gltf: a heap overflow), so the view is checked here and the bytes copied from the
// model's buffer (`user`: the model being loaded; its buffers and views are read by then).
bool keepImageBytes(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int, const unsigned char* bytes,
                    int size, void* user) {
  const auto* model = static_cast<const tinygltf::Model*>(user);
  image->width = image->height = -1;
  if (image->bufferView >= 0) {
    const auto refuse = [&](const std::string& why) {
      if (err) *err += "image " + std::to_string(index) + ": " + why + "\n";
      return false;
    };
    if (!model || image->bufferView >= static_cast<int>(model->bufferViews.size())) return refuse("its buffer view does not exist");
    const tinygltf::BufferView& bv = model->bufferViews[static_cast<std::size_t>(image->bufferView)];
    if (bv.buffer < 0 || bv.buffer >= static_cast<int>(model->buffers.size())) return refuse("its buffer does not exist");
    const std::vector<unsigned char>& data = model->buffers[static_cast<std::size_t>(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset) return refuse("its buffer view runs past its buffer");
    image->image.assign(data.begin() + static_cast<std::ptrdiff_t>(bv.byteOffset),
                        data.begin() + static_cast<std::ptrdiff_t>(bv.byteOffset + bv.byteLength));
    return true;
  }
  if (size < 0 || !bytes) return false;
  image->image.assign(bytes, bytes + size);
  return true;
}

bool finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// A checked view of an accessor's elements: every element lies inside its buffer view and
// buffer, whatever the offsets, stride and count claim.
struct AccessorView {
  const unsigned char* data = nullptr;
  std::size_t stride = 0, count = 0;
  int componentType = 0, components = 0;
  bool normalized = false;

  double component(std::size_t i, int c) const {
    const unsigned char* p = data + i * stride;
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p + 4 * c, 4);
        return f;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[c] / 255.0 : p[c];
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = static_cast<signed char>(p[c]);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
    }
    return 0.0;
  }
  std::uint64_t index(std::size_t i) const { return static_cast<std::uint64_t>(component(i, 0)); }
};

int componentBytes(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
  }
  return 0;
}

int typeComponents(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;
  }
  return 0;
}

class GltfReader {
 public:
  // Flatten: the whole scene in one mesh, every node's transform applied to its vertices.
  // Objects: one mesh per glTF mesh in its own space (a mirrored copy where a node mirrors it),
  // and one object per node that has a mesh.
  enum class Mode { Flatten, Objects };

  GltfReader(const std::string& name, const tinygltf::Model& model, LoadReport& report, Mode mode)
      : name_(name), m_(model), report_(report), warn_(report.warnings), mode_(mode) {}

  // A mesh being built: its soup, its report, and which of the file's materials and images it
  // has taken so far (each mesh carries only those its primitives use).
  struct Target {
    PolygonSoup soup;
    LoadReport report;
    std::map<int, int> material, image;
    std::unique_ptr<FaceBuilder> faces;
    int mesh = -1, skin = -1;      // the file's mesh and the skin it is built for (-1: none)
    std::string deformProblem;     // the first bad skin or morph datum: drawn at rest, named
  };
  struct Object {
    std::string name;
    std::size_t target = 0;
    glm::dmat4 world{1.0};
    int node = -1;             // into nodes()
    glm::dmat4 mirror{1.0};    // after the node's world transform
    int skin = -1;             // the file's skin
  };

  Status read() {
    for (const std::string& ext : m_.extensionsRequired)
      if (ext != "KHR_texture_transform" && ext != "KHR_materials_unlit" && ext != "KHR_lights_punctual")
        return fail("requires the extension " + printable(ext) + ", which this viewer does not read");
    if (Status s = readMaterials(); !s) return s;
    if (Status s = readLights(); !s) return s;
    if (mode_ == Mode::Flatten) newTarget();
    std::vector<int> roots;
    if (!m_.scenes.empty()) {
      const int scene = m_.defaultScene >= 0 ? m_.defaultScene : 0;
      if (scene >= static_cast<int>(m_.scenes.size())) return fail("the default scene " + std::to_string(scene) + " does not exist");
      roots = m_.scenes[static_cast<std::size_t>(scene)].nodes;
    } else {
      // No scene: every node that is no other node's child.
      std::vector<char> child(m_.nodes.size(), 0);
      for (const tinygltf::Node& n : m_.nodes)
        for (int c : n.children)
          if (c >= 0 && c < static_cast<int>(m_.nodes.size())) child[static_cast<std::size_t>(c)] = 1;
      for (std::size_t i = 0; i < m_.nodes.size(); ++i)
        if (!child[i]) roots.push_back(static_cast<int>(i));
    }
    std::vector<char> visited(m_.nodes.size(), 0);
    for (int root : roots)
      if (Status s = visit(root, glm::dmat4(1.0), -1, 0, visited); !s) return s;
    if (skippedPrimitives_ > 0)
      warn_.add(name_ + ": " + std::to_string(skippedPrimitives_) + " primitive(s) of points or lines not drawn (only triangles are)");
    if (mode_ == Mode::Flatten && (!m_.cameras.empty() || !lights_.empty()))
      warn_.add(name_ + ": " + std::to_string(m_.cameras.size()) + " camera(s) and " + std::to_string(lights_.size()) +
                " light(s) are not used when the file is read as one mesh");
    if (mode_ == Mode::Flatten && !m_.animations.empty())
      warn_.add(name_ + ": " + std::to_string(m_.animations.size()) + " animation(s) are not played when the file is read as one mesh");
    if (mode_ == Mode::Objects) {
      readSkins();
      readAnimations();
    } else if (!m_.skins.empty()) {
      warn_.add(name_ + ": " + std::to_string(m_.skins.size()) + " skin(s) are not applied when the file is read as one mesh");
    }
    for (Target& t : targets_) {
      t.report.texture_coordinates = t.soup.tracksTexcoords;
      t.report.vertex_colours = !t.soup.colours.empty();
      report_.texture_coordinates = report_.texture_coordinates || t.report.texture_coordinates;
      report_.vertex_colours = report_.vertex_colours || t.report.vertex_colours;
    }
    warn_.finish();
    return okStatus();
  }

  std::deque<Target>& targets() { return targets_; }
  const std::vector<Object>& objects() const { return objects_; }
  std::vector<SceneCamera>& cameras() { return cameras_; }
  std::vector<SceneLight> placedLights() const { return placedLights_; }
  std::vector<SceneNode>& nodes() { return nodes_; }
  std::vector<SceneAnimation>& animations() { return animations_; }
  std::vector<SceneSkin>& skins() { return skins_; }
  // The file's skin -> skins(), for the skins that were read (the others refused, named).
  const std::map<int, int>& skinOf() const { return skinOf_; }

 private:
  Error fail(const std::string& what) const { return Error{name_ + ": " + what}; }

  Target& newTarget(int mesh = -1, int skin = -1) {
    Target& t = targets_.emplace_back();
    t.mesh = mesh;
    t.skin = skin;
    if (mode_ == Mode::Objects && mesh >= 0) {
      const tinygltf::Mesh& g = m_.meshes[static_cast<std::size_t>(mesh)];
      t.soup.skinned = skin >= 0;
      t.soup.morphTargets = g.primitives.empty() ? 0 : std::min<std::size_t>(g.primitives.front().targets.size(), kMaxMorphTargets);
    }
    t.report.file = name_;
    t.faces = std::make_unique<FaceBuilder>(t.soup, t.report, warn_);
    return t;
  }

  Result<AccessorView> accessor(int index, const std::string& what, std::initializer_list<int> types) const {
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    if (index < 0 || index >= static_cast<int>(m_.accessors.size())) return fail(where + " does not exist");
    const tinygltf::Accessor& a = m_.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) return fail(where + " is sparse, which this viewer does not read");
    if (std::find(types.begin(), types.end(), a.type) == types.end()) return fail(where + " has the wrong type");
    AccessorView v;
    v.componentType = a.componentType;
    v.components = typeComponents(a.type);
    v.normalized = a.normalized;
    const int cb = componentBytes(a.componentType);
    if (cb == 0 || v.components == 0) return fail(where + " has an unknown component type");
    v.count = a.count;
    if (v.count == 0) return v;
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(m_.bufferViews.size()))
      return fail(where + " names no buffer view (buffer view " + std::to_string(a.bufferView) + ")");
    const tinygltf::BufferView& bv = m_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (bv.buffer < 0 || bv.buffer >= static_cast<int>(m_.buffers.size()))
      return fail(where + ": its buffer view names buffer " + std::to_string(bv.buffer) + ", which does not exist");
    const std::vector<unsigned char>& buffer = m_.buffers[static_cast<std::size_t>(bv.buffer)].data;
    const std::uint64_t element = std::uint64_t(cb) * std::uint64_t(v.components);
    const std::uint64_t stride = bv.byteStride ? bv.byteStride : element;
    if (stride < element || stride > 252) return fail(where + ": byte stride " + std::to_string(bv.byteStride) + " is invalid");
    // All in 64 bits, and the count bounded by the view before multiplying.
    const std::uint64_t viewEnd = std::uint64_t(bv.byteOffset) + std::uint64_t(bv.byteLength);
    if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() || viewEnd > buffer.size())
      return fail(where + ": its buffer view (bytes " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
                  ") runs past its buffer of " + std::to_string(buffer.size()) + " bytes");
    if (a.byteOffset > bv.byteLength || std::uint64_t(a.count) > bv.byteLength / stride + 1 ||
        std::uint64_t(a.byteOffset) + (std::uint64_t(a.count) - 1) * stride + element > bv.byteLength)
      return fail(where + ": " + std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                  " run past its buffer view of " + std::to_string(bv.byteLength) + " bytes");
    v.data = buffer.data() + bv.byteOffset + a.byteOffset;
    v.stride = static_cast<std::size_t>(stride);
    return v;
  }

  // The file's materials, mapped onto GL's (the formula atop this file), and the images their
  // base colour maps use, decoded once; each mesh copies the ones it uses (localMaterial).
  Status readMaterials() {
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
  int localMaterial(Target& t, int g) {
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
  glm::mat3 textureTransform(const tinygltf::ExtensionMap& ext) {
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
  int texture(int index) {
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

  // KHR_lights_punctual's lights (placed later by the nodes that name them); a malformed one
  // is reported and left out.
  Status readLights() {
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
  void addCamera(int index, const glm::dmat4& world) {
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

  void placeLight(const tinygltf::Node& n, const glm::dmat4& world) {
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

  Result<glm::dmat4> localTransform(const tinygltf::Node& n, int index) const {
    if (!n.matrix.empty()) {
      if (n.matrix.size() != 16 || !finite(n.matrix)) return fail("node " + std::to_string(index) + " has a malformed or non-finite matrix");
      return glm::make_mat4(n.matrix.data());
    }
    glm::dmat4 t(1.0);
    if (!n.translation.empty()) {
      if (n.translation.size() != 3 || !finite(n.translation)) return fail("node " + std::to_string(index) + " has a malformed translation");
      t = glm::translate(t, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (!n.rotation.empty()) {
      if (n.rotation.size() != 4 || !finite(n.rotation)) return fail("node " + std::to_string(index) + " has a malformed rotation");
      glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
      const double len = glm::length(q);
      if (!(len > 1e-12)) return fail("node " + std::to_string(index) + " has a zero rotation quaternion");
      t = t * glm::mat4_cast(q / len);
    }
    if (!n.scale.empty()) {
      if (n.scale.size() != 3 || !finite(n.scale)) return fail("node " + std::to_string(index) + " has a malformed scale");
      t = glm::scale(t, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    }
    return t;
  }

  Status visit(int index, const glm::dmat4& parent, int parentNode, int depth, std::vector<char>& visited) {
    if (index < 0 || index >= static_cast<int>(m_.nodes.size())) return fail("node " + std::to_string(index) + " does not exist");
    if (visited[static_cast<std::size_t>(index)]) {
      // Not the whole file: the node is drawn where it was first reached, the rest loads.
      warn_.add(name_ + ": node " + std::to_string(index) + " is reached twice (a cycle, or a node with two parents); its second place is left out");
      return okStatus();
    }
    if (depth > kMaxNodeDepth) return fail("the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth));
    visited[static_cast<std::size_t>(index)] = 1;
    const tinygltf::Node& n = m_.nodes[static_cast<std::size_t>(index)];
    Result<glm::dmat4> local = localTransform(n, index);
    if (!local) return Error{local.error()};
    const glm::dmat4 world = parent * *local;
    // The node as animation sees it (its fields checked by localTransform).
    const int node = static_cast<int>(nodes_.size());
    if (mode_ == Mode::Objects) {
      SceneNode& out = nodes_.emplace_back();
      out.name = printable(n.name);
      out.parent = parentNode;
      if (!n.matrix.empty()) out.matrix = glm::mat4(glm::make_mat4(n.matrix.data()));
      if (n.translation.size() == 3) out.translation = glm::vec3(n.translation[0], n.translation[1], n.translation[2]);
      if (n.rotation.size() == 4) out.rotation = glm::normalize(glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])));
      if (n.scale.size() == 3) out.scale = glm::vec3(n.scale[0], n.scale[1], n.scale[2]);
      // Morph weights at rest: the node's, else its mesh's, else zero, one per target.
      if (n.mesh >= 0 && n.mesh < static_cast<int>(m_.meshes.size())) {
        const tinygltf::Mesh& g = m_.meshes[static_cast<std::size_t>(n.mesh)];
        const std::size_t targets = g.primitives.empty() ? 0 : std::min<std::size_t>(g.primitives.front().targets.size(), kMaxMorphTargets);
        const std::vector<double>& given = n.weights.size() == targets ? n.weights : g.weights;
        out.weights.assign(targets, 0.0f);
        if (given.size() == targets)
          for (std::size_t k = 0; k < targets; ++k) out.weights[k] = std::isfinite(given[k]) ? static_cast<float>(given[k]) : 0.0f;
      }
      nodeOf_[index] = node;
    }
    if (n.mesh >= 0) {
      if (n.mesh >= static_cast<int>(m_.meshes.size())) return fail("node " + std::to_string(index) + " names mesh " + std::to_string(n.mesh) + ", which does not exist");
      if (Status s = mesh(n, index, node, world); !s) return s;
    }
    if (n.camera >= 0) addCamera(n.camera, world);
    placeLight(n, world);
    for (int c : n.children)
      if (Status s = visit(c, world, node, depth + 1, visited); !s) return s;
    return okStatus();
  }

  // Node `index`'s mesh: its primitives into the one mesh at its world transform (Flatten), or
  // an object instancing the glTF mesh, built the first time a node uses it (Objects).
  Status mesh(const tinygltf::Node& n, int index, int node, const glm::dmat4& world) {
    const tinygltf::Mesh& mesh = m_.meshes[static_cast<std::size_t>(n.mesh)];
    auto build = [&](Target& t, const glm::dmat4& placement) -> Status {
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
        if (Status s = primitive(mesh.primitives[p], placement, "mesh " + std::to_string(n.mesh) + " primitive " + std::to_string(p), t); !s)
          return s;
      return okStatus();
    };
    if (mode_ == Mode::Flatten) return build(targets_.front(), world);
    // A skinned node is placed by its joints alone (glTF ignores its own transform).
    const int skin = n.skin >= 0 && n.skin < static_cast<int>(m_.skins.size()) && skinUsable(n.skin) ? n.skin : -1;
    const glm::dmat4 placement = skin >= 0 ? glm::dmat4(1.0) : world;
    // A mirroring node gets a mirrored copy of the mesh (its winding reversed), so every
    // object's transform keeps the orientation the renderer's culling assumes.
    const bool mirrored = glm::determinant(glm::dmat3(placement)) < 0.0;
    const glm::dmat4 mirror = mirrored ? glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0)) : glm::dmat4(1.0);
    const auto key = std::make_tuple(n.mesh, mirrored, skin);
    auto built = built_.find(key);
    if (built == built_.end()) {
      const std::uint64_t before = sceneTriangles_;
      built = built_.emplace(key, std::make_pair(targets_.size(), std::uint64_t(0))).first;
      if (Status s = build(newTarget(n.mesh, skin), mirror); !s) return s;
      built->second.second = sceneTriangles_ - before;
    } else {
      // Drawn once more: the bound is on what the scene draws.
      sceneTriangles_ += built->second.second;
      if (sceneTriangles_ > kMaxSceneTriangles)
        return fail("the scene makes more than " + std::to_string(kMaxSceneTriangles) + " triangles (its meshes instanced by its nodes)");
    }
    std::string name = n.name.empty() ? (mesh.name.empty() ? "node " + std::to_string(index) : mesh.name) : n.name;
    objects_.push_back({printable(name), built->second.first, placement * mirror, node, mirror, skin});
    return okStatus();
  }

  // The file's animations: each checked whole, and one that breaks a rule refused with a
  // warning naming it and the rule (the scene stays, static where it would have moved).
  void readAnimations() {
    for (std::size_t i = 0; i < m_.animations.size(); ++i) {
      const tinygltf::Animation& a = m_.animations[i];
      const std::string label = "animation " + std::to_string(i) + (a.name.empty() ? std::string() : " '" + printable(a.name) + "'");
      Result<SceneAnimation> read = readAnimation(a);
      if (!read) {
        warn_.add(name_ + ": " + label + " is not played: " + read.error());
        continue;
      }
      read->name = a.name.empty() ? "animation " + std::to_string(i + 1) : printable(a.name);
      animations_.push_back(std::move(*read));
    }
  }

  // Whether skin `k` can be read at all (its joints exist); readSkins checks the rest.
  bool skinUsable(int k) const {
    const tinygltf::Skin& skin = m_.skins[static_cast<std::size_t>(k)];
    if (skin.joints.empty() || skin.joints.size() > kMaxJoints) return false;
    return std::all_of(skin.joints.begin(), skin.joints.end(), [&](int j) { return j >= 0 && j < static_cast<int>(m_.nodes.size()); });
  }

  // The skins the scene's objects use, each checked whole; a refused one is named and its
  // objects drawn in their bind pose.
  void readSkins() {
    std::set<int> used;
    for (const Object& o : objects_)
      if (o.skin >= 0) used.insert(o.skin);
    for (std::size_t k = 0; k < m_.skins.size(); ++k) {
      const tinygltf::Skin& g = m_.skins[k];
      const std::string label = "skin " + std::to_string(k) + (g.name.empty() ? std::string() : " '" + printable(g.name) + "'");
      if (!skinUsable(static_cast<int>(k))) {
        warn_.add(name_ + ": " + label + " is not applied: " +
                  (g.joints.empty() ? std::string("it has no joints")
                   : g.joints.size() > kMaxJoints ? "it has more than " + std::to_string(kMaxJoints) + " joints"
                                                  : std::string("a joint names a node that does not exist")));
        continue;
      }
      if (!used.count(static_cast<int>(k))) continue;
      Result<SceneSkin> read = readSkin(g);
      if (!read) {
        warn_.add(name_ + ": " + label + " is not applied: " + read.error() + "; its meshes are drawn in their bind pose");
        continue;
      }
      read->name = g.name.empty() ? "skin " + std::to_string(k + 1) : printable(g.name);
      skinOf_[static_cast<int>(k)] = static_cast<int>(skins_.size());
      skins_.push_back(std::move(*read));
    }
  }

  Result<SceneSkin> readSkin(const tinygltf::Skin& g) {
    SceneSkin out;
    for (int j : g.joints) {
      const auto node = nodeOf_.find(j);
      if (node == nodeOf_.end()) return Error{"its joint node " + std::to_string(j) + " is not in the scene"};
      out.joints.push_back(node->second);
    }
    // glTF: without inverse bind matrices every joint's is the identity.
    out.inverseBind.assign(g.joints.size(), glm::mat4(1.0f));
    if (g.inverseBindMatrices >= 0) {
      Result<AccessorView> ibm = accessor(g.inverseBindMatrices, "inverse bind matrices", {TINYGLTF_TYPE_MAT4});
      if (!ibm) return Error{ibm.error().rfind(name_ + ": ", 0) == 0 ? ibm.error().substr(name_.size() + 2) : ibm.error()};
      if (ibm->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) return Error{"its inverse bind matrices are not floats"};
      if (ibm->count < g.joints.size())
        return Error{"it has " + std::to_string(g.joints.size()) + " joints but " + std::to_string(ibm->count) + " inverse bind matrices"};
      for (std::size_t j = 0; j < g.joints.size(); ++j)
        for (int c = 0; c < 16; ++c) {
          const double v = ibm->component(j, c);
          if (!std::isfinite(v)) return Error{"inverse bind matrix " + std::to_string(j) + " is not finite"};
          out.inverseBind[j][c / 4][c % 4] = static_cast<float>(v);
        }
    }
    return out;
  }

  Result<SceneAnimation> readAnimation(const tinygltf::Animation& a) {
    SceneAnimation out;
    if (a.channels.empty()) return Error{"it has no channels"};
    bool first = true;
    for (std::size_t c = 0; c < a.channels.size(); ++c) {
      const tinygltf::AnimationChannel& ch = a.channels[c];
      const std::string where = "channel " + std::to_string(c);
      AnimationChannel channel;
      if (ch.target_path == "weights") channel.property = AnimatedProperty::Weights;
      else if (ch.target_path == "translation") channel.property = AnimatedProperty::Translation;
      else if (ch.target_path == "rotation") channel.property = AnimatedProperty::Rotation;
      else if (ch.target_path == "scale") channel.property = AnimatedProperty::Scale;
      else return Error{where + " animates '" + printable(ch.target_path, 40) + "' (translation, rotation, scale or weights are glTF's)"};
      if (ch.target_node < 0 || ch.target_node >= static_cast<int>(m_.nodes.size()))
        return Error{where + " names node " + std::to_string(ch.target_node) + ", which does not exist"};
      const auto node = nodeOf_.find(ch.target_node);
      if (node == nodeOf_.end()) continue;  // a node outside the default scene: nothing drawn moves
      if (nodes_[static_cast<std::size_t>(node->second)].matrix)
        return Error{where + " animates node " + std::to_string(ch.target_node) + ", which is given by a matrix (glTF allows animating only TRS nodes)"};
      channel.node = node->second;
      const bool weights = channel.property == AnimatedProperty::Weights;
      const std::size_t targets = nodes_[static_cast<std::size_t>(node->second)].weights.size();
      if (weights && targets == 0) return Error{where + " animates the morph weights of node " + std::to_string(ch.target_node) + ", whose mesh has no morph targets"};
      channel.width = weights ? static_cast<int>(targets) : channel.property == AnimatedProperty::Rotation ? 4 : 3;
      if (ch.sampler < 0 || ch.sampler >= static_cast<int>(a.samplers.size()))
        return Error{where + " names sampler " + std::to_string(ch.sampler) + ", which does not exist"};
      const tinygltf::AnimationSampler& sampler = a.samplers[static_cast<std::size_t>(ch.sampler)];
      if (sampler.interpolation == "STEP") channel.interpolation = Interpolation::Step;
      else if (sampler.interpolation == "CUBICSPLINE") channel.interpolation = Interpolation::CubicSpline;
      else if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty()) channel.interpolation = Interpolation::Linear;
      else return Error{where + ": interpolation '" + printable(sampler.interpolation, 40) + "' is not STEP, LINEAR or CUBICSPLINE"};
      // The accessor's message without the file's name, which the warning gives once.
      const auto unnamed = [&](const std::string& e) { return Error{e.rfind(name_ + ": ", 0) == 0 ? e.substr(name_.size() + 2) : e}; };
      Result<AccessorView> input = accessor(sampler.input, where + "'s keyframe times", {TINYGLTF_TYPE_SCALAR});
      if (!input) return unnamed(input.error());
      if (input->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) return Error{where + "'s keyframe times are not floats"};
      if (input->count == 0) return Error{where + " has no keyframes"};
      const bool rotation = channel.property == AnimatedProperty::Rotation;
      Result<AccessorView> output = accessor(sampler.output, where + "'s values",
                                             {weights ? TINYGLTF_TYPE_SCALAR : rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3});
      if (!output) return unnamed(output.error());
      // Weights: one scalar per morph target per value.
      const std::size_t perKey = (channel.interpolation == Interpolation::CubicSpline ? 3 : 1) * (weights ? targets : 1);
      if (output->count != input->count * perKey)
        return Error{where + " has " + std::to_string(input->count) + " keyframe times but " + std::to_string(output->count) + " values (" +
                     (channel.interpolation == Interpolation::CubicSpline ? "a cubic spline needs three per time" : "one per time") +
                     (weights ? ", times " + std::to_string(targets) + " morph targets" : std::string()) + ")"};
      // Channels copy their sampler's keys: bounded over the file, however often one is shared.
      animationKeys_ += output->count;
      if (animationKeys_ > kMaxAnimationKeys) return Error{"the file's animations hold more than " + std::to_string(kMaxAnimationKeys) + " keyframe values"};
      channel.times.resize(input->count);
      for (std::size_t k = 0; k < input->count; ++k) {
        const double t = input->component(k, 0);
        if (!std::isfinite(t)) return Error{where + ": keyframe time " + std::to_string(k) + " is not finite"};
        channel.times[k] = static_cast<float>(t);
        if (k > 0 && !(channel.times[k] > channel.times[k - 1]))
          return Error{where + ": keyframe times do not increase (time " + std::to_string(k) + " is " + json::number(t) + " after " +
                       json::number(channel.times[k - 1]) + ")"};
      }
      channel.values.resize(output->count * static_cast<std::size_t>(output->components));
      for (std::size_t k = 0; k < output->count; ++k)
        for (int j = 0; j < output->components; ++j) {
          const double x = output->component(k, j);
          if (!std::isfinite(x)) return Error{where + ": value " + std::to_string(k) + " is not finite"};
          channel.values[k * static_cast<std::size_t>(output->components) + static_cast<std::size_t>(j)] = static_cast<float>(x);
        }
      if (rotation && channel.interpolation != Interpolation::CubicSpline)
        for (std::size_t k = 0; k < output->count; ++k) {
          const float* q = &channel.values[4 * k];
          if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 1e-12f)) return Error{where + ": a rotation is the zero quaternion"};
        }
      out.start = first ? channel.times.front() : std::min(out.start, channel.times.front());
      out.end = first ? channel.times.back() : std::max(out.end, channel.times.back());
      first = false;
      out.channels.push_back(std::move(channel));
    }
    if (out.channels.empty()) return Error{"it moves nothing this viewer draws (its channels drive nodes outside the scene)"};
    return out;
  }

  // The primitive's skin weights and morph targets into the soup's per-vertex deformation
  // (zero where absent: the vertex stays at rest). Bad data does not fail the file: the first
  // problem is kept (Target::deformProblem) and the mesh is drawn at rest, named.
  void readDeformation(const tinygltf::Primitive& prim, const glm::dmat3& placement, std::size_t count, const std::string& where, Target& t) {
    PolygonSoup& soup = t.soup;
    const std::size_t width = soup.deformWidth();
    const std::size_t first = soup.deform.size() / width;
    soup.deform.resize((first + count) * width, 0.0f);
    const auto problem = [&](const std::string& what) {
      if (t.deformProblem.empty()) t.deformProblem = where + ": " + what;
    };
    const auto unnamed = [&](const std::string& e) { return e.rfind(name_ + ": ", 0) == 0 ? e.substr(name_.size() + 2) : e; };
    if (soup.skinned) {
      const std::size_t joints = m_.skins[static_cast<std::size_t>(t.skin)].joints.size();
      const auto j = prim.attributes.find("JOINTS_0"), w = prim.attributes.find("WEIGHTS_0");
      if (j == prim.attributes.end() || w == prim.attributes.end()) {
        problem("a skinned primitive without JOINTS_0 and WEIGHTS_0");
      } else {
        Result<AccessorView> ja = accessor(j->second, where + " JOINTS_0", {TINYGLTF_TYPE_VEC4});
        Result<AccessorView> wa = accessor(w->second, where + " WEIGHTS_0", {TINYGLTF_TYPE_VEC4});
        if (!ja) return problem(unnamed(ja.error()));
        if (!wa) return problem(unnamed(wa.error()));
        if (ja->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ja->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
          return problem("JOINTS_0 must be unsigned bytes or shorts");
        if (ja->count != count || wa->count != count)
          return problem("JOINTS_0 and WEIGHTS_0 have " + std::to_string(ja->count) + " and " + std::to_string(wa->count) + " elements for " +
                         std::to_string(count) + " positions");
        std::size_t renormalised = 0;
        for (std::size_t i = 0; i < count; ++i) {
          float* v = &soup.deform[(first + i) * width];
          float sum = 0.0f;
          for (int k = 0; k < 4; ++k) {
            const double weight = wa->component(i, k);
            if (!std::isfinite(weight) || weight < 0.0) return problem("vertex " + std::to_string(i) + " has a weight that is negative or not finite");
            const std::uint64_t joint = static_cast<std::uint64_t>(ja->component(i, k));
            if (weight > 0.0 && joint >= joints)
              return problem("vertex " + std::to_string(i) + " names joint " + std::to_string(joint) + ", past the skin's " + std::to_string(joints));
            v[k] = weight > 0.0 ? static_cast<float>(joint) : 0.0f;
            v[4 + k] = static_cast<float>(weight);
            sum += v[4 + k];
          }
          // glTF says the weights sum to one; a small drift (quantised weights) is normalised,
          // a vertex with none stays at rest.
          if (sum > 0.0f && std::abs(sum - 1.0f) > 1e-3f) {
            if (std::abs(sum - 1.0f) > 0.01f) ++renormalised;
            for (int k = 0; k < 4; ++k) v[4 + k] /= sum;
          }
        }
        if (renormalised > 0)
          warn_.add(name_ + ": " + where + ": " + std::to_string(renormalised) + " vertices' skin weights do not sum to one; normalised");
        if (prim.attributes.count("JOINTS_1")) warn_.add(name_ + ": " + where + ": only the first four joint influences per vertex are read");
      }
    }
    if (soup.morphTargets == 0) return;
    if (prim.targets.size() != soup.morphTargets)
      return problem("it has " + std::to_string(prim.targets.size()) + " morph targets where its mesh's first primitive has " +
                     std::to_string(soup.morphTargets));
    const std::size_t base = soup.skinned ? 8 : 0;
    for (std::size_t k = 0; k < soup.morphTargets; ++k)
      for (const char* attribute : {"POSITION", "NORMAL"}) {
        const auto a = prim.targets[k].find(attribute);
        if (a == prim.targets[k].end()) continue;
        Result<AccessorView> deltas = accessor(a->second, where + " morph target " + std::to_string(k) + " " + attribute, {TINYGLTF_TYPE_VEC3});
        if (!deltas) return problem(unnamed(deltas.error()));
        if (deltas->count != count)
          return problem("morph target " + std::to_string(k) + " " + attribute + " has " + std::to_string(deltas->count) + " elements for " +
                         std::to_string(count) + " positions");
        const std::size_t at = base + 6 * k + (attribute[0] == 'N' ? 3 : 0);
        for (std::size_t i = 0; i < count; ++i) {
          const glm::dvec3 d = placement * glm::dvec3(deltas->component(i, 0), deltas->component(i, 1), deltas->component(i, 2));
          if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z))
            return problem("morph target " + std::to_string(k) + " " + attribute + " " + std::to_string(i) + " is not finite");
          float* v = &soup.deform[(first + i) * width + at];
          v[0] = static_cast<float>(d.x), v[1] = static_cast<float>(d.y), v[2] = static_cast<float>(d.z);
        }
      }
  }

  Status primitive(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& where, Target& t) {
    PolygonSoup& soup = t.soup;
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP && prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      ++skippedPrimitives_;
      return okStatus();
    }
    const auto pos = prim.attributes.find("POSITION");
    if (pos == prim.attributes.end()) return fail(where + " has no POSITION");
    Result<AccessorView> positions = accessor(pos->second, where + " POSITION", {TINYGLTF_TYPE_VEC3});
    if (!positions) return Error{positions.error()};
    if (positions->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !positions->normalized)
      warn_.add(name_ + ": " + where + " has integer positions (KHR_mesh_quantization); read as they are stored");
    std::optional<AccessorView> uv, colour;
    if (const auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
      Result<AccessorView> a = accessor(it->second, where + " TEXCOORD_0", {TINYGLTF_TYPE_VEC2});
      if (!a) return Error{a.error()};
      if (a->count != positions->count) return fail(where + ": TEXCOORD_0 has " + std::to_string(a->count) + " elements for " + std::to_string(positions->count) + " positions");
      uv = *a;
    }
    if (const auto it = prim.attributes.find("COLOR_0"); it != prim.attributes.end()) {
      Result<AccessorView> a = accessor(it->second, where + " COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4});
      if (!a) return Error{a.error()};
      if (a->count != positions->count) return fail(where + ": COLOR_0 has " + std::to_string(a->count) + " elements for " + std::to_string(positions->count) + " positions");
      colour = *a;
    }
    std::optional<AccessorView> indices;
    if (prim.indices >= 0) {
      Result<AccessorView> a = accessor(prim.indices, where + " indices", {TINYGLTF_TYPE_SCALAR});
      if (!a) return Error{a.error()};
      if (a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
          a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        return fail(where + ": indices must be unsigned integers");
      indices = *a;
    }
    const std::size_t corners = indices ? indices->count : positions->count;
    const std::uint64_t triangles = prim.mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : (corners >= 3 ? corners - 2 : 0);
    sceneTriangles_ += triangles;
    if (sceneTriangles_ > kMaxSceneTriangles)
      return fail("the scene makes more than " + std::to_string(kMaxSceneTriangles) + " triangles (its meshes instanced by its nodes)");
    int fileMaterial = static_cast<int>(materials_.size()) - 1;  // the default
    if (prim.material >= 0) {
      if (prim.material >= static_cast<int>(m_.materials.size())) return fail(where + " names material " + std::to_string(prim.material) + ", which does not exist");
      fileMaterial = prim.material;
    }
    const int material = localMaterial(t, fileMaterial);

    // Vertices, placed by `world`; a mirroring transform reverses the winding.
    const std::size_t base = soup.vertices.size();
    for (std::size_t i = 0; i < positions->count; ++i) {
      const glm::dvec4 p = world * glm::dvec4(positions->component(i, 0), positions->component(i, 1), positions->component(i, 2), 1.0);
      if (!soup.addVertex(glm::dvec3(p))) warn_.add(name_ + ": " + where + " vertex " + std::to_string(i) + ": non-finite position; faces using it are skipped");
    }
    const bool textured = uv && soup.materials[static_cast<std::size_t>(material)].diffuseMap >= 0;
    if (textured || soup.tracksTexcoords) {
      if (!soup.tracksTexcoords) {
        soup.trackTexcoords();
        soup.texcoords.resize(base, glm::vec2(0.0f));
      }
      const glm::mat3& tt = transforms_[static_cast<std::size_t>(fileMaterial)];
      for (std::size_t i = 0; i < positions->count; ++i) {
        glm::vec2 c(0.0f);
        if (textured) {
          const glm::vec3 u = tt * glm::vec3(float(uv->component(i, 0)), float(uv->component(i, 1)), 1.0f);
          c = std::isfinite(u.x) && std::isfinite(u.y) ? glm::vec2(u.x, 1.0f - u.y) : glm::vec2(0.0f);  // glTF's v runs down
        }
        soup.texcoords.push_back(c);
      }
    }
    if (colour || !soup.colours.empty()) {
      soup.colours.resize(base, glm::vec3(1.0f));
      for (std::size_t i = 0; i < positions->count; ++i) {
        glm::vec3 c(1.0f);
        if (colour)
          for (int k = 0; k < 3; ++k) {
            const double v = colour->component(i, k);
            c[k] = std::isfinite(v) ? std::clamp(static_cast<float>(v), 0.0f, 1.0f) : 1.0f;
          }
        soup.colours.push_back(c);
      }
    }

    if (mode_ == Mode::Objects && soup.deformWidth() > 0) readDeformation(prim, glm::dmat3(world), positions->count, where, t);

    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    auto corner = [&](std::size_t k) -> long long {
      const std::uint64_t i = indices ? indices->index(k) : k;
      return i < positions->count ? static_cast<long long>(base + i) : static_cast<long long>(soup.vertices.size() + i);  // out of range: FaceBuilder refuses it, named
    };
    // Reused for every triangle (FaceBuilder takes the corners as scratch).
    std::vector<long long> face(3);
    std::vector<int> tex(3);
    const std::string unit = where + " triangle";
    const auto add = [&](long long a, long long b, long long c, std::size_t number) {
      face.assign({a, mirrored ? c : b, mirrored ? b : c});
      for (std::size_t k = 0; k < 3; ++k) tex[k] = textured ? static_cast<int>(face[k]) : -1;
      t.faces->add(face, tex, static_cast<std::uint16_t>(material), unit.c_str(), number);
    };
    if (prim.mode == TINYGLTF_MODE_TRIANGLES) {
      for (std::size_t i = 0; i + 2 < corners; i += 3) add(corner(i), corner(i + 1), corner(i + 2), i / 3);
    } else if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (std::size_t i = 0; i + 2 < corners; ++i)
        if (i % 2 == 0) add(corner(i), corner(i + 1), corner(i + 2), i);
        else add(corner(i + 1), corner(i), corner(i + 2), i);
    } else {
      for (std::size_t i = 1; i + 1 < corners; ++i) add(corner(0), corner(i), corner(i + 1), i - 1);
    }
    return okStatus();
  }

  const std::string& name_;
  const tinygltf::Model& m_;
  LoadReport& report_;
  Warnings warn_;
  Mode mode_;
  std::deque<Target> targets_;  // a deque: each FaceBuilder keeps references into its target
  std::vector<Object> objects_;
  std::map<std::tuple<int, bool, int>, std::pair<std::size_t, std::uint64_t>> built_;  // (mesh, mirrored, skin) -> (target, triangles)
  std::vector<MeshMaterial> materials_;  // the file's, then the default
  std::vector<glm::mat3> transforms_;    // per material: its base colour map's texture transform
  std::vector<MeshTexture> images_;      // decoded base colour maps
  std::map<int, int> decoded_;           // glTF image -> images_
  std::vector<std::optional<SceneLight>> lights_;  // KHR_lights_punctual's, null where malformed
  std::vector<SceneLight> placedLights_;
  std::vector<SceneCamera> cameras_;
  std::vector<SceneNode> nodes_;             // Objects: the visited nodes, parents first
  std::map<int, int> nodeOf_;                // the file's node -> nodes_
  std::vector<SceneAnimation> animations_;
  std::vector<SceneSkin> skins_;
  std::map<int, int> skinOf_;
  std::uint64_t animationKeys_ = 0;
  std::uint64_t sceneTriangles_ = 0;
  std::size_t skippedPrimitives_ = 0;
};

// tinygltf's parse of the bytes, with our file and image callbacks.
Status parseContainer(const std::string& name, std::string& bytes, tinygltf::Model& model) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keepImageBytes, &model);
  loader.SetFsCallbacks({fileExists, expandFilePath, readWholeFile, writeWholeFile, nullptr});
  loader.SetStoreOriginalJSONForExtrasAndExtensions(false);
  std::string err, warn;
  const std::string baseDir = fs::path(name).parent_path().string();
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (bytes.size() > std::size_t(std::numeric_limits<unsigned int>::max())) return Error{printable(name) + ": too large for the glTF reader"};
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                       static_cast<unsigned int>(bytes.size()), baseDir)
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), baseDir);
  bytes = std::string();
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    return Error{name + ": not a readable glTF 2.0 file: " + printable(err.empty() ? std::string("the loader gave no reason") : err, 300)};
  }
  return okStatus();
}

}  // namespace

Result<Mesh> parseGltf(const std::string& name, std::string bytes) {
  tinygltf::Model model;
  if (Status s = parseContainer(name, bytes, model); !s) return Error{s.error()};
  LoadReport report;
  report.file = name;
  GltfReader reader(name, model, report, GltfReader::Mode::Flatten);
  if (Status s = reader.read(); !s) return Error{s.error()};
  model = tinygltf::Model();  // the buffers go before the mesh is built (peak memory)
  GltfReader::Target& t = reader.targets().front();
  report.skipped_faces = t.report.skipped_faces;
  report.polygons_triangulated = t.report.polygons_triangulated;
  report.repeated_corner_faces = t.report.repeated_corner_faces;
  std::string firstWarning = report.warnings.empty() ? std::string() : report.warnings.front();
  Result<Mesh> mesh = buildMesh(std::move(t.soup), std::move(report));
  // Nothing to draw: the file's first warning often says why.
  if (!mesh && !firstWarning.empty()) return Error{mesh.error() + " (" + firstWarning + ")"};
  return mesh;
}

Result<LoadedScene> parseGltfScene(const std::string& name, std::string bytes) {
  tinygltf::Model model;
  if (Status s = parseContainer(name, bytes, model); !s) return Error{s.error()};
  LoadReport report;
  report.file = name;
  GltfReader reader(name, model, report, GltfReader::Mode::Objects);
  if (Status s = reader.read(); !s) return Error{s.error()};
  LoadedScene scene;
  scene.file = name;
  model = tinygltf::Model();
  scene.cameras = std::move(reader.cameras());
  scene.lights = reader.placedLights();
  scene.nodes = std::move(reader.nodes());
  scene.animations = std::move(reader.animations());
  scene.skins = std::move(reader.skins());
  scene.warnings = report.warnings;
  scene.report = report;
  std::vector<std::shared_ptr<const Mesh>> meshes(reader.targets().size());
  std::vector<glm::dmat4> unplace(reader.targets().size(), glm::dmat4(1.0));
  for (std::size_t i = 0; i < reader.targets().size(); ++i) {
    GltfReader::Target& t = reader.targets()[i];
    Result<Mesh> m = buildMesh(std::move(t.soup), std::move(t.report));
    if (!m) {
      // A mesh with nothing to draw (every face refused) is left out, not the whole file.
      scene.warnings.push_back(name + ": mesh " + std::to_string(i) + ": " + m.error());
      continue;
    }
    finalizeMesh(*m);
    // Bad skin or morph data, or a skin refused whole: the mesh is drawn at rest, named.
    if (!m->deformation.empty()) {
      if (!t.deformProblem.empty()) {
        scene.warnings.push_back(name + ": mesh " + std::to_string(t.mesh) + " is drawn at rest: " + t.deformProblem);
        m->deformation = MeshDeformation{};
      } else if (t.skin >= 0 && !reader.skinOf().count(t.skin)) {
        m->deformation.joints.clear();
        m->deformation.weights.clear();
      }
    }
    // The loader centred and scaled the mesh; its object transform puts it back.
    unplace[i] = glm::translate(glm::dmat4(1.0), m->report.original_centre) * glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / m->report.original_scale));
    meshes[i] = std::make_shared<const Mesh>(std::move(*m));
  }
  for (const GltfReader::Object& o : reader.objects()) {
    if (!meshes[o.target]) continue;
    const auto skin = reader.skinOf().find(o.skin);
    const int skinIndex = skin != reader.skinOf().end() && meshes[o.target]->deformation.skinned() ? skin->second : -1;
    scene.objects.push_back({o.name, meshes[o.target], glm::mat4(o.world * unplace[o.target]), o.node, glm::mat4(o.mirror * unplace[o.target]), skinIndex});
    scene.report.vertices += meshes[o.target]->positions.size();
    scene.report.triangles += meshes[o.target]->triangleCount();
  }
  for (const auto& m : meshes)
    if (m) {
      scene.report.skipped_faces += m->report.skipped_faces;
      scene.report.degenerate_triangles += m->report.degenerate_triangles;
      scene.report.polygons_triangulated += m->report.polygons_triangulated;
      scene.report.repeated_corner_faces += m->report.repeated_corner_faces;
      scene.report.non_manifold_faces += m->report.non_manifold_faces;
    }
  if (scene.objects.empty()) return Error{name + ": the scene has no triangles to draw"};
  return scene;
}

}  // namespace npr
