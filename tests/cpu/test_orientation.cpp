// CPU tier: hatching orientation. Principal directions and the smoothed, combed direction field
// against analytic principal directions on generated surfaces (cylinder, torus, ellipsoid);
// the field on degenerate input; palette entries' stroke orientation on synthetic textures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <cmath>
#include <optional>

#include "renderer/mesh/mesh_builder.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/orientation/direction_field.h"
#include "renderer/orientation/principal_curvature.h"
#include "renderer/palette/palette_orientation.h"
#include "support/analytic_surfaces.h"

namespace npr {
namespace {

using test::degreesBetweenLines;
using test::Principal;

double median(std::vector<double> v) {
  if (v.empty()) return 1e9;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

double medianFieldError(const Mesh& m, const std::function<Principal(const glm::vec3&)>& analytic, std::size_t* counted = nullptr) {
  const test::FieldError e = test::fieldError(m, computeDirectionField(m).directions, analytic);
  if (counted) *counted = e.vertices;
  return e.medianDegrees;
}

Principal cylinderAt(const glm::vec3& p) { return test::cylinderPrincipal(p); }
Principal torusAt(const glm::vec3& p) { return test::torusPrincipal(p); }
Principal ellipsoidAt(const glm::vec3& p, const glm::vec3& radii) { return test::ellipsoidPrincipal(p, radii); }

TEST(PrincipalCurvature, CylinderCurvesOneWayAroundItsAxis) {
  const Mesh m = cylinder(96, 48);
  const PrincipalCurvatures pc = estimatePrincipalCurvatures(m);
  EXPECT_EQ(pc.weld.positions.size(), 96u * 49u);  // the seam's copies welded
  std::vector<double> k1, k2, err;
  for (std::size_t v = 0; v < pc.weld.positions.size(); ++v) {
    const glm::vec3 p = pc.weld.positions[v];
    if (std::fabs(p.y) > 0.7f) continue;  // the boundary rows have half a neighbourhood
    k1.push_back(std::fabs(pc.kMax[v]));
    k2.push_back(std::fabs(pc.kMin[v]));
    err.push_back(degreesBetweenLines(pc.maxDirection[v], cylinderAt(p).e1));
  }
  EXPECT_NEAR(median(k1), 2.0, 0.05);  // radius 0.5
  EXPECT_LT(median(k2), 0.05);
  EXPECT_LT(median(err), 1.0);
}

// (turned off the model's up axis, which the field's guide follows where curvature is weak)
TEST(DirectionField, FollowsPrincipalDirectionsOnACylinder) {
  const glm::mat3 r = test::obliqueRotation();
  std::size_t n = 0;
  const double e = medianFieldError(test::rotatedMesh(cylinder(96, 48), r), test::rotatedPrincipal(cylinderAt, r), &n);
  EXPECT_GT(n, 4000u);
  EXPECT_LE(e, 3.0);
}

TEST(DirectionField, FollowsPrincipalDirectionsOnATorus) {
  std::size_t n = 0;
  const glm::mat3 r = test::obliqueRotation();
  const double e = medianFieldError(test::rotatedMesh(torus(160, 80), r), test::rotatedPrincipal(torusAt, r), &n);
  EXPECT_GT(n, 10000u);  // all but the inner rim
  EXPECT_LE(e, 3.0);
}

TEST(DirectionField, FollowsPrincipalDirectionsOnAnEllipsoid) {
  const glm::vec3 radii(1.0f, 0.7f, 0.45f);
  std::size_t n = 0;
  const glm::mat3 r = test::obliqueRotation();
  const double e = medianFieldError(test::rotatedMesh(ellipsoid(160, 80, radii), r),
                                    test::rotatedPrincipal([&](const glm::vec3& p) { return ellipsoidAt(p, radii); }, r), &n);
  EXPECT_GT(n, 1000u);
  EXPECT_LE(e, 3.0);
}

TEST(DirectionField, FollowsPrincipalDirectionsOnAnIrregularEllipsoid) {
  // A subdivided icosahedron stretched into the ellipsoid: its edges do not run along the
  // principal directions, as the grids' do.
  const glm::vec3 radii(1.0f, 0.7f, 0.45f);
  Mesh m = icosphere(4);
  for (glm::vec3& p : m.positions) p *= radii;
  const glm::mat3 r = test::obliqueRotation();
  std::size_t n = 0;
  const double e = medianFieldError(test::rotatedMesh(m, r), test::rotatedPrincipal([&](const glm::vec3& p) { return ellipsoidAt(p, radii); }, r), &n);
  EXPECT_GT(n, 1000u);
  EXPECT_LE(e, 3.0);
}

TEST(DirectionField, CombedSoNeighboursAgreeOnACylinder) {
  // Combing picks one of the four directions per vertex so that neighbours agree: along every
  // edge of the cylinder the two directions are nearly parallel (not opposite, not crossed).
  const Mesh m = cylinder(96, 48);
  const DirectionField f = computeDirectionField(m);
  std::size_t bad = 0;
  for (std::size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 a = f.directions[m.indices[t * 3 + k]], b = f.directions[m.indices[t * 3 + (k + 1) % 3]];
      if (glm::dot(a, b) < 0.9f) ++bad;
    }
  EXPECT_EQ(bad, 0u);
  // ... and the strokes wrap around the form: the largest-curvature direction
  std::size_t around = 0;
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    if (degreesBetweenLines(f.directions[i], cylinderAt(m.positions[i]).e1) < 10.0) ++around;
  EXPECT_GT(around, m.positions.size() * 95 / 100);
}

// Triangles around which the combed field turns: the three directions, laid into the
// triangle's plane as 4-way values (angle times four), turn a whole number of times around it;
// any turn is a singular point of the hatching (a star or a fan of strokes).
std::size_t singularTriangles(const Mesh& m, const std::vector<glm::vec3>& directions) {
  std::size_t singular = 0;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::vec3 p0 = m.positions[m.indices[3 * t]], p1 = m.positions[m.indices[3 * t + 1]], p2 = m.positions[m.indices[3 * t + 2]];
    const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
    if (!(glm::dot(n, n) > 1e-20f)) continue;
    const glm::vec3 u = glm::normalize(p1 - p0), v = glm::normalize(glm::cross(glm::normalize(n), u));
    double angle[3];
    bool valid = true;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 d = directions[m.indices[3 * t + k]];
      const double x = glm::dot(d, u), y = glm::dot(d, v);
      valid = valid && x * x + y * y > 1e-6;
      angle[k] = 4.0 * std::atan2(y, x);
    }
    if (!valid) continue;
    double turn = 0.0;
    for (int k = 0; k < 3; ++k) turn += std::remainder(angle[(k + 1) % 3] - angle[k], 2.0 * M_PI);
    if (std::fabs(turn) > M_PI) ++singular;
  }
  return singular;
}

// The woodcut bunny's hatching converged into a star at the hip: a singular point that noisy
// curvature directions, held too hard, kept in place. Smoothing must cancel most such pairs.
TEST(DirectionField, FewSingularPointsOnTheBunny) {
  Result<Mesh> bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  ASSERT_TRUE(bunny) << bunny.error();
  const std::size_t singular = singularTriangles(*bunny, computeDirectionField(*bunny).directions);
  DirectionFieldOptions held;
  held.curvatureWeight = 2.0f;
  const std::size_t heldSingular = singularTriangles(*bunny, computeDirectionField(*bunny, held).directions);
  std::printf("bunny: %zu of %zu triangles hold a singular point of the hatching field (%zu with the curvature held at 2)\n", singular,
              bunny->triangleCount(), heldSingular);
  EXPECT_LE(singular, 40u);
  EXPECT_GT(heldSingular, 60u) << "the count no longer tells the weights apart";
}

bool finiteUnitOrZero(const glm::vec3& d) {
  if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) return false;
  const float l = glm::length(d);
  return l == 0.0f || std::fabs(l - 1.0f) < 1e-3f;
}

