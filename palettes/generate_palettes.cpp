// Generates the shipped palettes into a folder (palettes/ by default; `cmake --build build
// --target palettes` regenerates them). Deterministic: the same program writes the same
// files. Each palette is a folder with its .palette file and PNG images, echoing the
// original renderer's set: crosshatch, stipple, cel, Gooch, an order set and wood; and two
// halftone screens (screentone: dots and lines).
//
// The ink palettes (crosshatch, hatch, stipple, pencil) are drawn: tonal art maps built stroke
// by stroke until each level reaches its evenly spaced tone, nested across tones and mip levels
// (renderer/palette/tonal_art_map.h); each entry lists its own mip levels.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "renderer/core/colour.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_analysis.h"
#include "renderer/palette/tonal_art_map.h"

namespace fs = std::filesystem;
using npr::ImageRGBA8;
using npr::Result;

namespace {

constexpr int kSize = 256;

std::uint32_t hash3(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  h *= 0x297a2d39u;
  h ^= h >> 15;
  return h;
}
float rand01(std::uint32_t x, std::uint32_t y, std::uint32_t seed) { return float(hash3(x, y, seed) & 0xFFFFFF) / float(0x1000000); }

// Tileable value noise with period `period` cells over the image.
float valueNoise(float x, float y, int period, std::uint32_t seed) {
  const float fx = x * period / kSize, fy = y * period / kSize;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float tx = fx - x0, ty = fy - y0;
  auto at = [&](int i, int j) { return rand01(std::uint32_t((i % period + period) % period), std::uint32_t((j % period + period) % period), seed); };
  const float sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
  const float a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * sx;
  const float b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * sx;
  return a + (b - a) * sy;
}

ImageRGBA8 blank(int size = kSize) { return ImageRGBA8{size, size, std::vector<std::uint8_t>(size_t(size) * size * 4, 0)}; }

void setPixel(ImageRGBA8& img, int x, int y, glm::vec3 c, float a) {
  std::uint8_t* p = &img.pixels[(size_t(y) * img.width + x) * 4];
  for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
  p[3] = std::uint8_t(std::lround(std::clamp(a, 0.0f, 1.0f) * 255.0f));
}

bool write(const fs::path& path, const ImageRGBA8& img, int channels = 4) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) return false;
  OIIO::ImageSpec spec(img.width, img.height, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // straight alpha, as PNG stores it
  std::vector<std::uint8_t> data;
  for (size_t i = 0; i < img.pixels.size(); i += 4)
    for (int k = 0; k < channels; ++k) data.push_back(img.pixels[i + size_t(k)]);
  return out->open(path.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, data.data()) && out->close();
}

ImageRGBA8 paper() {
  ImageRGBA8 img = blank();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float n = 0.6f * valueNoise(float(x), float(y), 32, 7) + 0.4f * valueNoise(float(x), float(y), 128, 8);
      const float fibre = 0.5f + 0.5f * std::sin(float(x + y) * 0.9f + 6.0f * valueNoise(float(x), float(y), 16, 9));
      const float v = 0.90f + 0.06f * n + 0.015f * fibre;
      setPixel(img, x, y, glm::vec3(v, v * 0.985f, v * 0.94f), 1.0f);
    }
  return img;
}

// A tonal art map's levels and their mip levels (renderer/palette/tonal_art_map.h).
struct Drawn {
  std::vector<ImageRGBA8> images;
  std::vector<std::vector<ImageRGBA8>> mips;
};
Drawn drawn(const npr::TamSpec& spec, const ImageRGBA8& paper, const char* name) {
  Result<npr::TonalArtMap> tam = npr::buildTonalArtMap(spec, paper);
  Drawn d;
  if (!tam) {
    std::fprintf(stderr, "%s: %s\n", name, tam.error().c_str());
    return d;
  }
  for (const std::string& n : tam->notes) std::fprintf(stderr, "%s: %s\n", name, n.c_str());
  for (const npr::TamLevel& l : tam->levels) {
    d.images.push_back(l.mips[0]);
    d.mips.emplace_back(l.mips.begin() + 1, l.mips.end());
  }
  std::printf("%s: %d marks in the darkest level\n", name, tam->levels.back().marks);
  return d;
}

