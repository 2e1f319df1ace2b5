// Per-triangle lighting, matching and bucketing (see triangle_shading.h).
#include "renderer/shading/triangle_shading.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/core/parallel.h"

namespace npr {

std::vector<glm::u8vec4> packFaceScale(const std::vector<glm::vec3>& scale) {
  std::vector<glm::u8vec4> out(scale.size());
  for (std::size_t i = 0; i < scale.size(); ++i)
    out[i] = glm::u8vec4(glm::vec4(glm::clamp(scale[i], 0.0f, 1.0f) * 255.0f + 0.5f, 255.0f));
  return out;
}

bool isSimilarity(const glm::mat4& m) {
  const glm::mat3 r(m);
  const float s2 = glm::dot(r[0], r[0]);
  if (!(s2 > 1e-12f) || !std::isfinite(s2) || glm::determinant(r) <= 0.0f) return false;
  const glm::mat3 d = glm::transpose(r) * r / s2 - glm::mat3(1.0f);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k)
      if (!(std::fabs(d[c][k]) < 1e-4f)) return false;
  return m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f;
}

namespace {

// The common case, specialised: directional lights, and positional ones without attenuation
// or spot, an infinite viewer and one-sided lighting (the viewer's default light is such a
// point light). Then every light's ambient folds into the base colour; a directional light's
// direction and half vector are constants, so only the face normal is read per triangle; a
// point light adds the centroid and two square roots. pow() for the specular term comes from
// a table over [0, 1] with linear interpolation (error below 1e-4 for shininess up to 128, far
// under the 1/255 that matching can see).
struct SimpleLighting {
  int count = 0;
  glm::vec3 base{0.0f};
  glm::vec3 emission{0.0f}, ambientBase{0.0f};  // base = emission + ambientBase
  glm::vec3 position[kMaxLights];  // directional: unit direction; positional: the point
  glm::vec3 half[kMaxLights];      // directional only
  glm::vec3 diffuse[kMaxLights], specular[kMaxLights];
  bool positional[kMaxLights] = {};
  bool anyPositional = false, hasSpecular = false;
  glm::vec3 viewDirection{0, 0, 1};
  static constexpr int kPowSteps = 4096;
  std::vector<float> powTable;

  static bool applies(const PreparedLighting<float>& p) {
    if (!p.lighting || p.localViewer || p.twoSided || p.tone != ToneModel::OpenGL) return false;
    for (int i = 0; i < p.count; ++i) {
      const auto& l = p.lights[i];
      if (l.spot) return false;
      if (l.positional && !(l.k0 == 1.0f && l.k1 == 0.0f && l.k2 == 0.0f)) return false;
    }
    return true;
  }

