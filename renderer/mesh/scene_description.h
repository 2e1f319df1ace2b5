// What a scene file holds beside its meshes, CPU-side and without GL: the objects (a mesh
// placed by a transform), the cameras and the lights, as the file gives them (its own units and
// axes). The app fits the whole scene into the view (app/scene_objects.h); the renderer only
// sees models and the lighting state.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/node_animation.h"
#include "renderer/mesh/mesh.h"

namespace npr {

struct SceneObject {
  std::string name;                  // the node's name, or the file's for a one-mesh file
  std::shared_ptr<const Mesh> mesh;  // finalised; shared by the nodes that instance one glTF mesh
  // The mesh's own space (centred and scaled into the unit sphere by the loader) to the file's,
  // in the rest pose.
  glm::mat4 transform{1.0f};
  // The node that places it (into LoadedScene::nodes; -1: placed by `transform` alone) and
  // what follows the node's world transform: transform = world(node) * afterNode.
  int node = -1;
  glm::mat4 afterNode{1.0f};
  // Its skin (into LoadedScene::skins; -1: none). A skinned object is placed by its joints
  // alone, as glTF says: transform = afterNode, whatever its node's transform.
  int skin = -1;
};

// A glTF skin: its joints (into LoadedScene::nodes) and their inverse bind matrices (file
// space to each joint's, in the bind pose).
struct SceneSkin {
  std::string name;
  std::vector<int> joints;
  std::vector<glm::mat4> inverseBind;
};

struct SceneCamera {
  std::string name;
  glm::mat4 world{1.0f};  // the camera's node: it looks down its -Z with +Y up
  bool perspective = true;
  float yfov = 0.8f;      // radians (perspective)
  float aspect = 0.0f;    // 0: the viewport's
  float znear = 0.01f, zfar = 0.0f;  // zfar 0: infinite
  float xmag = 1.0f, ymag = 1.0f;    // half extents (orthographic)
};

// KHR_lights_punctual: intensity in candela (point, spot) or lux (directional), range 0 when
// unbounded, cone angles in radians.
struct SceneLight {
  enum class Type { Directional, Point, Spot };
  std::string name;
  Type type = Type::Directional;
  glm::vec3 colour{1.0f};
  float intensity = 1.0f;
  float range = 0.0f;
  float innerCone = 0.0f, outerCone = 0.7853982f;
  glm::mat4 world{1.0f};  // the light's node: it points down its -Z
};

struct LoadedScene {
  std::string file;
  std::vector<SceneObject> objects;
  std::vector<SceneCamera> cameras;
  std::vector<SceneLight> lights;
  // The default scene's nodes (parents first) and the animations that move them; animations
  // the reader refused are left out, named in `warnings`.
  std::vector<SceneNode> nodes;
  std::vector<SceneAnimation> animations;
  std::vector<SceneSkin> skins;
  // The file's warnings (each object's mesh keeps its own report too).
  std::vector<std::string> warnings;
  // The file's load report: materials, textures found and missing, warnings; vertices and
  // triangles summed over the objects (a mesh instanced twice counts twice).
  LoadReport report;
  double load_ms = 0.0;
};

}  // namespace npr
