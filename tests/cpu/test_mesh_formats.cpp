// CPU tier: our PLY, OFF and STL readers (and OM through OpenMesh in a child process) read what
// OpenMesh's writers write, in every variant, into the same mesh the OBJ reader makes of the
// same model; plus the format details real files use (extra properties and elements, colours,
// comments, double coordinates, several solids).
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cmath>

#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/scene_loader.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::TempDir;

double totalArea(const Mesh& m) {
  double a = 0.0;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::dvec3 p(m.positions[m.indices[t * 3]]), q(m.positions[m.indices[t * 3 + 1]]), r(m.positions[m.indices[t * 3 + 2]]);
    a += 0.5 * glm::length(glm::cross(q - p, r - p));
  }
  return a;
}

TEST(MeshFormats, EveryWriterVariantReadsBackAsTheObjMesh) {
  TempDir d;
  const std::string obj = std::string(NPR_SOURCE_DIR) + "/models/bunny.obj";
  auto reference = loadMesh(obj);
  ASSERT_TRUE(reference) << reference.error();
  TriMesh om;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(om, obj));
  using O = OpenMesh::IO::Options;
  struct Variant { const char* name; O::Flag flags; bool sameOrder; };
  const Variant variants[] = {{"ascii.ply", O::Default, true},       {"le.ply", O::Binary, true},
                              {"be.ply", O::Flag(O::Binary | O::MSB), true}, {"a.off", O::Default, true},
                              {"ascii.stl", O::Default, false},      {"binary.stl", O::Binary, false},
                              {"b.om", O::Binary, true}};
  for (const Variant& v : variants) {
    const std::string path = (d.path() / v.name).string();
    ASSERT_TRUE(OpenMesh::IO::write_mesh(om, path, O(v.flags))) << v.name;
    auto m = loadMesh(path);
    ASSERT_TRUE(m) << v.name << ": " << m.error();
    EXPECT_EQ(m->triangleCount(), reference->triangleCount()) << v.name;
    EXPECT_EQ(m->positions.size(), reference->positions.size()) << v.name << " (STL corners must be welded)";
    EXPECT_EQ(m->report.skipped_faces, 0u) << v.name;
    EXPECT_NEAR(totalArea(*m), totalArea(*reference), 1e-4 * totalArea(*reference)) << v.name;
    if (!v.sameOrder) continue;
    for (std::size_t i = 0; i < m->positions.size(); ++i)
      ASSERT_LT(glm::length(m->positions[i] - reference->positions[i]), 1e-5f) << v.name << " vertex " << i;
  }
}

// OM files are checked chunk by chunk against their size before OpenMesh reads them
// (om_reader.cpp): every kind of chunk OpenMesh's writer writes must pass that check, in
// single and double precision, with byte and float colours and custom properties.
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  using Color = OpenMesh::Vec4f;
};
template <class M>
void tetrahedron(M& m) {
  using P = typename M::Point;
  const auto a = m.add_vertex(P(0, 0, 0)), b = m.add_vertex(P(1, 0, 0)), c = m.add_vertex(P(0, 1, 0)), e = m.add_vertex(P(0, 0, 1));
  m.add_face(a, b, c);
  m.add_face(a, e, b);
  m.add_face(a, c, e);
  m.add_face(b, e, c);
}

TEST(MeshFormats, OmFilesWithEveryKindOfChunkPassTheSizeCheckAndRead) {
  TempDir d;
  using O = OpenMesh::IO::Options;
  {
    TriMesh m;
    m.request_vertex_normals();
    m.request_vertex_colors();
    m.request_vertex_texcoords2D();
    m.request_face_normals();
    m.request_face_colors();
    m.request_vertex_status();
    m.request_face_status();
    m.request_edge_status();
    m.request_halfedge_status();
    tetrahedron(m);
    OpenMesh::VPropHandleT<float> weight;
    m.add_property(weight, "weight");
    m.property(weight).set_persistent(true);
    OpenMesh::FPropHandleT<int> label;
    m.add_property(label, "label");
    m.property(label).set_persistent(true);
    OpenMesh::MPropHandleT<std::string> note;
    m.add_property(note, "note");
    m.mproperty(note).set_persistent(true);
    m.property(note) = "a note";
    const O every(O::Binary | O::VertexNormal | O::VertexColor | O::VertexTexCoord | O::FaceNormal | O::FaceColor | O::Status | O::Custom);
    ASSERT_TRUE(OpenMesh::IO::write_mesh(m, (d.path() / "every.om").string(), every));
  }
  {
    OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits> m;
    m.request_vertex_normals();
    m.request_vertex_colors();
    m.request_face_colors();
    tetrahedron(m);
    ASSERT_TRUE(OpenMesh::IO::write_mesh(m, (d.path() / "double.om").string(),
                                         O(O::Binary | O::VertexNormal | O::VertexColor | O::FaceColor | O::ColorAlpha | O::ColorFloat)));
  }
  for (const char* name : {"every.om", "double.om"}) {
    auto m = loadMesh((d.path() / name).string());
    ASSERT_TRUE(m) << name << ": " << m.error();
    EXPECT_EQ(m->triangleCount(), 4u) << name;
    EXPECT_EQ(m->positions.size(), 4u) << name;
  }
}

