// Posters in tiles (see poster.h).
#include "app/video/poster.h"

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

Result<std::unique_ptr<PosterRender>> PosterRender::start(const std::string& path, glm::ivec2 size, int tile) {
  std::unique_ptr<PosterRender> p(new PosterRender());
  p->size_ = size;
  p->tile_ = std::max(64, std::min(tile > 0 ? tile : 4096, maxFramebufferSide() - 2 * kGutter));
  p->columns_ = (size.x + p->tile_ - 1) / p->tile_;
  p->rows_ = (size.y + p->tile_ - 1) / p->tile_;
  Result<OffscreenTarget> target = OffscreenTarget::create(std::min(size.x, p->tile_) + 2 * kGutter, std::min(size.y, p->tile_) + 2 * kGutter);
  if (!target) return Error{target.error()};
  p->target_ = std::move(*target);
  Result<StripWriter> out = StripWriter::open(path, size.x, size.y);
  if (!out) return Error{out.error()};
  p->out_ = std::move(*out);
  return p;
}

Status PosterRender::drawTile(ViewerState& state, Renderer& renderer, int index) {
  const int W = size_.x, H = size_.y, r = index / columns_, c = index % columns_;
  RenderSettings settings = state.settings;
  settings.pattern = PatternSpace::Screen;  // a still: the anchored frame would start at the screen's anyway
  const CameraMatrices whole = state.view(float(W) / float(H));
  if (Status s = state.applyLight(renderer, whole); !s) return Error{"light: " + s.error()};
  // Tile row r holds image rows [r tile, ...) counted from the top; GL counts from the bottom.
  const int top = r * tile_, h = std::min(tile_, H - top);
  const int y0 = H - top - h;
  if (c == 0) strip_ = ImageRGBA8{W, h, std::vector<std::uint8_t>(std::size_t(W) * std::size_t(h) * 4)};
  const int x0 = c * tile_, w = std::min(tile_, W - x0);
  const int gx0 = x0 - kGutter, gy0 = y0 - kGutter, gw = w + 2 * kGutter, gh = h + 2 * kGutter;
  CameraMatrices cam = whole;
  cam.projection = tileProjection(whole.projection, W, H, gx0, gy0, gx0 + gw, gy0 + gh);
  renderer.setTile(Renderer::Tile{{gx0, gy0}, whole.projection});
  target_->bind();
  const Status s = renderer.render(cam, settings, {0, 0, gw, gh});
  renderer.setTile(std::nullopt);
  if (!s) return Error{"poster tile " + std::to_string(index + 1) + ": " + s.error()};
  const ImageRGBA8 img = target_->readRGBA8();  // rows top first; the target may be larger than this tile
  const int targetTop = img.height - gh;        // GL's row 0 is the target's bottom row
  for (int y = 0; y < h; ++y)
    std::memcpy(&strip_.pixels[(std::size_t(y) * std::size_t(W) + std::size_t(x0)) * 4],
                &img.pixels[(std::size_t(targetTop + kGutter + y) * std::size_t(img.width) + kGutter) * 4], std::size_t(w) * 4);
  if (c + 1 < columns_) return okStatus();
  if (Status st = out_->append(strip_); !st) return st;
  if (index + 1 == tiles()) out_.reset();  // the file finished and closed
  return okStatus();
}

int renderPoster(const Options& o, ViewerState& state, Renderer& renderer) {
  if (o.screenshot.empty()) return reportFailure("a tiled poster needs --screenshot FILE to write to");
  Result<std::unique_ptr<PosterRender>> poster = PosterRender::start(o.screenshot, o.size, o.tile);
  if (!poster) return reportFailure(poster.error());
  PosterRender& p = **poster;
  ProgressLine progress("poster " + std::to_string(o.size.x) + "x" + std::to_string(o.size.y) + " in " + std::to_string(p.tiles()) + " tiles");
  for (int i = 0; i < p.tiles(); ++i) {
    if (Status s = p.drawTile(state, renderer, i); !s) return reportFailure(s.error());
    progress.update(double(i + 1) / double(p.tiles()));
  }
  tellUser("poster " + std::to_string(o.size.x) + "x" + std::to_string(o.size.y) + " written to " + o.screenshot + " (" + std::to_string(p.tiles()) +
           " tiles of " + std::to_string(p.tileSide()) + ")");
  if (const int errors = gl::checkErrors("poster")) return reportFailure(std::to_string(errors) + " OpenGL error(s) during the poster");
  return 0;
}

}  // namespace npr
