// CPU tier: the glTF 2.0 reader (renderer/mesh/gltf_reader.cpp). Hostile files the tests
// write (each case refused with a message naming the file and what is wrong, never a crash or
// a hang), and the Khronos sample models Debian's assimp-testmodels ships.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/scene_loader.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::TempDir;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned v = bytes[i] << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) | (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += table[v >> 18 & 63];
    out += table[v >> 12 & 63];
    out += i + 1 < bytes.size() ? table[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return out;
}

// A buffer with a unit right triangle's three float positions (bytes 0..35) and the indices
// 0 1 2 as unsigned shorts (bytes 36..41, padded to 44).
std::vector<unsigned char> triangleBuffer(float z = 0.0f) {
  const float p[9] = {0, 0, z, 1, 0, z, 0, 1, z};
  const std::uint16_t idx[4] = {0, 1, 2, 0};
  std::vector<unsigned char> b(44);
  std::memcpy(b.data(), p, 36);
  std::memcpy(b.data() + 36, idx, 8);
  return b;
}

// A glTF document around that buffer; the pieces can be replaced to make each hostile case.
struct Doc {
  std::string accessors = R"([{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                              {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}])";
  std::string bufferViews = R"([{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}])";
  std::string nodes = R"([{"mesh":0}])";
  std::string scenes = R"([{"nodes":[0]}])";
  std::string meshes = R"([{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}])";
  std::string materials = "[]";
  std::string extra;
  std::vector<unsigned char> buffer = triangleBuffer();
  std::string text() const {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":)" + scenes + R"(,"nodes":)" + nodes + R"(,"meshes":)" + meshes +
           R"(,"materials":)" + materials + R"(,"accessors":)" + accessors + R"(,"bufferViews":)" + bufferViews +
           R"(,"buffers":[{"byteLength":)" + std::to_string(buffer.size()) +
           R"(,"uri":"data:application/octet-stream;base64,)" + base64(buffer) + R"("}])" + extra + "}";
  }
};

Result<Mesh> load(const TempDir& d, const Doc& doc, const std::string& name = "case.gltf") { return loadMesh(d.write(name, doc.text())); }

TEST(Gltf, AWrittenTriangleLoads) {
  TempDir d;
  auto m = load(d, Doc());
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 1u);
  EXPECT_EQ(m->positions.size(), 3u);
}

// Points and lines primitives become the mesh's marks, placed and normalised as its vertices
// are: a strip of the triangle's three corners is two segments, a loop three, LINES one (of
// three indices), POINTS three dots; a line strip with an index past the positions skips that
// segment, named. A file of only points and lines loads, its marks setting its bounds.
TEST(Gltf, PointsAndLinesBecomeTheMeshsDotsAndSegments) {
  TempDir d;
  Doc doc;
  doc.meshes = R"([{"primitives":[{"attributes":{"POSITION":0},"indices":1},
                                  {"attributes":{"POSITION":0},"mode":3},
                                  {"attributes":{"POSITION":0},"mode":2},
                                  {"attributes":{"POSITION":0},"indices":1,"mode":1},
                                  {"attributes":{"POSITION":0},"mode":0}]}])";
  auto m = load(d, doc);
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 1u);
  EXPECT_EQ(m->dots.size(), 3u);
  ASSERT_EQ(m->segments.size(), 2u * (2 + 3 + 1));
  // The strip's first segment runs from the first corner to the second, where the triangle's are.
  EXPECT_EQ(m->segments[0], m->positions[0]);
  EXPECT_EQ(m->segments[1], m->positions[1]);
  EXPECT_EQ(m->dots[2], m->positions[2]);
  // The loop closes: its last segment ends where it began.
  EXPECT_EQ(m->segments[2 * 4 + 1], m->segments[2 * 2]);

  // Lines alone, reaching five units past the triangle: they load, and widen the bounds.
  Doc lines;
  lines.buffer.resize(44 + 24);
  const float far[6] = {0, 0, 0, 5, 0, 0};
  std::memcpy(lines.buffer.data() + 44, far, 24);
  lines.accessors = R"([{"bufferView":0,"componentType":5126,"count":2,"type":"VEC3"}])";
  lines.bufferViews = R"([{"buffer":0,"byteOffset":44,"byteLength":24}])";
  lines.meshes = R"([{"primitives":[{"attributes":{"POSITION":0},"mode":1}]}])";
  auto only = load(d, lines, "lines.gltf");
  ASSERT_TRUE(only) << only.error();
  EXPECT_EQ(only->triangleCount(), 0u);
  ASSERT_EQ(only->segments.size(), 2u);
  EXPECT_NEAR(glm::length(only->segments[1] - only->segments[0]), 2.0f, 1e-4f) << "the marks are not normalised with the model";

  // A strip indexing past its three positions: the two segments touching the bad index are skipped, named.
  Doc bad;
  bad.accessors = R"([{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                      {"bufferView":1,"componentType":5123,"count":4,"type":"SCALAR"}])";
  bad.bufferViews = R"([{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":8}])";
  bad.buffer = triangleBuffer();
  const std::uint16_t idx[4] = {0, 1, 7, 2};
  std::memcpy(bad.buffer.data() + 36, idx, 8);
  bad.meshes = R"([{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":3}]}])";
  auto skipped = load(d, bad, "bad.gltf");
  ASSERT_TRUE(skipped) << skipped.error();
  EXPECT_EQ(skipped->segments.size(), 2u);
  bool named = false;
  for (const std::string& w : skipped->report.warnings) named |= contains(w, "2 line segment(s) with an index past its 3 positions");
  EXPECT_TRUE(named) << "the skipped segments are not reported";
}

