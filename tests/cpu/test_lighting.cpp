// CPU tier: the OpenGL 2.1 lighting equation against hand-computed values, OpenGL's
// defaults and validation, and stability at the extremes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/lighting/control_weights.h"
#include "renderer/lighting/lighting_model.h"

namespace npr {
namespace {

glm::vec3 shadeEye(const LightingState& s, glm::vec3 pos, glm::vec3 n, bool back = false) {
  return shade(prepareLighting<float>(s), pos, n, back);
}

void expectColour(const glm::vec3& c, float v, float tol = 1e-4f) {
  EXPECT_NEAR(c.r, v, tol);
  EXPECT_NEAR(c.g, v, tol);
  EXPECT_NEAR(c.b, v, tol);
}

bool finiteIn01(const glm::vec3& c) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(c[k]) || c[k] < 0.0f || c[k] > 1.0f) return false;
  return true;
}

TEST(LightingDefaults, MatchOpenGL) {
  LightingState s;
  EXPECT_EQ(s.light(0).diffuse, glm::vec4(1, 1, 1, 1));
  EXPECT_EQ(s.light(0).specular, glm::vec4(1, 1, 1, 1));
  EXPECT_EQ(s.light(1).diffuse, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(s.light(7).specular, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(s.light(3).ambient, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(s.light(0).position, glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(s.light(0).spotDirection, glm::vec3(0, 0, -1));
  EXPECT_EQ(s.light(0).spotCutoff, 180.0f);
  EXPECT_EQ(s.light(0).spotExponent, 0.0f);
  EXPECT_EQ(s.light(0).constantAttenuation, 1.0f);
  EXPECT_EQ(s.front().ambient, glm::vec4(0.2f, 0.2f, 0.2f, 1));
  EXPECT_EQ(s.front().diffuse, glm::vec4(0.8f, 0.8f, 0.8f, 1));
  EXPECT_EQ(s.front().specular, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(s.front().emission, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(s.front().shininess, 0.0f);
  EXPECT_EQ(s.modelAmbient(), glm::vec4(0.2f, 0.2f, 0.2f, 1));
  EXPECT_FALSE(s.localViewer());
  EXPECT_FALSE(s.twoSided());
}

TEST(LightingTerms, AmbientAndDiffuseWithDefaults) {
  LightingState s;
  // 0.2 x 0.2 light-model ambient + 0.8 diffuse x (n . L = 1)
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, 1}), 0.84f);
  // Perpendicular and facing away: ambient only.
  expectColour(shadeEye(s, {0, 0, -3}, {1, 0, 0}), 0.04f);
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, -1}), 0.04f);
  // Unnormalised normals are normalised.
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, 7}), 0.84f);
}

TEST(LightingTerms, EmissionAndLightAmbient) {
  LightingState s;
  const float e[4] = {0.1f, 0.1f, 0.1f, 1};
  const float a[4] = {0.5f, 0.5f, 0.5f, 1};
  ASSERT_TRUE(s.Materialfv(GL_FRONT, GL_EMISSION, e));
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_AMBIENT, a));
  // 0.1 + 0.04 + 0.5 x 0.2 (light ambient x material ambient), facing away from the light
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, -1}), 0.24f);
}

TEST(LightingTerms, SpecularInfiniteAndLocalViewer) {
  LightingState s;
  const float spec[4] = {0.1f, 0.1f, 0.1f, 1};
  ASSERT_TRUE(s.Materialfv(GL_FRONT, GL_SPECULAR, spec));
  ASSERT_TRUE(s.Materialf(GL_FRONT, GL_SHININESS, 2.0f));
  const glm::vec3 n = glm::normalize(glm::vec3(0, 1, 1));
  // n.L = n.h = 0.7071 (h = (0,0,1)): 0.04 + 0.8 x 0.7071 + 0.1 x 0.5
  expectColour(shadeEye(s, {0, 0, -3}, n), 0.04f + 0.8f * 0.70710678f + 0.05f);
  // Local viewer at (1,0,0): h = normalize((0,0,1) + (-1,0,0)), n.h = 0.7071 for n = +z
  ASSERT_TRUE(s.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1));
  expectColour(shadeEye(s, {1, 0, 0}, {0, 0, 1}), 0.04f + 0.8f + 0.1f * 0.5f);
  ASSERT_TRUE(s.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 0));
  expectColour(shadeEye(s, {1, 0, 0}, {0, 0, 1}), 0.04f + 0.8f + 0.1f);
}

