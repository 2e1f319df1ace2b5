// PNG encoding (see png_encoder.h): the signature, IHDR, one IDAT stream, IEND.
#include "renderer/core/png_encoder.h"

#include <zlib.h>

#include <array>
#include <cstdlib>
#include <string>

namespace npr {
namespace {

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}

void chunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data, size_t size) {
  put32(out, std::uint32_t(size));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  put32(out, std::uint32_t(crc32(0L, out.data() + start, uInt(out.size() - start))));
}

std::uint8_t paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return std::uint8_t(pa <= pb && pa <= pc ? a : (pb <= pc ? b : c));
}

// The row filtered by each of the five filters, one loop per filter so each vectorises; the
// one with the smallest sum of magnitudes (bytes taken as signed) goes to `out`, its type first.
void filterRow(const std::uint8_t* row, const std::uint8_t* above, size_t bytes, std::array<std::vector<std::uint8_t>, 5>& rows,
               std::vector<std::uint8_t>& out) {
  constexpr size_t bpp = 4;
  static const std::uint8_t zeros[1] = {0};
  for (auto& r : rows) r.resize(bytes);
  auto up = [&](size_t i) -> int { return above ? above[i] : zeros[0]; };
  for (size_t i = 0; i < bytes; ++i) rows[0][i] = row[i];
  for (size_t i = 0; i < bytes; ++i) rows[1][i] = std::uint8_t(row[i] - (i >= bpp ? row[i - bpp] : 0));
  for (size_t i = 0; i < bytes; ++i) rows[2][i] = std::uint8_t(row[i] - up(i));
  for (size_t i = 0; i < bytes; ++i) rows[3][i] = std::uint8_t(row[i] - ((i >= bpp ? row[i - bpp] : 0) + up(i)) / 2);
  for (size_t i = 0; i < bytes; ++i)
    rows[4][i] = std::uint8_t(row[i] - (i >= bpp ? paeth(row[i - bpp], up(i), above ? above[i - bpp] : 0) : up(i)));
  unsigned long best = ~0ul;
  size_t bestType = 0;
  for (size_t type = 0; type < 5; ++type) {
    unsigned long sum = 0;
    for (std::uint8_t v : rows[type]) sum += v < 128 ? v : 256u - v;
    if (sum < best) best = sum, bestType = type;
  }
  out.push_back(std::uint8_t(bestType));
  out.insert(out.end(), rows[bestType].begin(), rows[bestType].end());
}

}  // namespace

Result<std::vector<std::uint8_t>> encodePngRgba8(const ImageRGBA8& image, int zlibLevel) {
  if (image.width < 1 || image.height < 1 || image.pixels.size() != size_t(image.width) * size_t(image.height) * 4)
    return Error{"PNG encoding: an empty or malformed image"};
  const size_t rowBytes = size_t(image.width) * 4;
  std::vector<std::uint8_t> raw;
  std::array<std::vector<std::uint8_t>, 5> rows;
  raw.reserve((rowBytes + 1) * size_t(image.height));
  for (int y = 0; y < image.height; ++y)
    filterRow(&image.pixels[size_t(y) * rowBytes], y > 0 ? &image.pixels[size_t(y - 1) * rowBytes] : nullptr, rowBytes, rows, raw);

  uLongf packedSize = compressBound(uLong(raw.size()));
  std::vector<std::uint8_t> packed(packedSize);
  if (compress2(packed.data(), &packedSize, raw.data(), uLong(raw.size()), zlibLevel) != Z_OK)
    return Error{"PNG encoding: zlib could not compress " + std::to_string(raw.size()) + " bytes (out of memory?)"};

  std::vector<std::uint8_t> out{0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  std::vector<std::uint8_t> header;
  put32(header, std::uint32_t(image.width));
  put32(header, std::uint32_t(image.height));
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, adaptive filters, not interlaced
  chunk(out, "IHDR", header.data(), header.size());
  chunk(out, "IDAT", packed.data(), packedSize);
  chunk(out, "IEND", nullptr, 0);
  return out;
}

}  // namespace npr