// Khronos' glTF-Asset-Generator primitive modes (assimp-testmodels): points, lines, a line
// loop and a line strip, each a square's outline with no faces, load as marks.
TEST(Gltf, KhronosPointAndLineModesLoadAsMarks) {
  const std::string dir = "/usr/share/assimp/models/glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/";
  const struct {
    const char* file;
    std::size_t dots, segments;
  } cases[] = {{"Mesh_PrimitiveMode_00.gltf", 1024, 0}, {"Mesh_PrimitiveMode_01.gltf", 0, 4}, {"Mesh_PrimitiveMode_02.gltf", 0, 4}, {"Mesh_PrimitiveMode_03.gltf", 0, 4}};
  for (const auto& c : cases) {
    auto m = loadMesh(dir + c.file);
    ASSERT_TRUE(m) << c.file << ": " << m.error();
    EXPECT_EQ(m->dots.size(), c.dots) << c.file;
    EXPECT_EQ(m->segments.size() / 2, c.segments) << c.file;
  }
}

TEST(Gltf, NodeTransformsPlaceTheMeshesAndMirroringKeepsTheWinding) {
  TempDir d;
  // Two instances of the triangle, one moved 10 along x and one mirrored in x: the flattened
  // mesh spans both, and both face +z (the mirror reverses the winding back).
  Doc doc;
  doc.nodes = R"([{"children":[1,2]},{"mesh":0,"translation":[10,0,0]},{"mesh":0,"scale":[-1,1,1]}])";
  auto m = load(d, doc);
  ASSERT_TRUE(m) << m.error();
  ASSERT_EQ(m->triangleCount(), 2u);
  for (const glm::vec3& n : m->faceNormals) EXPECT_GT(n.z, 0.99f) << "a triangle faces away";
  float minX = 1e9f, maxX = -1e9f;
  for (const glm::vec3& p : m->positions) minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
  // Normalised to the unit sphere: x spans -1..11 in the file, 12 units, about 2 radii here.
  EXPECT_GT(maxX - minX, 1.9f);
}

TEST(Gltf, HostileFilesAreRefusedWithAMessageNamingWhatIsWrong) {
  struct Case {
    const char* what;
    std::function<void(Doc&)> edit;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {"accessor past its buffer view", [](Doc& d) { d.accessors = R"([{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}])"; },
       "run past its buffer view"},
      {"buffer view past its buffer", [](Doc& d) { d.bufferViews = R"([{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":600}])"; },
       "runs past its buffer"},
      {"missing buffer", [](Doc& d) { d.bufferViews = R"([{"buffer":3,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}])"; },
       "buffer 3, which does not exist"},
      {"absurd count", [](Doc& d) { d.accessors = R"([{"bufferView":0,"componentType":5126,"count":4000000000,"type":"VEC3"},{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}])"; },
       "elements from byte"},
      {"a missing node", [](Doc& d) { d.scenes = R"([{"nodes":[7]}])"; }, "node 7 does not exist"},
      {"NaN in a matrix", [](Doc& d) { d.nodes = R"([{"mesh":0,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1e999]}])"; }, ""},
      {"a missing mesh", [](Doc& d) { d.nodes = R"([{"mesh":5}])"; }, "mesh 5, which does not exist"},
      {"a missing accessor", [](Doc& d) { d.meshes = R"([{"primitives":[{"attributes":{"POSITION":9}}]}])"; }, "accessor 9) does not exist"},
      {"positions of the wrong type", [](Doc& d) { d.meshes = R"([{"primitives":[{"attributes":{"POSITION":1}}]}])"; }, "wrong type"},
      {"signed indices", [](Doc& d) { d.accessors = R"([{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},{"bufferView":1,"componentType":5122,"count":3,"type":"SCALAR"}])"; },
       "unsigned integers"},
      // tinygltf reads a non-array "nodes" as no nodes: the scene then names a missing one.
      {"wrong JSON types", [](Doc& d) { d.nodes = R"({"mesh":"zero"})"; }, "node 0 does not exist"},
      {"a string where a number belongs", [](Doc& d) { d.accessors = R"([{"bufferView":0,"componentType":"float","count":3,"type":"VEC3"},{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}])"; }, "glTF"},
      {"a stride past the element", [](Doc& d) { d.bufferViews = R"([{"buffer":0,"byteOffset":0,"byteLength":36,"byteStride":4},{"buffer":0,"byteOffset":36,"byteLength":6}])"; },
       ""},
      {"a required extension", [](Doc& d) { d.extra = R"(,"extensionsRequired":["KHR_draco_mesh_compression"],"extensionsUsed":["KHR_draco_mesh_compression"])"; },
       "requires the extension KHR_draco_mesh_compression"},
  };
  TempDir d;
  for (const Case& c : cases) {
    Doc doc;
    c.edit(doc);
    auto m = load(d, doc, "hostile.gltf");
    ASSERT_FALSE(m) << c.what << ": loaded " << m->triangleCount() << " triangles";
    EXPECT_TRUE(contains(m.error(), "hostile.gltf")) << c.what << ": " << m.error();
    EXPECT_TRUE(contains(m.error(), c.expected)) << c.what << ": " << m.error();
  }
  // A cycle in the node hierarchy (or a node its own child) is named, and the nodes it does
  // not repeat still load.
  for (const char* nodes : {R"([{"mesh":0,"children":[1]},{"children":[0]}])", R"([{"mesh":0,"children":[0]}])"}) {
    Doc cyclic;
    cyclic.nodes = nodes;
    auto m = load(d, cyclic, "cyclic.gltf");
    ASSERT_TRUE(m) << m.error();
    EXPECT_EQ(m->triangleCount(), 1u);
    bool named = false;
    for (const std::string& w : m->report.warnings) named = named || contains(w, "node 0 is reached twice");
    EXPECT_TRUE(named) << nodes;
  }
}

TEST(Gltf, IndicesOutOfRangeSkipTheirTrianglesNamed) {
  TempDir d;
  Doc doc;
  doc.buffer = triangleBuffer();
  const std::uint16_t bad[3] = {0, 1, 7};
  std::memcpy(doc.buffer.data() + 36, bad, 6);
  auto m = load(d, doc);
  ASSERT_FALSE(m);  // its only triangle is refused: nothing to draw
  EXPECT_TRUE(contains(m.error(), "no faces") || contains(m.error(), "nothing to draw")) << m.error();
}

