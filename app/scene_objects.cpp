// The viewer's objects (see scene_objects.h).
#include "app/scene_objects.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/mesh/scene_loader.h"
#include "renderer/palette/palette.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

// The animations of `file` that `choice` plays; `number` is the scene-order number of the
// file's first animation, moved past its last (files are walked in order).
std::vector<const SceneAnimation*> playedAnimations(const SceneFile& file, const AnimationChoice& choice, std::size_t& number) {
  std::vector<const SceneAnimation*> playing;
  for (std::size_t a = 0; a < file.animations.size(); ++a, ++number)
    if (choice.which == AnimationChoice::Which::All || (choice.which == AnimationChoice::Which::One && choice.one == number))
      playing.push_back(&file.animations[a]);
  return playing;
}

// The sphere about the bounding box's centre holding every vertex of `objects` placed by
// `placement(object)`: what the loader fits a single mesh by, so a scene fits as tightly.
template <class Placement>
glm::vec4 boundsOf(const std::vector<const ViewerObject*>& objects, Placement&& placement) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const ViewerObject* o : objects) {
    const glm::mat4 t = placement(*o);
    for (const glm::vec3& p : o->mesh->positions) {
      const glm::vec3 q(t * glm::vec4(p, 1.0f));
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
  }
  if (!(lo.x <= hi.x)) return glm::vec4(0.0f, 0.0f, 0.0f, -1.0f);
  const glm::vec3 centre = 0.5f * (lo + hi);
  float r2 = 0.0f;
  for (const ViewerObject* o : objects) {
    const glm::mat4 t = placement(*o);
    for (const glm::vec3& p : o->mesh->positions) {
      const glm::vec3 d = glm::vec3(t * glm::vec4(p, 1.0f)) - centre;
      r2 = std::max(r2, glm::dot(d, d));
    }
  }
  return glm::vec4(centre, std::sqrt(r2));
}

// Where the file layout puts a file: where the file places it, or beside the scene it was added to.
glm::mat4 filePlacement(const SceneFile& file) { return file.beside ? *file.beside : glm::mat4(1.0f); }

}  // namespace

Status SceneObjects::load(const std::vector<std::string>& paths, bool add, Renderer& renderer, std::vector<std::string>& warnings) {
  std::vector<LoadedScene> loaded;
  for (const std::string& path : paths) {
    Result<LoadedScene> s = loadScene(path, SceneLoadOptions{split_, allWarnings_});
    if (!s) return Error{s.error()};
    loaded.push_back(std::move(*s));
  }
  if (!add) {
    renderer.scene().clear();
    objects_.clear();
    files_.clear();
  }
  // What the scene holds before the added files, as the file layout places it.
  std::vector<const ViewerObject*> before;
  for (const ViewerObject& o : objects_) before.push_back(&o);
  glm::vec4 existing = before.empty() ? glm::vec4(0.0f, 0.0f, 0.0f, -1.0f)
                                      : boundsOf(before, [&](const ViewerObject& o) { return filePlacement(files_[o.file]) * o.inFile; });
  for (LoadedScene& s : loaded) {
    for (const std::string& w : s.warnings) warnings.push_back(w);
    std::vector<const SceneAnimation*> every;
    for (const SceneAnimation& a : s.animations) every.push_back(&a);
    const std::vector<char> moved = animatedNodes(s.nodes, every);
    const auto movedNode = [&](int n) { return n >= 0 && n < static_cast<int>(moved.size()) && moved[static_cast<std::size_t>(n)]; };
    const std::size_t file = files_.size();
    files_.push_back({s.file, std::move(s.cameras), std::move(s.lights), std::move(s.nodes), std::move(s.animations), std::move(s.skins), false,
                      glm::mat4(1.0f), std::nullopt});
    for (SceneObject& o : s.objects) {
      ViewerObject v;
      v.name = o.name;
      v.file = file;
      v.mesh = std::move(o.mesh);
      v.inFile = o.transform;
      v.node = o.node;
      v.afterNode = o.afterNode;
      v.skin = o.skin;
      v.animated = movedNode(o.node);
      const std::vector<SceneSkin>& skins = files_.back().skins;  // the file's, moved there
      if (o.skin >= 0 && o.skin < static_cast<int>(skins.size()))
        for (int joint : skins[static_cast<std::size_t>(o.skin)].joints) v.animated = v.animated || movedNode(joint);
      v.id = renderer.scene().add(*v.mesh, glm::mat4(1.0f));
      renderer.scene().setName(v.id, v.name);  // line sets select objects by it
      if (!v.mesh->deformation.empty()) files_.back().deforms = true;
      objects_.push_back(std::move(v));
    }
    // Beside the scene, to its right, scaled to its radius, a fifth of that apart.
    if (add && existing.w > 0.0f && std::isfinite(existing.w)) {
      std::vector<const ViewerObject*> mine;
      for (const ViewerObject& o : objects_)
        if (o.file == file) mine.push_back(&o);
      const glm::vec4 b = boundsOf(mine, [](const ViewerObject& o) { return o.inFile; });
      if (b.w > 0.0f && std::isfinite(b.w)) {
        const float r = existing.w;
        const glm::vec3 at = glm::vec3(existing) + glm::vec3(existing.w + 1.2f * r, 0.0f, 0.0f);
        files_.back().beside = glm::translate(glm::mat4(1.0f), at) * glm::scale(glm::mat4(1.0f), glm::vec3(r / b.w)) *
                               glm::translate(glm::mat4(1.0f), -glm::vec3(b));
        // The next file added goes beside this one too.
        std::vector<const ViewerObject*> all;
        for (const ViewerObject& o : objects_) all.push_back(&o);
        existing = boundsOf(all, [&](const ViewerObject& o) { return filePlacement(files_[o.file]) * o.inFile; });
      }
    }
  }
  place(renderer);
  return okStatus();
}

