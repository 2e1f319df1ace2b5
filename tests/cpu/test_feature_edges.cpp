// CPU tier: feature edges from adjacency on small meshes built here: the cube's creases, a
// sphere's silhouette loop, an open grid's boundary, and a polygon soup that must give the
// same lines as the welded mesh; a two-material cube's material boundaries. Intersection lines
// of two crossing boxes (the square where they meet, exactly, as two objects, one object or
// placed by a transform), none on a closed surface or apart, and the hierarchy's answer equal
// to testing every pair. Traced palette regions (--svg-fill) cover exactly their pixels.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/lines/feature_edges.h"
#include "renderer/lines/intersection_lines.h"
#include "renderer/lines/region_trace.h"
#include "renderer/lines/suggestive_contours.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/mesh/scene_loader.h"
#include "renderer/lines/svg_export.h"
#include "renderer/mesh/mesh_builder.h"
#include "renderer/immediate_api.h"
#include "renderer/mesh/mesh_generators.h"

namespace npr {
namespace {

const glm::vec3 kCube[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
const int kCubeFaces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                               {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};

Mesh weldedCube() {
  Mesh m;
  std::vector<glm::vec3> verts(std::begin(kCube), std::end(kCube));
  std::vector<std::array<int, 3>> tris;
  for (const auto& f : kCubeFaces) tris.push_back({f[0], f[1], f[2]});
  buildTriMesh(verts, tris, m);
  finalizeMesh(m);
  return m;
}

std::vector<Triangle> cubeSoup() {
  std::vector<Triangle> tris;
  for (const auto& f : kCubeFaces) tris.push_back({{kCube[f[0]], kCube[f[1]], kCube[f[2]]}});
  return tris;
}

size_t countKind(const std::vector<FeatureLine>& lines, EdgeKind k) {
  return size_t(std::count_if(lines.begin(), lines.end(), [&](const FeatureLine& l) { return l.kind == float(k); }));
}

TEST(FeatureEdges, CubeHasTwelveCreasesAt60AndNoneAt100) {
  const Mesh cube = weldedCube();
  FeatureEdges e(cube);
  EXPECT_EQ(e.manifoldEdges(), 18u);  // 12 cube edges + 6 face diagonals
  EXPECT_EQ(countKind(e.staticLines(60.0f), EdgeKind::Crease), 12u);
  EXPECT_EQ(countKind(e.staticLines(60.0f), EdgeKind::Boundary), 0u);
  EXPECT_EQ(countKind(e.staticLines(100.0f), EdgeKind::Crease), 0u);
  EXPECT_EQ(countKind(e.staticLines(89.0f), EdgeKind::Crease), 12u);
}

TEST(FeatureEdges, SoupWithUnweldedVerticesAndADoubledFaceGivesTheSameCreases) {
  std::vector<Triangle> soup = cubeSoup();
  soup.push_back(soup[3]);  // a doubled face
  const Mesh m = meshFromTriangles(soup);
  ASSERT_EQ(m.positions.size(), 39u);  // nothing shared in the file
  FeatureEdges e(m);
  EXPECT_EQ(e.weldedVertices(), 8u);
  EXPECT_EQ(e.duplicateFaces(), 1u);
  const auto& lines = e.staticLines(60.0f);
  EXPECT_EQ(countKind(lines, EdgeKind::Crease), 12u);
  EXPECT_EQ(countKind(lines, EdgeKind::Boundary), 0u);  // seams in the file are not edges
  // The creases are the cube's edges: both ends differ in exactly one coordinate.
  for (const auto& l : lines) EXPECT_EQ(int(l.a.x != l.b.x) + int(l.a.y != l.b.y) + int(l.a.z != l.b.z), 1);
}

TEST(FeatureEdges, SphereSilhouetteIsAClosedLoopThatMovesWithTheEye) {
  const Mesh sphere = icosphere(3);
  FeatureEdges e(sphere);
  auto loopCheck = [&](const glm::vec3& eye) {
    const auto lines = e.silhouettes(eye);
    EXPECT_GT(lines.size(), 10u);
    std::map<std::tuple<float, float, float>, int> degree;
    for (const auto& l : lines) {
      ++degree[{l.a.x, l.a.y, l.a.z}];
      ++degree[{l.b.x, l.b.y, l.b.z}];
      // Silhouette edges lie where the surface turns away: near the great circle facing the eye.
      const glm::vec3 mid = glm::normalize(0.5f * (l.a + l.b));
      EXPECT_LT(std::fabs(glm::dot(mid, glm::normalize(eye))), 0.45f);
    }
    for (const auto& [v, d] : degree) EXPECT_EQ(d % 2, 0) << "open end at a vertex of degree " << d;
    return lines;
  };
  const auto fromZ = loopCheck({0, 0, 5});
  const auto fromX = loopCheck({5, 0, 0});
  // Different views, different edges.
  size_t shared = 0;
  for (const auto& a : fromZ)
    for (const auto& b : fromX) shared += (a.a == b.a && a.b == b.b);
  EXPECT_LT(shared, fromZ.size() / 2);
}

TEST(FeatureEdges, OpenGridHasItsBorderAsBoundary) {
  std::vector<Triangle> tris;
  const int n = 5;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::vec3 a(x, y, 0), b(x + 1, y, 0), c(x + 1, y + 1, 0), d(x, y + 1, 0);
      tris.push_back({{a, b, c}});
      tris.push_back({{a, c, d}});
    }
  FeatureEdges e(meshFromTriangles(tris));
  const auto& lines = e.staticLines(60.0f);
  EXPECT_EQ(countKind(lines, EdgeKind::Boundary), size_t(4 * n));
  EXPECT_EQ(countKind(lines, EdgeKind::Crease), 0u);
  EXPECT_TRUE(e.silhouettes({2.5f, 2.5f, 10.0f}).empty());  // a flat sheet seen from the front
}

TEST(FeatureEdges, NonManifoldEdgesAreJunctions) {
  // Three triangles on one edge: the third is refused by the halfedge structure.
  const std::vector<Triangle> tris = {{{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}},
                                      {{glm::vec3(1, 0, 0), glm::vec3(0, 0, 0), glm::vec3(0, -1, 0)}},
                                      {{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)}}};
  FeatureEdges e(meshFromTriangles(tris));
  EXPECT_GE(e.junctionEdges(), 1u);
  // Every junction is drawn with the boundaries; no edge is lost or doubled.
  EXPECT_EQ(countKind(e.staticLines(60.0f), EdgeKind::Boundary), 7u);
}

}  // namespace
}  // namespace npr