ImageRGBA8 solid(glm::vec3 c, int size = 64) {
  ImageRGBA8 img = blank(size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) setPixel(img, x, y, c, 1.0f);
  return img;
}

// A colourful painted base image for the order set.
ImageRGBA8 orderBase() {
  ImageRGBA8 img = blank();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float a = valueNoise(float(x), float(y), 4, 21), b = valueNoise(float(x), float(y), 8, 22), c = valueNoise(float(x), float(y), 16, 23);
      setPixel(img, x, y, glm::vec3(0.35f + 0.6f * a, 0.3f + 0.5f * b, 0.45f + 0.5f * c * a), 1.0f);
    }
  return img;
}

ImageRGBA8 boxBlur(const ImageRGBA8& src, int radius) {
  if (radius <= 0) return src;
  ImageRGBA8 tmp = src, out = src;
  for (int pass = 0; pass < 2; ++pass) {
    const ImageRGBA8& in = pass == 0 ? src : tmp;
    ImageRGBA8& dst = pass == 0 ? tmp : out;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int k = 0; k < 3; ++k) {
          int sum = 0;
          for (int d = -radius; d <= radius; ++d) {
            const int xx = pass == 0 ? (x + d + kSize) % kSize : x, yy = pass == 0 ? y : (y + d + kSize) % kSize;
            sum += in.pixels[(size_t(yy) * kSize + xx) * 4 + size_t(k)];
          }
          dst.pixels[(size_t(y) * kSize + x) * 4 + size_t(k)] = std::uint8_t(sum / (2 * radius + 1));
        }
  }
  return out;
}

// Solarizes: channel values above the threshold are inverted (the darker entries more so).
ImageRGBA8 solarize(const ImageRGBA8& src, float threshold) {
  ImageRGBA8 out = src;
  for (size_t i = 0; i < out.pixels.size(); i += 4)
    for (int k = 0; k < 3; ++k) {
      const float v = out.pixels[i + size_t(k)] / 255.0f;
      out.pixels[i + size_t(k)] = std::uint8_t(std::lround((v > threshold ? 1.0f - v : v) * 255.0f));
    }
  return out;
}

ImageRGBA8 wood(float t) {
  // Pine (light, yellow) to cherry (dark, red-brown), with rings and fibre.
  const glm::vec3 light0(0.93f, 0.80f, 0.55f), light1(0.52f, 0.22f, 0.12f);
  const glm::vec3 dark0(0.80f, 0.62f, 0.38f), dark1(0.30f, 0.10f, 0.05f);
  const int size = 128;
  ImageRGBA8 img = blank(size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float n = valueNoise(float(x) * 2, float(y) * 2, 4, 41);
      const float ring = 0.5f + 0.5f * std::sin((float(y) / size * 6.2831853f * 4.0f) + 5.0f * n);
      const float fibre = valueNoise(float(x) * 2, float(y) * 2, 64, 42);
      const glm::vec3 a = light0 + (light1 - light0) * t, b = dark0 + (dark1 - dark0) * t;
      setPixel(img, x, y, (a + (b - a) * (0.6f * ring + 0.4f * fibre * ring)), 1.0f);
    }
  return img;
}

