// PNG encoding (see png_encoder.h): the signature, IHDR, one IDAT stream, IEND.
#include "renderer/core/png_encoder.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>

#include "renderer/core/parallel.h"

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
  for (auto& r : rows) r.resize(bytes);
  auto up = [&](size_t i) -> int { return above ? above[i] : 0; };
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

// Bands of rows filtered and deflated on their own threads (as pigz does): each band a raw
// deflate stream ended on a byte boundary (a sync flush), the last one finished; the zlib
// header before them and the Adler-32 of the whole after, combined from the bands'. A 1280x720
// frame took 55 ms on one core of this machine (docs/performance-history.md, "Start-up").
struct Band {
  std::vector<std::uint8_t> packed;
  uLong adler = 1;
  size_t rawSize = 0;
  bool ok = false;
};

Band deflateBand(const ImageRGBA8& image, int y0, int y1, bool last, int level) {
  const size_t rowBytes = size_t(image.width) * 4;
  std::vector<std::uint8_t> raw;
  std::array<std::vector<std::uint8_t>, 5> rows;
  raw.reserve((rowBytes + 1) * size_t(y1 - y0));
  for (int y = y0; y < y1; ++y)
    filterRow(&image.pixels[size_t(y) * rowBytes], y > 0 ? &image.pixels[size_t(y - 1) * rowBytes] : nullptr, rowBytes, rows, raw);
  Band band;
  band.rawSize = raw.size();
  band.adler = adler32(1L, raw.data(), uInt(raw.size()));
  z_stream z{};
  if (deflateInit2(&z, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return band;
  band.packed.resize(deflateBound(&z, uLong(raw.size())) + 16);
  z.next_in = raw.data();
  z.avail_in = uInt(raw.size());
  z.next_out = band.packed.data();
  z.avail_out = uInt(band.packed.size());
  const int r = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
  band.ok = last ? r == Z_STREAM_END : (r == Z_OK && z.avail_in == 0);
  band.packed.resize(band.packed.size() - z.avail_out);
  deflateEnd(&z);
  return band;
}

}  // namespace

Result<std::vector<std::uint8_t>> encodePngRgba8(const ImageRGBA8& image, int zlibLevel) {
  if (image.width < 1 || image.height < 1 || image.pixels.size() != size_t(image.width) * size_t(image.height) * 4)
    return Error{"PNG encoding: an empty or malformed image"};
  // Bands of at least 64 rows and 256 KB: a thread's start costs more than a smaller band saves.
  const size_t rowBytes = size_t(image.width) * 4;
  const int minRows = std::max(64, int((size_t(256) << 10) / rowBytes));
  const int bands = std::max(1, std::min(workerCount(), image.height / minRows));
  std::vector<Band> out(static_cast<size_t>(bands));
  parallelChunks(size_t(bands), bands, [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i) {
      const int y0 = int(i * size_t(image.height) / size_t(bands)), y1 = int((i + 1) * size_t(image.height) / size_t(bands));
      out[i] = deflateBand(image, y0, y1, i + 1 == size_t(bands), zlibLevel);
    }
  }, 1);
  std::vector<std::uint8_t> stream{0x78, 0x5e};  // deflate, 32K window; a level-3 hint; no dictionary
  uLong adler = 1;
  for (const Band& band : out) {
    if (!band.ok) return Error{"PNG encoding: zlib could not compress the image (out of memory?)"};
    stream.insert(stream.end(), band.packed.begin(), band.packed.end());
    adler = adler32_combine(adler, band.adler, z_off_t(band.rawSize));
  }
  put32(stream, std::uint32_t(adler));

  std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  std::vector<std::uint8_t> header;
  put32(header, std::uint32_t(image.width));
  put32(header, std::uint32_t(image.height));
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, adaptive filters, not interlaced
  chunk(png, "IHDR", header.data(), header.size());
  chunk(png, "IDAT", stream.data(), stream.size());
  chunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace npr