namespace npr {
namespace {

// Vector export: edges that share ends chain into polylines in drawing order; a closed outline
// is one closed chain; a surface in front cuts a line.
TEST(SvgExport, EdgesChainAtSharedEndsAndHiddenPartsAreCut) {
  CameraMatrices cam;
  cam.view = glm::lookAt(glm::vec3(0, 0, 3), glm::vec3(0), glm::vec3(0, 1, 0));
  cam.projection = glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 10.0f);
  const glm::ivec2 size(200, 200);
  ImageRGBA32F empty{200, 200, std::vector<float>(200 * 200 * 4, 0.0f)};  // no surface anywhere
  const float s = float(EdgeKind::Silhouette), c = float(EdgeKind::Crease);
  const glm::vec3 p[4] = {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
  // The square's sides listed out of order, one reversed, plus a crease elsewhere.
  const std::vector<FeatureLine> lines = {{p[2], p[3], s}, {p[0], p[1], s}, {p[2], p[1], s}, {p[3], p[0], s},
                                          {{0.8f, 0.8f, 0}, {0.9f, 0.9f, 0}, c}};
  const SvgLines out = visibleLineChains(lines, cam, size, empty);
  ASSERT_EQ(out.chains[0].size(), 1u);
  const auto& loop = out.chains[0][0];
  ASSERT_EQ(loop.size(), 5u);
  EXPECT_LT(glm::length(loop.front() - loop.back()), 1e-3f);
  for (size_t i = 1; i < loop.size(); ++i) EXPECT_GT(glm::length(loop[i] - loop[i - 1]), 10.0f) << "consecutive points are the sides' ends";
  EXPECT_EQ(out.chains[1].size(), 1u);
  EXPECT_EQ(out.paths, 2);
  // A surface in front of the square's left half (eye z -1, the square at -3) hides that part.
  ImageRGBA32F front = empty;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 100; ++x) {
      front.pixels[(size_t(y) * 200 + size_t(x)) * 4 + 2] = -1.0f;
      front.pixels[(size_t(y) * 200 + size_t(x)) * 4 + 3] = 1.0f;
    }
  const SvgLines cut = visibleLineChains(lines, cam, size, front);
  for (const auto& chain : cut.chains[0])
    for (const glm::vec2& q : chain) EXPECT_GE(q.x, 98.0f) << "a point of a hidden part was kept";
  EXPECT_LT(cut.lengthPx, 0.7 * out.lengthPx);
  EXPECT_GT(cut.lengthPx, 0.3 * out.lengthPx);
  // The hidden parts (--hidden-lines, a set's visibility=hidden): the other half.
  const SvgLines behind = visibleLineChains(lines, cam, size, front, true);
  for (const auto& chain : behind.chains[0])
    for (const glm::vec2& q : chain) EXPECT_LE(q.x, 102.0f) << "a point of a visible part was kept";
  EXPECT_NEAR(behind.lengthPx + cut.lengthPx, out.lengthPx - 0.0, 0.05 * out.lengthPx);
  const std::string svg = svgDocument(kindGroups(out, LineSettings{}), size, {});
  EXPECT_NE(svg.find("<g id=\"silhouettes\""), std::string::npos);
  EXPECT_NE(svg.find("<g id=\"creases\""), std::string::npos);
  EXPECT_EQ(svg.find("<image"), std::string::npos);
}

// Tapered lines in the SVG: filled outlines, zero wide at the chain's ends, the set's width past
// the taper, the width in between as the GPU's lines.frag gives it (linear in the distance from
// the end); dashes cut out of the outline along the chain; a closed chain keeps its width.
TEST(SvgExport, TaperedChainsAreOutlinesNarrowingToPointsAndDashedAlongTheChain) {
  const std::vector<glm::vec2> line{{0, 50}, {40, 50}, {100, 50}};
  const auto widths = [](const std::vector<glm::vec2>& polygon) {
    // Left side first, then the right side backwards: pair them up.
    std::vector<std::pair<float, float>> out;  // (x, width)
    const std::size_t n = polygon.size() / 2;
    for (std::size_t i = 0; i < n; ++i) out.push_back({polygon[i].x, glm::length(polygon[i] - polygon[polygon.size() - 1 - i])});
    return out;
  };
  const auto outlines = taperedOutlines(line, 8.0f, 20.0f, glm::vec2(0.0f));
  ASSERT_EQ(outlines.size(), 1u);
  int checked = 0;
  for (const auto& [x, w] : widths(outlines[0])) {
    const float expected = 8.0f * std::clamp(std::min(x, 100.0f - x) / 20.0f, 0.0f, 1.0f);
    EXPECT_NEAR(w, expected, 0.01f) << "at x = " << x;
    ++checked;
  }
  EXPECT_GE(checked, 19) << "the tapers are not drawn as curves";
  const auto dashed = taperedOutlines(line, 8.0f, 20.0f, glm::vec2(10.0f, 10.0f));
  ASSERT_EQ(dashed.size(), 5u);
  for (std::size_t i = 0; i < dashed.size(); ++i) {
    float lo = 1e9f, hi = -1e9f;
    for (const glm::vec2& p : dashed[i]) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    EXPECT_NEAR(lo, 20.0f * float(i), 0.01f);
    EXPECT_NEAR(hi, 20.0f * float(i) + 10.0f, 0.01f);
  }
  const std::vector<glm::vec2> loop{{0, 0}, {50, 0}, {50, 50}, {0, 50}, {0, 0}};
  for (const auto& [x, w] : widths(taperedOutlines(loop, 6.0f, 20.0f, glm::vec2(0.0f)).at(0))) EXPECT_NEAR(w, 6.0f, 1e-3f) << x;
  SvgGroup g{"set1-silhouettes", glm::vec3(0.0f), 8.0f, 1.0f, glm::vec2(0.0f), {line}, 20.0f};
  const std::string svg = svgDocument({g}, glm::ivec2(100, 100), {});
  EXPECT_NE(svg.find("<g id=\"set1-silhouettes\" fill=\"#000000\" stroke=\"none\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("<path d=\"M0.00 50.00L"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("<polyline"), std::string::npos);
}

// A sheet corrugated as y = A sin x, its normals up. Its radial curvature along x is A sin x
// (positive on the bumps, bending away from the normal), zero at the inflections x = k pi.
Mesh corrugatedSheet(float amplitude) {
  Mesh m;
  const int nx = 240, nz = 30;
  const float x0 = -1.5f * float(M_PI), x1 = 1.5f * float(M_PI), z0 = -1.5f, z1 = 1.5f;
  for (int j = 0; j <= nz; ++j)
    for (int i = 0; i <= nx; ++i) {
      const float x = x0 + (x1 - x0) * float(i) / float(nx), z = z0 + (z1 - z0) * float(j) / float(nz);
      m.positions.push_back({x, amplitude * std::sin(x), z});
    }
  const auto at = [&](int i, int j) { return std::uint32_t(j * (nx + 1) + i); };
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i)
      for (std::uint32_t v : {at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)}) m.indices.push_back(v);
  finalizeMesh(m);
  return m;
}