TEST(Gltf, NonFinitePositionsSkipTheirFaces) {
  TempDir d;
  Doc doc;
  doc.buffer = triangleBuffer(std::nanf(""));
  auto m = load(d, doc);
  ASSERT_FALSE(m);
}

TEST(Gltf, AnImageViewPastItsBufferIsRefusedNotRead) {
  // Found by fuzz_gltf: tinygltf handed the image callback a view's bytes unchecked (a heap
  // overflow under ASan). The view is now checked before a byte is copied.
  auto m = loadMesh(std::string(NPR_SOURCE_DIR) + "/tests/fuzz/regressions/gltf/glb-image-view-past-its-buffer.glb");
  if (!m) {
    EXPECT_TRUE(contains(m.error(), "glb-image-view-past-its-buffer.glb")) << m.error();
  }
}

const std::string kSamples = "/usr/share/assimp/models/glTF2/";

TEST(Gltf, KhronosBoxTexturedLoadsFromEveryContainer) {
  for (const char* file : {"BoxTextured-glTF-Binary/BoxTextured.glb", "BoxTextured-glTF/BoxTextured.gltf",
                           "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    auto m = loadMesh(kSamples + file);
    ASSERT_TRUE(m) << file << ": " << m.error();
    EXPECT_EQ(m->triangleCount(), 12u) << file;
    EXPECT_EQ(m->report.textures_loaded.size(), 1u) << file;
    EXPECT_EQ(m->textures.size(), 1u) << file;
    EXPECT_TRUE(m->report.texture_coordinates) << file;
    ASSERT_FALSE(m->materials.empty());
    EXPECT_EQ(m->materials.front().diffuseMap, 0) << file;
  }
}

TEST(Gltf, KhronosBrokenSamplesAreRefusedOrReadWithWarnings) {
  // Each either loads (with what it could read) or is refused with a message; none crashes.
  for (const char* file : {"RecursiveNodes/RecursiveNodes.gltf", "IndexOutOfRange/IndexOutOfRange.gltf",
                           "IndexOutOfRange/AllIndicesOutOfRange.gltf", "MissingBin/BoxTextured.gltf",
                           "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "wrongTypes/badArray.gltf",
                           "wrongTypes/badNumber.gltf", "wrongTypes/badObject.gltf", "wrongTypes/badString.gltf",
                           "wrongTypes/badUint.gltf", "wrongTypes/badExtension.gltf", "SchemaFailures/sceneWrongType.gltf",
                           "IncorrectVertexArrays/Cube.gltf", "issue_3269/texcoord_crash.gltf", "draco/2CylinderEngine.gltf",
                           "TestNoRootNode/NoScene.gltf", "TestNoRootNode/SceneWithoutNodes.gltf"}) {
    auto m = loadMesh(kSamples + file);
    if (!m) {
      EXPECT_TRUE(contains(m.error(), file)) << file << ": " << m.error();
    }
  }
  auto recursive = loadMesh(kSamples + "RecursiveNodes/RecursiveNodes.gltf");
  ASSERT_FALSE(recursive);  // nothing but the cycle: nothing to draw, and the cycle named
  EXPECT_TRUE(contains(recursive.error(), "reached twice")) << recursive.error();
  auto missing = loadMesh(kSamples + "MissingBin/BoxTextured.gltf");
  ASSERT_FALSE(missing);
  EXPECT_TRUE(contains(missing.error(), "BoxTextured0.bin") || contains(missing.error(), ".bin")) << missing.error();
}

TEST(Gltf, AlphaModesBecomeMasksAndScreenDoorBlends) {
  TempDir d;
  auto withMaterial = [&](const std::string& material) {
    Doc doc;
    doc.materials = "[" + material + "]";
    doc.meshes = R"([{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}])";
    return load(d, doc);
  };
  auto mask = withMaterial(R"({"alphaMode":"MASK","alphaCutoff":0.3,"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.2]}})");
  ASSERT_TRUE(mask) << mask.error();
  ASSERT_FALSE(mask->materials.empty());
  EXPECT_EQ(mask->materials[0].alpha, MeshMaterial::Alpha::Mask);
  EXPECT_FLOAT_EQ(mask->materials[0].alphaCutoff, 0.3f);
  EXPECT_TRUE(mask->seeThrough);  // alpha 0.2 under a cutoff of 0.3: cut away whole
  EXPECT_TRUE(mask->report.warnings.empty());
  auto kept = withMaterial(R"({"alphaMode":"MASK","pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.6]}})");
  ASSERT_TRUE(kept) << kept.error();
  EXPECT_FLOAT_EQ(kept->materials[0].alphaCutoff, 0.5f);  // the specification's default
  EXPECT_FALSE(kept->seeThrough);  // 0.6 reaches 0.5 everywhere: nothing is cut, drawn as opaque
  auto blend = withMaterial(R"({"alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.4]}})");
  ASSERT_TRUE(blend) << blend.error();
  EXPECT_EQ(blend->materials[0].alpha, MeshMaterial::Alpha::Blend);
  EXPECT_FLOAT_EQ(blend->materials[0].opacity, 0.4f);
  EXPECT_TRUE(blend->seeThrough);
  auto opaque = withMaterial(R"({"alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1]}})");
  ASSERT_TRUE(opaque) << opaque.error();
  EXPECT_FALSE(opaque->seeThrough);  // a blend at full opacity without a map covers every pixel
  auto odd = withMaterial(R"({"alphaMode":"GLASS\u0007"})");
  ASSERT_TRUE(odd) << odd.error();
  EXPECT_EQ(odd->materials[0].alpha, MeshMaterial::Alpha::Opaque);
  ASSERT_EQ(odd->report.warnings.size(), 1u);
  EXPECT_TRUE(contains(odd->report.warnings[0], "unknown alphaMode 'GLASS")) << odd->report.warnings[0];
  EXPECT_FALSE(contains(odd->report.warnings[0], "\a")) << "a control character printed raw";
}