TEST(LightingTerms, SpecularNeedsTheLightOnTheFrontOfTheSurface) {
  LightingState s;
  const float spec[4] = {1, 1, 1, 1};
  ASSERT_TRUE(s.Materialfv(GL_FRONT, GL_SPECULAR, spec));
  // Shininess 0: (n.h)^0 = 1, but only where n.L > 0 (f_i in the spec).
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, -1}), 0.04f);
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, 1}), 1.0f);
}

TEST(LightingTerms, PositionalLightWithAttenuation) {
  LightingState s;
  const float pos[4] = {0, 0, 2, 1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1.0f));
  ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.5f));
  ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.25f));
  // d = 2: 1 / (1 + 1 + 1) = 1/3
  expectColour(shadeEye(s, {0, 0, 0}, {0, 0, 1}), 0.04f + 0.8f / 3.0f);
}

TEST(LightingTerms, Spotlight) {
  LightingState s;
  const float pos[4] = {0, 0, 2, 1};
  const float dir[3] = {0, 0, -1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, dir));
  ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30.0f));
  ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2.0f));
  expectColour(shadeEye(s, {0, 0, 0}, {0, 0, 1}), 0.84f);  // on the axis: spot factor 1
  // At (1,0,0): cos = 2/sqrt(5) = 0.894 > cos 30; spot = 0.8; n.L = 0.894
  expectColour(shadeEye(s, {1, 0, 0}, {0, 0, 1}), 0.04f + 0.8f * 0.894427f * 0.8f);
  // At (2,0,0): cos = 0.707 < cos 30: outside the cone
  expectColour(shadeEye(s, {2, 0, 0}, {0, 0, 1}), 0.04f);
}

TEST(LightingTerms, TwoSidedUsesBackMaterialAndFlippedNormal) {
  LightingState s;
  const float back[4] = {0.5f, 0.5f, 0.5f, 1};
  ASSERT_TRUE(s.Materialfv(GL_BACK, GL_DIFFUSE, back));
  // One-sided: the back face is lit with the front material and the unflipped normal.
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, -1}, true), 0.04f);
  ASSERT_TRUE(s.LightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1));
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, -1}, true), 0.04f + 0.5f);
}

TEST(LightingTerms, SeveralLightsAddAndClamp) {
  LightingState s;
  const float white[4] = {1, 1, 1, 1};
  const float pos[4] = {0, 0, 1, 0};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT1, GL_DIFFUSE, white));
  ASSERT_TRUE(s.Lightfv(GL_LIGHT1, GL_POSITION, pos));
  ASSERT_TRUE(s.Enable(GL_LIGHT1));
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, 1}), 1.0f);  // 0.04 + 0.8 + 0.8, clamped
  ASSERT_TRUE(s.Disable(GL_LIGHT1));
  expectColour(shadeEye(s, {0, 0, -3}, {0, 0, 1}), 0.84f);
}

TEST(LightingTerms, LightingOffGivesTheCurrentColour) {
  LightingState s;
  ASSERT_TRUE(s.Disable(GL_LIGHTING));
  expectColour(shadeEye(s, {0, 0, -3}, {1, 0, 0}), 1.0f);
}

TEST(LightingState, PositionIsTransformedByTheModelviewWhenSet) {
  LightingState s;
  s.setModelView(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -5)));
  const float pos[4] = {0, 0, 2, 1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  EXPECT_EQ(s.light(0).position, glm::vec4(0, 0, -3, 1));
  s.setModelView(glm::mat4(1.0f));  // a later modelview does not move it
  EXPECT_EQ(s.light(0).position, glm::vec4(0, 0, -3, 1));
  s.setModelView(glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)));
  const float dir[3] = {0, 0, -1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, dir));
  EXPECT_NEAR(s.light(0).spotDirection.x, -1.0f, 1e-6f);
}

