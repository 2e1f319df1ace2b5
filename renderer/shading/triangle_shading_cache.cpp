// Per-triangle shading cache (see triangle_shading_cache.h).
#include "renderer/shading/triangle_shading_cache.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "renderer/core/elapsed.h"
#include "renderer/core/parallel.h"
#include "renderer/materials/mesh_materials.h"
#include "renderer/lighting/occlusion_factor.h"

namespace npr {
namespace {

bool nearlyEqual(float a, float b) { return std::fabs(a - b) <= 1e-5f * std::max(1.0f, std::max(std::fabs(a), std::fabs(b))); }
bool nearlyEqual(const glm::vec3& a, const glm::vec3& b) { return nearlyEqual(a.x, b.x) && nearlyEqual(a.y, b.y) && nearlyEqual(a.z, b.z); }

// Whether per-triangle results can differ between two preparations of the lighting (in the
// same space). The eye matters only to specular and two-sided terms.
bool sameLighting(const PreparedLighting<float>& a, const PreparedLighting<float>& b) {
  if (a.count != b.count || a.lighting != b.lighting || a.specular != b.specular || a.localViewer != b.localViewer ||
      a.twoSided != b.twoSided || a.tone != b.tone)
    return false;
  if (a.tone != ToneModel::OpenGL)
    for (int s = 0; s < 2; ++s)
      if (!nearlyEqual(a.cool[s], b.cool[s]) || !nearlyEqual(a.warm[s], b.warm[s]) || a.splashAlpha != b.splashAlpha ||
          a.splashPower != b.splashPower)
        return false;
  for (int s = 0; s < 2; ++s)
    if (!nearlyEqual(a.base[s], b.base[s]) || a.shininess[s] != b.shininess[s]) return false;
  if (a.specular || a.twoSided)
    if (!nearlyEqual(a.eye, b.eye) || !nearlyEqual(a.viewDirection, b.viewDirection)) return false;
  for (int i = 0; i < a.count; ++i) {
    const auto &x = a.lights[i], &y = b.lights[i];
    for (int s = 0; s < 2; ++s)
      if (!nearlyEqual(x.ambient[s], y.ambient[s]) || !nearlyEqual(x.diffuse[s], y.diffuse[s]) ||
          !nearlyEqual(x.specular[s], y.specular[s]))
        return false;
    if (x.positional != y.positional || !nearlyEqual(x.position, y.position) || x.spot != y.spot || x.k0 != y.k0 ||
        x.k1 != y.k1 || x.k2 != y.k2)
      return false;
    // A light's spot direction matters only when it is a spotlight.
    if (x.spot && (!nearlyEqual(x.spotDirection, y.spotDirection) || x.spotExponent != y.spotExponent ||
                   x.spotCosCutoff != y.spotCosCutoff))
      return false;
  }
  return true;
}

}  // namespace

void TriangleShadingCache::geometryChanged() {
  ++meshId_;
  key_.valid = false;
  boundsValid_ = false;
  gpu_.geometryChanged();
}

void TriangleShadingCache::setMesh(const Mesh* mesh, const Mesh* vertices) {
  mesh_ = mesh;
  vertices_ = vertices ? vertices : mesh;
  faceScale_.clear();
  faceScaleValid_ = false;
  occludedScale_.clear();
  occludedWith_ = nullptr;
  gpu_.setMesh(mesh, vertices);
  ++meshId_;
  key_.valid = false;
  bucketsUploaded_ = false;
  boundsValid_ = false;
  if (!bucketIndices_) bucketIndices_ = gl::createBuffer();
}

void TriangleShadingCache::update(const LightingState& lighting, const glm::mat4& modelView, const PaletteMatcher& matcher,
                                  unsigned matcherId, FrameStats& stats, bool materials, const std::vector<float>* occlusion,
                                  float occlusionStrength) {
  prepare(lighting, modelView, matcher, matcherId, stats, materials, occlusion, occlusionStrength);
  if (!bucketsUploaded_ && !rowsNext_) {
    gl::uploadBuffer(bucketIndices_, shading_.bucketIndices.data(), shading_.bucketIndices.size() * sizeof(std::uint32_t),
                     GL_STREAM_DRAW);
    bucketsUploaded_ = true;
    ++stats.bufferUploads;
  }
  stats.nonEmptyBuckets = shading_.nonEmptyBuckets;
}

void TriangleShadingCache::prepare(const LightingState& lighting, const glm::mat4& modelView, const PaletteMatcher& matcher,
                                   unsigned matcherId, FrameStats& stats, bool materials, const std::vector<float>* occlusion,
                                   float occlusionStrength) {
  const bool rigid = isSimilarity(modelView);
  materials = materials && vertices_->hasAppearance();
  const float* occ = occlusion && occlusion->size() == vertices_->positions.size() ? occlusion->data() : nullptr;
  if (!occ) occlusionStrength = 0.0f;
  const glm::mat4 toSpace = rigid ? glm::inverse(modelView) : glm::mat4(1.0f);
  PreparedLighting<float> prepared = prepareLighting<float>(lighting, toSpace);
  // With the mesh's materials, the lights' own colours matter even where the state's
  // material hides them (a zero specular): compare the lighting of a white material too.
  Material white;
  white.ambient = white.diffuse = white.specular = white.emission = glm::vec4(1.0f);
  white.shininess = lighting.front().shininess;
  PreparedLighting<float> probe = materials ? prepareLighting<float>(lighting.withMaterial(white), toSpace) : prepared;
  const bool same = key_.valid && rigid && key_.mesh == meshId_ && key_.matcher == matcherId && key_.materials == materials &&
                    key_.occlusion == occ && key_.occlusionStrength == occlusionStrength && sameLighting(key_.lighting, prepared) &&
                    sameLighting(key_.probe, probe);
  if (!same) {
    const auto t0 = std::chrono::steady_clock::now();
    TriangleShadingOptions opt;
    // Both per-triangle paths draw bucket by bucket: the triangle path sets the entry as a
    // uniform per bucket, because reading a per-triangle value by gl_PrimitiveID made llvmpipe
    // process the 871K-triangle mesh about 30% slower than the reference render.
    opt.buildBuckets = !rowsNext_;  // rows: applyRows buckets by layer instead
    if (materials || occ) {
      if (materials && !faceScaleValid_) {
        faceScale_ = packFaceScale(faceColourScale(*mesh_, *vertices_));
        const auto& fmat = mesh_->faceMaterials;
        singleMaterial_ = fmat.empty() ? -1 : fmat[0];
        for (std::uint16_t x : fmat)
          if (x != fmat[0]) singleMaterial_ = -1;
        faceScaleValid_ = true;
      }
      FaceMaterials fm;
      if (materials) {
        fm.materials = glMaterials(*vertices_, lighting);
        fm.faceMaterial = mesh_->faceMaterials.size() == mesh_->triangleCount() ? mesh_->faceMaterials.data() : nullptr;
        if (fm.faceMaterial && singleMaterial_ >= 0) {  // every face has one material: no per-face lookup
          fm.materials = {fm.materials[static_cast<std::size_t>(singleMaterial_)]};
          fm.faceMaterial = nullptr;
        }
        fm.faceScale = faceScale_.empty() ? nullptr : faceScale_.data();
      } else {
        fm.materials = {lighting.front()};
      }
      if (occ) {
        if (occludedWith_ != occ || occludedStrength_ != occlusionStrength || occludedMaterials_ != materials) {
          const std::size_t nf = mesh_->triangleCount();
          occludedScale_.resize(nf);
          for (std::size_t f = 0; f < nf; ++f) {
            const std::uint32_t* v = &mesh_->indices[f * 3];
            const float mean = (occ[v[0]] + occ[v[1]] + occ[v[2]]) / 3.0f;
            const float k = occlusionFactor(mean, occlusionStrength);
            const glm::vec4 base = fm.faceScale ? glm::vec4(fm.faceScale[f]) : glm::vec4(255.0f);
            occludedScale_[f] = glm::u8vec4(glm::clamp(glm::round(base * glm::vec4(k, k, k, 1.0f)), 0.0f, 255.0f));
          }
          occludedWith_ = occ;
          occludedStrength_ = occlusionStrength;
          occludedMaterials_ = materials;
        }
        fm.faceScale = occludedScale_.data();
      }
      shadeTriangles(*mesh_, lighting, modelView, matcher, opt, shading_, &fm);
    } else {
      shadeTriangles(*mesh_, lighting, modelView, matcher, opt, shading_);
    }
    stats.cpuShadingMs += msSince(t0);
    ++stats.lightingRecomputes;
    key_ = {meshId_, matcherId, prepared, probe, materials, occ, occlusionStrength, /*valid=*/rigid};  // eye-space results are not reusable
    bucketsUploaded_ = false;
    columnsFresh_ = true;
    boundsValid_ = false;
  }
}

void TriangleShadingCache::setEntries(std::vector<std::uint8_t>&& entries, int paletteSize, FrameStats& stats) {
  const auto t0 = std::chrono::steady_clock::now();
  shading_.entry = std::move(entries);
  shading_.entry.resize(mesh_->triangleCount(), 0);
  key_.valid = false;
  columnsFresh_ = true;
  if (rowsNext_) return;  // applyRows buckets by layer
  bucketTriangles(*mesh_, paletteSize, 0, shading_);
  stats.cpuShadingMs += msSince(t0);
  gl::uploadBuffer(bucketIndices_, shading_.bucketIndices.data(), shading_.bucketIndices.size() * sizeof(std::uint32_t), GL_STREAM_DRAW);
  bucketsUploaded_ = true;
  boundsValid_ = false;
  ++stats.bufferUploads;
  stats.nonEmptyBuckets = shading_.nonEmptyBuckets;
}

void TriangleShadingCache::applyRows(const PaletteAxis& axis, const glm::vec2& axisMap, int columns, const glm::mat4& modelView,
                                     FrameStats& stats, float detail) {
  const bool rows = axis.rows > 1 && columns > 0;
  if (columnsFresh_ && !rows) {
    layered_ = false;  // just matched: columns, as drawn
    return;
  }
  if (!columnsFresh_ && (rows ? layered_ && modelView == rowsView_ && axisMap == rowsMap_ && axis.rows == rowsCount_ && detail == rowsDetail_ : !layered_)) return;
  const auto t0 = std::chrono::steady_clock::now();
  if (columnsFresh_) columns_ = shading_.entry;
  const std::size_t nt = mesh_->triangleCount();
  columns_.resize(nt, 0);
  if (rows) {
    shading_.entry.resize(nt);
    const bool haveFaces = mesh_->faceCentroids.size() == nt && mesh_->faceNormals.size() == nt;
    const glm::vec3* centroids = mesh_->faceCentroids.data();
    const glm::vec3* faceNormals = mesh_->faceNormals.data();
    const std::uint32_t* idx = mesh_->indices.data();
    const glm::vec3* pos = vertices_->positions.data();
    // Under a similarity (a scene's usual placement) in object space: the eye brought into the
    // mesh's space, distances scaled back; angles are kept. Otherwise in eye space, normals by
    // the inverse transpose.
    const bool rigid = haveFaces && isSimilarity(modelView);
    const glm::vec3 eye = glm::vec3(glm::inverse(modelView) * glm::vec4(0, 0, 0, 1));
    const float scale = glm::length(glm::vec3(modelView[0]));
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(modelView)));
    parallelChunks(nt, workerCount(), [&](std::size_t b, std::size_t e, int) {
      for (std::size_t f = b; f < e; ++f) {
        float value;
        if (axis.kind == PaletteAxisKind::Detail) {
          value = detail;
        } else if (rigid) {
          const glm::vec3 toFace = centroids[f] - eye;
          value = axis.kind == PaletteAxisKind::Depth ? scale * glm::length(toFace) : paletteAxisValue(axis.kind, toFace, faceNormals[f]);
        } else {
          const glm::vec3 p0 = pos[idx[3 * f]], p1 = pos[idx[3 * f + 1]], p2 = pos[idx[3 * f + 2]];
          const glm::vec3 centre = glm::vec3(modelView * glm::vec4((p0 + p1 + p2) * (1.0f / 3.0f), 1.0f));
          value = paletteAxisValue(axis.kind, centre, normalMatrix * glm::cross(p1 - p0, p2 - p0));
        }
        const int row = static_cast<int>(paletteRowAt(value, axisMap, axis.rows) + 0.5f);
        shading_.entry[f] = static_cast<std::uint8_t>(std::min<int>(columns_[f], columns - 1) + row * columns);
      }
    });
    bucketTriangles(*mesh_, columns * axis.rows, 0, shading_);
  } else {
    shading_.entry = columns_;  // the axis turned off: back to the columns
    bucketTriangles(*mesh_, std::max(columns, 1), 0, shading_);
  }
  gl::uploadBuffer(bucketIndices_, shading_.bucketIndices.data(), shading_.bucketIndices.size() * sizeof(std::uint32_t), GL_STREAM_DRAW);
  bucketsUploaded_ = true;
  boundsValid_ = false;
  ++stats.bufferUploads;
  stats.nonEmptyBuckets = shading_.nonEmptyBuckets;
  stats.cpuShadingMs += msSince(t0);
  columnsFresh_ = false;
  layered_ = rows;
  rowsView_ = modelView;
  rowsMap_ = axisMap;
  rowsCount_ = axis.rows;
  rowsDetail_ = detail;
}

void TriangleShadingCache::updateBounds(const glm::mat4& mvp, const glm::ivec2& size, FrameStats& stats) {
  if (mvp != projectedWith_ || size != projectedSize_ || projectedMesh_ != meshId_) {
    const auto t0 = std::chrono::steady_clock::now();
    projectVertices(vertices_->positions, mvp, size, 0, screenVertices_);
    stats.cpuShadingMs += msSince(t0);
    projectedWith_ = mvp;
    projectedSize_ = size;
    projectedMesh_ = meshId_;
    boundsValid_ = false;
  }
  if (!boundsValid_) {
    const auto t0 = std::chrono::steady_clock::now();
    computeBucketBounds(screenVertices_, size, 0, shading_);
    stats.cpuShadingMs += msSince(t0);
    boundsValid_ = true;
  }
}

}  // namespace npr