void SceneObjects::setLayout(Layout layout, Renderer& renderer) {
  layout_ = layout;
  place(renderer);
}

void SceneObjects::place(Renderer& renderer) {
  std::vector<const ViewerObject*> all;
  for (const ViewerObject& o : objects_) all.push_back(&o);
  // Each file's bounding sphere in its own space (row and grid only).
  std::vector<glm::vec4> fileBounds(files_.size(), glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
  if (layout_ != Layout::File && files_.size() > 1)
    for (std::size_t f = 0; f < files_.size(); ++f) {
      std::vector<const ViewerObject*> mine;
      for (const ViewerObject* o : all)
        if (o->file == f) mine.push_back(o);
      fileBounds[f] = boundsOf(mine, [](const ViewerObject& o) { return o.inFile; });
    }
  // Row and grid: every file scaled to a unit sphere and set two and a half radii apart,
  // left to right (and top to bottom), centred on the origin.
  const std::size_t n = files_.size();
  const std::size_t columns = layout_ == Layout::Grid ? static_cast<std::size_t>(std::ceil(std::sqrt(double(n)))) : n;
  const std::size_t rows = columns ? (n + columns - 1) / columns : 0;
  for (std::size_t f = 0; f < n; ++f) {
    glm::mat4& l = files_[f].layout;
    const glm::vec4 b = fileBounds[f];
    if (layout_ == Layout::File || n < 2 || !(b.w > 0.0f)) {
      l = layout_ == Layout::File ? filePlacement(files_[f]) : glm::mat4(1.0f);
      continue;
    }
    const float spacing = 2.5f;
    const glm::vec3 at((float(f % columns) - 0.5f * float(columns - 1)) * spacing, (0.5f * float(rows - 1) - float(f / columns)) * spacing, 0.0f);
    l = glm::translate(glm::mat4(1.0f), at) * glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / b.w)) * glm::translate(glm::mat4(1.0f), -glm::vec3(b));
  }
  // The scene into the unit sphere. One object is drawn as loaded (its mesh is centred and
  // scaled already): exactly, not through a product of transforms that rounds.
  posed_.valid = false;
  if (objects_.size() == 1) {
    fit_ = glm::inverse(files_[objects_.front().file].layout * objects_.front().inFile);
    objects_.front().placed = glm::mat4(1.0f);
    renderer.scene().setTransform(objects_.front().id, glm::mat4(1.0f));
    return;
  }
  const glm::vec4 scene = boundsOf(all, [&](const ViewerObject& o) { return files_[o.file].layout * o.inFile; });
  const float r = scene.w > 0.0f && std::isfinite(scene.w) ? scene.w : 1.0f;
  fit_ = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / r)) * glm::translate(glm::mat4(1.0f), -glm::vec3(scene));
  for (ViewerObject& o : objects_) {
    o.placed = toViewer(o.file) * o.inFile;
    renderer.scene().setTransform(o.id, o.placed);
  }
}