  explicit SimpleLighting(const PreparedLighting<float>& p, bool powTableAlways = false)
      : count(p.count), base(p.base[0]), hasSpecular(p.specular), viewDirection(p.viewDirection) {
    for (int i = 0; i < count; ++i) {
      const auto& l = p.lights[i];
      base += l.ambient[0];
      position[i] = l.position;
      positional[i] = l.positional;
      anyPositional = anyPositional || l.positional;
      half[i] = l.positional ? glm::vec3(0.0f) : lighting_detail::safeNormalize(l.position + p.viewDirection);
      diffuse[i] = l.diffuse[0];
      specular[i] = l.specular[0];
    }
    emission = p.emission[0];
    ambientBase = base - emission;
    if (hasSpecular || powTableAlways) {
      powTable.resize(kPowSteps + 2);
      for (int k = 0; k <= kPowSteps; ++k) powTable[static_cast<size_t>(k)] = lighting_detail::powGL(float(k) / kPowSteps, p.shininess[0]);
      powTable[kPowSteps + 1] = powTable[kPowSteps];
    }
  }
};

// One light at one triangle, for the specialised loops below: n.l times `diffuse` into
// `scaled`, the highlight times `specular` into `unscaled` (the same variable when nothing
// scales the material). Inlined into each loop, so what the caller keeps in registers stays
// there.
template <bool kSpecular, bool kPositional>
inline void addLight(const glm::vec3& nrm, const glm::vec3& centroid, const glm::vec3& position, const glm::vec3& directionalHalf,
                     bool point, const glm::vec3& view, const glm::vec3& diffuse, const glm::vec3& specular, const float* pow,
                     glm::vec3& scaled, glm::vec3& unscaled) {
  glm::vec3 vp = position, h = directionalHalf;
  float ndl;
  if (kPositional && point) {
    const glm::vec3 d = position - centroid;
    const float dist2 = glm::dot(d, d);
    if (dist2 > 0.0f && dist2 <= std::numeric_limits<float>::max()) {
      // Facing away needs no square root: the sign of n.d is the sign of n.vp.
      const float nd = glm::dot(nrm, d);
      if (nd <= 0.0f) return;
      // One division per normalisation (glm's vector / scalar divides each component).
      const float inv = 1.0f / std::sqrt(dist2);
      vp = d * inv;
      ndl = nd * inv;
    } else {
      // A light at the point has no direction: lit head-on, as the general model does.
      vp = nrm;
      ndl = glm::dot(nrm, nrm);
    }
  } else {
    ndl = glm::dot(nrm, vp);
  }
  if (ndl <= 0.0f) return;
  scaled += ndl * diffuse;
  if (kSpecular) {
    if (kPositional && point) {
      h = vp + view;
      const float len2 = glm::dot(h, h);
      h *= len2 > 0.0f && len2 <= std::numeric_limits<float>::max() ? 1.0f / std::sqrt(len2) : 0.0f;
    }
    const float t = lighting_detail::clamp01(glm::dot(nrm, h)) * float(SimpleLighting::kPowSteps);  // NaN: 0
    const int k = static_cast<int>(t);
    unscaled += (pow[k] + (t - float(k)) * (pow[k + 1] - pow[k])) * specular;
  }
}

// The inner loop, specialised so that everything it reads stays in registers: a loop over
// lights with run-time count and flags kept the lights in memory and the loop counter on the
// stack (the byte stores could alias them), at about twice the cost per triangle. kScale: the
// ambient and diffuse sum is scaled by each triangle's colour (`scale`, a mesh's maps or
// vertex colours).
template <int kLights, bool kSpecular, bool kPositional, bool kScale = false>
void shadeSimpleLoop(const SimpleLighting& light, const glm::u8vec4* __restrict scale, const PaletteMatcher::UnitLookup lookup,
                     const glm::vec3* __restrict centroids, const glm::vec3* __restrict normals, size_t n,
                     std::uint8_t* __restrict entry, std::uint32_t* __restrict cnt) {
  const int count = kLights > 0 ? kLights : light.count;
  const glm::vec3 base = kScale ? light.ambientBase : light.base, emission = light.emission, view = light.viewDirection;
  glm::vec3 pos[kMaxLights], half[kMaxLights], dif[kMaxLights], spe[kMaxLights];
  bool point[kMaxLights];
  for (int l = 0; l < count; ++l) {
    pos[l] = light.position[l];
    half[l] = light.half[l];
    dif[l] = light.diffuse[l];
    spe[l] = light.specular[l];
    point[l] = light.positional[l];
  }
  const float* pow = kSpecular ? light.powTable.data() : nullptr;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 nrm = normals[i];
    glm::vec3 c;
    if constexpr (kScale) {
      glm::vec3 sc = base;
      c = emission;
      for (int l = 0; l < count; ++l)
        addLight<kSpecular, kPositional>(nrm, centroids[i], pos[l], half[l], point[l], view, dif[l], spe[l], pow, sc, c);
      c += sc * (glm::vec3(scale[i]) * (1.0f / 255.0f));
    } else {
      c = base;
      for (int l = 0; l < count; ++l)
        addLight<kSpecular, kPositional>(nrm, centroids[i], pos[l], half[l], point[l], view, dif[l], spe[l], pow, c, c);
    }
    // NaN-safe clamp: with huge colours a sum can be inf - inf or inf x 0, and a NaN query
    // would index the lookup table out of bounds. NaN becomes 0, as in the general model.
    using lighting_detail::clamp01;
    const int k = lookup(glm::vec3(clamp01(c.r), clamp01(c.g), clamp01(c.b)));
    entry[i] = static_cast<std::uint8_t>(k);
    ++cnt[k];
  }
}