TEST(Gltf, TextureTransformMovesTheCoordinates) {
  auto m = loadMesh(kSamples + "textureTransform/TextureTransformTest.gltf");
  ASSERT_TRUE(m) << m.error();
  ASSERT_TRUE(m->report.texture_coordinates);
  // The sample's planes use offsets, rotations and scales: the coordinates leave 0..1.
  bool outside = false;
  for (const glm::vec2& t : m->texcoords) outside = outside || t.x < -0.01f || t.x > 1.01f || t.y < -0.01f || t.y > 1.01f;
  EXPECT_TRUE(outside);
}

// ---------------------------------------------------------------------------------------
// The file as a scene (parseGltfScene through loadScene): objects, cameras, lights.

Result<LoadedScene> loadAsScene(const TempDir& d, const Doc& doc, const std::string& name = "scene.gltf") {
  return loadScene(d.write(name, doc.text()));
}

// The object's mesh put back where its file had it.
std::vector<glm::vec3> placed(const SceneObject& o) {
  std::vector<glm::vec3> out;
  for (const glm::vec3& p : o.mesh->positions) out.push_back(glm::vec3(o.transform * glm::vec4(p, 1.0f)));
  return out;
}

bool near(const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-4f; }

// EXT_mesh_gpu_instancing (required by the file): a node of three instances becomes three
// objects sharing one mesh, each placed by the node's transform times its instance's
// (translation and scale); the file flattened has the three copies. Instances whose streams
// disagree in count are refused, named; a non-finite one is left out, named.
TEST(GltfScene, GpuInstancesBecomeObjectsPlacedByNodeTimesInstance) {
  TempDir d;
  Doc doc;
  doc.buffer.resize(44 + 72);
  const float translations[9] = {0, 0, 0, 5, 0, 0, 0, 5, 0};
  const float scales[9] = {1, 1, 1, 2, 2, 2, 1, 3, 1};
  std::memcpy(doc.buffer.data() + 44, translations, 36);
  std::memcpy(doc.buffer.data() + 80, scales, 36);
  doc.accessors = R"([{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                      {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},
                      {"bufferView":2,"componentType":5126,"count":3,"type":"VEC3"},
                      {"bufferView":3,"componentType":5126,"count":3,"type":"VEC3"},
                      {"bufferView":3,"componentType":5126,"count":2,"type":"VEC3"}])";
  doc.bufferViews = R"([{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6},
                        {"buffer":0,"byteOffset":44,"byteLength":36},{"buffer":0,"byteOffset":80,"byteLength":36}])";
  doc.nodes = R"([{"name":"grid","mesh":0,"translation":[10,0,0],
                   "extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":2,"SCALE":3}}}}])";
  doc.extra = R"(,"extensionsUsed":["EXT_mesh_gpu_instancing"],"extensionsRequired":["EXT_mesh_gpu_instancing"])";
  auto s = loadAsScene(d, doc);
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->objects.size(), 3u);
  EXPECT_EQ(s->objects[1].name, "grid #1");
  EXPECT_EQ(s->objects[0].mesh.get(), s->objects[2].mesh.get());
  const glm::vec3 file[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::vector<glm::vec3> at = placed(s->objects[k]);
    const glm::vec3 t(translations[3 * k], translations[3 * k + 1], translations[3 * k + 2]);
    const glm::vec3 sc(scales[3 * k], scales[3 * k + 1], scales[3 * k + 2]);
    for (const glm::vec3& want : file) {
      const glm::vec3 p = glm::vec3(10, 0, 0) + t + sc * want;
      bool found = false;
      for (const glm::vec3& q : at) found = found || near(q, p);
      EXPECT_TRUE(found) << "instance " << k << " lacks " << p.x << ", " << p.y << ", " << p.z;
    }
  }
  auto flat = load(d, doc, "flat.gltf");
  ASSERT_TRUE(flat) << flat.error();
  EXPECT_EQ(flat->triangleCount(), 3u);

  Doc mismatched = doc;
  mismatched.nodes = R"([{"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":{"attributes":{"TRANSLATION":2,"SCALE":4}}}}])";
  auto refused = loadAsScene(d, mismatched, "mismatched.gltf");
  ASSERT_FALSE(refused);
  EXPECT_TRUE(contains(refused.error(), "SCALE has 2 elements for 3 instances")) << refused.error();

  Doc nonFinite = doc;
  const float inf = INFINITY;
  std::memcpy(nonFinite.buffer.data() + 44 + 12, &inf, 4);
  auto two = loadAsScene(d, nonFinite, "nonfinite.gltf");
  ASSERT_TRUE(two) << two.error();
  EXPECT_EQ(two->objects.size(), 2u);
  bool named = false;
  for (const std::string& w : two->warnings) named |= contains(w, "1 instance(s) with a non-finite or zero transform left out");
  EXPECT_TRUE(named) << "the left-out instance is not reported";
}

TEST(GltfScene, NodesBecomeObjectsSharingTheirMeshPlacedAsInTheFile) {
  TempDir d;
  Doc doc;
  doc.nodes = R"([{"name":"left","mesh":0,"translation":[10,0,0]},{"mesh":0,"children":[2]},{"name":"child","mesh":0,"translation":[0,0,-3]}])";
  doc.scenes = R"([{"nodes":[0,1]}])";
  auto s = loadAsScene(d, doc);
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->objects.size(), 3u);
  EXPECT_EQ(s->objects[0].name, "left");
  EXPECT_EQ(s->objects[1].name, "node 1");
  EXPECT_EQ(s->objects[2].name, "child");
  // One glTF mesh instanced three times: one Mesh.
  EXPECT_EQ(s->objects[0].mesh.get(), s->objects[1].mesh.get());
  EXPECT_EQ(s->objects[1].mesh.get(), s->objects[2].mesh.get());
  const glm::vec3 file[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const glm::vec3 offset[3] = {{10, 0, 0}, {0, 0, 0}, {0, 0, -3}};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::vector<glm::vec3> at = placed(s->objects[k]);
    ASSERT_EQ(at.size(), 3u);
    for (const glm::vec3& want : file) {
      bool found = false;
      for (const glm::vec3& p : at) found = found || near(p, want + offset[k]);
      EXPECT_TRUE(found) << "object " << k << " lacks the file's vertex at " << want.x + offset[k].x << ", " << want.y << ", " << want.z + offset[k].z;
    }
  }
  EXPECT_EQ(s->report.triangles, 3u);
  // The same file flattened has the same triangles.
  auto flat = load(d, doc, "flat.gltf");
  ASSERT_TRUE(flat) << flat.error();
  EXPECT_EQ(flat->triangleCount(), s->report.triangles);
}