void SceneObjects::deform(ViewerObject& o, const SceneFile& file, Renderer& renderer) {
  // Skinned: each joint's matrix taken into the mesh's own space (afterNode puts the mesh in
  // the file's, where joints and inverse bind matrices live).
  jointMatrices_.clear();
  if (o.skin >= 0 && o.skin < static_cast<int>(file.skins.size())) {
    const SceneSkin& skin = file.skins[static_cast<std::size_t>(o.skin)];
    const glm::mat4 toMesh = glm::inverse(o.afterNode);
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
      const int node = skin.joints[j];
      const glm::mat4 joint = node >= 0 && node < static_cast<int>(nodePose_.world.size()) ? nodePose_.world[static_cast<std::size_t>(node)] : glm::mat4(1.0f);
      jointMatrices_.push_back(toMesh * joint * skin.inverseBind[j] * o.afterNode);
    }
  }
  static const std::vector<float> none;
  const std::vector<float>& weights = o.node >= 0 && o.node < static_cast<int>(nodePose_.weights.size()) ? nodePose_.weights[static_cast<std::size_t>(o.node)] : none;
  renderer.scene().deform(o.id, jointMatrices_, weights);
}

std::vector<SceneObjects::AnimationRef> SceneObjects::animations() const {
  std::vector<AnimationRef> out;
  for (std::size_t f = 0; f < files_.size(); ++f)
    for (std::size_t a = 0; a < files_[f].animations.size(); ++a) out.push_back({f, a, &files_[f].animations[a]});
  return out;
}

std::vector<std::string> SceneObjects::animationNames() const {
  std::vector<std::string> names;
  for (const AnimationRef& a : animations()) names.push_back(a.animation->name);
  return names;
}

double SceneObjects::animationLength(const AnimationChoice& choice) const {
  const std::vector<AnimationRef> all = animations();
  double end = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (choice.which == AnimationChoice::Which::All || (choice.which == AnimationChoice::Which::One && choice.one == i))
      end = std::max(end, double(all[i].animation->end));
  return end;
}

void SceneObjects::pose(const AnimationChoice& choice, double time, Renderer& renderer) {
  if (posed_.valid && posed_.choice == choice && posed_.time == time) return;
  // The first pose after a load or a layout poses every object (a skinned one's rest pose is
  // its skin's too); later ones only what the file's animations move.
  const bool first = !posed_.valid;
  posed_ = {choice, time, true};
  std::size_t number = 0;  // the scene-order number of each file's first animation
  for (std::size_t f = 0; f < files_.size(); ++f) {
    const SceneFile& file = files_[f];
    if (file.animations.empty() && !file.deforms) continue;
    const std::vector<const SceneAnimation*> playing = playedAnimations(file, choice, number);
    // Objects any of the file's animations moves are posed (at rest when none of them plays).
    poseNodes(file.nodes, playing, static_cast<float>(time), nodePose_);
    const std::vector<glm::mat4>& world = nodePose_.world;
    for (ViewerObject& o : objects_) {
      if (o.file != f || o.node < 0 || o.node >= static_cast<int>(world.size()) || (!first && !o.animated)) continue;
      if (!o.mesh->deformation.empty()) deform(o, file, renderer);
      if (o.skin >= 0 || !o.animated) continue;
      const glm::mat4 placed = toViewer(f) * world[static_cast<std::size_t>(o.node)] * o.afterNode;
      // A pose that overflows (keys of 1e30 scaled by 1e30) is not drawn: the last one stays.
      bool finite = true;
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(placed[c][r]);
      if (!finite) continue;
      o.placed = placed;
      renderer.scene().pose(o.id, o.placed);
    }
  }
}

bool SceneObjects::setVisible(std::size_t object, bool visible, Renderer& renderer) {
  if (object >= objects_.size()) return false;
  objects_[object].visible = visible;
  return renderer.scene().setVisible(objects_[object].id, visible);
}