TEST(DirectionField, DegenerateInputGivesFiniteDirections) {
  // A plane (no curvature anywhere), zero-area and repeated-corner triangles, an isolated
  // vertex, duplicated vertices, a non-manifold fan of three faces on one edge, a lone triangle.
  std::vector<glm::vec3> v;
  std::vector<std::array<int, 3>> t;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) v.push_back(glm::vec3(i * 0.2f, j * 0.2f, 0.0f));
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      t.push_back({j * 6 + i, j * 6 + i + 1, (j + 1) * 6 + i + 1});
      t.push_back({j * 6 + i, (j + 1) * 6 + i + 1, (j + 1) * 6 + i});
    }
  const int base = int(v.size());
  v.insert(v.end(), {{2, 0, 0}, {3, 0, 0}, {4, 0, 0}});  // collinear: zero area
  t.push_back({base, base + 1, base + 2});
  v.push_back({9, 9, 9});  // isolated
  const int dup = int(v.size());
  v.insert(v.end(), {{0, 0, 0}, {0.2f, 0, 0}, {0.2f, 0.2f, 0}});  // a doubled face on duplicated vertices
  t.push_back({dup, dup + 1, dup + 2});
  const int fan = int(v.size());
  v.insert(v.end(), {{5, 0, 0}, {5, 1, 0}, {6, 0, 0}, {5, 0, 1}, {4, 0, 0.5f}});
  t.push_back({fan, fan + 1, fan + 2});
  t.push_back({fan, fan + 1, fan + 3});
  t.push_back({fan, fan + 1, fan + 4});
  Mesh m;
  buildTriMesh(v, t, m);
  finalizeMesh(m);
  const DirectionField f = computeDirectionField(m);
  ASSERT_EQ(f.directions.size(), m.positions.size());
  for (std::size_t i = 0; i < f.directions.size(); ++i) {
    EXPECT_TRUE(finiteUnitOrZero(f.directions[i])) << "vertex " << i;
    EXPECT_TRUE(std::isfinite(f.confidence[i]));
  }
  // The flat grid gets a calm field: every direction along one of the guide's quarter turns.
  for (int i = 0; i < 36; ++i) {
    const glm::vec3 d = f.directions[size_t(i)];
    ASSERT_NE(d, glm::vec3(0.0f));
    EXPECT_LT(std::min(degreesBetweenLines(d, {1, 0, 0}), degreesBetweenLines(d, {0, 1, 0})), 1.0) << "vertex " << i;
  }

  Mesh empty;
  EXPECT_TRUE(computeDirectionField(empty).directions.empty());
}

