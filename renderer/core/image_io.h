// Images: reading any format OpenImageIO knows as encoded RGBA8 (palette textures), resizing,
// and writing (screenshots, test diffs, the palette generator) in the format the file's
// extension names (PNG, TGA, EXR, ...). PNG and JPEG are read and PNG written without
// OpenImageIO, which is loaded only for the rest (image_io.cpp says why).
#pragma once

#include <memory>
#include <string>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

inline constexpr int kMaxImageSide = 16384;

struct ImageSize {
  int width = 0, height = 0;
};

// The size the file declares, from its header alone (nothing decoded): what budgets are
// checked against before any pixel is read. Refuses non-regular files, files over
// kMaxImageFileBytes and sides outside 1..kMaxImageSide.
[[nodiscard]] Result<ImageSize> readImageSize(const std::string& path);

// Grey, grey+alpha, RGB or RGBA; 8-bit, 16-bit or float (float taken as linear light and
// encoded); at most kMaxImageSide pixels a side. Alpha stays straight (unassociated).
// An image larger than `fit` is reduced to fit while it is read (an area average in linear
// light, weighted by alpha, streamed a few rows at a time), so the full-size pixels never
// exist in memory.
[[nodiscard]] Result<ImageRGBA8> loadImage(const std::string& path, ImageSize fit = {kMaxImageSide, kMaxImageSide});
[[nodiscard]] Result<ImageRGBA8> resizeImage(const ImageRGBA8& image, int width, int height);
[[nodiscard]] Status writeImage(const std::string& path, const ImageRGBA8& image);
// The image as PNG file bytes (for embedding).
[[nodiscard]] Result<std::vector<std::uint8_t>> encodePng(const ImageRGBA8& image);

// A large image written in horizontal strips, top to bottom, as they are made (a poster
// rendered in tiles): the whole image is never in memory.
class StripWriter {
 public:
  [[nodiscard]] static Result<StripWriter> open(const std::string& path, int width, int height);
  StripWriter(StripWriter&&) noexcept;
  StripWriter& operator=(StripWriter&&) noexcept;
  ~StripWriter();
  // The next rows (`strip` is width wide); the file is finished after the last row.
  [[nodiscard]] Status append(const ImageRGBA8& strip);

 private:
  StripWriter() = default;
  struct State;
  std::unique_ptr<State> state_;
};

// An animation written frame by frame as the frames are made (an animated GIF, or any format
// OpenImageIO writes with several subimages): the frames are never all in memory.
class AnimationWriter {
 public:
  [[nodiscard]] static Result<AnimationWriter> open(const std::string& path, int width, int height, int frames, int fps);
  AnimationWriter(AnimationWriter&&) noexcept;
  AnimationWriter& operator=(AnimationWriter&&) noexcept;
  ~AnimationWriter();
  // Each frame must be width x height; the file is finished after the last one.
  [[nodiscard]] Status append(const ImageRGBA8& frame);

 private:
  AnimationWriter() = default;
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace npr