// Seen from straight above, every inflection line of the sheet is a suggestive contour (kappa_r
// rises toward the eye on both sides); tilted toward +x past the slope, only the inflection
// whose slope faces the eye keeps one. Nowhere else: the lines lie on the inflections.
TEST(SuggestiveContours, ACorrugatedSheetHasThemAlongItsInflections) {
  const float amplitude = 0.6f;
  const Mesh sheet = corrugatedSheet(amplitude);
  ASSERT_GT(sheet.faceNormals[0].y, 0.0f) << "the sheet's normals must face up";
  SuggestiveContours sc(sheet);
  const auto inflectionsCovered = [&](const glm::vec3& eye, float covered[3], int& off) {
    off = 0;
    std::fill(covered, covered + 3, 0.0f);
    for (const FeatureLine& l : sc.lines(eye)) {
      EXPECT_EQ(l.kind, float(EdgeKind::Suggestive));
      const glm::vec3 mid = 0.5f * (l.a + l.b);
      if (std::abs(mid.z) > 1.2f) continue;  // the estimate is one-sided at the border
      const float k = std::round(mid.x / float(M_PI));
      if (std::abs(mid.x - k * float(M_PI)) > 0.08f || std::abs(k) > 1.0f) {
        ++off;
        continue;
      }
      covered[int(k) + 1] += glm::length(l.b - l.a);
    }
  };
  float covered[3];
  int off = 0;
  inflectionsCovered(glm::vec3(0.0f, 60.0f, 0.0f), covered, off);
  EXPECT_EQ(off, 0);
  for (int k = 0; k < 3; ++k) EXPECT_GT(covered[k], 0.9f * 2.4f) << "inflection x = " << k - 1 << " pi, seen from above";
  // Tilted 50 degrees toward +x (tan 50 > A): the inflections at +-pi, whose slope faces away,
  // lose theirs; x = 0 keeps it.
  const float a = glm::radians(50.0f);
  inflectionsCovered(60.0f * glm::vec3(std::sin(a), std::cos(a), 0.0f), covered, off);
  EXPECT_EQ(off, 0);
  EXPECT_GT(covered[1], 0.9f * 2.4f);
  EXPECT_LT(covered[0], 0.1f);
  EXPECT_LT(covered[2], 0.1f);
  // A threshold above the curvature's rate of change there keeps nothing.
  EXPECT_TRUE(sc.lines(glm::vec3(0.0f, 60.0f, 0.0f), 1000.0f).empty());
}

