// The glTF 2.0 reader's insides (mesh/gltf/, by job): the reader class that walks a parsed
// file, the accessor views it reads every array through, and the bounds on what one file may
// make. The entry points (parseGltf, parseGltfScene) are in mesh_formats.h; what the reader
// does and how materials map onto the lighting model is in gltf_container.cpp.
#pragma once

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

namespace npr::gltf {
namespace fs = std::filesystem;

// Bounds on what one file may make, whatever its counts say: instancing one mesh from many
// nodes multiplies it, so the flattened scene is bounded, not only each accessor.
inline constexpr std::uint64_t kMaxSceneTriangles = 50'000'000;
inline constexpr std::uint64_t kMaxSceneMarks = 20'000'000;  // points and line segments
inline constexpr int kMaxNodeDepth = 256;
inline constexpr std::size_t kMaxInstances = 1'000'000;  // EXT_mesh_gpu_instancing's, per node
inline constexpr std::size_t kMaxSceneObjects = 100'000;  // objects placed, instances counted
// Keyframe values over every channel (each copies its sampler's, and samplers may be shared).
inline constexpr std::uint64_t kMaxAnimationKeys = 4'000'000;
inline constexpr std::size_t kMaxMorphTargets = 64;
inline constexpr std::size_t kMaxJoints = 4096;

inline bool finite(const std::vector<double>& v) {
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

inline int componentBytes(int type) {
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

inline int typeComponents(int type) {
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

  Status read();

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

  Target& newTarget(int mesh = -1, int skin = -1);

  Result<AccessorView> accessor(int index, const std::string& what, std::initializer_list<int> types) const;
  Result<std::vector<glm::dmat4>> gpuInstances(const tinygltf::Node& n, int index);
  Status instance(const tinygltf::Node& n, int index, int node, const glm::dmat4& world, const glm::dmat4& instance, int number);
  // A primitive's indices (none when it has none), checked to be unsigned integers.
  Result<std::optional<AccessorView>> indices(const tinygltf::Primitive& prim, const std::string& where) const;

  // The file's materials, mapped onto GL's (the formula in gltf_container.cpp's opening comment), and the images their
  // base colour maps use, decoded once; each mesh copies the ones it uses (localMaterial).
  Status readMaterials();

  // The mesh's index of the file's material `g` (the default: the last), copied in with its
  // image the first time the mesh uses it.
  int localMaterial(Target& t, int g);

  // KHR_texture_transform as a 3x3 matrix on (u, v, 1): translation * rotation * scale.
  glm::mat3 textureTransform(const tinygltf::ExtensionMap& ext);

  // The decoded image of texture `index` in images_, or -1 (reported missing).
  int texture(int index);

  // KHR_lights_punctual's lights (placed later by the nodes that name them); a malformed one
  // is reported and left out.
  Status readLights();

  // The camera of node `n` (placed at `world`), or a warning when it is malformed.
  void addCamera(int index, const glm::dmat4& world);

  void placeLight(const tinygltf::Node& n, const glm::dmat4& world);

  Result<glm::dmat4> localTransform(const tinygltf::Node& n, int index) const;

  Status visit(int index, const glm::dmat4& parent, int parentNode, int depth, std::vector<char>& visited);

  // Node `index`'s mesh: its primitives into the one mesh at its world transform (Flatten), or
  // an object instancing the glTF mesh, built the first time a node uses it (Objects).
  Status mesh(const tinygltf::Node& n, int index, int node, const glm::dmat4& world);

  // The file's animations: each checked whole, and one that breaks a rule refused with a
  // warning naming it and the rule (the scene stays, static where it would have moved).
  void readAnimations();

  // Whether skin `k` can be read at all (its joints exist); readSkins checks the rest.
  bool skinUsable(int k) const;

  // The skins the scene's objects use, each checked whole; a refused one is named and its
  // objects drawn in their bind pose.
  void readSkins();

  Result<SceneSkin> readSkin(const tinygltf::Skin& g);

  Result<SceneAnimation> readAnimation(const tinygltf::Animation& a);

  // The primitive's skin weights and morph targets into the soup's per-vertex deformation
  // (zero where absent: the vertex stays at rest). Bad data does not fail the file: the first
  // problem is kept (Target::deformProblem) and the mesh is drawn at rest, named.
  void readDeformation(const tinygltf::Primitive& prim, const glm::dmat3& placement, std::size_t count, const std::string& where, Target& t);

  Status primitive(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& where, Target& t);
  // A POINTS or LINES, LINE_LOOP or LINE_STRIP primitive: its points as dots and its lines as
  // segments of the soup's marks, placed by `world` (gltf_marks.cpp).
  Status marks(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& where, Target& t);

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
  std::size_t skippedPrimitives_ = 0;  // of points or lines on a deforming mesh
  std::uint64_t sceneMarks_ = 0;      // dots and segments made, instances counted

};

}  // namespace npr::gltf
