// libFuzzer harness: the palette file parser on arbitrary text. Its entries can name the small
// valid and broken images this harness writes beside it once (good.png, grey16.png,
// truncated.png, text.png, empty.png), a folder, a missing file or a device.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "renderer/core/image_io.h"
#include "renderer/palette/palette.h"

namespace {

std::string setUp() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("npr-fuzz-palette-" + std::to_string(::getpid()));
  fs::create_directories(dir / "folder");
  npr::ImageRGBA8 img{4, 3, std::vector<std::uint8_t>(4 * 3 * 4)};
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = static_cast<std::uint8_t>(i * 37);
  (void)npr::writeImage((dir / "good.png").string(), img);
  (void)npr::writeImage((dir / "other.tga").string(), img);
  std::FILE* f = std::fopen((dir / "good.png").string().c_str(), "rb");
  std::string png(4096, '\0');
  png.resize(f ? std::fread(png.data(), 1, png.size(), f) : 0);
  if (f) std::fclose(f);
  auto write = [&](const char* name, const std::string& bytes) {
    std::FILE* o = std::fopen((dir / name).string().c_str(), "wb");
    if (o) std::fwrite(bytes.data(), 1, bytes.size(), o), std::fclose(o);
  };
  write("truncated.png", png.substr(0, png.size() / 2));
  write("text.png", "not an image\n");
  write("empty.png", "");
  return (dir / "fuzz.palette").string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = setUp();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  npr::Result<npr::Palette> p = npr::loadPalette(path);
  if (!p && p.error().empty()) __builtin_trap();
  if (p && (p->entries.empty() || p->entries.size() > std::size_t(npr::kMaxPaletteEntries))) __builtin_trap();
  return 0;
}