// A torus (axis y): seen straight down its axis it has none; from a grazing view, suggestive
// contours on its inner side (nearer the axis than the tube's centre), none on the outer.
TEST(SuggestiveContours, ATorusHasThemOnItsInnerSideFromAGrazingViewAndNoneStraightOn) {
  const Mesh t = torus(96, 48);
  float lo = 1e9f, hi = 0.0f;
  for (const glm::vec3& p : t.positions) {
    lo = std::min(lo, std::hypot(p.x, p.z));
    hi = std::max(hi, std::hypot(p.x, p.z));
  }
  const float major = 0.5f * (lo + hi);
  SuggestiveContours sc(t);
  EXPECT_TRUE(sc.lines(glm::vec3(0.0f, 6.0f, 0.0f)).empty());
  for (float elevation : {40.0f, 30.0f, 20.0f}) {
    const float a = glm::radians(elevation);
    float inner = 0.0f, outer = 0.0f;
    for (const FeatureLine& l : sc.lines(6.0f * glm::vec3(std::cos(a), std::sin(a), 0.0f))) {
      const glm::vec3 m = 0.5f * (l.a + l.b);
      (std::hypot(m.x, m.z) < major ? inner : outer) += glm::length(l.b - l.a);
    }
    EXPECT_GT(inner, 0.3f) << elevation << " degrees";
    EXPECT_EQ(outer, 0.0f) << elevation << " degrees";
  }
}