bool SceneObjects::setDetail(std::size_t object, float detail, Renderer& renderer) {
  if (object >= objects_.size() || !renderer.scene().setDetail(objects_[object].id, detail)) return false;
  objects_[object].detail = renderer.scene().find(objects_[object].id)->detail();
  return true;
}

Status SceneObjects::setPalette(std::size_t object, const std::string& path, Renderer& renderer) {
  if (object >= objects_.size()) return Error{"no object number " + std::to_string(object + 1) + " (the scene has " + std::to_string(objects_.size()) + ")"};
  ViewerObject& o = objects_[object];
  if (path.empty()) {
    renderer.scene().clearPalette(o.id);
    o.palette.clear();
    return okStatus();
  }
  Result<Palette> p = loadPalette(path);
  if (!p) return Error{p.error()};
  if (Status s = renderer.scene().setPalette(o.id, *p); !s) return s;
  o.palette = path;
  return okStatus();
}

std::size_t SceneObjects::triangles() const {
  std::size_t n = 0;
  for (const ViewerObject& o : objects_) n += o.mesh->triangleCount();
  return n;
}

std::vector<glm::vec3> SceneObjects::framingPoints(const AnimationChoice& choice, std::size_t budget) const {
  // Poses over the animation: enough that a turn or a bounce is seen whole, few enough that a
  // large moving object's share of the budget stays dense (16 poses of every 16th vertex).
  constexpr int kPoses = 16;
  const double length = choice.which == AnimationChoice::Which::None ? 0.0 : animationLength(choice);
  const auto moves = [&](const ViewerObject& o) { return length > 0.0 && o.animated && o.skin < 0 && o.node >= 0; };
  // What is drawn of a mesh: its vertices and a file's points and lines (Mesh::dots, segments).
  const auto drawnPoints = [](const Mesh& m) { return m.positions.size() + m.dots.size() + m.segments.size(); };
  const auto drawnPoint = [](const Mesh& m, std::size_t i) -> const glm::vec3& {
    if (i < m.positions.size()) return m.positions[i];
    i -= m.positions.size();
    return i < m.dots.size() ? m.dots[i] : m.segments[i - m.dots.size()];
  };
  std::size_t total = 0;
  for (const ViewerObject& o : objects_)
    if (o.visible) total += drawnPoints(*o.mesh);
  const std::size_t stride = std::max<std::size_t>(1, total / std::max<std::size_t>(budget, 1));
  std::vector<glm::vec3> points;
  points.reserve(total / stride + objects_.size());
  for (const ViewerObject& o : objects_) {
    if (!o.visible || moves(o)) continue;
    // One object is drawn as loaded (place()): its rest placement is the identity.
    const glm::mat4 rest = objects_.size() == 1 ? glm::mat4(1.0f) : toViewer(o.file) * o.inFile;
    for (std::size_t i = 0, n = drawnPoints(*o.mesh); i < n; i += stride) points.push_back(glm::vec3(rest * glm::vec4(drawnPoint(*o.mesh, i), 1.0f)));
  }
  if (length <= 0.0) return points;
  NodePose pose;
  std::size_t number = 0;  // the scene-order number of each file's first animation (as pose())
  for (std::size_t f = 0; f < files_.size(); ++f) {
    const SceneFile& file = files_[f];
    const std::vector<const SceneAnimation*> playing = playedAnimations(file, choice, number);
    if (playing.empty()) continue;
    for (int k = 0; k < kPoses; ++k) {
      poseNodes(file.nodes, playing, static_cast<float>(length * k / (kPoses - 1)), pose);
      for (const ViewerObject& o : objects_) {
        if (o.file != f || !o.visible || !moves(o) || o.node >= static_cast<int>(pose.world.size())) continue;
        const glm::mat4 placed = toViewer(f) * pose.world[static_cast<std::size_t>(o.node)] * o.afterNode;
        const std::size_t n = drawnPoints(*o.mesh);
        // At least 64 of a small mesh's vertices each pose (every one of a square's four).
        const std::size_t step = std::max<std::size_t>(1, std::min(stride * kPoses, n / 64));
        for (std::size_t i = 0; i < n; i += step) {
          const glm::vec3 q(placed * glm::vec4(drawnPoint(*o.mesh, i), 1.0f));
          if (std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z)) points.push_back(q);  // an overflowing pose is not drawn (pose())
        }
      }
    }
  }
  return points;
}

