// The objects the viewer shows, from one or more files: each with its name, its file, its
// placement, whether it is shown and its own palette. Files are placed as in their own space
// (--layout file) or set apart in a row or grid, and the whole scene is then fitted into the
// unit sphere about the origin, which the camera, the light and the ground are sized for.
// Loads are all-or-nothing: a file that fails leaves the scene as it was.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/animation_playback.h"
#include "app/scene_layout.h"
#include <optional>
#include "renderer/mesh/node_animation.h"
#include "renderer/mesh/scene_description.h"
#include "renderer/renderer.h"

namespace npr {


struct ViewerObject {
  std::string name;
  std::size_t file = 0;  // into SceneObjects::files()
  std::shared_ptr<const Mesh> mesh;
  glm::mat4 inFile{1.0f};  // the mesh's space to its file's, at rest
  int node = -1;           // its file's node (animated ones move it)
  glm::mat4 afterNode{1.0f};  // inFile = the node's world transform * afterNode (skinned: inFile = afterNode)
  int skin = -1;           // into its file's skins: placed by its joints
  bool animated = false;   // an animation of its file moves its node, a joint of its skin or its weights
  glm::mat4 placed{1.0f};  // the mesh's space to the viewer's, as drawn now (posed)
  ModelId id = 0;
  bool visible = true;
  std::string palette;  // its own palette's file; empty: the main palette
  float detail = 0.0f;  // what a palette with `axis detail` picks its row by
};

struct SceneFile {
  std::string path;
  std::vector<SceneCamera> cameras;  // in the file's space
  std::vector<SceneLight> lights;
  std::vector<SceneNode> nodes;
  std::vector<SceneAnimation> animations;
  std::vector<SceneSkin> skins;
  bool deforms = false;  // an object of it is skinned or has morph targets
  glm::mat4 layout{1.0f};  // the file's space to the scene's (before the fit)
  // Added to a scene (Shift-drop, Ctrl+Shift+O) laid out as the files place them: set beside
  // what was there at its size, not at its own units (a teapot in centimetres beside a spider
  // in metres would be a speck or hide it).
  std::optional<glm::mat4> beside;
};

class SceneObjects {
 public:
  // Loads every file of `paths` and puts their objects in place of the scene's (or beside
  // them, `add`). The files' warnings go to `warnings`. Nothing changes when one fails.
  [[nodiscard]] Status load(const std::vector<std::string>& paths, bool add, Renderer& renderer, std::vector<std::string>& warnings);
  // OBJ groups as objects in the loads that follow (--split-objects).
  void setSplitObjects(bool split) { split_ = split; }
  void setAllWarnings(bool all) { allWarnings_ = all; }  // --verbose
  void setLayout(Layout layout, Renderer& renderer);
  Layout layout() const { return layout_; }
  bool setVisible(std::size_t object, bool visible, Renderer& renderer);
  // Draws object `object` with the palette at `path` (empty: the main one again).
  [[nodiscard]] Status setPalette(std::size_t object, const std::string& path, Renderer& renderer);
  // The object's detail in [0, 1] (Renderer::setModelDetail).
  bool setDetail(std::size_t object, float detail, Renderer& renderer);

  const std::vector<ViewerObject>& objects() const { return objects_; }
  const std::vector<SceneFile>& files() const { return files_; }
  bool empty() const { return objects_.empty(); }
  std::size_t triangles() const;
  // The shown objects' vertices as the layout places them, at most about `budget` of them
  // (every k-th of a large scene): what the camera frames, the same whatever time the scene is
  // posed at. An object that `choice`'s animations move by its node is taken at poses spread
  // over the animation, so it stays in the frame all through its motion; the others (and
  // skinned ones, whose vertices move on the GPU) at rest.
  std::vector<glm::vec3> framingPoints(const AnimationChoice& choice = {AnimationChoice::Which::None}, std::size_t budget = 200000) const;
  // The shown object whose surface the ray through `ndc` (-1..1) meets first, or none.
  std::optional<std::size_t> pick(const CameraMatrices& camera, const glm::vec2& ndc) const;
  // The object's bounding sphere in the viewer's space (centre, radius).
  glm::vec4 sphere(std::size_t object) const;
  // The distinct names of the objects' materials (the default one left out), at most `limit`.
  std::vector<std::string> materialNames(std::size_t limit) const;
  // "bunny.obj", or "scene.glb (12 objects)", or "3 files (14 objects)".
  std::string label() const;
  // File space to the viewer's (the layout, then the fit into the unit sphere).
  glm::mat4 toViewer(std::size_t file) const { return fit_ * files_[file].layout; }
  // Every file's cameras and lights in the viewer's space, in file order.
  std::vector<SceneCamera> cameras() const;
  std::vector<SceneLight> lights() const;
  // The length of one of the first file's units in the viewer's space.
  float fileUnits() const;

  // Every file's animations in scene order (what --animation numbers), with their names.
  struct AnimationRef {
    std::size_t file = 0, index = 0;
    const SceneAnimation* animation = nullptr;
  };
  std::vector<AnimationRef> animations() const;
  std::vector<std::string> animationNames() const;
  // The scene time the clock loops over for `choice`: the latest last keyframe (0: nothing moves).
  double animationLength(const AnimationChoice& choice) const;
  // Poses the animated objects at the clock's time with the chosen animations (the rest pose
  // for the others); nothing is done when the time and choice are those of the last pose.
  void pose(const AnimationChoice& choice, double time, Renderer& renderer);

 private:
  // Places every file by the layout, fits the scene and gives the renderer the transforms.
  void place(Renderer& renderer);
  // Deforms a deforming object's posed mesh to the file's current node pose.
  void deform(ViewerObject& o, const SceneFile& file, Renderer& renderer);

  std::vector<ViewerObject> objects_;
  std::vector<SceneFile> files_;
  Layout layout_ = Layout::File;
  bool split_ = false;
  bool allWarnings_ = false;
  glm::mat4 fit_{1.0f};
  struct PoseKey {
    AnimationChoice choice;
    double time = 0.0;
    bool valid = false;
  } posed_;
  NodePose nodePose_;              // scratch: one file's posed nodes
  std::vector<glm::mat4> jointMatrices_;
};

}  // namespace npr