// Fading: the bunny orbited 2 degrees a frame. A segment with no segment of the frame before
// near it (a twentieth of the radius) has just appeared; those carry less ink than the contours
// as a whole (some come in at the threshold, where the fade starts), which keep most of theirs.
// Measured: 0.97 of the length inked, 0.87 of what appeared, which is 1% of the length a frame:
// most new segments are far above the threshold (contours growing faster than the tolerance),
// so the fade lightens popping rather than removing it.
TEST(SuggestiveContours, ContoursFadeInInsteadOfPoppingAsTheViewTurns) {
  Result<Mesh> bunny = loadMesh(std::string(NPR_SOURCE_DIR) + "/models/bunny.obj");
  ASSERT_TRUE(bunny) << bunny.error();
  SuggestiveContours sc(*bunny);
  std::vector<glm::vec3> before;
  double appearedLength = 0.0, appearedInk = 0.0, length = 0.0, ink = 0.0;
  for (int frame = 0; frame < 30; ++frame) {
    const float a = glm::radians(2.0f * float(frame));
    const std::vector<FeatureLine> lines = sc.lines(3.0f * bunny->radius * glm::vec3(std::sin(a), 0.3f, std::cos(a)));
    std::vector<glm::vec3> now;
    for (const FeatureLine& l : lines) {
      const glm::vec3 m = 0.5f * (l.a + l.b);
      const double len = glm::length(l.b - l.a);
      EXPECT_GT(l.attributes.ink, 0.0f);
      EXPECT_LE(l.attributes.ink, 1.0f);
      length += len;
      ink += len * l.attributes.ink;
      bool seen = frame == 0;
      for (const glm::vec3& p : before) seen = seen || glm::length(p - m) < 0.05f * bunny->radius;
      if (!seen) {
        appearedLength += len;
        appearedInk += len * l.attributes.ink;
      }
      now.push_back(m);
    }
    before = std::move(now);
  }
  std::printf("suggestive contours over 30 frames: %.3f of their length inked; the segments that appeared %.3f (%.2f of the length)\n",
              ink / length, appearedInk / std::max(appearedLength, 1e-9), appearedLength / length);
  ASSERT_GT(appearedLength, 0.0) << "nothing appeared: the orbit tests nothing";
  EXPECT_GT(ink / length, 0.9) << "the fade took much of the contours' ink";
  EXPECT_LT(appearedInk / appearedLength, ink / length - 0.05) << "new contours pop in at full ink";
}

TEST(FeatureEdges, MaterialBoundariesAreTheEdgesBetweenTwoMaterials) {
  // The cube with its top (y = 1, faces 6 and 7) in a second material: the four edges around
  // the top, and nothing else, are material boundaries; the 12 creases are unchanged.
  Mesh m = weldedCube();
  ASSERT_EQ(m.triangleCount(), 12u);
  m.faceMaterials.assign(12, 0);
  m.faceMaterials[6] = m.faceMaterials[7] = 1;
  FeatureEdges edges(m);
  const auto& lines = edges.staticLines(60.0f);
  EXPECT_EQ(countKind(lines, EdgeKind::Crease), 12u);
  EXPECT_EQ(countKind(lines, EdgeKind::Material), 4u);
  for (const FeatureLine& l : lines)
    if (l.kind == float(EdgeKind::Material)) {
      EXPECT_FLOAT_EQ(l.a.y, 1.0f);
      EXPECT_FLOAT_EQ(l.b.y, 1.0f);
    }
  // Each line knows its faces' materials (what line sets select by): the creases around the top
  // border both, the others only the sides' and bottom's, and so do the silhouettes.
  for (const FeatureLine& l : lines) {
    const bool top = l.a.y == 1.0f && l.b.y == 1.0f;
    const glm::u16vec2 want = top ? glm::u16vec2(0, 1) : glm::u16vec2(0, 0);
    EXPECT_TRUE(l.attributes.materials == want || l.attributes.materials == glm::u16vec2(want.y, want.x)) << "kind " << l.kind << " at y " << l.a.y << ", " << l.b.y;
  }
  for (const FeatureLine& l : edges.silhouettes(glm::vec3(3.0f, 2.0f, 2.5f))) {
    const bool top = l.a.y == 1.0f && l.b.y == 1.0f;
    EXPECT_EQ(l.attributes.materials.x == 1 || l.attributes.materials.y == 1, top);
  }
  // One material: none.
  m.faceMaterials.assign(12, 0);
  FeatureEdges one(m);
  EXPECT_EQ(countKind(one.staticLines(60.0f), EdgeKind::Material), 0u);
  // No materials at all: none named.
  m.faceMaterials.clear();
  FeatureEdges none(m);
  for (const FeatureLine& l : none.staticLines(60.0f)) EXPECT_EQ(l.attributes.materials, glm::u16vec2(kNoMaterial));
}


// A box from the cube's faces, its corners at `lo` and `hi`, built directly (no centring).
Mesh boxMesh(const glm::vec3& lo, const glm::vec3& hi) {
  Mesh m;
  for (const glm::vec3& c : kCube) m.positions.push_back(glm::mix(lo, hi, 0.5f * (c + 1.0f)));
  for (const auto& f : kCubeFaces)
    for (int k : f) m.indices.push_back(std::uint32_t(k));
  return m;
}

