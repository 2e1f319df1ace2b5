// CPU tier: the mesh loader's rules, on small OBJ files the tests write themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <sstream>

#include "renderer/mesh/manifold_fans.h"
#include "renderer/mesh/mesh_builder.h"
#include "renderer/mesh/mesh_loader.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::TempDir;

bool hasWarningContaining(const LoadReport& r, const std::string& s) {
  for (const auto& w : r.warnings)
    if (w.find(s) != std::string::npos) return true;
  return false;
}

bool allNormalsFinite(const Mesh& m) {
  for (const auto& n : m.normals)
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return false;
  for (const auto& n : m.faceNormals)
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return false;
  return true;
}

double triangleArea(const Mesh& m, size_t t) {
  const glm::dvec3 a(m.positions[m.indices[t * 3]]), b(m.positions[m.indices[t * 3 + 1]]), c(m.positions[m.indices[t * 3 + 2]]);
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

TEST(MeshLoader, LoadsATriangleAndReportsIt) {
  TempDir d;
  auto m = loadMesh(d.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.vertices, 3u);
  EXPECT_EQ(m->report.triangles, 1u);
  EXPECT_EQ(m->triangleCount(), 1u);
  EXPECT_EQ(m->report.skipped_faces, 0u);
  EXPECT_NEAR(glm::length(m->faceNormals[0]), 1.0f, 1e-6f);
  EXPECT_NEAR(m->faceNormals[0].z, 1.0f, 1e-6f);  // counter-clockwise in xy faces +z
}

// Mesh::closed (what lets the mesh passes drop back faces) only for a surface that encloses a
// volume from outside: a cube, also with its corners split for texture coordinates; not
// with a face missing, nor turned inside out, nor with a face wound against its neighbours.
TEST(MeshLoader, ClosedSurfacesAreToldFromOpenInvertedAndMiswoundOnes) {
  TempDir d;
  const std::string corners = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n";
  const std::vector<std::string> faces = {"1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"};  // outward
  auto cube = [&](int skip, int flip, bool inverted, bool texcoords) {
    std::string obj = corners + (texcoords ? "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n" : "");
    for (int i = 0; i < int(faces.size()); ++i) {
      if (i == skip) continue;
      std::istringstream in(faces[std::size_t(i)]);
      std::vector<std::string> v{std::istream_iterator<std::string>(in), {}};
      if (inverted || i == flip) std::reverse(v.begin(), v.end());
      obj += "f";
      for (std::size_t k = 0; k < v.size(); ++k) obj += " " + v[k] + (texcoords ? "/" + std::to_string(k + 1) : "");
      obj += "\n";
    }
    auto m = loadMesh(d.write("cube.obj", obj));
    EXPECT_TRUE(m) << m.error();
    return m ? m->closed : false;
  };
  EXPECT_TRUE(cube(-1, -1, false, false));
  EXPECT_TRUE(cube(-1, -1, false, true));  // vertices split by texture coordinates are welded
  EXPECT_FALSE(cube(2, -1, false, false));
  EXPECT_FALSE(cube(-1, -1, true, false));
  EXPECT_FALSE(cube(-1, 3, false, false));
  // Generated meshes too: the icosphere and torus are closed, a square is not.
  EXPECT_TRUE(test::icosphere(2).closed);
  EXPECT_TRUE(test::torus(24, 12).closed);
  EXPECT_FALSE(test::square(2).closed);
}

TEST(MeshLoader, ConcavePolygonIsEarClippedNotFanned) {
  TempDir d;
  // A U shape: a fan from its first corner would cover the slot between the arms.
  auto m = loadMesh(d.write("u.obj", "v 0 0 0\nv 3 0 0\nv 3 3 0\nv 2 3 0\nv 2 1 0\nv 1 1 0\nv 1 3 0\nv 0 3 0\n"
                                     "f 1 2 3 4 5 6 7 8\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.polygons_triangulated, 1u);
  ASSERT_EQ(m->triangleCount(), 6u);
  // Coverage: the triangles' areas sum to the polygon's (9 - 2 = 7), so none overlap or
  // spill into the slot, and every triangle keeps the polygon's orientation.
  const double scale = m->report.original_scale;
  double sum = 0.0;
  for (size_t t = 0; t < 6; ++t) {
    sum += triangleArea(*m, t);
    EXPECT_GT(m->faceNormals[t].z, 0.0f) << t;
    // No triangle's centroid lies in the slot (1 < x < 2, y > 1).
    const glm::dvec3 c = glm::dvec3(m->faceCentroids[t]) / scale + m->report.original_centre;
    EXPECT_FALSE(c.x > 1.0 && c.x < 2.0 && c.y > 1.0) << t;
  }
  EXPECT_NEAR(sum / (scale * scale), 7.0, 1e-5);
}

TEST(MeshLoader, PolygonBecomesNMinus2Triangles) {
  TempDir d;
  std::string obj;
  const int n = 9;
  for (int i = 0; i < n; ++i) {
    // A star-shaped (concave) nonagon.
    const double a = 2 * M_PI * i / n, r = (i % 2) ? 0.4 : 1.0;
    obj += "v " + std::to_string(r * std::cos(a)) + " " + std::to_string(r * std::sin(a)) + " 0\n";
  }
  obj += "f";
  for (int i = 1; i <= n; ++i) obj += " " + std::to_string(i);
  obj += "\n";
  auto m = loadMesh(d.write("star.obj", obj));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->triangleCount(), size_t(n - 2));
}

TEST(MeshLoader, AcceptsObjSyntaxVariants) {
  TempDir d;
  const std::string obj =
      "# comment\n"
      "mtllib missing.mtl\n"
      "o thing\ng group\ns 1\nusemtl stuff\n"
      "v  0 0 0 \t\nv 1 0 0\r\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvn 0 0 1\n"
      "f 1/1/1 2/1/1 3/1/1\n"
      "f -4//1 -2//1 -1//1\n"  // relative indices: 1 3 4
      "f 1/1 3/1 4/1";          // no final newline
  auto m = loadMesh(d.write("v.obj", obj));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.triangles, 3u);
  EXPECT_EQ(m->report.skipped_faces, 0u);
  EXPECT_TRUE(hasWarningContaining(m->report, "missing.mtl"));
}

TEST(MeshLoader, FaceWithMissingVertexIsSkippedWithFileAndLine) {
  TempDir d;
  const std::string path = d.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 40\n");
  auto m = loadMesh(path);
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.triangles, 1u);
  EXPECT_EQ(m->report.skipped_faces, 1u);
  EXPECT_TRUE(hasWarningContaining(m->report, path + " line 5"));
  EXPECT_TRUE(hasWarningContaining(m->report, "vertex 40"));
}

