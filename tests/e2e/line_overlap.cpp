// Compares two line drawings (dark lines on a light ground): the share of each one's line
// pixels that lie within `radius` pixels of a line pixel of the other. Used by the SVG export
// test: the raster lines against the SVG rasterised by rsvg-convert.
// Usage: line_overlap A.png B.png RADIUS MIN_SHARE  (exit 1 when either share is below it)
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "renderer/core/image_io.h"

using namespace npr;

namespace {

std::vector<char> lineMask(const ImageRGBA8& img) {
  std::vector<char> m(std::size_t(img.width) * std::size_t(img.height));
  for (std::size_t i = 0; i < m.size(); ++i) {
    const std::uint8_t* p = &img.pixels[i * 4];
    // Composited over white (rsvg-convert leaves the ground transparent).
    const float a = p[3] / 255.0f;
    const float luminance = (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f * a + (1.0f - a);
    m[i] = luminance < 0.5f;
  }
  return m;
}

double share(const std::vector<char>& a, const std::vector<char>& b, int w, int h, int radius, int* count) {
  int n = 0, near = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!a[std::size_t(y) * std::size_t(w) + std::size_t(x)]) continue;
      ++n;
      bool found = false;
      for (int dy = -radius; dy <= radius && !found; ++dy)
        for (int dx = -radius; dx <= radius && !found; ++dx) {
          const int xx = x + dx, yy = y + dy;
          found = xx >= 0 && yy >= 0 && xx < w && yy < h && b[std::size_t(yy) * std::size_t(w) + std::size_t(xx)];
        }
      near += found;
    }
  *count = n;
  return n ? double(near) / n : 0.0;
}

}  // namespace

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
  const std::vector<char> ma = lineMask(*a), mb = lineMask(*b);
  int na = 0, nb = 0;
  const double ab = share(ma, mb, a->width, a->height, radius, &na), ba = share(mb, ma, a->width, a->height, radius, &nb);
  std::printf("line_overlap: %d line pixels in A, %.1f%% within %d px of B; %d in B, %.1f%% within %d px of A\n", na, 100 * ab, radius, nb,
              100 * ba, radius);
  return na > 0 && nb > 0 && ab >= minShare && ba >= minShare ? 0 : 1;
}