double totalLength(const std::vector<FeatureLine>& lines) {
  double sum = 0.0;
  for (const FeatureLine& l : lines) sum += double(glm::length(l.b - l.a));
  return sum;
}

float distanceToSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = b - a;
  const float t = glm::dot(d, d) > 0.0f ? std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * d));
}

// The box [-1,1]^3 and a bar [0,2]x[-0.5,0.5]^2 through its face x = 1 meet along the square
// of side 1 on that face: total length 4, every end on it, every point of it covered.
void expectTheSquare(const std::vector<FeatureLine>& lines) {
  ASSERT_FALSE(lines.empty());
  EXPECT_NEAR(totalLength(lines), 4.0, 1e-5);
  for (const FeatureLine& l : lines) {
    EXPECT_EQ(l.kind, float(EdgeKind::Intersection));
    for (const glm::vec3& p : {l.a, l.b}) {
      EXPECT_NEAR(p.x, 1.0f, 1e-6f);
      EXPECT_NEAR(std::max(std::abs(p.y), std::abs(p.z)), 0.5f, 1e-6f);
    }
  }
  for (int i = 0; i < 400; ++i) {
    const float s = float(i) / 100.0f;  // along the square's perimeter, 4 sides of 1
    const int side = int(s);
    const float t = s - float(side) - 0.5f;
    const glm::vec3 p = side == 0 ? glm::vec3(1, t, -0.5f) : side == 1 ? glm::vec3(1, 0.5f, t) : side == 2 ? glm::vec3(1, -t, 0.5f) : glm::vec3(1, -0.5f, -t);
    float nearest = INFINITY;
    for (const FeatureLine& l : lines) nearest = std::min(nearest, distanceToSegment(p, l.a, l.b));
    EXPECT_LT(nearest, 1e-5f) << "the square's point " << p.x << "," << p.y << "," << p.z << " has no line";
  }
}

TEST(IntersectionLines, TwoCrossingBoxesMeetAlongTheSquareOfTheirCrossing) {
  const Mesh box = boxMesh(glm::vec3(-1.0f), glm::vec3(1.0f)), bar = boxMesh({0.0f, -0.5f, -0.5f}, {2.0f, 0.5f, 0.5f});
  IntersectionCounts counts;
  expectTheSquare(intersectionLines({{&box, glm::mat4(1.0f)}, {&bar, glm::mat4(1.0f)}}, &counts));
  EXPECT_EQ(counts.triangles, 24u);
  EXPECT_GT(counts.pairsTested, 0u);
}

TEST(IntersectionLines, WithinOneObjectAsBetweenTwo) {
  Mesh both = boxMesh(glm::vec3(-1.0f), glm::vec3(1.0f));
  const Mesh bar = boxMesh({0.0f, -0.5f, -0.5f}, {2.0f, 0.5f, 0.5f});
  for (std::uint32_t i : bar.indices) both.indices.push_back(i + 8u);
  both.positions.insert(both.positions.end(), bar.positions.begin(), bar.positions.end());
  expectTheSquare(intersectionLines({{&both, glm::mat4(1.0f)}}));
}

TEST(IntersectionLines, EachObjectIsPlacedByItsTransform) {
  const Mesh box = boxMesh(glm::vec3(-1.0f), glm::vec3(1.0f)), bar = boxMesh({-1.0f, -0.5f, -0.5f}, {1.0f, 0.5f, 0.5f});
  expectTheSquare(intersectionLines({{&box, glm::mat4(1.0f)}, {&bar, glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 0.0f))}}));
  // Moved clear of the box, it meets nothing.
  EXPECT_TRUE(intersectionLines({{&box, glm::mat4(1.0f)}, {&bar, glm::translate(glm::mat4(1.0f), glm::vec3(2.5f, 0.0f, 0.0f))}}).empty());
}

TEST(IntersectionLines, AClosedSurfaceCrossesNothing) {
  // Its neighbours share corners and are tested, and give nothing; so does a finer sphere.
  const Mesh box = boxMesh(glm::vec3(-1.0f), glm::vec3(1.0f));
  IntersectionCounts counts;
  EXPECT_TRUE(intersectionLines({{&box, glm::mat4(1.0f)}}, &counts).empty());
  EXPECT_GT(counts.pairsTested, 0u);
  const Mesh sphere = icosphere(3);
  EXPECT_TRUE(intersectionLines({{&sphere, glm::mat4(1.0f)}}).empty());
  // The same sphere twice in one place is one surface doubled: coplanar pairs, no lines.
  EXPECT_TRUE(intersectionLines({{&sphere, glm::mat4(1.0f)}, {&sphere, glm::mat4(1.0f)}}).empty());
}