template <int kLights>
void shadeSimpleLights(const SimpleLighting& light, const PaletteMatcher::UnitLookup lookup, const glm::vec3* centroids,
                       const glm::vec3* normals, size_t n, std::uint8_t* entry, std::uint32_t* cnt) {
  if (light.hasSpecular)
    light.anyPositional ? shadeSimpleLoop<kLights, true, true>(light, nullptr, lookup, centroids, normals, n, entry, cnt)
                        : shadeSimpleLoop<kLights, true, false>(light, nullptr, lookup, centroids, normals, n, entry, cnt);
  else
    light.anyPositional ? shadeSimpleLoop<kLights, false, true>(light, nullptr, lookup, centroids, normals, n, entry, cnt)
                        : shadeSimpleLoop<kLights, false, false>(light, nullptr, lookup, centroids, normals, n, entry, cnt);
}

void shadeSimple(const SimpleLighting& light, const PaletteMatcher::UnitLookup lookup, const glm::vec3* centroids,
                 const glm::vec3* normals, size_t n, std::uint8_t* entry, std::uint32_t* cnt) {
  if (light.count == 1) shadeSimpleLights<1>(light, lookup, centroids, normals, n, entry, cnt);
  else shadeSimpleLights<0>(light, lookup, centroids, normals, n, entry, cnt);
}

// The same loop with a material per triangle, run by run: faces of one material come in runs
// (an OBJ's usemtl groups), and each run takes the one-material loop with that material's
// products in registers. Reading them from the triangle's row of the table instead cost 16
// materials by region 1.28-1.49x the one-material loop, against 1.14-1.18x so (bench_shading,
// Materials, the same runs).
template <int kLights, bool kSpecular, bool kPositional>
void shadeMaterialLoop(const SimpleLighting* table, const std::uint16_t* __restrict material, const glm::u8vec4* __restrict scale,
                       const PaletteMatcher::UnitLookup lookup, const glm::vec3* __restrict centroids,
                       const glm::vec3* __restrict normals, size_t n, std::uint8_t* __restrict entry, std::uint32_t* __restrict cnt) {
  for (size_t b = 0; b < n;) {
    const std::uint16_t m = material ? material[b] : 0;
    size_t e = b + 1;
    if (material) {
      while (e < n && material[e] == m) ++e;
    } else {
      e = n;
    }
    if (scale)
      shadeSimpleLoop<kLights, kSpecular, kPositional, true>(table[m], scale + b, lookup, centroids + b, normals + b, e - b, entry + b, cnt);
    else
      shadeSimpleLoop<kLights, kSpecular, kPositional, false>(table[m], nullptr, lookup, centroids + b, normals + b, e - b, entry + b, cnt);
    b = e;
  }
}

void shadeMaterials(const std::vector<SimpleLighting>& table, const std::uint16_t* material, const glm::u8vec4* scale,
                    const PaletteMatcher::UnitLookup lookup, const glm::vec3* centroids, const glm::vec3* normals, size_t n,
                    std::uint8_t* entry, std::uint32_t* cnt) {
  bool specular = false, positional = false;
  for (const SimpleLighting& l : table) {
    specular |= l.hasSpecular;
    positional |= l.anyPositional;
  }
  const SimpleLighting* t = table.data();
  const bool one = table[0].count == 1;
#define NPR_MATERIAL_LOOP(L, S, P) shadeMaterialLoop<L, S, P>(t, material, scale, lookup, centroids, normals, n, entry, cnt)
  if (specular) {
    if (positional) one ? NPR_MATERIAL_LOOP(1, true, true) : NPR_MATERIAL_LOOP(0, true, true);
    else one ? NPR_MATERIAL_LOOP(1, true, false) : NPR_MATERIAL_LOOP(0, true, false);
  } else {
    if (positional) one ? NPR_MATERIAL_LOOP(1, false, true) : NPR_MATERIAL_LOOP(0, false, true);
    else one ? NPR_MATERIAL_LOOP(1, false, false) : NPR_MATERIAL_LOOP(0, false, false);
  }
#undef NPR_MATERIAL_LOOP
}

}  // namespace