// A tiling texture of parallel lines whose strokes run at `degrees` (screen convention: y up),
// anti-aliased, period in texels; `second` adds a weaker family at degrees + 90.
ImageRGBA8 lineTexture(float degrees, float period = 8.0f, float second = 0.0f) {
  const int size = 128;
  ImageRGBA8 img{size, size, std::vector<std::uint8_t>(size_t(size) * size * 4, 255)};
  const double a = (degrees + 90.0) * M_PI / 180.0;  // the direction across the strokes
  const double nx = std::cos(a), ny = std::sin(a);
  for (int row = 0; row < size; ++row)
    for (int x = 0; x < size; ++x) {
      const double y = size - 1 - row;
      const double across = x * nx + y * ny, along = -x * ny + y * nx;
      double ink = 0.5 + 0.5 * std::cos(2 * M_PI * across / period);
      ink = std::max(ink, second * (0.5 + 0.5 * std::cos(2 * M_PI * along / period)));
      const auto g = std::uint8_t(std::lround(255.0 * (1.0 - ink)));
      for (int c = 0; c < 3; ++c) img.pixels[(size_t(row) * size + x) * 4 + c] = g;
    }
  return img;
}

double angleDifference(double a, double b) {
  const double d = std::fmod(std::fabs(a - b), 180.0);
  return std::min(d, 180.0 - d);
}