TEST(IntersectionLines, CrossingTrianglesShareTheSegmentInsideBoth) {
  const glm::vec3 flat[3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const glm::vec3 upright[3] = {{0.5f, -1, -1}, {0.5f, 3, -1}, {0.5f, 1, 1}};
  glm::vec3 from, to;
  ASSERT_TRUE(triangleIntersection(flat, upright, from, to));
  // The upright one meets z = 0 for y in [0, 2]; the flat one holds x = 0.5 for y in [0, 1.5].
  const glm::vec3 lo = from.y < to.y ? from : to, hi = from.y < to.y ? to : from;
  EXPECT_NEAR(glm::length(lo - glm::vec3(0.5f, 0.0f, 0.0f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(hi - glm::vec3(0.5f, 1.5f, 0.0f)), 0.0f, 1e-6f);
  // Touching at one point, lying in one plane, or sharing a corner: none.
  const glm::vec3 touching[3] = {{2, 0, 0}, {3, 0, 1}, {3, 0, -1}};
  EXPECT_FALSE(triangleIntersection(flat, touching, from, to));
  const glm::vec3 coplanar[3] = {{0.5f, 0.5f, 0}, {3, 0.5f, 0}, {0.5f, 3, 0}};
  EXPECT_FALSE(triangleIntersection(flat, coplanar, from, to));
  const glm::vec3 neighbour[3] = {{0, 0, 0}, {1, 1, 1}, {1, 1, -1}};
  EXPECT_FALSE(triangleIntersection(flat, neighbour, from, to));
}

TEST(IntersectionLines, TheHierarchyFindsWhatTestingEveryPairFinds) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> at(-1.0f, 1.0f), offset(-0.3f, 0.3f);
  Mesh soup;
  for (std::uint32_t t = 0; t < 400; ++t) {
    const glm::vec3 c(at(rng), at(rng), at(rng));
    for (int k = 0; k < 3; ++k) {
      soup.positions.push_back(c + glm::vec3(offset(rng), offset(rng), offset(rng)));
      soup.indices.push_back(3 * t + std::uint32_t(k));
    }
  }
  double expected = 0.0;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < 400; ++i)
    for (std::size_t j = i + 1; j < 400; ++j) {
      glm::vec3 from, to;
      if (triangleIntersection(&soup.positions[3 * i], &soup.positions[3 * j], from, to)) {
        expected += double(glm::length(to - from));
        ++pairs;
      }
    }
  const std::vector<FeatureLine> lines = intersectionLines({{&soup, glm::mat4(1.0f)}});
  ASSERT_GT(pairs, 50u);  // a tangle: the test means something
  EXPECT_EQ(lines.size(), pairs);
  EXPECT_NEAR(totalLength(lines), expected, 1e-4 * expected);
}

TEST(IntersectionLines, APileOfCoincidentTrianglesStopsAtThePairBudget) {
  // 30,000 copies of one triangle, slightly tilted each (not coplanar, no shared corner):
  // every pair overlaps, 450M pairs; the search stops at its budget (a small one here, so the
  // test is quick) and says so.
  Mesh pile;
  for (std::uint32_t t = 0; t < 30000; ++t) {
    const float tilt = 1e-3f * float(t % 97);
    pile.positions.insert(pile.positions.end(), {{0, 0, tilt}, {1, 0, -tilt}, {0, 1, 0.5f * tilt + 1e-4f * float(t)}});
    pile.indices.insert(pile.indices.end(), {3 * t, 3 * t + 1, 3 * t + 2});
  }
  IntersectionCounts counts;
  (void)intersectionLines({{&pile, glm::mat4(1.0f)}}, &counts, 2'000'000);
  EXPECT_TRUE(counts.stopped);
  EXPECT_LE(counts.pairsTested, 2'000'000u);
  // The torus-sized searches of the benchmark are far inside it; so is a normal scene.
  const Mesh sphere = icosphere(3);
  (void)intersectionLines({{&sphere, glm::mat4(1.0f)}}, &counts);
  EXPECT_FALSE(counts.stopped);
}

// Winding number of the loops around point p (nonzero: inside), as an SVG viewer fills them.
int winding(const std::vector<RegionLoop>& loops, const glm::vec2& p) {
  int w = 0;
  for (const RegionLoop& loop : loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const glm::vec2 a(loop[i]), b(loop[(i + 1) % loop.size()]);
      if (a.y <= p.y && b.y > p.y && (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y) > 0.0f) ++w;
      else if (a.y > p.y && b.y <= p.y && (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y) < 0.0f) --w;
    }
  return w;
}

TEST(RegionTrace, LoopsFilledByTheNonzeroRuleCoverExactlyEachLabelsPixels) {
  // Random blobs of 4 labels and background (-1): holes, islands, pixels touching at corners.
  std::mt19937 rng(3);
  const int w = 40, h = 30;
  std::vector<int> labels(std::size_t(w * h), -1);
  for (int k = 0; k < 60; ++k) {
    const int cx = int(rng() % w), cy = int(rng() % h), r = int(rng() % 6), l = int(rng() % 5) - 1;
    for (int y = std::max(0, cy - r); y < std::min(h, cy + r + 1); ++y)
      for (int x = std::max(0, cx - r); x < std::min(w, cx + r + 1); ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) labels[std::size_t(y * w + x)] = l;
  }
  for (int k = 0; k < 80; ++k) labels[rng() % labels.size()] = int(rng() % 5) - 1;  // single pixels, corner contacts
  const auto regions = traceRegions(labels, w, h, 4);
  ASSERT_EQ(regions.size(), 4u);
  int wrong = 0;
  for (int l = 0; l < 4; ++l)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool inside = winding(regions[std::size_t(l)], glm::vec2(x + 0.5f, y + 0.5f)) != 0;
        wrong += inside != (labels[std::size_t(y * w + x)] == l);
      }
  EXPECT_EQ(wrong, 0);
  // Corners only: a lone 3x2 block is one loop of 4 corners, clockwise on screen (y down).
  std::vector<int> block(std::size_t(w * h), -1);
  for (int y = 5; y < 7; ++y)
    for (int x = 10; x < 13; ++x) block[std::size_t(y * w + x)] = 0;
  const auto one = traceRegions(block, w, h, 1);
  ASSERT_EQ(one[0].size(), 1u);
  const RegionLoop& loop = one[0][0];
  ASSERT_EQ(loop.size(), 4u);
  EXPECT_EQ(winding(one[0], glm::vec2(11.5f, 5.5f)), 1);
}
}  // namespace
}  // namespace npr