TEST(MeshFormats, PlyExtraPropertiesElementsAndDoubles) {
  TempDir d;
  // Colours, an extra element before the faces, a face property after the list, and double
  // coordinates offset by 1e7 (single precision would lose the triangle's shape).
  auto m = loadMesh(d.write("x.ply", "ply\nformat ascii 1.0\ncomment made by hand\nobj_info x\nelement vertex 4\n"
                                     "property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
                                     "element material 1\nproperty float shininess\n"
                                     "element face 2\nproperty list uchar uint vertex_index\nproperty int flags\nend_header\n"
                                     "10000000 0 0 255\n10000000.001 0 0 0\n10000000.001 0.001 0 0\n10000000 0.001 0 0\n"
                                     "0.5\n3 0 1 2 7\n3 0 2 3 9\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 2u);
  EXPECT_NEAR(totalArea(*m), 2.0, 1e-3);  // a square of side sqrt(2) in the unit sphere
}

TEST(MeshFormats, OffColoursCommentsAndPolygons) {
  TempDir d;
  auto m = loadMesh(d.write("c.off", "COFF\n# a comment line\n5 2 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 1 0 0 1\n"
                                     "0 1 0 1 0 0 1\n0.5 2 0 0 0 0 1\n4 0 1 2 3 255 0 0\n3 3 2 4\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 3u);
  EXPECT_EQ(m->report.polygons_triangulated, 1u);
  auto binary = loadMesh(d.write("b.off", "OFF BINARY\n"));
  ASSERT_FALSE(binary);
  EXPECT_NE(binary.error().find("binary OFF"), std::string::npos) << binary.error();
}

TEST(MeshFormats, StlAsciiWithSeveralSolidsAndNonFiniteFacets) {
  TempDir d;
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  const std::string facet2 = "facet normal 0 0 1\n outer loop\n  vertex 1 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n endloop\nendfacet\n";
  const std::string bad = "facet normal 0 0 1\nouter loop\nvertex nan 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  auto m = loadMesh(d.write("s.stl", "solid a\n" + facet + "endsolid a\nsolid b\n" + facet2 + bad + "endsolid b\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), 2u);
  EXPECT_EQ(m->positions.size(), 4u);  // the shared edge's corners welded
  EXPECT_EQ(m->report.skipped_faces, 1u);
}

}  // namespace
// A file with thousands of faces wrong the same way reports the first few and a count, not
// fifty lines of the same: the engine's 10,413 degenerate faces print four lines.
TEST(MeshFormats, RepeatedWarningsAreCountedPerKind) {
  test::TempDir d;
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (int i = 0; i < 200; ++i) obj += "f 1 1 2\n";  // fewer than 3 different vertices
  for (int i = 0; i < 2; ++i) obj += "f 1 2 9\n";    // a vertex that does not exist
  auto m = loadMesh(d.write("many.obj", obj));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.skipped_faces, 202u);
  std::string all;
  for (const std::string& w : m->report.warnings) all += w + "\n";
  EXPECT_LE(m->report.warnings.size(), 6u) << all;
  EXPECT_NE(all.find("197 more like this (200 in all)"), std::string::npos) << all;
  EXPECT_NE(all.find("line 206"), std::string::npos) << all;  // the other kind still shown where it is
}

// --verbose: every warning, each where it is, and the cache (which keeps the summed ones) is
// neither read nor written.
TEST(MeshFormats, EveryWarningWhenAskedForAll) {
  test::TempDir d;
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (int i = 0; i < 200; ++i) obj += "f 1 1 2\n";
  const std::string path = d.write("many.obj", obj);
  (void)loadMesh(path);  // a summed load, cached
  Result<LoadedScene> s = [&] { return loadScene(path, SceneLoadOptions{false, true}); }();
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(s->warnings.size(), 200u);
  EXPECT_FALSE(s->report.from_cache);
  EXPECT_NE(s->warnings.back().find("line 204"), std::string::npos) << s->warnings.back();
  Result<LoadedScene> summed = loadScene(path);
  ASSERT_TRUE(summed);
  EXPECT_LE(summed->warnings.size(), 6u);  // and the next ordinary load is summed again
}

}  // namespace npr