std::optional<std::size_t> SceneObjects::pick(const CameraMatrices& camera, const glm::vec2& ndc) const {
  const glm::mat4 inv = glm::inverse(camera.projection * camera.view);
  const glm::vec4 a = inv * glm::vec4(ndc, -1.0f, 1.0f), b = inv * glm::vec4(ndc, 1.0f, 1.0f);
  if (!(std::abs(a.w) > 0.0f) || !(std::abs(b.w) > 0.0f)) return std::nullopt;
  const glm::vec3 from = glm::vec3(a) / a.w, to = glm::vec3(b) / b.w;
  // The segment's parameter is the same in every object's own space (its transform is
  // affine), so the nearest hit is compared across objects as it is.
  float nearest = 2.0f;
  std::optional<std::size_t> hit;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    const ViewerObject& o = objects_[i];
    if (!o.visible) continue;
    const glm::mat4 toMesh = glm::inverse(o.placed);
    const glm::vec3 p(toMesh * glm::vec4(from, 1.0f)), q(toMesh * glm::vec4(to, 1.0f));
    const glm::vec3 d = q - p;
    const Mesh& m = *o.mesh;
    for (std::size_t f = 0; f < m.triangleCount(); ++f) {
      // Moller-Trumbore, both sides.
      const glm::vec3 v0 = m.positions[m.indices[3 * f]], e1 = m.positions[m.indices[3 * f + 1]] - v0, e2 = m.positions[m.indices[3 * f + 2]] - v0;
      const glm::vec3 h = glm::cross(d, e2);
      const float det = glm::dot(e1, h);
      if (std::abs(det) < 1e-12f) continue;
      const glm::vec3 s = p - v0;
      const float u = glm::dot(s, h) / det;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 qv = glm::cross(s, e1);
      const float v = glm::dot(d, qv) / det;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float t = glm::dot(e2, qv) / det;
      if (t >= 0.0f && t < nearest) {
        nearest = t;
        hit = i;
      }
    }
  }
  return hit;
}

glm::vec4 SceneObjects::sphere(std::size_t object) const {
  const ViewerObject& o = objects_.at(object);
  const glm::mat4& t = o.placed;
  float scale = 0.0f;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, glm::length(glm::vec3(t[c])));
  return glm::vec4(glm::vec3(t[3]), o.mesh->radius * scale);
}

std::vector<std::string> SceneObjects::materialNames(std::size_t limit) const {
  std::vector<std::string> names;
  for (const ViewerObject& o : objects_)
    for (const MeshMaterial& m : o.mesh->materials) {
      if (names.size() >= limit) return names;
      if (m.fromLightingState && m.name == "(default)") continue;
      if (std::find(names.begin(), names.end(), m.name) == names.end()) names.push_back(m.name);
    }
  return names;
}

std::string SceneObjects::label() const {
  if (files_.empty()) return "-";
  const std::string objects = std::to_string(objects_.size()) + (objects_.size() == 1 ? " object" : " objects");
  if (files_.size() > 1) return std::to_string(files_.size()) + " files (" + objects + ")";
  const std::string name = fs::path(files_.front().path).filename().string();
  return objects_.size() == 1 ? name : name + " (" + objects + ")";
}

std::vector<SceneCamera> SceneObjects::cameras() const {
  std::vector<SceneCamera> out;
  for (std::size_t f = 0; f < files_.size(); ++f)
    for (SceneCamera c : files_[f].cameras) {
      c.world = toViewer(f) * c.world;
      out.push_back(c);
    }
  return out;
}

float SceneObjects::fileUnits() const {
  return files_.empty() ? 1.0f : glm::length(glm::vec3(toViewer(0)[0]));
}

std::vector<SceneLight> SceneObjects::lights() const {
  std::vector<SceneLight> out;
  for (std::size_t f = 0; f < files_.size(); ++f)
    for (SceneLight l : files_[f].lights) {
      l.world = toViewer(f) * l.world;
      out.push_back(l);
    }
  return out;
}

}  // namespace npr