namespace npr {
namespace {

// The lines of `mesh` found through OpenMesh's halfedges and through the edge pairing that
// takes its place on oriented manifolds: the same lines, in the same order and direction.
void expectSameLines(const Mesh& mesh, const std::string& what) {
  FeatureEdges fast(mesh), general(mesh, FeatureEdges::Topology::Halfedges);
  for (float angle : {30.0f, 60.0f}) {
    const std::vector<FeatureLine>& a = fast.staticLines(angle);
    const std::vector<FeatureLine> b = general.staticLines(angle);
    ASSERT_EQ(a.size(), b.size()) << what << " at " << angle;
    for (size_t i = 0; i < a.size(); ++i)
      ASSERT_TRUE(a[i].a == b[i].a && a[i].b == b[i].b && a[i].kind == b[i].kind) << what << ": static line " << i;
  }
  for (const glm::vec3 eye : {glm::vec3(0, 0, 3), glm::vec3(2, 1, -2)}) {
    const std::vector<FeatureLine>& a = fast.silhouettes(eye);
    const std::vector<FeatureLine> b = general.silhouettes(eye);
    ASSERT_EQ(a.size(), b.size()) << what;
    for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(a[i].a == b[i].a && a[i].b == b[i].b) << what << ": silhouette " << i;
  }
}

TEST(FeatureEdges, PairingEdgesGivesTheHalfedgesLinesOnRealModels) {
  int meshes = 0;
  for (const char* file : {"/models/bunny.obj", "/models/teapot.obj"}) {
    Result<Mesh> m = loadMesh(std::string(NPR_SOURCE_DIR) + file);
    ASSERT_TRUE(m) << m.error();
    expectSameLines(*m, file);
    ++meshes;
  }
  expectSameLines(torus(48, 24), "torus");
  // The Khronos engine's 67 parts and assimp's spider (assimp-testmodels): parts no one here made.
  for (const char* file : {"/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                           "/usr/share/assimp/models/OBJ/spider.obj"}) {
    Result<LoadedScene> scene = loadScene(file);
    ASSERT_TRUE(scene) << scene.error();
    for (const SceneObject& o : scene->objects) expectSameLines(*o.mesh, file + (": " + o.name)), ++meshes;
  }
  EXPECT_GT(meshes, 60);
}

}  // namespace
}  // namespace npr