TEST(LightingState, InvalidParametersAreRefusedAndChangeNothing) {
  LightingState s;
  const unsigned rev = s.revision();
  const float v95 = 95.0f, vneg = -1.0f, v129 = 129.0f, nan = std::numeric_limits<float>::quiet_NaN();
  const float inf4[4] = {INFINITY, 0, 0, 1};
  struct Case { Status st; };
  const Status refused[] = {
      s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, v95),
      s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, vneg),
      s.Lightf(GL_LIGHT0, GL_SPOT_EXPONENT, vneg),
      s.Lightf(GL_LIGHT0, GL_SPOT_EXPONENT, v129),
      s.Lightf(GL_LIGHT0, GL_SPOT_EXPONENT, nan),
      s.Lightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, vneg),
      s.Lightf(GL_LIGHT0 + 8, GL_SPOT_CUTOFF, 10.0f),
      s.Lightfv(GL_LIGHT0, GL_POSITION, inf4),
      s.Materialf(GL_FRONT, GL_SHININESS, v129),
      s.Materialf(GL_FRONT, GL_SHININESS, vneg),
      s.Materialfv(GL_FRONT, GL_DIFFUSE, inf4),
      s.Materialfv(GL_LIGHT0, GL_DIFFUSE, inf4),
      s.Enable(GL_LIGHT0 + 8),
  };
  for (const Status& st : refused) {
    EXPECT_FALSE(st);
    EXPECT_NE(st.error().find("unchanged"), std::string::npos) << st.error();
  }
  EXPECT_EQ(s.revision(), rev);
  EXPECT_EQ(s.light(0).spotCutoff, 180.0f);
  EXPECT_EQ(s.light(0).spotExponent, 0.0f);
  EXPECT_EQ(s.front().shininess, 0.0f);
  EXPECT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f));
  EXPECT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90.0f));
  EXPECT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 0.0f));
}

TEST(LightingFeatures, DescribeOnlyWhatIsUsed) {
  LightingState s;
  LightingFeatures f = s.features();
  EXPECT_EQ(f.lightCount, 1);
  EXPECT_FALSE(f.specular);  // material specular is black by default
  EXPECT_FALSE(f.spot);
  EXPECT_FALSE(f.attenuation);
  EXPECT_FALSE(f.positional);
  const float spec[4] = {1, 1, 1, 1};
  ASSERT_TRUE(s.Materialfv(GL_FRONT, GL_SPECULAR, spec));
  ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 45.0f));
  const float pos[4] = {1, 2, 3, 1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  f = s.features();
  EXPECT_TRUE(f.specular);
  EXPECT_TRUE(f.spot);
  EXPECT_TRUE(f.positional);
  EXPECT_FALSE(f.attenuation);  // (1, 0, 0) is no attenuation
  const auto defines = f.glslDefines();
  EXPECT_NE(std::find(defines.begin(), defines.end(), "HAS_SPOT"), defines.end());
  EXPECT_NE(std::find(defines.begin(), defines.end(), "NUM_LIGHTS 1"), defines.end());
}

TEST(ToneModels, GoochCoolToWarm) {
  LightingState s;
  ASSERT_TRUE(s.setToneModel(ToneModel::Gooch, ToneParameters{}));
  // k_cool = (0,0,0.4) + 0.2 x 0.8 = (0.16,0.16,0.56); k_warm = (0.4,0.4,0) + 0.6 x 0.8 = (0.88,0.88,0.48)
  const glm::vec3 facing = shadeEye(s, {0, 0, -3}, {0, 0, 1});  // towards the light: warm
  EXPECT_NEAR(facing.r, 0.88f, 1e-5f);
  EXPECT_NEAR(facing.b, 0.48f, 1e-5f);
  const glm::vec3 away = shadeEye(s, {0, 0, -3}, {0, 0, -1});  // away: cool
  EXPECT_NEAR(away.r, 0.16f, 1e-5f);
  EXPECT_NEAR(away.b, 0.56f, 1e-5f);
  const glm::vec3 side = shadeEye(s, {0, 0, -3}, {1, 0, 0});  // halfway
  EXPECT_NEAR(side.r, 0.52f, 1e-5f);
  EXPECT_NEAR(side.b, 0.52f, 1e-5f);
  const std::vector<std::string> defines = s.features().glslDefines();  // one vector: find needs one range
  EXPECT_NE(std::find(defines.begin(), defines.end(), "TONE_GOOCH"), defines.end());
}

