// CPU tier: per-triangle shading of a whole mesh (what the stencil and triangle paths draw)
// chooses, for every triangle, the entry the lighting model and matcher choose at its centroid
// in double precision; its buckets hold exactly those triangles, in mesh order; threads do not
// change the result. Covers the specialised directional loop and the general one.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/lighting/lighting_model.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/palette/palette_matcher.h"
#include "renderer/shading/triangle_shading.h"

namespace npr {
namespace {

struct Scene {
  const char* name;
  int lights;
  int pointLights;  // the first ones are positional, the rest directional
  bool attenuated;  // positional with attenuation: the general loop
  bool specular;
  MatchMode mode;
  float scale = 1.0f;  // the model's uniform scale in the modelview (a scene's object)
};

LightingState lightingFor(const Scene& sc) {
  LightingState l;
  for (int i = 0; i < sc.lights; ++i) {
    const float c = 0.9f / float(sc.lights);
    const float colour[4] = {c, c * 0.8f, c * 0.6f, 1};
    const bool point = i < sc.pointLights;
    const float pos[4] = {2.0f * std::cos(float(i) * 2.0f), 1.4f, 2.0f * std::sin(float(i) * 2.0f) + 1.0f, point ? 1.0f : 0.0f};
    EXPECT_TRUE(l.Enable(GL_LIGHT0 + GLenum(i)));
    EXPECT_TRUE(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_DIFFUSE, colour));
    EXPECT_TRUE(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_SPECULAR, colour));
    EXPECT_TRUE(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_POSITION, pos));
    if (sc.attenuated) {
      EXPECT_TRUE(l.Lightf(GL_LIGHT0 + GLenum(i), GL_QUADRATIC_ATTENUATION, 0.05f));
    }
  }
  if (sc.specular) {
    const float spec[4] = {0.6f, 0.6f, 0.6f, 1};
    EXPECT_TRUE(l.Materialfv(GL_FRONT, GL_SPECULAR, spec));
    EXPECT_TRUE(l.Materialf(GL_FRONT, GL_SHININESS, 40.0f));
  }
  return l;
}

std::vector<glm::vec3> paletteFor(MatchMode mode) {
  std::vector<glm::vec3> v;
  for (int i = 0; i < 12; ++i) {
    const float t = float(i) / 11.0f;
    // Colours: warm greys like the lit colours below, two hues interleaved.
    v.push_back(mode == MatchMode::Colors ? t * (i % 2 ? glm::vec3(1.0f, 0.9f, 0.4f) : glm::vec3(1.0f, 0.8f, 0.6f)) : glm::vec3(1.0f - t));
  }
  return v;
}

void PrintTo(const Scene& s, std::ostream* os) { *os << s.name; }

class TriangleShadingTest : public testing::TestWithParam<Scene> {};

