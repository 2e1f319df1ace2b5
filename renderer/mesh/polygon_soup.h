// What every mesh reader (OBJ, PLY, OFF, STL, OM) produces before the mesh is built: positions
// in double precision with a flag for the unusable ones, and triangles. Faces enter through one
// FaceBuilder, so repeated corners, polygons, bad indices and the warning budget are handled the
// same way whatever the format, and buildMesh is the one way from a soup to a Mesh.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/result.h"
#include "renderer/mesh/mesh.h"
#include "renderer/mesh/polygon_triangulation.h"

namespace npr {

struct PolygonSoup {
  std::vector<glm::dvec3> vertices;
  std::vector<char> vertexValid;  // 0: non-finite or unparsable; faces using it are skipped
  std::vector<std::array<int, 3>> triangles;
  // Appearance (OBJ only), each empty until the file uses it: a colour per vertex, texture
  // coordinates, and per triangle its corners' texture coordinates (-1: none) and material.
  std::vector<glm::vec3> colours;
  std::vector<glm::vec2> texcoords;
  std::vector<std::array<int, 3>> triangleTexcoords;
  std::vector<std::uint16_t> triangleMaterials;
  std::vector<MeshMaterial> materials;  // what triangleMaterials index
  std::vector<MeshTexture> textures;
  // Deformation (glTF): per vertex `deformWidth()` floats, the skin's four joints and four
  // weights when `skinned`, then per morph target a position delta and a normal delta (file
  // units); empty when the mesh does not deform. buildMesh makes MeshDeformation of them.
  std::vector<float> deform;
  bool skinned = false;
  std::size_t morphTargets = 0;
  std::size_t deformWidth() const { return (skinned ? 8 : 0) + 6 * morphTargets; }
  // Marks (glTF POINTS and LINES primitives, placed as the vertices are): dots, and segments
  // as pairs of ends. They count in the model's bounds and become Mesh::dots and segments.
  std::vector<glm::dvec3> dots, segments;

  // Starts per-triangle texture coordinates / materials, giving the triangles so far none / 0.
  void trackTexcoords() { triangleTexcoords.resize(triangles.size(), {-1, -1, -1}); tracksTexcoords = true; }
  void trackMaterials() { triangleMaterials.resize(triangles.size(), 0); tracksMaterials = true; }
  bool tracksTexcoords = false, tracksMaterials = false;

  // Adds a vertex; a non-finite one is stored at the origin, marked invalid, and false returned.
  bool addVertex(const glm::dvec3& v);
};

// Collects warnings so a file with a million bad faces cannot flood the report: each kind (the
// text after the warning's place, "face names fewer than 3 different vertices; skipped") is
// shown for its first few places, then counted; at most a limit in all.
// While one exists on this thread, loads keep every warning (--verbose), not the first three
// of each kind (up to kAllWarningsCap, so a file of a million bad faces costs no gigabytes).
class WarningDetail {
 public:
  explicit WarningDetail(bool all);
  ~WarningDetail();
  WarningDetail(const WarningDetail&) = delete;
  WarningDetail& operator=(const WarningDetail&) = delete;
  static bool all();
  static constexpr std::size_t kAllWarningsCap = 100000;

 private:
  bool before_;
};

class Warnings {
 public:
  explicit Warnings(std::vector<std::string>& out) : out_(out) {}
  void add(std::string w);
  void finish();  // appends "... and N more like this (M in all): KIND" per kind, "... and N more warnings"

 private:
  std::vector<std::string>& out_;
  std::vector<std::pair<std::string, std::size_t>> kinds_;  // kind, how many in all
  std::size_t dropped_ = 0;
};

class FaceBuilder {
 public:
  FaceBuilder(PolygonSoup& soup, LoadReport& report, Warnings& warnings) : soup_(soup), report_(report), warn_(warnings) {}

  // `corners` are 0-based vertex indices as the file gives them; warnings name the file and
  // `unit` `number` ("line 12", "face 7"). Out-of-range or invalid vertices skip the face;
  // corners repeated in a row are dropped; polygons are ear-clipped. Returns whether anything
  // was added. `corners` is used as scratch.
  bool add(std::vector<long long>& corners, const char* unit, std::size_t number);
  // The same with each corner's texture coordinate index (-1: none; same length as `corners`)
  // and the face's material, kept through the repeat removal and the triangulation.
  bool add(std::vector<long long>& corners, const std::vector<int>& texcoords, std::uint16_t material, const char* unit,
           std::size_t number);

 private:
  PolygonSoup& soup_;
  LoadReport& report_;
  Warnings& warn_;
  TriangulationBudget budget_;
  bool budgetWarned_ = false;
  std::vector<int> face_, faceTex_;
  std::vector<glm::dvec3> poly_;
};

// The soup's triangles split by `group` (one per triangle, each < groups): one soup per group
// with only the vertices, texture coordinates, materials and texture maps its triangles use.
// Groups without a triangle give empty soups. Takes the soup (peak memory).
std::vector<PolygonSoup> splitSoup(PolygonSoup soup, const std::vector<std::uint32_t>& group, std::size_t groups);

// Centres and scales the soup's positions into the unit sphere and builds the mesh (not yet
// finalised: see loadMesh). Fails when there is no triangle to draw. Takes the soup so its
// double-precision positions are freed as soon as they are converted (peak memory).
[[nodiscard]] Result<Mesh> buildMesh(PolygonSoup soup, LoadReport report);

}  // namespace npr