// Halftone screens (Freudenberg, Masuch and Strothotte 2002; the comics' screentone): a spot
// function over a 45-degree lattice of pitch `pitch` texels (8 on a 256 tile: 5.7 texels from
// dot to dot), thresholded at each level's coverage, so the levels are one threshold map cut at
// evenly spaced tones and nest exactly. Dots: the Euclidean dot, round dots that meet at half
// cover and become round holes; lines: lines whose width grows. 4x4 samples a texel antialias
// the edges; each level's cut is the sample rank that gives its tone in linear light.
std::vector<ImageRGBA8> halftone(bool dots, int levels, glm::vec3 ink, glm::vec3 paper, int pitch) {
  constexpr int kSub = 4;
  const int n = kSize * kSub;
  std::vector<float> spot(size_t(n) * size_t(n));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float fx = (float(x) + 0.5f) / kSub, fy = (float(y) + 0.5f) / kSub;
      // Lattice coordinates: one cell per `pitch` texels along each diagonal, periodic over the tile.
      float u = (fx + fy) / float(pitch), v = (fx - fy) / float(pitch);
      const float du = u - std::floor(u) - 0.5f, dv = v - std::floor(v) - 0.5f;
      float value;
      if (!dots) value = std::fabs(dv);
      else if (std::fabs(du) + std::fabs(dv) <= 0.5f) value = du * du + dv * dv;  // a dot from the cell's centre
      else value = 1.0f - ((0.5f - std::fabs(du)) * (0.5f - std::fabs(du)) + (0.5f - std::fabs(dv)) * (0.5f - std::fabs(dv)));  // a hole at its corner
      // Symmetric spots give many samples one value; a tiny jitter breaks the ties so that the
      // cut at a rank covers exactly that many samples.
      spot[size_t(y) * size_t(n) + size_t(x)] = value + 1e-4f * rand01(std::uint32_t(x), std::uint32_t(y), 77);
    }
  std::vector<float> sorted = spot;
  std::sort(sorted.begin(), sorted.end());
  const float inkLight = (npr::srgbToLinear(ink.r) + npr::srgbToLinear(ink.g) + npr::srgbToLinear(ink.b)) / 3.0f;
  const float paperLight = (npr::srgbToLinear(paper.r) + npr::srgbToLinear(paper.g) + npr::srgbToLinear(paper.b)) / 3.0f;
  const float paperCode = (paper.r + paper.g + paper.b) / 3.0f, inkCode = (ink.r + ink.g + ink.b) / 3.0f;
  std::vector<ImageRGBA8> out;
  for (int k = 0; k < levels; ++k) {
    // Evenly spaced in encoded tone, as the palette analysis measures it; the cover that emits it.
    const float code = paperCode + (inkCode - paperCode) * float(k) / float(levels - 1);
    const float cover = std::clamp((paperLight - npr::srgbToLinear(code)) / (paperLight - inkLight), 0.0f, 1.0f);
    const size_t cut = size_t(std::lround(double(cover) * double(sorted.size())));
    const float below = cut == 0 ? -1.0f : cut >= sorted.size() ? 2.0f : sorted[cut];
    ImageRGBA8 img = blank();
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        int inked = 0;
        for (int sy = 0; sy < kSub; ++sy)
          for (int sx = 0; sx < kSub; ++sx) inked += spot[size_t(y * kSub + sy) * size_t(n) + size_t(x * kSub + sx)] < below;
        // Mixed in linear light: an edge texel emits its share of each.
        const float c = float(inked) / float(kSub * kSub);
        glm::vec3 colour;
        for (int ch = 0; ch < 3; ++ch)
          colour[ch] = npr::linearToSrgb((1.0f - c) * npr::srgbToLinear(paper[ch]) + c * npr::srgbToLinear(ink[ch]));
        setPixel(img, x, y, colour, 1.0f);
      }
    out.push_back(std::move(img));
  }
  return out;
}