TEST(MeshLoader, NonManifoldAndDuplicateFacesAreStillDrawn) {
  TempDir d;
  // Three triangles on one edge (1-2), a duplicated face and a flipped neighbour.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                          "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 2 3\nf 1 3 2\n";
  auto m = loadMesh(d.write("nm.obj", obj));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.triangles, 5u);  // every face is drawn
  EXPECT_GE(m->report.non_manifold_faces, 2u);
  EXPECT_EQ(m->report.skipped_faces, 0u);
}

TEST(MeshLoader, ZeroAreaTrianglesKeepFiniteNormals) {
  TempDir d;
  auto m = loadMesh(d.write("z.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.triangles, 2u);
  EXPECT_TRUE(allNormalsFinite(*m));
}

TEST(MeshLoader, FarFromOriginKeepsItsShape) {
  TempDir d;
  // A unit right triangle offset by 1e7: in float the offset alone would eat the shape
  // (float spacing at 1e7 is 1.0).
  auto m = loadMesh(d.write("far.obj", "v 10000000.25 10000000.5 0\nv 10000001.25 10000000.5 0\nv 10000000.25 10000001.5 0\nf 1 2 3\n"));
  ASSERT_TRUE(m) << m.error();
  const double s = m->report.original_scale;
  const glm::dvec3 a(m->positions[0]), b(m->positions[1]), c(m->positions[2]);
  EXPECT_NEAR(glm::length(b - a) / s, 1.0, 1e-6);
  EXPECT_NEAR(glm::length(c - a) / s, 1.0, 1e-6);
  EXPECT_NEAR(m->report.original_centre.x, 10000000.75, 1e-6);
  EXPECT_NEAR(m->radius, 1.0f, 1e-5f);
}

TEST(MeshLoader, RefusesFilesWithNothingToDraw) {
  TempDir d;
  struct Case { std::string name, content, expect; };
  const std::vector<Case> cases = {
      {"empty.obj", "", "empty"},
      {"blank.obj", "\n  \n", "empty"},
      {"points.obj", "v 0 0 0\nv 1 0 0\np 1 2\nl 1 2\n", "no faces"},
      {"binary.obj", std::string("v 0 0\0\x01\x02", 9), "binary"},
      {"utf16.obj", std::string("\xFF\xFEv\0 \0", 6), "UTF-16"},
  };
  for (const auto& c : cases) {
    auto m = loadMesh(d.write(c.name, c.content));
    ASSERT_FALSE(m) << c.name;
    EXPECT_NE(m.error().find(c.name), std::string::npos) << m.error();
    EXPECT_NE(m.error().find(c.expect), std::string::npos) << m.error();
  }
}

TEST(MeshLoader, RefusesMissingFilesDirectoriesAndUnknownFormats) {
  TempDir d;
  auto missing = loadMesh((d.path() / "nope.obj").string());
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("no such file"), std::string::npos);
  std::filesystem::create_directories(d.path() / "dir.obj");
  auto dir = loadMesh((d.path() / "dir.obj").string());
  ASSERT_FALSE(dir);
  EXPECT_NE(dir.error().find("directory"), std::string::npos);
  auto fmt = loadMesh(d.write("m.xyz", "1 2 3\n"));
  ASSERT_FALSE(fmt);
  EXPECT_NE(fmt.error().find("unsupported"), std::string::npos);
}

TEST(MeshLoader, NonFiniteVerticesAreRefusedNotPropagated) {
  TempDir d;
  auto m = loadMesh(d.write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 1e400 0 0\nf 1 2 3\nf 1 2 4\nf 1 2 5\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.triangles, 1u);
  EXPECT_EQ(m->report.skipped_faces, 2u);
  EXPECT_TRUE(allNormalsFinite(*m));
  for (const auto& p : m->positions) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

TEST(MeshLoader, ReadsOtherFormatsThroughTheirReaders) {
  TempDir d;
  auto m = loadMesh(d.write("t.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->report.triangles, 2u);
}

TEST(MeshLoader, ShippedModelsLoadCleanly) {
  for (const char* name : {"bunny.obj", "teapot.obj"}) {
    auto m = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/" + name);
    ASSERT_TRUE(m) << m.error();
    EXPECT_GT(m->report.triangles, 900u);
    EXPECT_EQ(m->report.skipped_faces, 0u);
    EXPECT_TRUE(allNormalsFinite(*m));
  }
}

TEST(MeshLoader, ReportJsonHasTheDocumentedFields) {
  TempDir d;
  auto m = loadMesh(d.write("a \"quoted\" name.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_TRUE(m);
  const std::string j = m->report.toJson();
  for (const char* key : {"\"file\":", "\"vertices\":3", "\"triangles\":1", "\"polygons_triangulated\":0", "\"skipped_faces\":0",
                          "\"non_manifold_faces\":0", "\"warnings\":[", "\"load_ms\":"})
    EXPECT_NE(j.find(key), std::string::npos) << key << " in " << j;
  EXPECT_NE(j.find("a \\\"quoted\\\" name.obj"), std::string::npos) << j;
}


// The builder skips the halfedge structure for triangles forming manifold fans, on the premise
// that OpenMesh would refuse none of them in any order. Checked here on closed and open
// surfaces with their faces shuffled and their corners rotated: OpenMesh, fed the same faces in
// the same order, refuses none and keeps every corner where it was, so the two builds are the
// same mesh. Surfaces that are not such fans are told apart, and the builder refuses the same
// faces as before on them.
std::vector<std::array<int, 3>> facesOf(const Mesh& m) {
  std::vector<std::array<int, 3>> t(m.triangleCount());
  for (std::size_t f = 0; f < t.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) t[f][k] = static_cast<int>(m.indices[f * 3 + k]);
  return t;
}

TEST(ManifoldFans, OpenMeshRefusesNoFaceOfManifoldFansInAnyOrder) {
  auto bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  ASSERT_TRUE(bunny) << bunny.error();
  std::mt19937 rng(7);
  const std::vector<Mesh> surfaces = {test::icosphere(3), test::torus(48, 24), test::square(6), *bunny};
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    for (int round = 0; round < 4; ++round) {
      std::vector<std::array<int, 3>> faces = facesOf(surfaces[s]);
      if (round > 0) std::shuffle(faces.begin(), faces.end(), rng);
      for (auto& f : faces) std::rotate(f.begin(), f.begin() + std::uniform_int_distribution<int>(0, 2)(rng), f.end());
      ASSERT_TRUE(formsManifoldFans(faces, surfaces[s].positions.size())) << "surface " << s << ": the check tests nothing";
      TriMesh om;
      std::vector<TriMesh::VertexHandle> vh;
      for (const glm::vec3& p : surfaces[s].positions) vh.push_back(om.add_vertex(TriMesh::Point(p.x, p.y, p.z)));
      std::size_t refused = 0, moved = 0;
      for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto fh = om.add_face(vh[std::size_t(faces[f][0])], vh[std::size_t(faces[f][1])], vh[std::size_t(faces[f][2])]);
        if (!fh.is_valid()) {
          ++refused;
          continue;
        }
        auto h = om.halfedge_handle(fh);
        for (std::size_t k = 0; k < 3; ++k, h = om.next_halfedge_handle(h)) moved += om.to_vertex_handle(h).idx() != faces[f][k];
      }
      EXPECT_EQ(refused, 0u) << "surface " << s << ", round " << round;
      EXPECT_EQ(moved, 0u) << "surface " << s << ", round " << round;
      Mesh built;
      buildTriMesh(surfaces[s].positions, faces, built);
      ASSERT_EQ(built.indices.size(), faces.size() * 3);
      for (std::size_t f = 0; f < faces.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) ASSERT_EQ(built.indices[f * 3 + k], std::uint32_t(faces[f][k]));
    }
}

TEST(ManifoldFans, WhatIsNotOneFanPerVertexIsLeftToTheHalfedgeStructure) {
  const Mesh sphere = test::icosphere(2);
  const std::size_t nv = sphere.positions.size();
  std::vector<std::array<int, 3>> faces = facesOf(sphere);
  ASSERT_TRUE(formsManifoldFans(faces, nv));
  auto with = [&](auto change) {
    std::vector<std::array<int, 3>> f = faces;
    change(f);
    return f;
  };
  const auto duplicate = with([](auto& f) { f.push_back(f[0]); });
  const auto flipped = with([](auto& f) { std::swap(f[3][0], f[3][1]); });
  EXPECT_FALSE(formsManifoldFans(duplicate, nv));
  EXPECT_FALSE(formsManifoldFans(flipped, nv));
  // Two triangles touching at one vertex only (a bowtie): two fans there.
  const std::vector<std::array<int, 3>> bowtie = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_FALSE(formsManifoldFans(bowtie, 5));
  EXPECT_TRUE(formsManifoldFans({{0, 1, 2}, {0, 2, 3}}, 4));  // an open fan
  // Three triangles on one edge.
  EXPECT_FALSE(formsManifoldFans({{0, 1, 2}, {1, 0, 3}, {1, 0, 4}}, 5));
  // A vertex on more triangles than the check walks: a closed fan of 70 about vertex 0.
  std::vector<std::array<int, 3>> wide;
  for (int i = 0; i < 70; ++i) wide.push_back({0, 1 + i, 1 + (i + 1) % 70});
  EXPECT_FALSE(formsManifoldFans(wide, 71));
  // Refused faces still come out as before: drawn on copies, counted.
  Mesh built;
  buildTriMesh(sphere.positions, duplicate, built);
  EXPECT_EQ(built.report.non_manifold_faces, 1u);
  EXPECT_EQ(built.positions.size(), nv + 3);
  EXPECT_EQ(built.triangleCount(), duplicate.size());
}

}  // namespace
}  // namespace npr