TEST(GltfScene, AMirroringNodeGetsAMirroredMeshAndAnUnmirroredTransform) {
  TempDir d;
  Doc doc;
  doc.nodes = R"([{"mesh":0,"scale":[-1,1,1]},{"mesh":0,"translation":[3,0,0]}])";
  doc.scenes = R"([{"nodes":[0,1]}])";
  auto s = loadAsScene(d, doc);
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->objects.size(), 2u);
  EXPECT_NE(s->objects[0].mesh.get(), s->objects[1].mesh.get()) << "the mirrored instance needs a mesh of its own";
  for (const SceneObject& o : s->objects) {
    EXPECT_GT(glm::determinant(glm::mat3(o.transform)), 0.0f) << o.name;
    // Its triangle, placed, faces +z as in the file (the mirror reverses the winding back).
    const std::vector<glm::vec3> p = placed(o);
    const std::uint32_t* i = o.mesh->indices.data();
    EXPECT_GT(glm::cross(p[i[1]] - p[i[0]], p[i[2]] - p[i[0]]).z, 0.0f) << o.name;
  }
  bool mirroredVertex = false;
  for (const glm::vec3& p : placed(s->objects[0])) mirroredVertex = mirroredVertex || near(p, {-1, 0, 0});
  EXPECT_TRUE(mirroredVertex);
}

TEST(GltfScene, CamerasAndLightsArePlacedByTheirNodesAndMalformedOnesNamed) {
  TempDir d;
  Doc doc;
  doc.nodes = R"([{"mesh":0},{"camera":0,"translation":[0,0,5]},{"camera":1},{"translation":[0,4,0],"extensions":{"KHR_lights_punctual":{"light":0}}},
                  {"extensions":{"KHR_lights_punctual":{"light":1}}},{"extensions":{"KHR_lights_punctual":{"light":7}}}])";
  doc.scenes = R"([{"nodes":[0,1,2,3,4,5]}])";
  doc.extra = R"(,"cameras":[{"type":"perspective","name":"front","perspective":{"yfov":0.6,"znear":0.1,"zfar":50}},
                             {"type":"perspective","perspective":{"yfov":0,"znear":0.1}}],
                 "extensionsUsed":["KHR_lights_punctual"],
                 "extensions":{"KHR_lights_punctual":{"lights":[{"type":"spot","name":"key","intensity":20,"color":[1,0.5,0.25],"spot":{"outerConeAngle":0.5}},
                                                                 {"type":"point","intensity":-3}]}})";
  auto s = loadAsScene(d, doc);
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->cameras.size(), 1u);
  EXPECT_EQ(s->cameras[0].name, "front");
  EXPECT_FLOAT_EQ(s->cameras[0].yfov, 0.6f);
  EXPECT_TRUE(near(glm::vec3(s->cameras[0].world[3]), {0, 0, 5}));
  ASSERT_EQ(s->lights.size(), 1u);
  EXPECT_EQ(s->lights[0].name, "key");
  EXPECT_EQ(s->lights[0].type, SceneLight::Type::Spot);
  EXPECT_FLOAT_EQ(s->lights[0].intensity, 20.0f);
  EXPECT_FLOAT_EQ(s->lights[0].outerCone, 0.5f);
  EXPECT_TRUE(near(s->lights[0].colour, {1, 0.5f, 0.25f}));
  EXPECT_TRUE(near(glm::vec3(s->lights[0].world[3]), {0, 4, 0}));
  std::string all;
  for (const std::string& w : s->warnings) all += w + "\n";
  EXPECT_TRUE(contains(all, "camera 1 is malformed")) << all;
  EXPECT_TRUE(contains(all, "light 1 of KHR_lights_punctual is malformed")) << all;
  EXPECT_TRUE(contains(all, "names light 7, which does not exist")) << all;
  // The report lists them.
  const std::string json = sceneReportJson(*s);
  EXPECT_TRUE(contains(json, R"("cameras":[{"name":"front","type":"perspective")")) << json;
  EXPECT_TRUE(contains(json, R"("lights":[{"name":"key","type":"spot")")) << json;
}

TEST(GltfScene, KhronosEngineIsItsPartsWithTheFlattenedTrianglesAndMaterials) {
  const std::string file = kSamples + "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  auto s = loadScene(file);
  ASSERT_TRUE(s) << s.error();
  // Flattened (one load of the engine for both checks: it is the slowest file of the suite
  // under the sanitizers): all its parts and materials in one mesh.
  auto flat = loadMesh(file);
  ASSERT_TRUE(flat) << flat.error();
  EXPECT_GT(flat->triangleCount(), 100000u);
  EXPECT_GE(flat->report.materials, 2u);
  EXPECT_FALSE(flat->faceMaterials.empty());
  EXPECT_GT(s->objects.size(), 20u);
  EXPECT_EQ(s->report.triangles, flat->triangleCount());
  std::size_t textured = 0;
  for (const SceneObject& o : s->objects) textured += o.mesh->materials.size();
  EXPECT_GE(textured, s->objects.size()) << "every part keeps its material";
  // Each part carries only the materials it uses.
  for (const SceneObject& o : s->objects) EXPECT_LE(o.mesh->materials.size(), 3u) << o.name;
}

TEST(GltfScene, AnotherFormatIsOneObjectPlacedAsInItsFile) {
  TempDir d;
  const std::string obj = d.write("moved.obj", "v 10 0 0\nv 12 0 0\nv 10 2 0\nf 1 2 3\n");
  auto s = loadScene(obj);
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->objects.size(), 1u);
  EXPECT_EQ(s->objects[0].name, "moved");
  bool found = false;
  for (const glm::vec3& p : placed(s->objects[0])) found = found || near(p, {12, 0, 0});
  EXPECT_TRUE(found);
}

