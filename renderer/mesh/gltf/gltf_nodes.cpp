// The glTF reader: The scene walk: the default scene's nodes visited from the roots (cycles and depth bounded),
// each node's transform, its meshes' primitives read into the mesh being built, flattened or
// one per glTF mesh.
#include "renderer/mesh/gltf/gltf_reader.h"

namespace npr::gltf {

Status GltfReader::read() {
  for (const std::string& ext : m_.extensionsRequired)
    if (ext != "KHR_texture_transform" && ext != "KHR_materials_unlit" && ext != "KHR_lights_punctual" && ext != "EXT_mesh_gpu_instancing")
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
    warn_.add(name_ + ": " + std::to_string(skippedPrimitives_) + " primitive(s) of points or lines on a skinned or morphed mesh not drawn (their marks do not follow the pose)");
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

GltfReader::Target& GltfReader::newTarget(int mesh, int skin) {
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

Result<glm::dmat4> GltfReader::localTransform(const tinygltf::Node& n, int index) const {
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

Status GltfReader::visit(int index, const glm::dmat4& parent, int parentNode, int depth, std::vector<char>& visited) {
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

// EXT_mesh_gpu_instancing: the node's instances' transforms (translation, rotation, scale per
// instance, any of them absent), each after the node's own; empty when the node has none.
Result<std::vector<glm::dmat4>> GltfReader::gpuInstances(const tinygltf::Node& n, int index) {
  const auto it = n.extensions.find("EXT_mesh_gpu_instancing");
  if (it == n.extensions.end()) return std::vector<glm::dmat4>{};
  const std::string where = "node " + std::to_string(index) + " EXT_mesh_gpu_instancing";
  const tinygltf::Value& attributes = it->second.Get("attributes");
  if (!attributes.IsObject()) return fail(where + " has no attributes");
  std::optional<AccessorView> streams[3];  // translation, rotation, scale
  const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
  std::size_t count = 0;
  for (int k = 0; k < 3; ++k) {
    if (!attributes.Has(names[k])) continue;
    const tinygltf::Value& a = attributes.Get(names[k]);
    if (!a.IsInt()) return fail(where + " " + names[k] + " is not an accessor index");
    Result<AccessorView> view = accessor(a.Get<int>(), where + " " + names[k], {k == 1 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3});
    if (!view) return Error{view.error()};
    if (count && view->count != count) return fail(where + ": " + names[k] + " has " + std::to_string(view->count) + " elements for " + std::to_string(count) + " instances");
    count = view->count;
    streams[k] = *view;
  }
  if (count > kMaxInstances) return fail(where + " has " + std::to_string(count) + " instances; at most " + std::to_string(kMaxInstances) + " are read");
  std::vector<glm::dmat4> out;
  out.reserve(count);
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < count; ++i) {
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat q(1.0, 0.0, 0.0, 0.0);
    if (streams[0]) t = {streams[0]->component(i, 0), streams[0]->component(i, 1), streams[0]->component(i, 2)};
    if (streams[1]) q = glm::dquat(streams[1]->component(i, 3), streams[1]->component(i, 0), streams[1]->component(i, 1), streams[1]->component(i, 2));
    if (streams[2]) s = {streams[2]->component(i, 0), streams[2]->component(i, 1), streams[2]->component(i, 2)};
    const double length = glm::length(q);
    const bool finiteAll = std::isfinite(t.x + t.y + t.z + s.x + s.y + s.z) && std::isfinite(length);
    if (!finiteAll || !(length > 1e-12)) {
      ++skipped;
      continue;
    }
    out.push_back(glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q / length) * glm::scale(glm::dmat4(1.0), s));
  }
  if (skipped) warn_.add(name_ + ": " + where + ": " + std::to_string(skipped) + " instance(s) with a non-finite or zero transform left out");
  if (out.empty()) warn_.add(name_ + ": " + where + ": no instance to draw");
  return out;
}

// Node `index`'s mesh: its primitives into the one mesh at its world transform (Flatten), or
// an object instancing the glTF mesh, built the first time a node uses it (Objects); a node
// with EXT_mesh_gpu_instancing places one object per instance.
Status GltfReader::mesh(const tinygltf::Node& n, int index, int node, const glm::dmat4& world) {
  Result<std::vector<glm::dmat4>> instances = gpuInstances(n, index);
  if (!instances) return Error{instances.error()};
  if (instances->empty() && n.extensions.count("EXT_mesh_gpu_instancing")) return okStatus();  // none to draw, said
  if (instances->empty()) instances->push_back(glm::dmat4(1.0));
  for (std::size_t i = 0; i < instances->size(); ++i)
    if (Status s = instance(n, index, node, world * (*instances)[i], (*instances)[i], instances->size() > 1 ? int(i) : -1); !s) return s;
  return okStatus();
}

// One placement of node `index`'s mesh: the node's world transform times `instance` (its
// EXT_mesh_gpu_instancing instance's, else the identity), numbered `number` (-1: the node's only).
Status GltfReader::instance(const tinygltf::Node& n, int index, int node, const glm::dmat4& world, const glm::dmat4& instance, int number) {
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
  if (mode_ == Mode::Objects && objects_.size() >= kMaxSceneObjects)
    return fail("the scene places more than " + std::to_string(kMaxSceneObjects) + " objects (its nodes and their instances)");
  std::string name = n.name.empty() ? (mesh.name.empty() ? "node " + std::to_string(index) : mesh.name) : n.name;
  if (number >= 0) name += " #" + std::to_string(number);
  // A skinned node's joints place it alone; else what follows the node is the instance's.
  objects_.push_back({printable(name), built->second.first, placement * mirror, node, skin >= 0 ? mirror : instance * mirror, skin});
  return okStatus();
}

Status GltfReader::primitive(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& where, Target& t) {
  PolygonSoup& soup = t.soup;
  if (prim.mode == TINYGLTF_MODE_POINTS || prim.mode == TINYGLTF_MODE_LINE || prim.mode == TINYGLTF_MODE_LINE_LOOP ||
      prim.mode == TINYGLTF_MODE_LINE_STRIP)
    return marks(prim, world, where, t);
  if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP && prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    warn_.add(name_ + ": " + where + " has mode " + std::to_string(prim.mode) + ", which glTF does not define; skipped");
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
  Result<std::optional<AccessorView>> read = this->indices(prim, where);
  if (!read) return Error{read.error()};
  const std::optional<AccessorView>& indices = *read;
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

}  // namespace npr::gltf