struct Writer {
  fs::path root;
  bool ok = true;
  void palette(const std::string& name, const std::string& header, const std::vector<ImageRGBA8>& images,
               const ImageRGBA8* background = nullptr, const std::string& prefix = "level",
               const std::vector<std::vector<ImageRGBA8>>& mips = {}, int rows = 1) {
    if (images.empty()) {
      ok = false;
      return;
    }
    const fs::path dir = root / name;
    fs::create_directories(dir);
    std::ofstream pf(dir / (name + ".palette"));
    pf << "# Generated by palettes/generate_palettes.cpp: regenerate with `cmake --build build --target palettes`.\n";
    pf << header;
    if (background) {
      ok = ok && write(dir / "paper.png", *background, 3);
      pf << "background paper.png\n";
    }
    for (size_t i = 0; i < images.size(); ++i) {
      char file[64];
      std::snprintf(file, sizeof file, "%s%02zu.png", prefix.c_str(), i);
      const bool opaque = [&] {
        for (size_t p = 3; p < images[i].pixels.size(); p += 4)
          if (images[i].pixels[p] != 255) return false;
        return true;
      }();
      ok = ok && write(dir / file, images[i], opaque ? 3 : 4);
      // A palette with rows: each row's tone ladder after its 'row' line.
      if (rows > 1 && i % (images.size() / size_t(rows)) == 0) pf << "row\n";
      pf << file << "\n";
      for (size_t m = 0; i < mips.size() && m < mips[i].size(); ++m) {
        char mipFile[80];
        std::snprintf(mipFile, sizeof mipFile, "%s%02zu-mip%zu.png", prefix.c_str(), i, m + 1);
        ok = ok && write(dir / mipFile, mips[i][m], 4);
        pf << "mip " << mipFile << "\n";
      }
    }
    std::printf("wrote %s (%zu entries)\n", (dir / (name + ".palette")).string().c_str(), images.size());
  }
};

}  // namespace

