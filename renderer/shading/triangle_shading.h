// Per-triangle lighting of a whole mesh on the CPU, as the original renderer did: the OpenGL
// lighting model at each triangle's centroid with its face normal, then a palette match, then
// bucketing of triangles by palette entry (what the stencil and triangle paths draw).
// Data-parallel over contiguous chunks of the mesh's structure-of-arrays data. The cache that
// runs it only when its inputs changed is triangle_shading_cache.h.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/lighting/lighting_model.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/palette_matcher.h"

namespace npr {

// A mesh's own materials, for per-face lighting (--materials on): each triangle is lit with
// its material (and, where the mesh has vertex colours or texture maps, its ambient and
// diffuse reflectance scaled by the triangle's colour).
struct FaceMaterials {
  std::vector<Material> materials;             // GL materials, by mesh material
  const std::uint16_t* faceMaterial = nullptr;  // per triangle; nullptr: all use materials[0]
  // Per triangle, 8 bits a channel (x / 255); nullptr: 1. Packed: at 871K triangles a float
  // colour was 10 MB more to stream through the cache per relight.
  const glm::u8vec4* faceScale = nullptr;
};

struct TriangleShadingOptions {
  bool buildBuckets = false;   // group triangles by palette entry (both per-triangle paths draw them so)
  int threads = 0;             // 0: one per hardware thread
};

struct TriangleShading {
  std::vector<std::uint8_t> entry;          // palette entry per triangle
  std::vector<std::uint32_t> bucketStart;   // N + 1 offsets, in triangles, into bucketIndices
  std::vector<std::uint32_t> bucketIndices; // vertex indices, 3 per triangle, grouped by entry
  std::vector<glm::ivec4> bucketBounds;     // per entry: x0, y0, x1, y1 in pixels (empty if x1 <= x0)
  int nonEmptyBuckets = 0;
};

// Lighting space for the loop: object space when the modelview is rigid (rotation and
// translation: dot products and distances are unchanged, so the loop needs no matrix work),
// eye space otherwise.
// faceColourScale (mesh_materials.h) packed for FaceMaterials::faceScale.
std::vector<glm::u8vec4> packFaceScale(const std::vector<glm::vec3>& scale);

void shadeTriangles(const Mesh& mesh, const LightingState& lighting, const glm::mat4& modelView,
                    const PaletteMatcher& matcher, const TriangleShadingOptions& options, TriangleShading& out,
                    const FaceMaterials* materials = nullptr);

// Buckets (offsets and grouped indices) from entries already in out.entry, one per triangle
// and below `entries`: for entries chosen elsewhere (the GPU per-triangle lighting pass).
void bucketTriangles(const Mesh& mesh, int entries, int threads, TriangleShading& out);

// Every vertex in window pixels (NaN where it lies behind the eye). Depends only on the view,
// so callers keep it while only the lighting changes.
void projectVertices(const std::vector<glm::vec3>& positions, const glm::mat4& modelViewProjection, const glm::ivec2& viewport, int threads,
                     std::vector<glm::vec2>& screen);

// The screen rectangle (x0, y0, x1, y1 in pixels) each bucket's triangles cover, for the
// stencil path's scissor, from projectVertices' output. Needs the buckets.
void computeBucketBounds(const std::vector<glm::vec2>& screen, const glm::ivec2& viewport, int threads, TriangleShading& shading);

// True when `m` is a rotation, a uniform scale and a translation (within float rounding): then
// lighting can be worked out in object space, where the per-triangle loop needs no matrix
// work (angles are kept; prepareLighting rescales the attenuation for the scale). A scene's
// objects are placed by such transforms.
bool isSimilarity(const glm::mat4& m);

}  // namespace npr