TEST(ToneModels, SplashbackMultiplier) {
  LightingState s;
  ToneParameters p;
  p.splashAlpha = 0.5f;
  p.splashPower = 2.0f;
  ASSERT_TRUE(s.setToneModel(ToneModel::Splashback, p));
  // Perpendicular to the light: (0.5 x 0 + 0.5)^2 = 0.25 times the Gooch 0.52
  EXPECT_NEAR(shadeEye(s, {0, 0, -3}, {1, 0, 0}).g, 0.52f * 0.25f, 1e-5f);
  // Facing or opposite the light: |cos| = 1, factor 1
  EXPECT_NEAR(shadeEye(s, {0, 0, -3}, {0, 0, 1}).r, 0.88f, 1e-5f);
  EXPECT_NEAR(shadeEye(s, {0, 0, -3}, {0, 0, -1}).b, 0.56f, 1e-5f);
  // A tilted normal: cos = 0.6, factor (0.3 + 0.5)^2 = 0.64; t = 0.2: 0.2 k_cool + 0.8 k_warm
  const glm::vec3 c = shadeEye(s, {0, 0, -3}, {0.8f, 0, 0.6f});
  EXPECT_NEAR(c.r, (0.2f * 0.16f + 0.8f * 0.88f) * 0.64f, 1e-5f);
}

TEST(ToneModels, CharcoalIsOnePlusViewDotNormalOverThree) {
  LightingState s;
  ASSERT_TRUE(s.setToneModel(ToneModel::Charcoal, ToneParameters{}));
  // Facing the eye: 2/3; at the silhouette (normal across the ray to the eye): 1/3; facing
  // away: 0. The true direction to the eye counts, not the view axis: a point off the axis
  // whose normal is the axis is not at its brightest.
  EXPECT_NEAR(shadeEye(s, {0, 0, -3}, {0, 0, 1}).r, 2.0f / 3.0f, 1e-5f);
  EXPECT_NEAR(shadeEye(s, {0, 0, -3}, {1, 0, 0}).g, 1.0f / 3.0f, 1e-5f);
  EXPECT_NEAR(shadeEye(s, {0, 0, -3}, {0, 0, -1}).b, 0.0f, 1e-5f);
  EXPECT_NEAR(shadeEye(s, {3, 0, -3}, {-1, 0, 1}).r, 2.0f / 3.0f, 1e-5f);
  EXPECT_NEAR(shadeEye(s, {3, 0, -3}, {0, 0, 1}).r, (1.0f + std::sqrt(0.5f)) / 3.0f, 1e-5f);
  // Lights and materials play no part.
  const float red[4] = {1, 0, 0, 1};
  ASSERT_TRUE(s.Materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red));
  EXPECT_NEAR(shadeEye(s, {0, 0, -3}, {0, 0, 1}).g, 2.0f / 3.0f, 1e-5f);
  const std::vector<std::string> defines = s.features().glslDefines();
  EXPECT_NE(std::find(defines.begin(), defines.end(), "TONE_CHARCOAL"), defines.end());
}

TEST(ToneModels, ParametersAreValidated) {
  LightingState s;
  ToneParameters bad;
  bad.alpha = 1.5f;
  EXPECT_FALSE(s.setToneModel(ToneModel::Gooch, bad));
  bad = ToneParameters{};
  bad.splashPower = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(s.setToneModel(ToneModel::Splashback, bad));
  EXPECT_EQ(s.toneModel(), ToneModel::OpenGL);
}

// ---- Extremes: always finite and within [0,1] ------------------------------------------

TEST(LightingExtremes, AttenuationZeroOrHuge) {
  for (float k : {0.0f, 1e30f, 3e38f}) {
    LightingState s;
    const float pos[4] = {0, 0, 1, 1};
    ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
    ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, k));
    ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, k));
    ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, k));
    const glm::vec3 c = shadeEye(s, {0, 0, 0}, {0, 0, 1});
    EXPECT_TRUE(finiteIn01(c)) << k;
    if (k == 0.0f) expectColour(c, 1.0f);  // infinite light: saturates, as OpenGL would clamp
    else expectColour(c, 0.04f, 1e-3f);     // no light arrives
  }
}

TEST(LightingExtremes, LightAtTheSurfacePoint) {
  LightingState s;
  const float pos[4] = {1, 2, 3, 1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  expectColour(shadeEye(s, {1, 2, 3}, {0, 0, 1}), 0.84f);  // lit head-on, not NaN
  ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.0f));
  EXPECT_TRUE(finiteIn01(shadeEye(s, {1, 2, 3}, {0, 0, 1})));
}

