// CPU tier: the automatic tone range (renderer/palette/tone_range.h) and the matcher's tone
// target. A known distribution of lit tones gives its percentiles; the target fits the
// palette's levels onto them; the tracker never moves faster than its rate, settles on a
// steady estimate and holds still when nothing changes; sampling a lit sphere sees the tones
// the lighting model gives and only the front faces.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/mesh/mesh_generators.h"
#include "renderer/palette/palette_matcher.h"
#include "renderer/palette/tone_range.h"
#include "renderer/settings/choice_names.h"

namespace npr {
namespace {

std::vector<glm::vec3> greyLevels(int n) {
  std::vector<glm::vec3> v;
  for (int i = 0; i < n; ++i) v.push_back(glm::vec3(float(i) / float(n - 1)));  // level 0 .. 3
  return v;
}

TEST(ToneRange, PercentilesOfAKnownDistribution) {
  std::vector<ToneSample> s;
  for (int i = 0; i < 1000; ++i) s.push_back({3.0f * float(i) / 999.0f, 1.0f});
  auto r = percentileRange(s, 2.0f, 98.0f, 0.0f);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->x, 0.06f, 0.01f);
  EXPECT_NEAR(r->y, 2.94f, 0.01f);
  // Weights count: the upper half weighing 9 times the lower moves the 2nd percentile up.
  for (ToneSample& t : s) t.weight = t.query > 1.5f ? 9.0f : 1.0f;
  r = percentileRange(s, 2.0f, 98.0f, 0.0f);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->x, 0.3f, 0.02f);
  // A flat tone is widened to the minimum span about itself; nothing to weigh gives none.
  std::vector<ToneSample> flat(50, ToneSample{1.2f, 1.0f});
  r = percentileRange(flat, 2.0f, 98.0f, 0.2f);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->x, 1.1f, 1e-5f);
  EXPECT_NEAR(r->y, 1.3f, 1e-5f);
  std::vector<ToneSample> none{{1.0f, 0.0f}};
  EXPECT_FALSE(percentileRange(none, 2.0f, 98.0f, 0.2f));
}

TEST(ToneRange, TheTargetFitsThePalettesLevelsOntoIt) {
  for (MatchMode mode : {MatchMode::Intensity, MatchMode::Order}) {
    auto fixed = PaletteMatcher::create(greyLevels(10), mode, 1.0f);
    auto fitted = PaletteMatcher::create(greyLevels(10), mode, 1.0f, {}, glm::vec2(0.3f, 0.9f));
    ASSERT_TRUE(fixed && fitted);
    // Dark tones 0.3 .. 0.9 reach three levels at most with the palette's own range, and
    // every level once fitted onto them.
    std::set<int> before, after;
    for (int i = 0; i <= 600; ++i) {
      const float q = 0.3f + 0.6f * float(i) / 600.0f;
      const glm::vec3 lit(q / 3.0f);
      before.insert(fixed->match(lit));
      after.insert(fitted->match(lit));
    }
    EXPECT_LE(before.size(), 3u) << choiceName(mode);
    EXPECT_EQ(after.size(), 10u) << choiceName(mode);
    // The ends of the target are the palette's ends.
    EXPECT_EQ(fitted->match(glm::vec3(0.3f / 3.0f)), fixed->match(glm::vec3(0.0f)));
    EXPECT_EQ(fitted->match(glm::vec3(0.9f / 3.0f)), fixed->match(glm::vec3(1.0f)));
  }
  EXPECT_FALSE(PaletteMatcher::create(greyLevels(4), MatchMode::Intensity, 1.0f, {}, glm::vec2(1.0f, 1.0f)));
  EXPECT_FALSE(PaletteMatcher::create(greyLevels(4), MatchMode::Intensity, 1.0f, {}, glm::vec2(NAN, 1.0f)));
}

TEST(ToneRange, TheTrackerSmoothsBoundedAndSettles) {
  ToneRangeTracker t;
  EXPECT_FALSE(t.update(std::nullopt, 0.25f));
  auto first = t.update(glm::vec2(0.5f, 1.5f), 0.25f);
  ASSERT_TRUE(first);
  EXPECT_NEAR(first->x, 0.5f, ToneRangeTracker::kStep);
  // Estimates jumping by 0.4 every frame move the range by at most a quarter of that (plus
  // the quantisation) per frame: no pumping.
  glm::vec2 last = *first;
  for (int i = 0; i < 40; ++i) {
    const float j = i % 2 ? 0.4f : -0.4f;
    const glm::vec2 r = *t.update(glm::vec2(0.5f + j, 1.5f + j), 0.25f);
    EXPECT_LE(std::abs(r.x - last.x), 0.25f * 0.8f + ToneRangeTracker::kStep) << i;
    last = r;
  }
  // A steady estimate is reached and then held exactly (no rebuilds while still).
  for (int i = 0; i < 60; ++i) t.update(glm::vec2(0.2f, 2.2f), 0.25f);
  const glm::vec2 settled = *t.current();
  EXPECT_NEAR(settled.x, 0.2f, ToneRangeTracker::kStep);
  EXPECT_NEAR(settled.y, 2.2f, ToneRangeTracker::kStep);
  EXPECT_EQ(*t.update(glm::vec2(0.2f, 2.2f), 0.25f), settled);
}

TEST(ToneRange, SamplingSeesTheLitFrontOfASphere) {
  const Mesh sphere = icosphere(4);
  LightingState l;  // light 0: white, directional from +z (the eye's direction)
  const glm::mat4 view = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -3));
  const glm::mat4 projection = glm::perspective(glm::radians(40.0f), 1.0f, 0.1f, 10.0f);
  std::vector<ToneSample> s;
  sampleTones(sphere, l, view, projection, false, MatchMode::Intensity, 100000, s);
  // Front faces only: from 3 radii away the eye sees the cap within acos(1/3) of it, a third
  // of the sphere's area.
  EXPECT_GT(s.size(), sphere.triangleCount() * 30 / 100);
  EXPECT_LT(s.size(), sphere.triangleCount() * 37 / 100);
  // Default material: ambient 0.2 x 0.2 (model) and diffuse 0.8 N.L, light from the eye: tones
  // from 3 x (0.04 + 0.8 / 3) = 0.92 at that rim to 3 x 0.84 = 2.52 facing the light; weighted
  // by area on screen the rim's thin ring is little of the picture.
  auto r = percentileRange(s, 2.0f, 98.0f, 0.0f);
  ASSERT_TRUE(r);
  EXPECT_GT(r->x, 0.9f);
  EXPECT_LT(r->x, 1.5f);
  EXPECT_GT(r->y, 2.3f);
  EXPECT_LE(r->y, 2.53f);
  // A budget samples evenly: fewer samples, the same range within a few hundredths.
  std::vector<ToneSample> few;
  sampleTones(sphere, l, view, projection, false, MatchMode::Intensity, 512, few);
  EXPECT_LT(few.size(), 400u);
  auto rf = percentileRange(few, 2.0f, 98.0f, 0.0f);
  ASSERT_TRUE(rf);
  EXPECT_NEAR(rf->y, r->y, 0.08f);
}

}  // namespace
}  // namespace npr