TEST_P(TriangleShadingTest, MatchesTheDoublePrecisionModelAtEveryCentroid) {
  const Scene sc = GetParam();
  const Mesh mesh = torus(60, 40);
  const LightingState l = lightingFor(sc);
  auto matcher = PaletteMatcher::create(paletteFor(sc.mode), sc.mode, 1.0f);
  ASSERT_TRUE(matcher) << matcher.error();
  // A similarity (rigid, or with the uniform scale of a scene's object): the loops light in
  // object space, the reference in eye space.
  const glm::mat4 view = glm::lookAt(glm::vec3(1.5f, 1.0f, 2.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(sc.scale));
  ASSERT_TRUE(isSimilarity(view));
  TriangleShadingOptions opt;
  opt.buildBuckets = true;
  opt.threads = 2;
  TriangleShading out;
  shadeTriangles(mesh, l, view, *matcher, opt, out);

  const size_t nt = mesh.triangleCount();
  ASSERT_EQ(out.entry.size(), nt);
  const auto ref = prepareLighting<double>(l);
  const glm::dmat3 normalMatrix = glm::dmat3(glm::transpose(glm::inverse(glm::mat3(view))));
  size_t exact = 0, nearBoundary = 0;
  std::vector<int> seen(static_cast<size_t>(matcher->size()), 0);
  for (size_t i = 0; i < nt; ++i) {
    const glm::dvec3 pos = glm::dvec3(view * glm::vec4(mesh.faceCentroids[i], 1.0f));
    const glm::dvec3 c = shade(ref, pos, glm::normalize(normalMatrix * glm::dvec3(mesh.faceNormals[i])), false);
    const int want = matcher->match(glm::vec3(c));
    const int got = out.entry[i];
    seen[static_cast<size_t>(got)] = 1;
    if (got == want) {
      ++exact;
      continue;
    }
    // Float lighting may fall on the other side of a tone boundary: then a tiny change of
    // the lit colour must give the entry the loop chose.
    const glm::vec3 lo = glm::vec3(c) - 2e-3f, hi = glm::vec3(c) + 2e-3f;
    const bool boundary = matcher->match(glm::clamp(lo, 0.0f, 1.0f)) == got || matcher->match(glm::clamp(hi, 0.0f, 1.0f)) == got;
    ASSERT_TRUE(boundary) << sc.name << ": triangle " << i << " got entry " << got << ", the model says " << want;
    ++nearBoundary;
  }
  EXPECT_LT(double(nearBoundary), 0.002 * double(nt)) << sc.name;
  // The scene must exercise the palette, or the comparison says little.
  int used = 0;
  for (int s : seen) used += s;
  EXPECT_GE(used, 5) << sc.name;

  // Buckets: every triangle once, grouped by entry, in mesh order within a bucket.
  ASSERT_EQ(out.bucketStart.size(), static_cast<size_t>(matcher->size()) + 1);
  ASSERT_EQ(out.bucketStart.back(), nt);
  ASSERT_EQ(out.bucketIndices.size(), nt * 3);
  int nonEmpty = 0;
  size_t at = 0;
  for (int k = 0; k < matcher->size(); ++k) {
    nonEmpty += out.bucketStart[size_t(k) + 1] > out.bucketStart[size_t(k)];
    for (size_t i = 0; i < nt; ++i) {
      if (out.entry[i] != k) continue;
      for (int v = 0; v < 3; ++v) ASSERT_EQ(out.bucketIndices[at * 3 + size_t(v)], mesh.indices[i * 3 + size_t(v)]) << "bucket " << k;
      ++at;
    }
    ASSERT_EQ(at, out.bucketStart[size_t(k) + 1]) << "bucket " << k << " size";
  }
  EXPECT_EQ(out.nonEmptyBuckets, nonEmpty);

  // One thread gives the same entries and buckets as two.
  TriangleShading single;
  opt.threads = 1;
  shadeTriangles(mesh, l, view, *matcher, opt, single);
  EXPECT_EQ(single.entry, out.entry);
  EXPECT_EQ(single.bucketIndices, out.bucketIndices);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, TriangleShadingTest,
    testing::Values(Scene{"one directional light, specular", 1, 0, false, true, MatchMode::Intensity},
                    Scene{"one directional light, no specular", 1, 0, false, false, MatchMode::Intensity},
                    Scene{"three directional lights, specular, order", 3, 0, false, true, MatchMode::Order},
                    Scene{"two directional lights, colours", 2, 0, false, true, MatchMode::Colors},
                    Scene{"one point light, specular", 1, 1, false, true, MatchMode::Intensity},
                    Scene{"two point lights, no specular", 2, 2, false, false, MatchMode::Intensity},
                    Scene{"a point and a directional light, specular", 2, 1, false, true, MatchMode::Order},
                    Scene{"two attenuated point lights (general loop)", 2, 2, true, true, MatchMode::Intensity},
                    Scene{"a point and a directional light, scaled by 0.4", 2, 1, false, true, MatchMode::Order, 0.4f},
                    Scene{"two attenuated point lights, scaled by 2.5", 2, 2, true, true, MatchMode::Intensity, 2.5f}),
    [](const testing::TestParamInfo<Scene>& info) { return "Scene" + std::to_string(info.index); });

// A material per face, in runs of every length from one face up (the loop takes the faces of
// a run together) and with a colour per face: every triangle's entry is what the
// double-precision model gives with its own material and colour.
TEST(TriangleShadingMaterials, EachFaceLitWithItsMaterialAndColour) {
  const Mesh mesh = torus(60, 40);
  const size_t nt = mesh.triangleCount();
  for (bool point : {false, true}) {
    LightingState l;
    const float white[4] = {0.9f, 0.85f, 0.8f, 1}, pos[4] = {1.2f, 1.4f, 2.0f, point ? 1.0f : 0.0f};
    ASSERT_TRUE(l.Enable(GL_LIGHT0));
    ASSERT_TRUE(l.Lightfv(GL_LIGHT0, GL_DIFFUSE, white));
    ASSERT_TRUE(l.Lightfv(GL_LIGHT0, GL_SPECULAR, white));
    ASSERT_TRUE(l.Lightfv(GL_LIGHT0, GL_POSITION, pos));
    FaceMaterials fm;
    for (int m = 0; m < 5; ++m) {
      Material mat;
      mat.diffuse = glm::vec4(0.3f + 0.15f * float(m), 0.9f - 0.12f * float(m), 0.5f, 1.0f);
      mat.ambient = mat.diffuse * 0.25f;
      mat.specular = glm::vec4(glm::vec3(m % 2 ? 0.5f : 0.0f), 1.0f);
      mat.shininess = 10.0f + 20.0f * float(m);
      mat.emission = glm::vec4(glm::vec3(m == 3 ? 0.1f : 0.0f), 1.0f);
      fm.materials.push_back(mat);
    }
    // Runs of 1, 2, 3, ... faces, cycling through the materials; colours vary per face.
    std::vector<std::uint16_t> material(nt);
    std::vector<glm::u8vec4> colour(nt);
    for (size_t i = 0, run = 1, left = 1, m = 0; i < nt; ++i) {
      material[i] = std::uint16_t(m);
      colour[i] = glm::u8vec4(255 - (i * 7) % 160, 255 - (i * 13) % 120, 200 + (i % 56), 255);
      if (--left == 0) {
        m = (m + 1) % fm.materials.size();
        left = ++run % 40 + 1;
      }
    }
    fm.faceMaterial = material.data();
    for (bool scaled : {false, true}) {
      fm.faceScale = scaled ? colour.data() : nullptr;
      for (MatchMode mode : {MatchMode::Intensity, MatchMode::Colors}) {
        auto matcher = PaletteMatcher::create(paletteFor(mode), mode, 1.0f);
        ASSERT_TRUE(matcher) << matcher.error();
        const glm::mat4 view = glm::lookAt(glm::vec3(1.5f, 1.0f, 2.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
        TriangleShadingOptions opt;
        opt.threads = 2;
        TriangleShading out;
        shadeTriangles(mesh, l, view, *matcher, opt, out, &fm);
        ASSERT_EQ(out.entry.size(), nt);
        std::vector<PreparedLighting<double>> ref;
        for (const Material& m : fm.materials) ref.push_back(prepareLighting<double>(l.withMaterial(m)));
        const glm::dmat3 normalMatrix = glm::dmat3(glm::transpose(glm::inverse(glm::mat3(view))));
        size_t nearBoundary = 0;
        std::vector<int> seen(static_cast<size_t>(matcher->size()), 0);
        for (size_t i = 0; i < nt; ++i) {
          const glm::dvec3 eyePos = glm::dvec3(view * glm::vec4(mesh.faceCentroids[i], 1.0f));
          const glm::dvec3 scale = scaled ? glm::dvec3(colour[i]) / 255.0 : glm::dvec3(1.0);
          const glm::dvec3 c = shade(ref[material[i]], eyePos, normalMatrix * glm::dvec3(mesh.faceNormals[i]), false, scale);
          const int want = matcher->match(glm::vec3(c)), got = out.entry[i];
          seen[size_t(got)] = 1;
          if (got == want) continue;
          const glm::vec3 lo = glm::vec3(c) - 2e-3f, hi = glm::vec3(c) + 2e-3f;
          const bool boundary = matcher->match(glm::clamp(lo, 0.0f, 1.0f)) == got || matcher->match(glm::clamp(hi, 0.0f, 1.0f)) == got;
          ASSERT_TRUE(boundary) << "triangle " << i << " (material " << material[i] << (scaled ? ", coloured" : "") << (point ? ", point light" : "")
                                << ") got entry " << got << ", the model says " << want;
          ++nearBoundary;
        }
        EXPECT_LT(double(nearBoundary), 0.002 * double(nt));
        int used = 0;
        for (int u : seen) used += u;
        EXPECT_GE(used, 5);
      }
    }
  }
}

// Huge and opposite light colours (inf - inf, inf x 0 in the sums) must still give an entry of
// the palette: the loops clamp NaN to 0 before the lookup table is indexed.
TEST(TriangleShadingExtremes, HugeAndOppositeColoursStayInThePalette) {
  const Mesh mesh = torus(30, 20);
  for (bool point : {false, true}) {
    LightingState l;
    const float huge[4] = {3e38f, -3e38f, 3e38f, 1}, negative[4] = {-3e38f, 3e38f, -3e38f, 1};
    for (int i = 0; i < 2; ++i) {
      const float pos[4] = {float(i) - 0.5f, 1.0f, 2.0f, point ? 1.0f : 0.0f};
      ASSERT_TRUE(l.Enable(GL_LIGHT0 + GLenum(i)));
      ASSERT_TRUE(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_DIFFUSE, i ? negative : huge));
      ASSERT_TRUE(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_SPECULAR, i ? huge : negative));
      ASSERT_TRUE(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_AMBIENT, i ? huge : negative));
      ASSERT_TRUE(l.Lightfv(GL_LIGHT0 + GLenum(i), GL_POSITION, pos));
    }
    // Light x material products overflow to +-inf; a zero specular power times inf is NaN.
    const float big[4] = {3e38f, 3e38f, 3e38f, 1};
    ASSERT_TRUE(l.Materialfv(GL_FRONT, GL_SPECULAR, big));
    ASSERT_TRUE(l.Materialfv(GL_FRONT, GL_DIFFUSE, big));
    ASSERT_TRUE(l.Materialf(GL_FRONT, GL_SHININESS, 128.0f));
    for (MatchMode mode : {MatchMode::Intensity, MatchMode::Order, MatchMode::Colors}) {
      auto matcher = PaletteMatcher::create(paletteFor(mode), mode, 1.0f);
      ASSERT_TRUE(matcher) << matcher.error();
      TriangleShading out;
      shadeTriangles(mesh, l, glm::mat4(1.0f), *matcher, {}, out);
      ASSERT_EQ(out.entry.size(), mesh.triangleCount());
      for (std::uint8_t e : out.entry) ASSERT_LT(int(e), matcher->size()) << (point ? "point" : "directional");
      EXPECT_EQ(out.bucketStart.back(), mesh.triangleCount());
    }
  }
}

}  // namespace
}  // namespace npr
