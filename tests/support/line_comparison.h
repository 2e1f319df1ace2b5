// Comparing two line drawings of the same view (hardware outlines against object-space
// silhouettes; the SVG export against the raster lines, tests/e2e/line_overlap): how much of
// each lies near the other, and how wide lines are across the silhouette. Images are dark
// lines on a light ground (transparent counts as ground), rows top-down.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/image.h"
#include "renderer/lines/feature_edges.h"

namespace npr::test {

struct LineMask {
  int width = 0, height = 0;
  std::vector<char> ink;
  bool at(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height && ink[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  int count() const;
};
// Ink: luminance composited over white below one half.
LineMask lineMask(const ImageRGBA8& image);

// The share of `a`'s ink pixels that lie within `radius` pixels (a square) of ink in `b`.
double nearShare(const LineMask& a, const LineMask& b, int radius);

// Line widths in pixels across the silhouette: at the screen midpoint of each edge in
// `edges` (visible in `mask`: ink within a pixel of it), the run of ink crossing it along the
// edge's screen normal. Edges shorter than two pixels on screen are skipped (no normal).
std::vector<float> widthsAcross(const LineMask& mask, const std::vector<FeatureLine>& edges, const CameraMatrices& camera);

struct Spread {
  float median = 0, p10 = 0, p90 = 0;
  int samples = 0;
};
Spread spreadOf(std::vector<float> values);

}  // namespace npr::test
