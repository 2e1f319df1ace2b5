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
//
// This file: the input gate (tinygltf's file and image callbacks), the container's parse, and
// the two entry points.
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <limits>

#include "renderer/mesh/gltf/gltf_reader.h"

namespace npr {
namespace {
namespace fs = std::filesystem;
using gltf::GltfReader;

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
