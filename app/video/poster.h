// Posters: a still larger than the GL framebuffer limit (or --tile N) rendered in tiles, each a
// sub-frustum of the whole frame with its pixels offset so palette patterns continue across
// the seams, drawn with a gutter that is cut off (image-space edges read neighbours), and
// written strip by strip so the whole image is never in memory. Headless runs draw every tile
// at once; the window's export (Ctrl+E) a few at a time between its frames.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "app/cli.h"
#include "app/viewer_state.h"
#include "renderer/core/image_io.h"
#include "renderer/core/result.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/renderer.h"

namespace npr {

inline constexpr int kMaxPosterSide = 65536;  // pixels a side, as --size allows

class PosterRender {
 public:
  // A `size` poster in tiles of `tile` pixels (0: the largest the GL allows, at most 4096),
  // written to `path`.
  [[nodiscard]] static Result<std::unique_ptr<PosterRender>> start(const std::string& path, glm::ivec2 size, int tile);
  int tiles() const { return columns_ * rows_; }
  int tileSide() const { return tile_; }
  // Draws tile `index` (row by row from the top; each in turn) with `state`'s camera and light;
  // a row's last tile writes the row's strip, and the last one finishes the file.
  [[nodiscard]] Status drawTile(ViewerState& state, Renderer& renderer, int index);

 private:
  PosterRender() = default;
  glm::ivec2 size_{0};
  int tile_ = 0, columns_ = 0, rows_ = 0;
  std::optional<OffscreenTarget> target_;
  std::optional<StripWriter> out_;
  ImageRGBA8 strip_;
};

// Renders `state`'s scene at o.size in tiles of o.tile (or the largest the GL allows) into
// o.screenshot. Returns the exit status.
int renderPoster(const Options& o, ViewerState& state, Renderer& renderer);

}  // namespace npr