int main(int argc, char** argv) {
  Writer w{argc > 1 ? fs::path(argv[1]) : fs::path("palettes")};
  const ImageRGBA8 bg = paper();
  const glm::vec3 ink(0.06f, 0.05f, 0.08f);

  // Drawn palettes: tonal art maps, strokes added one by one until each level reaches its
  // tone, with their own mip levels (256, 128 and 64 texels; coarser ones are reduced).
  npr::TamSpec cross;
  cross.tones = 10;
  cross.darkest = 0.85f;
  cross.seed = 11;
  cross.families = {npr::StrokeFamily{45.0f, 4.0f, 0.2f, 0.35f, 1.6f, 0.35f, 0.04f, 0.9f, 0.15f, 0.0f},
                    npr::StrokeFamily{135.0f, 4.0f, 0.2f, 0.35f, 1.6f, 0.35f, 0.04f, 0.9f, 0.15f, 0.28f},
                    npr::StrokeFamily{5.0f, 4.0f, 0.18f, 0.35f, 1.4f, 0.35f, 0.04f, 0.9f, 0.15f, 0.55f}};
  cross.ink = ink;
  const Drawn crossMaps = drawn(cross, bg, "crosshatch");
  w.palette("crosshatch",
            "name Crosshatch\nmatch intensity\n# 10 levels of drawn strokes (a tonal art map), nested, evenly spaced in intensity, with their own mip levels.\n",
            crossMaps.images, &bg, "level", crossMaps.mips);

  npr::TamSpec hatch;
  hatch.tones = 8;
  hatch.darkest = 0.8f;
  hatch.seed = 12;
  hatch.families = {npr::StrokeFamily{0.0f, 3.0f, 0.26f, 0.3f, 1.6f, 0.35f, 0.03f, 0.9f, 0.15f, 0.0f}};
  hatch.ink = ink;
  const Drawn hatchMaps = drawn(hatch, bg, "hatch");
  w.palette("hatch", "name Hatch (one direction)\nmatch intensity\n# 8 levels of horizontal drawn strokes: try --orient curvature.\n",
            hatchMaps.images, &bg, "level", hatchMaps.mips);

  npr::TamSpec stipple;
  stipple.tones = 16;
  stipple.darkest = 0.7f;
  stipple.dots = true;
  stipple.dotRadius = 1.3f;
  stipple.seed = 13;
  stipple.ink = ink;
  const Drawn stippleMaps = drawn(stipple, bg, "stipple");
  w.palette("stipple", "name Stipple\nmatch intensity\n# 16 nested levels of ink dots of one size in blue-noise order.\n", stippleMaps.images,
            &bg, "level", stippleMaps.mips);

  // Pencil: soft graphite strokes, long and light, a second direction in the darker levels.
  npr::TamSpec pencil;
  pencil.tones = 10;
  pencil.darkest = 0.75f;
  pencil.seed = 14;
  pencil.families = {npr::StrokeFamily{62.0f, 6.0f, 0.3f, 0.4f, 1.3f, 0.4f, 0.06f, 0.45f, 0.3f, 0.0f},
                     npr::StrokeFamily{152.0f, 6.0f, 0.28f, 0.4f, 1.3f, 0.4f, 0.06f, 0.45f, 0.3f, 0.45f}};
  pencil.ink = glm::vec3(0.22f, 0.22f, 0.25f);
  const Drawn pencilMaps = drawn(pencil, bg, "pencil");
  w.palette("pencil", "name Pencil\nmatch intensity\n# 10 levels of soft graphite strokes (a tonal art map).\n", pencilMaps.images, &bg,
            "level", pencilMaps.mips);

  // Charcoal: broad, grainy strokes that catch on the tooth of a rougher paper (the charcoal
  // style of the NPR lecture slides draws through it).
  ImageRGBA8 tooth = blank(), roughPaper = blank();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float t = std::clamp(0.55f * valueNoise(float(x), float(y), 128, 51) + 0.45f * rand01(std::uint32_t(x), std::uint32_t(y), 52), 0.0f, 1.0f);
      setPixel(tooth, x, y, glm::vec3(t), 1.0f);
      const float v = 0.86f + 0.08f * t;
      setPixel(roughPaper, x, y, glm::vec3(v, v * 0.98f, v * 0.95f), 1.0f);
    }
  npr::TamSpec charcoal;
  charcoal.tones = 10;
  charcoal.darkest = 0.8f;
  charcoal.seed = 15;
  charcoal.tooth = tooth;
  charcoal.families = {npr::StrokeFamily{70.0f, 10.0f, 0.3f, 0.4f, 4.5f, 0.4f, 0.08f, 0.75f, 0.25f, 0.0f, 0.85f},
                       npr::StrokeFamily{160.0f, 10.0f, 0.28f, 0.4f, 4.0f, 0.4f, 0.08f, 0.75f, 0.25f, 0.5f, 0.85f}};
  charcoal.ink = glm::vec3(0.09f, 0.08f, 0.08f);
  const Drawn charcoalMaps = drawn(charcoal, roughPaper, "charcoal");
  w.palette("charcoal", "name Charcoal\nmatch intensity\n# 10 levels of broad grainy strokes on toothed paper (a tonal art map).\n", charcoalMaps.images,
            &roughPaper, "level", charcoalMaps.mips);

  std::vector<ImageRGBA8> cel;
  for (glm::vec3 c : {glm::vec3(0.16f, 0.18f, 0.30f), glm::vec3(0.38f, 0.42f, 0.62f), glm::vec3(0.66f, 0.71f, 0.88f), glm::vec3(0.95f, 0.96f, 1.0f)})
    cel.push_back(solid(c));
  w.palette("cel", "name Cel (4 tones)\nmatch intensity\nbackground #FFFFFF\n", cel, nullptr, "tone");

  // Gooch: the ramp from k_cool = blue + alpha kd to k_warm = yellow + beta kd with the
  // renderer's default tone parameters (blue = yellow = 0.4, alpha = 0.2, beta = 0.6) and
  // OpenGL's default diffuse (0.8): with --tone gooch and match colors every tone the model
  // produces has an entry, and the result is technical-illustration shading.
  std::vector<ImageRGBA8> gooch;
  const glm::vec3 kd(0.8f), cool = glm::vec3(0, 0, 0.4f) + 0.2f * kd, warm = glm::vec3(0.4f, 0.4f, 0) + 0.6f * kd;
  for (int i = 0; i < 16; ++i) gooch.push_back(solid(cool + (warm - cool) * (float(i) / 15.0f)));
  w.palette("gooch", "name Gooch cool-to-warm\nmatch colors\nbackground #F4F4F0\n", gooch, nullptr, "tone");

  // The order set: one image, blurred and solarized progressively; entry 0 is the most
  // transformed, so darker triangles get the stronger effect, as in the original.
  std::vector<ImageRGBA8> order;
  const ImageRGBA8 base = orderBase();
  for (int i = 0; i < 12; ++i) {
    const float k = float(11 - i) / 11.0f;
    order.push_back(solarize(boxBlur(base, int(k * 6)), 1.0f - 0.5f * k));
  }
  w.palette("solarize", "name Solarize (order)\nmatch order\nbackground #202020\n", order, nullptr, "step");

  // Screentone: halftone dots and lines in black on white, as comics print them.
  const glm::vec3 toneInk(0.07f, 0.07f, 0.08f), white(1.0f);
  w.palette("screentone", "name Screentone (dots)\nmatch intensity\nbackground #FFFFFF\n# 13 levels of one 45-degree halftone dot screen (a threshold map cut at evenly spaced tones).\n",
            halftone(true, 13, toneInk, white, 8), nullptr, "level");
  w.palette("screentone-lines", "name Screentone (lines)\nmatch intensity\nbackground #FFFFFF\n# 13 levels of one 45-degree line screen.\n",
            halftone(false, 13, toneInk, white, 8), nullptr, "level");

  // Two-dimensional palettes (X-Toon): a crosshatch whose strokes thin out and lighten with
  // distance (aerial perspective), three rows of the same 8 tones from near to far, each a
  // nested tonal art map of its own; and the cel tones with a rim row, lighter and warmer,
  // where the surface turns away from the eye (backlighting).
  std::vector<ImageRGBA8> depthImages;
  std::vector<std::vector<ImageRGBA8>> depthMips;
  const struct {
    float width, darkest;
    glm::vec3 ink;
  } depthRows[] = {{1.6f, 0.85f, ink}, {1.15f, 0.62f, glm::vec3(0.24f, 0.25f, 0.30f)}, {0.8f, 0.4f, glm::vec3(0.42f, 0.44f, 0.50f)}};
  for (const auto& row : depthRows) {
    npr::TamSpec d = cross;
    d.tones = 8;
    d.darkest = row.darkest;
    d.ink = row.ink;
    d.seed = 16;
    for (auto& f : d.families) f.width = row.width;
    const Drawn maps = drawn(d, bg, "depth-hatch");
    depthImages.insert(depthImages.end(), maps.images.begin(), maps.images.end());
    depthMips.insert(depthMips.end(), maps.mips.begin(), maps.mips.end());
  }
  w.palette("depth-hatch",
            "name Depth hatch (near to far)\nmatch intensity\n# 3 rows of 8 crosshatch levels: far away the strokes are thinner, greyer and fewer.\n"
            "# Rows by distance from the eye, in scene radii: the first at 2 and nearer, the last at 4.5 and beyond.\naxis depth 2 4.5\n",
            depthImages, &bg, "level", depthMips, 3);

  std::vector<ImageRGBA8> celRim = cel;
  const glm::vec3 rimLight(1.0f, 0.86f, 0.55f);
  for (glm::vec3 c : {glm::vec3(0.16f, 0.18f, 0.30f), glm::vec3(0.38f, 0.42f, 0.62f), glm::vec3(0.66f, 0.71f, 0.88f), glm::vec3(0.95f, 0.96f, 1.0f)})
    celRim.push_back(solid(c + (rimLight - c) * 0.7f));
  w.palette("cel-rim", "name Cel with a rim (4 tones, 2 rows)\nmatch intensity\nbackground #FFFFFF\n"
            "# The cel tones, and where the surface turns edge-on to the eye a warm rim light.\naxis facing 0.45 0.6\n",
            celRim, nullptr, "tone", {}, 2);

  std::vector<ImageRGBA8> woods;
  for (int i = 0; i < 30; ++i) woods.push_back(wood(1.0f - float(i) / 29.0f));
  w.palette("wood", "name Wood (30, cherry to pine)\nmatch intensity\nbackground #FFFFFF\n", woods, nullptr, "wood");
  return w.ok ? 0 : 1;
}
