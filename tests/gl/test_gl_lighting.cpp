// GL tier: the GLSL lighting equals the CPU lighting within 1/255 per channel on thousands
// of random points, normals, lights and materials.
#include <gtest/gtest.h>

#include <random>

#include "gl/gl_test_env.h"
#include "renderer/lighting/lighting_model.h"
#include "support/lighting_probe.h"

namespace npr {
namespace {

LightingState randomState(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f), s(-1.0f, 1.0f);
  LightingState st;
  const int lights = 1 + int(rng() % 8);
  for (int i = 0; i < 8; ++i) {
    const GLenum L = GL_LIGHT0 + GLenum(i);
    if (i >= lights) {
      (void)st.Disable(L);
      continue;
    }
    (void)st.Enable(L);
    const float amb[4] = {u(rng) * 0.3f, u(rng) * 0.3f, u(rng) * 0.3f, 1}, dif[4] = {u(rng), u(rng), u(rng), 1},
                spe[4] = {u(rng), u(rng), u(rng), 1};
    (void)st.Lightfv(L, GL_AMBIENT, amb);
    (void)st.Lightfv(L, GL_DIFFUSE, dif);
    (void)st.Lightfv(L, GL_SPECULAR, spe);
    const bool positional = rng() % 2;
    const float pos[4] = {s(rng) * 4, s(rng) * 4, s(rng) * 4, positional ? 1.0f : 0.0f};
    (void)st.Lightfv(L, GL_POSITION, pos);
    if (rng() % 3 == 0) {
      const float dir[3] = {s(rng), s(rng), s(rng)};
      (void)st.Lightfv(L, GL_SPOT_DIRECTION, dir);
      (void)st.Lightf(L, GL_SPOT_CUTOFF, u(rng) * 90.0f);
      (void)st.Lightf(L, GL_SPOT_EXPONENT, u(rng) * 128.0f);
    }
    if (rng() % 3 == 0) {
      (void)st.Lightf(L, GL_CONSTANT_ATTENUATION, 0.2f + u(rng));
      (void)st.Lightf(L, GL_LINEAR_ATTENUATION, u(rng) * 0.5f);
      (void)st.Lightf(L, GL_QUADRATIC_ATTENUATION, u(rng) * 0.2f);
    }
  }
  for (GLenum face : {GLenum(GL_FRONT), GLenum(GL_BACK)}) {
    const float a[4] = {u(rng), u(rng), u(rng), 1}, d[4] = {u(rng), u(rng), u(rng), 1}, sp[4] = {u(rng), u(rng), u(rng), 1},
                e[4] = {u(rng) * 0.2f, u(rng) * 0.2f, u(rng) * 0.2f, 1};
    (void)st.Materialfv(face, GL_AMBIENT, a);
    (void)st.Materialfv(face, GL_DIFFUSE, d);
    if (rng() % 2) (void)st.Materialfv(face, GL_SPECULAR, sp);
    (void)st.Materialfv(face, GL_EMISSION, e);
    (void)st.Materialf(face, GL_SHININESS, u(rng) * 128.0f);
  }
  (void)st.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, int(rng() % 2));
  (void)st.LightModeli(GL_LIGHT_MODEL_TWO_SIDE, int(rng() % 2));
  if (rng() % 4 == 0) {  // the tone models go through the same comparison
    ToneParameters tp{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng) * 8.0f};
    const ToneModel tones[] = {ToneModel::Gooch, ToneModel::Splashback, ToneModel::Charcoal};
    (void)st.setToneModel(tones[rng() % 3], tp);
  }
  return st;
}

TEST(GlLighting, GlslMatchesCpuWithinOneStep) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> s(-1.0f, 1.0f);
  int compared = 0;
  double worst = 0.0;
  for (int state = 0; state < 40; ++state) {
    const LightingState st = randomState(rng);
    std::vector<LightingSample> samples;
    for (int i = 0; i < 256; ++i)
      samples.push_back({{s(rng) * 2, s(rng) * 2, -3.0f + s(rng) * 2}, {s(rng), s(rng), s(rng)}, rng() % 2 == 0});
    auto gpu = evaluateLightingOnGpu(st, samples);
    ASSERT_TRUE(gpu) << gpu.error();
    const auto prepared = prepareLighting<float>(st);
    for (size_t i = 0; i < samples.size(); ++i) {
      const glm::vec3 cpu = shade(prepared, samples[i].position, samples[i].normal, samples[i].back);
      for (int k = 0; k < 3; ++k) {
        const double diff = std::fabs(double(cpu[k]) - double((*gpu)[i][k]));
        worst = std::max(worst, diff);
        ASSERT_LE(diff, 1.0 / 255.0) << "state " << state << " sample " << i << " channel " << k << ": cpu " << cpu[k]
                                     << " gpu " << (*gpu)[i][k];
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 40 * 256);
  std::printf("worst CPU/GLSL difference over %d samples: %.3g\n", compared, worst);
}

TEST(GlLighting, DegenerateInputIsFiniteOnTheGpuToo) {
  LightingState st;
  const float pos[4] = {0, 0, -1, 1}, spec[4] = {1, 1, 1, 1};
  ASSERT_TRUE(st.Lightfv(GL_LIGHT0, GL_POSITION, pos));
  ASSERT_TRUE(st.Lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.0f));
  ASSERT_TRUE(st.Materialfv(GL_FRONT, GL_SPECULAR, spec));
  ASSERT_TRUE(st.LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1));
  const float nan = std::nanf("");
  const std::vector<LightingSample> samples = {
      {{0, 0, -1}, {0, 0, 1}}, {{0, 0, 0}, {0, 0, 1}}, {{0, 0, -2}, {0, 0, 0}}, {{0, 0, -2}, {nan, nan, nan}}, {{nan, 0, 0}, {0, 0, 1}}};
  auto gpu = evaluateLightingOnGpu(st, samples);
  ASSERT_TRUE(gpu) << gpu.error();
  for (const auto& c : *gpu)
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(c[k]) && c[k] >= 0.0f && c[k] <= 1.0f) << c[k];
}

}  // namespace
}  // namespace npr