TEST(SceneLoader, ObjGroupsBecomeObjectsWithOnlyWhatTheyUse) {
  TempDir d;
  d.write("two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  const std::string obj = d.write("groups.obj",
                                  "mtllib two.mtl\n"
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\nv 1 1 0\n"
                                  "f 1 2 3\n"                   // before any group
                                  "o left\nusemtl red\nf 1 2 7\n"
                                  "g right\nusemtl blue\nf 4 5 6\n"
                                  "o left\nf 1 7 3\n");         // continues 'left'
  auto s = loadScene(obj, SceneLoadOptions{true});
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->objects.size(), 3u);
  EXPECT_EQ(s->objects[0].name, "(no group)");
  EXPECT_EQ(s->objects[1].name, "left");
  EXPECT_EQ(s->objects[2].name, "right");
  EXPECT_EQ(s->objects[1].mesh->triangleCount(), 2u);
  EXPECT_EQ(s->objects[2].mesh->triangleCount(), 1u);
  EXPECT_EQ(s->report.triangles, 4u);
  // Each keeps only the materials its faces use (OBJ's usemtl lasts across groups: 'left''s
  // last face is blue).
  ASSERT_EQ(s->objects[2].mesh->materials.size(), 1u);
  EXPECT_EQ(s->objects[2].mesh->materials[0].name, "blue");
  ASSERT_EQ(s->objects[1].mesh->materials.size(), 2u);
  EXPECT_EQ(s->objects[1].mesh->materials[0].name, "red");
  EXPECT_EQ(s->objects[1].mesh->materials[1].name, "blue");
  ASSERT_EQ(s->objects[0].mesh->materials.size(), 1u);
  EXPECT_EQ(s->objects[0].mesh->materials[0].name, "(default)");
  // Placed back where the file had them.
  bool found = false;
  for (const glm::vec3& p : placed(s->objects[2])) found = found || near(p, {6, 0, 0});
  EXPECT_TRUE(found);
  for (const glm::vec3& p : placed(s->objects[1])) EXPECT_LT(p.x, 1.01f);
  // Without the option: one object of all four triangles.
  auto whole = loadScene(obj);
  ASSERT_TRUE(whole) << whole.error();
  ASSERT_EQ(whole->objects.size(), 1u);
  EXPECT_EQ(whole->objects[0].mesh->triangleCount(), 4u);
}

// The triangle's document with an animation of node 0 ("mover", a child of node 1 at x = 5):
// keyframe times at buffer byte 44 (accessor 2), values after them (accessor 3). `times` and
// `values` as floats; the sampler's interpolation and the channel's path replaceable.
struct AnimatedDoc : Doc {
  AnimatedDoc(std::vector<float> times, std::vector<float> values, int valueComponents, const std::string& path = "translation",
              const std::string& interpolation = "LINEAR") {
    const std::size_t t0 = buffer.size(), v0 = t0 + 4 * times.size();
    buffer.resize(v0 + 4 * values.size());
    std::memcpy(buffer.data() + t0, times.data(), 4 * times.size());
    std::memcpy(buffer.data() + v0, values.data(), 4 * values.size());
    const char* type = valueComponents == 4 ? "VEC4" : "VEC3";
    accessors = R"([{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                    {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},
                    {"bufferView":2,"componentType":5126,"count":)" + std::to_string(times.size()) + R"(,"type":"SCALAR"},
                    {"bufferView":3,"componentType":5126,"count":)" + std::to_string(values.size() / valueComponents) + R"(,"type":")" + type + R"("}])";
    bufferViews = R"([{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6},
                      {"buffer":0,"byteOffset":)" + std::to_string(t0) + R"(,"byteLength":)" + std::to_string(4 * times.size()) + R"(},
                      {"buffer":0,"byteOffset":)" + std::to_string(v0) + R"(,"byteLength":)" + std::to_string(4 * values.size()) + "}]";
    nodes = R"([{"name":"mover","mesh":0},{"name":"parent","translation":[5,0,0],"children":[0]},{"name":"still","mesh":0,"translation":[0,0,-4]}])";
    scenes = R"([{"nodes":[1,2]}])";
    channel = R"({"sampler":0,"target":{"node":0,"path":")" + path + R"("}})";
    sampler = R"({"input":2,"output":3,"interpolation":")" + interpolation + R"("})";
  }
  std::string channel, sampler;
  std::string withAnimation() {
    extra = R"(,"animations":[{"name":"slide","channels":[)" + channel + R"(],"samplers":[)" + sampler + "]}]";
    return text();
  }
};

TEST(GltfScene, AnimationsAreReadWithTheNodesTheyMove) {
  TempDir d;
  AnimatedDoc doc({0.0f, 2.0f}, {0, 0, 0, 4, 0, 0}, 3);
  auto s = loadScene(d.write("anim.gltf", doc.withAnimation()));
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->animations.size(), 1u);
  EXPECT_EQ(s->animations[0].name, "slide");
  EXPECT_FLOAT_EQ(s->animations[0].end, 2.0f);
  ASSERT_EQ(s->nodes.size(), 3u);
  // Parents first: the parent, its child, the second root.
  EXPECT_EQ(s->nodes[0].name, "parent");
  EXPECT_EQ(s->nodes[1].parent, 0);
  ASSERT_EQ(s->objects.size(), 2u);
  const SceneObject& mover = s->objects[0];
  EXPECT_EQ(mover.name, "mover");
  ASSERT_EQ(mover.node, 1);
  EXPECT_EQ(s->animations[0].channels[0].node, 1);
  // The rest pose is the object's transform; posed at t = 1 it has slid 2 along x.
  NodePose pose;
  poseNodes(s->nodes, {}, 0.0f, pose);
  const glm::mat4 rest = pose.world[1] * mover.afterNode;
  for (int c = 0; c < 4; ++c) EXPECT_TRUE(near(glm::vec3(rest[c]), glm::vec3(mover.transform[c])));
  poseNodes(s->nodes, {&s->animations[0]}, 1.0f, pose);
  const glm::vec3 moved = glm::vec3((pose.world[1] * mover.afterNode)[3]) - glm::vec3(mover.transform[3]);
  EXPECT_TRUE(near(moved, {2, 0, 0})) << moved.x << " " << moved.y << " " << moved.z;
  EXPECT_EQ(s->objects[1].node, 2);
  // --info lists it.
  EXPECT_TRUE(contains(sceneReportJson(*s), R"("animations":[{"name":"slide","start":0,"end":2,"channels":1}])")) << sceneReportJson(*s);
}