TEST(PaletteOrientation, LineTexturesAtKnownAnglesWithinTwoDegrees) {
  for (float deg : {0.0f, 10.0f, 30.0f, 45.0f, 60.0f, 90.0f, 112.5f, 135.0f, 170.0f}) {
    const TextureOrientation o = textureOrientation(lineTexture(deg), glm::vec3(1.0f));
    EXPECT_LE(angleDifference(o.degrees, deg), 2.0) << deg << " degrees: measured " << o.degrees;
    EXPECT_TRUE(o.oriented()) << deg << " degrees: strength " << o.strength;
  }
}

TEST(PaletteOrientation, CrosshatchTurnsByItsMainFamily) {
  // (3 degrees: where the families cross, max() bends the gradient a little)
  const TextureOrientation o = textureOrientation(lineTexture(30.0f, 8.0f, 0.6f), glm::vec3(1.0f));
  EXPECT_LE(angleDifference(o.degrees, 30.0), 3.0) << o.degrees;
  EXPECT_TRUE(o.oriented()) << o.strength;
}

TEST(PaletteOrientation, StippleAndBlankAreLeftUnrotated) {
  const int size = 128;
  ImageRGBA8 noise{size, size, std::vector<std::uint8_t>(size_t(size) * size * 4, 255)};
  std::uint32_t h = 12345;
  for (std::size_t i = 0; i < noise.pixels.size(); i += 4) {
    h = h * 1664525u + 1013904223u;
    const auto g = std::uint8_t((h >> 24) < 40 ? 0 : 255);  // random dots
    noise.pixels[i] = noise.pixels[i + 1] = noise.pixels[i + 2] = g;
  }
  const TextureOrientation dots = textureOrientation(noise, glm::vec3(1.0f));
  EXPECT_FALSE(dots.oriented()) << dots.strength;
  ImageRGBA8 blank{size, size, std::vector<std::uint8_t>(size_t(size) * size * 4, 255)};
  EXPECT_EQ(textureOrientation(blank, glm::vec3(1.0f)).strength, 0.0f);
  // Transparent strokes over the background colour: none of the texel colours matter.
  ImageRGBA8 clear = lineTexture(45.0f);
  for (std::size_t i = 3; i < clear.pixels.size(); i += 4) clear.pixels[i] = 0;
  EXPECT_FALSE(textureOrientation(clear, glm::vec3(1.0f)).oriented());
  EXPECT_EQ(textureOrientation(ImageRGBA8{}, glm::vec3(1.0f)).strength, 0.0f);
}

TEST(PaletteOrientation, SharedStrokeDirectionOnlyWhereEveryOrientedEntryAgrees) {
  auto entry = [](float degrees, float strength = 0.9f) { return TextureOrientation{degrees, strength}; };
  const TextureOrientation none = entry(0.0f, 0.1f);
  // 179.5 and 0.5 are one direction: the mean sits across the wrap, not at 90.
  const std::optional<float> wrap = sharedStrokeDegrees({none, entry(179.5f), entry(0.5f), none});
  ASSERT_TRUE(wrap.has_value());
  EXPECT_NEAR(std::min(*wrap, 180.0f - *wrap), 0.0f, 1e-3f);
  const std::optional<float> close = sharedStrokeDegrees({entry(44.0f), entry(46.0f)});
  ASSERT_TRUE(close.has_value());
  EXPECT_NEAR(*close, 45.0f, 1e-3f);
  EXPECT_FALSE(sharedStrokeDegrees({entry(40.0f), entry(46.0f)}).has_value());  // 3 degrees from their mean
  EXPECT_FALSE(sharedStrokeDegrees({entry(0.0f), entry(90.0f)}).has_value());   // cancel on doubled angles
  EXPECT_FALSE(sharedStrokeDegrees({none, none}).has_value());
}

}  // namespace
}  // namespace npr