TEST(LightingExtremes, DegenerateNormalsAndPositions) {
  LightingState s;
  const float spec[4] = {1, 1, 1, 1};
  ASSERT_TRUE(s.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec));
  ASSERT_TRUE(s.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1));
  const float pos[4] = {0, 0, 1, 1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (glm::vec3 n : {glm::vec3(0), glm::vec3(nan), glm::vec3(inf, 0, 0), glm::vec3(1e-30f, 0, 0)})
    EXPECT_TRUE(finiteIn01(shadeEye(s, {0, 0, -1}, n)));
  expectColour(shadeEye(s, {0, 0, -1}, glm::vec3(0)), 0.04f);  // zero normal: ambient only
  for (glm::vec3 p : {glm::vec3(nan), glm::vec3(inf), glm::vec3(-inf, 0, 0), glm::vec3(0)})
    EXPECT_TRUE(finiteIn01(shadeEye(s, p, {0, 0, 1})));
}

TEST(LightingExtremes, SpotCutoffsExponentsAndShininess) {
  for (float cutoff : {0.0f, 90.0f, 180.0f})
    for (float exponent : {0.0f, 128.0f})
      for (float shininess : {0.0f, 128.0f}) {
        LightingState s;
        const float pos[4] = {0, 0, 2, 1}, spec[4] = {1, 1, 1, 1};
        ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
        ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff));
        ASSERT_TRUE(s.Lightf(GL_LIGHT0, GL_SPOT_EXPONENT, exponent));
        ASSERT_TRUE(s.Materialfv(GL_FRONT, GL_SPECULAR, spec));
        ASSERT_TRUE(s.Materialf(GL_FRONT, GL_SHININESS, shininess));
        for (glm::vec3 p : {glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 3)})
          EXPECT_TRUE(finiteIn01(shadeEye(s, p, {0, 0, 1}))) << cutoff << " " << exponent << " " << shininess;
        // On the axis, below the light: a cutoff of 0 still lights exactly there.
        if (cutoff == 0.0f) {
          EXPECT_GT(shadeEye(s, {0, 0, 0}, {0, 0, 1}).r, 0.5f);
        }
      }
}

TEST(LightingExtremes, HugeAndNegativeColours) {
  LightingState s;
  const float huge[4] = {3e38f, 3e38f, 3e38f, 1}, neg[4] = {-3e38f, -3e38f, -3e38f, 1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_DIFFUSE, huge));
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_SPECULAR, huge));
  ASSERT_TRUE(s.Materialfv(GL_FRONT, GL_SPECULAR, huge));
  ASSERT_TRUE(s.Lightfv(GL_LIGHT1, GL_AMBIENT, neg));
  ASSERT_TRUE(s.Enable(GL_LIGHT1));
  for (glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0)})
    EXPECT_TRUE(finiteIn01(shadeEye(s, {0, 0, -2}, n)));
}

TEST(LightingExtremes, RandomStatesAreAlwaysFiniteAndInRange) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos01(0.0f, 1.0f);
  const float specials[] = {0.0f, -0.0f, 1e-38f, 1e38f, -1e38f, std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
  auto any = [&]() { return (rng() % 4 == 0) ? specials[rng() % 8] : u(rng) * 10.0f; };
  for (int iter = 0; iter < 2000; ++iter) {
    LightingState s;
    for (int i = 0; i < 8; ++i) {
      const float c[4] = {any(), any(), any(), 1}, p[4] = {any(), any(), any(), float(rng() % 2)};
      (void)s.Lightfv(GL_LIGHT0 + i, GL_DIFFUSE, c);
      (void)s.Lightfv(GL_LIGHT0 + i, GL_SPECULAR, c);
      (void)s.Lightfv(GL_LIGHT0 + i, GL_POSITION, p);
      (void)s.Lightf(GL_LIGHT0 + i, GL_SPOT_CUTOFF, rng() % 2 ? 180.0f : pos01(rng) * 90.0f);
      (void)s.Lightf(GL_LIGHT0 + i, GL_SPOT_EXPONENT, pos01(rng) * 128.0f);
      (void)s.Lightf(GL_LIGHT0 + i, GL_QUADRATIC_ATTENUATION, std::fabs(any()));
      if (rng() % 2) (void)s.Enable(GL_LIGHT0 + i);
    }
    (void)s.Materialf(GL_FRONT_AND_BACK, GL_SHININESS, pos01(rng) * 128.0f);
    const float sc[4] = {any(), any(), any(), 1};
    (void)s.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, sc);
    (void)s.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, int(rng() % 2));
    (void)s.LightModeli(GL_LIGHT_MODEL_TWO_SIDE, int(rng() % 2));
    const glm::vec3 c = shadeEye(s, {any(), any(), any()}, {any(), any(), any()}, rng() % 2);
    ASSERT_TRUE(finiteIn01(c)) << iter << ": " << c.r << " " << c.g << " " << c.b;
    const glm::dvec3 d = shade(prepareLighting<double>(s), glm::dvec3(u(rng)), glm::dvec3(u(rng), u(rng), 1.0), false);
    ASSERT_TRUE(std::isfinite(d.x) && d.x >= 0.0 && d.x <= 1.0);
  }
}