// Bucket offsets from per-chunk counts of out.entry (chunk c covering parallelChunks' c-th
// range of triangles) and, with `build`, the triangles' indices grouped by bucket.
static void scatterBuckets(const Mesh& mesh, const std::vector<std::vector<std::uint32_t>>& counts, int entries, int chunks, bool build,
                    TriangleShading& out) {
  const size_t nt = mesh.triangleCount();
  const std::uint8_t* entry = out.entry.data();
  out.nonEmptyBuckets = 0;
  out.bucketStart.assign(static_cast<size_t>(entries) + 1, 0);
  for (int k = 0; k < entries; ++k) {
    std::uint32_t total = 0;
    for (const auto& cnt : counts) total += cnt[static_cast<size_t>(k)];
    out.bucketStart[static_cast<size_t>(k) + 1] = out.bucketStart[static_cast<size_t>(k)] + total;
    out.nonEmptyBuckets += total > 0;
  }
  if (!build) return;

  // Each chunk writes its triangles of bucket k after those of the chunks before it, so the
  // scatter runs in parallel without atomics and the order within a bucket is the mesh order.
  std::vector<std::vector<std::uint32_t>> cursor(counts.size(), std::vector<std::uint32_t>(static_cast<size_t>(entries)));
  for (int k = 0; k < entries; ++k) {
    std::uint32_t at = out.bucketStart[static_cast<size_t>(k)];
    for (size_t c = 0; c < counts.size(); ++c) {
      cursor[c][static_cast<size_t>(k)] = at;
      at += counts[c][static_cast<size_t>(k)];
    }
  }
  out.bucketIndices.resize(nt * 3);
  const std::uint32_t* idx = mesh.indices.data();
  std::uint32_t* dst = out.bucketIndices.data();

  parallelChunks(nt, chunks, [&](size_t b, size_t e, int c) {
    std::uint32_t cur[kMaxPaletteEntries];  // thread-local cursors, as for the counts
    std::copy(cursor[static_cast<size_t>(c)].begin(), cursor[static_cast<size_t>(c)].end(), cur);
    for (size_t i = b; i < e; ++i) {
      const int k = entry[i];
      const std::uint32_t at = cur[k]++;
      dst[at * 3 + 0] = idx[i * 3 + 0];
      dst[at * 3 + 1] = idx[i * 3 + 1];
      dst[at * 3 + 2] = idx[i * 3 + 2];
    }
  });
}

