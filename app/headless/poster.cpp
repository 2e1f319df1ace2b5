// Posters in tiles (see poster.h).
#include "app/headless/poster.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "app/progress_line.h"
#include "renderer/core/image_io.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/offscreen_target.h"
#include "app/cli.h"

namespace npr {
namespace {

constexpr int kGutter = 8;  // pixels drawn around each tile and cut off: edge filters see their neighbours

// The projection that shows the pixel rectangle [x0, x1) x [y0, y1) (GL's, y up) of a
// width x height frame on a whole viewport.
glm::mat4 tileProjection(const glm::mat4& projection, int width, int height, int x0, int y0, int x1, int y1) {
  const float nx0 = 2.0f * float(x0) / float(width) - 1.0f, nx1 = 2.0f * float(x1) / float(width) - 1.0f;
  const float ny0 = 2.0f * float(y0) / float(height) - 1.0f, ny1 = 2.0f * float(y1) / float(height) - 1.0f;
  glm::mat4 m(1.0f);
  m[0][0] = 2.0f / (nx1 - nx0);
  m[1][1] = 2.0f / (ny1 - ny0);
  m[3][0] = -(nx0 + nx1) / (nx1 - nx0);
  m[3][1] = -(ny0 + ny1) / (ny1 - ny0);
  return m * projection;
}

}  // namespace

int renderPoster(const Options& o, ViewerState& state, Renderer& renderer) {
  if (o.screenshot.empty()) return reportFailure("a tiled poster needs --screenshot FILE to write to");
  const int W = o.size.x, H = o.size.y;
  const int tile = std::max(64, std::min(o.tile > 0 ? o.tile : 4096, maxFramebufferSide() - 2 * kGutter));
  const int columns = (W + tile - 1) / tile, rows = (H + tile - 1) / tile;
  auto target = OffscreenTarget::create(std::min(W, tile) + 2 * kGutter, std::min(H, tile) + 2 * kGutter);
  if (!target) return reportFailure(target.error());
  Result<StripWriter> out = StripWriter::open(o.screenshot, W, H);
  if (!out) return reportFailure(out.error());
  RenderSettings settings = state.settings;
  settings.pattern = PatternSpace::Screen;  // a still: the anchored frame would start at the screen's anyway
  const CameraMatrices whole = state.view(float(W) / float(H));
  if (Status s = state.applyLight(renderer, whole); !s) return reportFailure("light: " + s.error());
  ProgressLine progress("poster " + std::to_string(W) + "x" + std::to_string(H) + " in " + std::to_string(columns * rows) + " tiles");
  for (int r = 0; r < rows; ++r) {
    // Tile row r holds image rows [r tile, ...) counted from the top; GL counts from the bottom.
    const int top = r * tile, h = std::min(tile, H - top);
    const int y0 = H - top - h;
    ImageRGBA8 strip{W, h, std::vector<std::uint8_t>(std::size_t(W) * std::size_t(h) * 4)};
    for (int c = 0; c < columns; ++c) {
      const int x0 = c * tile, w = std::min(tile, W - x0);
      const int gx0 = x0 - kGutter, gy0 = y0 - kGutter, gw = w + 2 * kGutter, gh = h + 2 * kGutter;
      CameraMatrices cam = whole;
      cam.projection = tileProjection(whole.projection, W, H, gx0, gy0, gx0 + gw, gy0 + gh);
      renderer.setTile(Renderer::Tile{{gx0, gy0}, whole.projection});
      target->bind();
      const Status s = renderer.render(cam, settings, {0, 0, gw, gh});
      renderer.setTile(std::nullopt);
      if (!s) return reportFailure("poster tile " + std::to_string(r * columns + c + 1) + ": " + s.error());
      const ImageRGBA8 img = target->readRGBA8();  // rows top first; the target may be larger than this tile
      const int targetTop = img.height - gh;       // GL's row 0 is the target's bottom row
      for (int y = 0; y < h; ++y)
        std::memcpy(&strip.pixels[(std::size_t(y) * std::size_t(W) + std::size_t(x0)) * 4],
                    &img.pixels[(std::size_t(targetTop + kGutter + y) * std::size_t(img.width) + kGutter) * 4], std::size_t(w) * 4);
      progress.update(double(r * columns + c + 1) / double(rows * columns));
    }
    if (Status s = out->append(strip); !s) return reportFailure(s.error());
  }
  tellUser("poster " + std::to_string(W) + "x" + std::to_string(H) + " written to " + o.screenshot + " (" + std::to_string(rows * columns) +
           " tiles of " + std::to_string(tile) + ")");
  if (const int errors = gl::checkErrors("poster")) return reportFailure(std::to_string(errors) + " OpenGL error(s) during the poster");
  return 0;
}

}  // namespace npr