TEST(GltfScene, BadAnimationDataIsRefusedNamedAndTheSceneStillLoadsStill) {
  struct Case {
    const char* what;
    std::function<void(AnimatedDoc&)> spoil;
    std::vector<float> times;
    std::vector<float> values;
    int components;
    std::string expect;
  };
  const std::vector<float> xyz = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  const std::vector<Case> cases = {
      {"times not increasing", [](AnimatedDoc&) {}, {0.0f, 1.0f, 1.0f}, xyz, 3, "keyframe times do not increase"},
      {"NaN time", [](AnimatedDoc&) {}, {0.0f, NAN, 2.0f}, xyz, 3, "keyframe time 1 is not finite"},
      {"counts disagree", [](AnimatedDoc&) {}, {0.0f, 1.0f}, xyz, 3, "2 keyframe times but 3 values"},
      {"cubic counts", [](AnimatedDoc& d) { d.sampler = R"({"input":2,"output":3,"interpolation":"CUBICSPLINE"})"; }, {0.0f, 1.0f, 2.0f}, xyz, 3,
       "a cubic spline needs three per time"},
      {"NaN value", [](AnimatedDoc&) {}, {0.0f, 1.0f, 2.0f}, {0, 0, 0, NAN, 0, 0, 2, 0, 0}, 3, "value 1 is not finite"},
      {"node missing", [](AnimatedDoc& d) { d.channel = R"({"sampler":0,"target":{"node":9,"path":"translation"}})"; }, {0.0f, 1.0f, 2.0f}, xyz, 3,
       "names node 9, which does not exist"},
      {"sampler missing", [](AnimatedDoc& d) { d.channel = R"({"sampler":4,"target":{"node":0,"path":"translation"}})"; }, {0.0f, 1.0f, 2.0f}, xyz, 3,
       "names sampler 4"},
      {"matrix node", [](AnimatedDoc& d) { d.nodes = R"([{"mesh":0,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]},{"translation":[5,0,0],"children":[0]},{"mesh":0}])"; },
       {0.0f, 1.0f, 2.0f}, xyz, 3, "given by a matrix"},
      {"interpolation", [](AnimatedDoc& d) { d.sampler = R"({"input":2,"output":3,"interpolation":"BOUNCY"})"; }, {0.0f, 1.0f, 2.0f}, xyz, 3,
       "interpolation 'BOUNCY'"},
      {"rotation as vec3", [](AnimatedDoc& d) { d.channel = R"({"sampler":0,"target":{"node":0,"path":"rotation"}})"; }, {0.0f, 1.0f, 2.0f}, xyz, 3,
       "has the wrong type"},
      {"zero quaternion", [](AnimatedDoc& d) { d.channel = R"({"sampler":0,"target":{"node":0,"path":"rotation"}})"; }, {0.0f, 1.0f},
       {0, 0, 0, 1, 0, 0, 0, 0}, 4, "zero quaternion"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d;
    AnimatedDoc doc(c.times, c.values, c.components);
    c.spoil(doc);
    auto s = loadScene(d.write("bad.gltf", doc.withAnimation()));
    ASSERT_TRUE(s) << s.error();  // the scene loads ...
    EXPECT_EQ(s->objects.size(), 2u);
    EXPECT_TRUE(s->animations.empty());  // ... without the animation, named in a warning
    bool named = false;
    for (const std::string& w : s->warnings) named = named || (contains(w, "bad.gltf: animation 0 'slide' is not played") && contains(w, c.expect));
    EXPECT_TRUE(named) << "no warning naming '" << c.expect << "'";
  }
}

// The triangle skinned to two joint nodes: JOINTS_0 (unsigned bytes, buffer byte 44) and
// WEIGHTS_0 (floats, byte 56), and two inverse bind matrices (byte 104). `joints` and
// `weights` give each vertex's first two influences.
struct SkinnedDoc : Doc {
  SkinnedDoc(const std::vector<std::uint8_t>& joints, const std::vector<float>& weights, int inverseBindMatrices = 2) {
    buffer.resize(104 + 128, 0);
    for (std::size_t v = 0; v < 3; ++v) {
      buffer[44 + 4 * v] = joints[2 * v];
      buffer[44 + 4 * v + 1] = joints[2 * v + 1];
      const float w[4] = {weights[2 * v], weights[2 * v + 1], 0.0f, 0.0f};
      std::memcpy(buffer.data() + 56 + 16 * v, w, 16);
    }
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    std::memcpy(buffer.data() + 104, identity, 64);
    std::memcpy(buffer.data() + 168, identity, 64);
    accessors = R"([{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
                    {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},
                    {"bufferView":2,"componentType":5121,"count":3,"type":"VEC4"},
                    {"bufferView":3,"componentType":5126,"count":3,"type":"VEC4"},
                    {"bufferView":4,"componentType":5126,"count":)" + std::to_string(inverseBindMatrices) + R"(,"type":"MAT4"}])";
    bufferViews = R"([{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6},
                      {"buffer":0,"byteOffset":44,"byteLength":12},{"buffer":0,"byteOffset":56,"byteLength":48},
                      {"buffer":0,"byteOffset":104,"byteLength":128}])";
    meshes = R"([{"primitives":[{"attributes":{"POSITION":0,"JOINTS_0":2,"WEIGHTS_0":3},"indices":1}]}])";
    nodes = R"([{"name":"skinned","mesh":0,"skin":0,"translation":[100,0,0]},{"name":"root","children":[2]},{"name":"tip","translation":[0,0,1]}])";
    scenes = R"([{"nodes":[0,1]}])";
    extra = R"(,"skins":[{"joints":[1,2],"inverseBindMatrices":4}])";
  }
};

