// Compares two line drawings (dark lines on a light ground): the share of each one's line
// pixels that lie within `radius` pixels of a line pixel of the other (support/line_comparison).
// Used by the SVG export test: the raster lines against the SVG rasterised by rsvg-convert.
// Usage: line_overlap A.png B.png RADIUS MIN_SHARE  (exit 1 when either share is below it)
#include <cstdio>
#include <cstdlib>

#include "renderer/core/image_io.h"
#include "support/line_comparison.h"

using namespace npr;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: line_overlap A.png B.png RADIUS MIN_SHARE\n");
    return 2;
  }
  Result<ImageRGBA8> a = loadImage(argv[1]), b = loadImage(argv[2]);
  if (!a || !b) {
    std::fprintf(stderr, "line_overlap: %s\n", (!a ? a.error() : b.error()).c_str());
    return 2;
  }
  if (a->width != b->width || a->height != b->height) {
    std::fprintf(stderr, "line_overlap: the images differ in size\n");
    return 2;
  }
  const int radius = std::atoi(argv[3]);
  const double minShare = std::atof(argv[4]);
  const test::LineMask ma = test::lineMask(*a), mb = test::lineMask(*b);
  const int na = ma.count(), nb = mb.count();
  const double ab = test::nearShare(ma, mb, radius), ba = test::nearShare(mb, ma, radius);
  std::printf("line_overlap: %d line pixels in A, %.1f%% within %d px of B; %d in B, %.1f%% within %d px of A\n", na, 100 * ab, radius, nb,
              100 * ba, radius);
  return na > 0 && nb > 0 && ab >= minShare && ba >= minShare ? 0 : 1;
}