void shadeTriangles(const Mesh& mesh, const LightingState& lighting, const glm::mat4& modelView,
                    const PaletteMatcher& matcher, const TriangleShadingOptions& opt, TriangleShading& out,
                    const FaceMaterials* fm) {
  const size_t nt = mesh.triangleCount();
  const int entries = matcher.size();
  out.entry.resize(nt);
  const bool rigid = isSimilarity(modelView);
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(modelView)));
  const int chunks = opt.threads > 0 ? opt.threads : workerCount();
  std::vector<std::vector<std::uint32_t>> counts(static_cast<size_t>(chunks), std::vector<std::uint32_t>(static_cast<size_t>(entries), 0));
  const glm::vec3* centroids = mesh.faceCentroids.data();
  const glm::vec3* normals = mesh.faceNormals.data();
  std::uint8_t* entry = out.entry.data();

  // One preparation per material when the mesh's own materials are drawn. One material and
  // no per-face colour is the lighting state's case with another material: today's loop.
  std::vector<PreparedLighting<float>> perMaterial;
  const std::uint16_t* faceMaterial = fm ? fm->faceMaterial : nullptr;
  const glm::u8vec4* faceScale = fm ? fm->faceScale : nullptr;
  PreparedLighting<float> p = prepareLighting<float>(lighting, rigid ? glm::inverse(modelView) : glm::mat4(1.0f));
  if (fm && fm->materials.size() == 1 && !faceScale) {
    p = prepareLighting<float>(lighting.withMaterial(fm->materials[0]), rigid ? glm::inverse(modelView) : glm::mat4(1.0f));
  } else if (fm && !fm->materials.empty()) {
    for (const Material& m : fm->materials)
      perMaterial.push_back(prepareLighting<float>(lighting.withMaterial(m), rigid ? glm::inverse(modelView) : glm::mat4(1.0f)));
  }

  if (!perMaterial.empty() && rigid && SimpleLighting::applies(perMaterial[0])) {
    std::vector<SimpleLighting> table;
    bool anySpecular = false;
    for (const auto& q : perMaterial) anySpecular |= q.specular;
    for (const auto& q : perMaterial) table.emplace_back(q, anySpecular);
    parallelChunks(nt, chunks, [&](size_t b, size_t e, int c) {
      std::uint32_t cnt[kMaxPaletteEntries] = {};
      shadeMaterials(table, faceMaterial ? faceMaterial + b : nullptr, faceScale ? faceScale + b : nullptr, matcher.unitLookup(),
                     centroids + b, normals + b, e - b, entry + b, cnt);
      std::copy(cnt, cnt + entries, counts[static_cast<size_t>(c)].begin());
    });
  } else if (!perMaterial.empty()) {
    parallelChunks(nt, chunks, [&](size_t b, size_t e, int c) {
      std::uint32_t cnt[kMaxPaletteEntries] = {};
      for (size_t i = b; i < e; ++i) {
        const PreparedLighting<float>& q = perMaterial[faceMaterial ? faceMaterial[i] : 0];
        glm::vec3 pos = centroids[i], n = normals[i];
        if (!rigid) {
          pos = glm::vec3(modelView * glm::vec4(pos, 1.0f));
          n = normalMatrix * n;
        }
        const bool back = q.twoSided && glm::dot(n, q.eye - pos) < 0.0f;
        const int k = matcher.match(shade(q, pos, n, back, faceScale ? glm::vec3(faceScale[i]) * (1.0f / 255.0f) : glm::vec3(1.0f)));
        entry[i] = static_cast<std::uint8_t>(k);
        ++cnt[k];
      }
      std::copy(cnt, cnt + entries, counts[static_cast<size_t>(c)].begin());
    });
  } else if (rigid && SimpleLighting::applies(p)) {
    const SimpleLighting fast(p);
    parallelChunks(nt, chunks, [&](size_t b, size_t e, int c) {
      // Counting into a thread-local array: the threads' shared vectors could sit on one
      // cache line, and incrementing them per triangle made two threads slower than one.
      std::uint32_t cnt[kMaxPaletteEntries] = {};
      shadeSimple(fast, matcher.unitLookup(), centroids + b, normals + b, e - b, entry + b, cnt);
      std::copy(cnt, cnt + entries, counts[static_cast<size_t>(c)].begin());
    });
  } else parallelChunks(nt, chunks, [&](size_t b, size_t e, int c) {
    std::uint32_t cnt[kMaxPaletteEntries] = {};
    for (size_t i = b; i < e; ++i) {
      glm::vec3 pos = centroids[i], n = normals[i];
      if (!rigid) {
        pos = glm::vec3(modelView * glm::vec4(pos, 1.0f));
        n = normalMatrix * n;
      }
      // Facing decides the material only under two-sided lighting; skip the test otherwise.
      const bool back = p.twoSided && glm::dot(n, p.eye - pos) < 0.0f;
      const int k = matcher.match(shade(p, pos, n, back));
      entry[i] = static_cast<std::uint8_t>(k);
      ++cnt[k];
    }
    std::copy(cnt, cnt + entries, counts[static_cast<size_t>(c)].begin());
  });

  scatterBuckets(mesh, counts, entries, chunks, opt.buildBuckets, out);
}

void bucketTriangles(const Mesh& mesh, int entries, int threads, TriangleShading& out) {
  const size_t nt = mesh.triangleCount();
  const int chunks = threads > 0 ? threads : workerCount();
  std::vector<std::vector<std::uint32_t>> counts(static_cast<size_t>(chunks), std::vector<std::uint32_t>(static_cast<size_t>(entries), 0));
  const std::uint8_t* entry = out.entry.data();
  parallelChunks(nt, chunks, [&](size_t b, size_t e, int c) {
    std::uint32_t cnt[kMaxPaletteEntries] = {};
    for (size_t i = b; i < e; ++i) ++cnt[std::min<int>(entry[i], entries - 1)];
    std::copy(cnt, cnt + entries, counts[static_cast<size_t>(c)].begin());
  });
  scatterBuckets(mesh, counts, entries, chunks, true, out);
}

void projectVertices(const std::vector<glm::vec3>& positions, const glm::mat4& modelViewProjection, const glm::ivec2& viewport, int threads,
                     std::vector<glm::vec2>& screen) {
  const size_t nv = positions.size();
  screen.resize(nv);
  const glm::vec2 half = glm::vec2(viewport) * 0.5f;
  parallelChunks(nv, threads > 0 ? threads : workerCount(), [&](size_t b, size_t e, int) {
    for (size_t v = b; v < e; ++v) {
      const glm::vec4 cp = modelViewProjection * glm::vec4(positions[v], 1.0f);
      // Behind the eye the projection is meaningless: mark it so the bucket spans the screen.
      screen[v] = cp.w > 1e-6f ? (glm::vec2(cp) / cp.w + 1.0f) * half : glm::vec2(NAN);
    }
  });
}