TEST(LightingSpaces, ObjectSpaceEqualsEyeSpaceForRigidModelview) {
  // The renderer lights in object space when the modelview is rigid: same result.
  LightingState s;
  const float pos[4] = {0.5f, 1.0f, 2.0f, 1}, spec[4] = {0.5f, 0.5f, 0.5f, 1};
  ASSERT_TRUE(s.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  ASSERT_TRUE(s.Materialfv(GL_FRONT, GL_SPECULAR, spec));
  ASSERT_TRUE(s.Materialf(GL_FRONT, GL_SHININESS, 20.0f));
  ASSERT_TRUE(s.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1));
  const glm::mat4 mv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, -0.2f, -4.0f)), 0.7f, glm::vec3(0.3f, 1.0f, 0.2f));
  const auto eye = prepareLighting<float>(s);
  const auto obj = prepareLighting<float>(s, glm::inverse(mv));
  const glm::vec3 p(0.3f, 0.2f, 0.1f), n = glm::normalize(glm::vec3(0.2f, 0.5f, 0.8f));
  const glm::vec3 pe = glm::vec3(mv * glm::vec4(p, 1)), ne = glm::mat3(mv) * n;
  const glm::vec3 a = shade(eye, pe, ne), b = shade(obj, p, n);
  EXPECT_NEAR(a.r, b.r, 1e-5f);
  EXPECT_GT(a.r, 0.1f);
}

TEST(ControlWeights, PartitionOfUnityAtEveryParameterIncludingExtremes) {
  // Control-image palettes: the main, occlusion and shadow weights sum to 1 and stay in [0, 1]
  // for any parameters, NaN and infinities included; an absent palette's weight is 0.
  const float values[] = {0.0f, 1e-7f, 0.25f, 0.5f, 0.999f, 1.0f, -1.0f, 2.0f, INFINITY, -INFINITY, NAN};
  for (float sh : values)
    for (float oc : values)
      for (int present = 0; present < 4; ++present) {
        const bool hasShadow = present & 1, hasOcclusion = present & 2;
        const ControlWeights w = controlWeights(sh, oc, hasShadow, hasOcclusion);
        SCOPED_TRACE(testing::Message() << sh << " " << oc << " " << present);
        EXPECT_NEAR(w.main + w.occlusion + w.shadow, 1.0f, 1e-6f);
        for (float x : {w.main, w.occlusion, w.shadow}) EXPECT_TRUE(x >= 0.0f && x <= 1.0f);
        if (!hasShadow) {
          EXPECT_EQ(w.shadow, 0.0f);
        }
        if (!hasOcclusion) {
          EXPECT_EQ(w.occlusion, 0.0f);
        }
      }
  // Full shadow is the shadow palette alone; a crevice in the light blends by its depth.
  EXPECT_EQ(controlWeights(1.0f, 0.7f, true, true).shadow, 1.0f);
  EXPECT_FLOAT_EQ(controlWeights(0.0f, 0.3f, true, true).occlusion, 0.3f);
  EXPECT_FLOAT_EQ(controlWeights(0.5f, 0.5f, true, true).main, 0.25f);
  EXPECT_FLOAT_EQ(controlWeights(NAN, 0.0f, true, true).main, 1.0f);
}

}  // namespace
}  // namespace npr