TEST(GltfScene, SkinsAreReadWithTheirJointsAndTheSkinnedNodesOwnTransformIgnored) {
  TempDir d;
  // Vertex 0 on the root, vertex 1 on the tip, vertex 2 half and half.
  SkinnedDoc doc({0, 0, 1, 0, 0, 1}, {1, 0, 1, 0, 0.5f, 0.5f});
  auto s = loadScene(d.write("skinned.gltf", doc.text()));
  ASSERT_TRUE(s) << s.error();
  ASSERT_EQ(s->skins.size(), 1u);
  ASSERT_EQ(s->objects.size(), 1u);
  const SceneObject& o = s->objects[0];
  EXPECT_EQ(o.skin, 0);
  const MeshDeformation& def = o.mesh->deformation;
  ASSERT_TRUE(def.skinned());
  ASSERT_EQ(s->skins[0].joints.size(), 2u);
  EXPECT_EQ(s->nodes[static_cast<std::size_t>(s->skins[0].joints[1])].name, "tip");
  // glTF ignores a skinned node's transform: the object is where its joints put it (the
  // node's translation of 100 plays no part).
  EXPECT_LT(std::abs(o.transform[3].x), 2.0f);
  // Each mesh vertex keeps its file vertex's influences.
  for (std::size_t i = 0; i < o.mesh->positions.size(); ++i) {
    const glm::vec3 file = glm::vec3(o.transform * glm::vec4(o.mesh->positions[i], 1.0f));
    const glm::vec4 w = def.weights[i];
    if (near(file, {0, 0, 0})) {
      EXPECT_EQ(w, glm::vec4(1, 0, 0, 0));
    } else if (near(file, {1, 0, 0})) {
      EXPECT_EQ(w.y * def.joints[i].y + w.x * def.joints[i].x, 1.0f);  // all on joint 1
    } else if (near(file, {0, 1, 0})) {
      EXPECT_EQ(w, glm::vec4(0.5f, 0.5f, 0, 0));
    }
  }
  EXPECT_TRUE(contains(sceneReportJson(*s), R"("skins":1)"));
}

TEST(GltfScene, BadSkinDataIsNamedAndTheMeshDrawnAtRest) {
  struct Case {
    const char* what;
    std::vector<std::uint8_t> joints;
    std::vector<float> weights;
    int matrices;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {"joint out of range", {0, 0, 5, 0, 0, 1}, {1, 0, 1, 0, 0.5f, 0.5f}, 2, "vertex 1 names joint 5, past the skin's 2"},
      {"negative weight", {0, 0, 1, 0, 0, 1}, {1, 0, -1, 0, 0.5f, 0.5f}, 2, "vertex 1 has a weight that is negative or not finite"},
      {"NaN weight", {0, 0, 1, 0, 0, 1}, {1, 0, NAN, 0, 0.5f, 0.5f}, 2, "vertex 1 has a weight that is negative or not finite"},
      {"too few inverse bind matrices", {0, 0, 1, 0, 0, 1}, {1, 0, 1, 0, 0.5f, 0.5f}, 1, "has 2 joints but 1 inverse bind matrices"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    TempDir d;
    SkinnedDoc doc(c.joints, c.weights, c.matrices);
    auto s = loadScene(d.write("bad-skin.gltf", doc.text()));
    ASSERT_TRUE(s) << s.error();
    ASSERT_EQ(s->objects.size(), 1u);
    EXPECT_EQ(s->objects[0].skin, -1);
    EXPECT_FALSE(s->objects[0].mesh->deformation.skinned());
    bool named = false;
    for (const std::string& w : s->warnings) named = named || (contains(w, "bad-skin.gltf") && contains(w, c.expect));
    EXPECT_TRUE(named) << "no warning naming '" << c.expect << "'";
  }
  // Weights that do not sum to one are normalised, and said so.
  TempDir d;
  SkinnedDoc drift({0, 0, 1, 0, 0, 1}, {1, 0, 1, 0, 0.25f, 0.25f});
  auto s = loadScene(d.write("drift.gltf", drift.text()));
  ASSERT_TRUE(s) << s.error();
  bool said = false;
  for (const std::string& w : s->warnings) said = said || contains(w, "1 vertices' skin weights do not sum to one; normalised");
  EXPECT_TRUE(said);
  for (const glm::vec4& w : s->objects[0].mesh->deformation.weights) EXPECT_NEAR(w.x + w.y + w.z + w.w, 1.0f, 1e-6f);
}

TEST(GltfScene, KhronosSkinAndMorphSamplesPlay) {
  // simple_skin: a strip whose upper joint turns; AnimatedMorphCube: two targets' weights.
  auto skin = loadScene(kSamples + "simple_skin/simple_skin.gltf");
  ASSERT_TRUE(skin) << skin.error();
  ASSERT_EQ(skin->objects.size(), 1u);
  ASSERT_EQ(skin->skins.size(), 1u);
  EXPECT_TRUE(skin->warnings.empty()) << skin->warnings.front();
  ASSERT_EQ(skin->animations.size(), 1u);
  auto morph = loadScene(kSamples + "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
  ASSERT_TRUE(morph) << morph.error();
  ASSERT_EQ(morph->animations.size(), 1u);
  EXPECT_EQ(morph->animations[0].channels[0].property, AnimatedProperty::Weights);
  EXPECT_EQ(morph->animations[0].channels[0].width, 2);
  EXPECT_EQ(morph->objects[0].mesh->deformation.targets(), 2u);
  NodePose pose;
  poseNodes(morph->nodes, {&morph->animations[0]}, 0.0f, pose);
  const std::vector<float> atStart = pose.weights[static_cast<std::size_t>(morph->objects[0].node)];
  poseNodes(morph->nodes, {&morph->animations[0]}, 2.0f, pose);
  EXPECT_NE(pose.weights[static_cast<std::size_t>(morph->objects[0].node)], atStart);
}

}  // namespace
}  // namespace npr