void computeBucketBounds(const std::vector<glm::vec2>& screen, const glm::ivec2& viewport, int threads, TriangleShading& shading) {
  const int entries = static_cast<int>(shading.bucketStart.size()) - 1;
  shading.bucketBounds.assign(static_cast<size_t>(std::max(entries, 0)), glm::ivec4(0));
  if (entries <= 0) return;
  const int chunks = threads > 0 ? threads : workerCount();
  // Per chunk and bucket, float extents; rounding and clamping happen once per bucket. A vertex
  // behind the eye (NaN) makes its bucket span the screen.
  struct Box {
    glm::vec2 lo{INFINITY}, hi{-INFINITY};
    bool behindEye = false;
  };
  std::vector<std::vector<Box>> partial(static_cast<size_t>(chunks), std::vector<Box>(static_cast<size_t>(entries)));
  const std::uint32_t* idx = shading.bucketIndices.data();
  const glm::vec2* pos = screen.data();
  const size_t nt = shading.bucketIndices.size() / 3;
  parallelChunks(nt, chunks, [&](size_t b, size_t e, int c) {
    Box* boxes = partial[static_cast<size_t>(c)].data();
    // Triangles are grouped by bucket: walk the bucket boundaries alongside, the current
    // bucket's box in registers.
    size_t k = static_cast<size_t>(std::upper_bound(shading.bucketStart.begin(), shading.bucketStart.end(), b) - shading.bucketStart.begin()) - 1;
    while (b >= shading.bucketStart[k + 1]) ++k;
    size_t next = shading.bucketStart[k + 1];
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    bool nan = false;
    for (size_t i = b; i < e; ++i) {
      if (i >= next) {
        boxes[k] = {lo, hi, nan};
        while (i >= shading.bucketStart[k + 1]) ++k;
        next = shading.bucketStart[k + 1];
        lo = glm::vec2(INFINITY);
        hi = glm::vec2(-INFINITY);
        nan = false;
      }
      const glm::vec2 p0 = pos[idx[i * 3]], p1 = pos[idx[i * 3 + 1]], p2 = pos[idx[i * 3 + 2]];
      nan |= std::isnan(p0.x + p0.y + p1.x + p1.y + p2.x + p2.y);
      // glm::min/max keep the first argument where the second is NaN.
      lo = glm::min(lo, glm::min(p0, glm::min(p1, p2)));
      hi = glm::max(hi, glm::max(p0, glm::max(p1, p2)));
    }
    if (e > b) boxes[k] = {lo, hi, nan};
  });
  const glm::vec2 limit = glm::vec2(viewport) + 2.0f;
  for (int k = 0; k < entries; ++k) {
    if (shading.bucketStart[size_t(k) + 1] == shading.bucketStart[size_t(k)]) continue;
    Box r;
    for (const auto& p : partial) {
      const Box& q = p[static_cast<size_t>(k)];
      r = {glm::min(r.lo, q.lo), glm::max(r.hi, q.hi), r.behindEye || q.behindEye};
    }
    if (r.behindEye) {
      shading.bucketBounds[static_cast<size_t>(k)] = glm::ivec4(0, 0, viewport.x, viewport.y);
      continue;
    }
    // One pixel of margin covers rasterisation rounding at the rectangle's edges.
    const glm::vec2 lo = glm::clamp(r.lo, glm::vec2(-2.0f), limit), hi = glm::clamp(r.hi, glm::vec2(-2.0f), limit);
    const glm::ivec4 q(int(std::floor(lo.x)) - 1, int(std::floor(lo.y)) - 1, int(std::ceil(hi.x)) + 1, int(std::ceil(hi.y)) + 1);
    if (q.z > q.x && q.w > q.y)
      shading.bucketBounds[static_cast<size_t>(k)] =
          glm::ivec4(std::max(q.x, 0), std::max(q.y, 0), std::min(q.z, viewport.x), std::min(q.w, viewport.y));
  }
}

}  // namespace npr
