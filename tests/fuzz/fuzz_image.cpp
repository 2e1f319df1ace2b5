// libFuzzer harness: the image path (OpenImageIO's readers behind our checks and the
// streamed reduction) on arbitrary bytes. The first byte picks the extension OpenImageIO is
// told, and whether the image is read whole or reduced to fit 7 x 5 pixels. Images declaring
// more than 4 megapixels are skipped (see below).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "renderer/core/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const exts[] = {".png", ".tga", ".jpg", ".tif", ".bmp", ".exr", ".hdr", ".ppm"};
  const std::string path = "/tmp/npr-fuzz-image-" + std::to_string(::getpid()) + exts[data[0] & 7];
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  // A valid header declaring 16384 x 16384 pixels costs seconds to decode (correctly); skip
  // those so the fuzzer spends its time on the parsers, not on inflating zeros.
  npr::Result<npr::ImageSize> declared = npr::readImageSize(path);
  if (declared && double(declared->width) * declared->height > 2048.0 * 2048.0) {
    std::remove(path.c_str());
    return 0;
  }
  const npr::ImageSize fit = (data[0] & 8) ? npr::ImageSize{7, 5} : npr::ImageSize{npr::kMaxImageSide, npr::kMaxImageSide};
  npr::Result<npr::ImageRGBA8> img = npr::loadImage(path, fit);
  if (img && img->pixels.size() != std::size_t(img->width) * img->height * 4) __builtin_trap();
  if (!img && img.error().empty()) __builtin_trap();
  std::remove(path.c_str());
  return 0;
}
