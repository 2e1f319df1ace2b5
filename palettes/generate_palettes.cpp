// Generates the shipped palettes into a folder (palettes/ by default; `cmake --build build
// --target palettes` regenerates them). Deterministic: the same program writes the same
// files. Each palette is a folder with its .palette file and PNG images, echoing the
// original renderer's set: crosshatch, stipple, cel, Gooch, an order set and wood.
//
// Tone sets are built from one threshold field per style: texel (x, y) is inked at level k
// when field(x, y) < s_k, so every level keeps all the ink of the lighter ones (levels nest
// and tone changes do not flicker). Each s_k is found by bisection so that the level's
// measured average intensity (over the paper, as the renderer analyses it) is evenly spaced.
#include <OpenImageIO/imageio.h>

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

namespace fs = std::filesystem;
using npr::ImageRGBA8;

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

// Inks (opaque `ink`) every texel whose field value is below s.
ImageRGBA8 inkLevel(const std::vector<float>& field, float s, glm::vec3 ink) {
  ImageRGBA8 img = blank();
  for (int i = 0; i < kSize * kSize; ++i)
    if (field[size_t(i)] < s) setPixel(img, i % kSize, i / kSize, ink, 1.0f);
  return img;
}

// Levels from blank to solid with evenly spaced average intensity over `bg`.
std::vector<ImageRGBA8> toneLevels(const std::vector<float>& field, int levels, const ImageRGBA8& bg, glm::vec3 ink) {
  const glm::vec3 bgMean = [&] {
    glm::dvec3 s(0);
    for (size_t i = 0; i < bg.pixels.size(); i += 4) s += glm::dvec3(npr::srgbToLinear(bg.pixels[i] / 255.0f), npr::srgbToLinear(bg.pixels[i + 1] / 255.0f), npr::srgbToLinear(bg.pixels[i + 2] / 255.0f));
    return npr::linearToSrgb(glm::vec3(s / double(bg.pixels.size() / 4)));
  }();
  auto intensity = [&](float s) {
    const glm::vec3 a = npr::compositeAverage(inkLevel(field, s, ink), bgMean, &bg);
    return a.r + a.g + a.b;
  };
  const float top = intensity(-1.0f), bottom = intensity(2.0f);
  std::vector<ImageRGBA8> out;
  for (int k = 0; k < levels; ++k) {
    const float target = top + (bottom - top) * float(k) / float(levels - 1);
    float lo = -1.0f, hi = 2.0f;  // intensity decreases as s grows
    for (int it = 0; it < 40; ++it) {
      const float mid = 0.5f * (lo + hi);
      (intensity(mid) > target ? lo : hi) = mid;
    }
    out.push_back(inkLevel(field, k == 0 ? -1.0f : (k == levels - 1 ? 2.0f : hi), ink));
  }
  return out;
}

// Hatching: four families of wobbly parallel strokes appear one after another as the tone
// darkens (45 deg, then -45, 0 and 90 deg), each stroke thickening with the tone.
std::vector<float> hatchField() {
  std::vector<float> f(size_t(kSize) * kSize);
  const int spacing = 8;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      float best = 10.0f;
      for (int fam = 0; fam < 4; ++fam) {
        // Coordinate across the strokes; every family is periodic over the 256-texel tile.
        const int u = fam == 0 ? x + y : fam == 1 ? x - y + kSize : fam == 2 ? y : x;
        const int line = u / spacing;
        const float along = float(fam == 0 ? x - y + kSize : fam == 1 ? x + y : fam == 2 ? x : y);
        const float wobble = 1.2f * (valueNoise(along, float(line * 8), 8, std::uint32_t(31 + fam)) - 0.5f);
        float d = std::fabs(float(u % spacing) + 0.5f - spacing * 0.5f + wobble) / (spacing * 0.5f);  // 0 on the stroke
        if (fam < 2) d /= std::sqrt(2.0f) * 0.75f;
        // Family j starts at s = 0.15 j and thickens slowly, so the next direction joins in
        // long before one family alone could fill the tile: tones build up as crosshatching.
        best = std::min(best, 0.15f * float(fam) + 0.6f * d);
      }
      f[size_t(y) * kSize + x] = best;
    }
  return f;
}

// One family of horizontal strokes, wobbling a little and thickening with the tone: the
// palette whose direction hatching orientation (--orient) turns along the form.
std::vector<float> lineField() {
  std::vector<float> f(size_t(kSize) * kSize);
  const int spacing = 6;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const int line = y / spacing;
      const float wobble = 0.8f * (valueNoise(float(x), float(line * 8), 16, 77u) - 0.5f);
      f[size_t(y) * kSize + x] = std::fabs(float(y % spacing) + 0.5f - spacing * 0.5f + wobble) / (spacing * 0.5f);
    }
  return f;
}

// Stipple: dots on a jittered grid, each appearing at its own random tone and growing.
std::vector<float> stippleField() {
  std::vector<float> f(size_t(kSize) * kSize, 10.0f);
  const int cell = 8;
  const int cells = kSize / cell;
  for (int cy = 0; cy < cells; ++cy)
    for (int cx = 0; cx < cells; ++cx) {
      const float px = (float(cx) + 0.2f + 0.6f * rand01(std::uint32_t(cx), std::uint32_t(cy), 11)) * cell;
      const float py = (float(cy) + 0.2f + 0.6f * rand01(std::uint32_t(cx), std::uint32_t(cy), 12)) * cell;
      const float start = 0.6f * rand01(std::uint32_t(cx), std::uint32_t(cy), 13);
      for (int dy = -2 * cell; dy <= 2 * cell; ++dy)
        for (int dx = -2 * cell; dx <= 2 * cell; ++dx) {
          const int x = (int(px) + dx + kSize) % kSize, y = (int(py) + dy + kSize) % kSize;
          const float d = std::hypot(float(int(px) + dx) + 0.5f - px, float(int(py) + dy) + 0.5f - py) / cell;
          float& v = f[size_t(y) * kSize + x];
          v = std::min(v, start + 0.45f * d);
        }
    }
  return f;
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

struct Writer {
  fs::path root;
  bool ok = true;
  void palette(const std::string& name, const std::string& header, const std::vector<ImageRGBA8>& images,
               const ImageRGBA8* background = nullptr, const std::string& prefix = "level") {
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
      pf << file << "\n";
    }
    std::printf("wrote %s (%zu entries)\n", (dir / (name + ".palette")).string().c_str(), images.size());
  }
};

}  // namespace

int main(int argc, char** argv) {
  Writer w{argc > 1 ? fs::path(argv[1]) : fs::path("palettes")};
  const ImageRGBA8 bg = paper();
  const glm::vec3 ink(0.06f, 0.05f, 0.08f);

  w.palette("crosshatch",
            "name Crosshatch\nmatch intensity\n# 10 nested levels from bare paper to solid ink, evenly spaced in intensity.\n",
            toneLevels(hatchField(), 10, bg, ink), &bg);
  w.palette("hatch", "name Hatch (one direction)\nmatch intensity\n# 8 levels of horizontal strokes: try --orient curvature.\n",
            toneLevels(lineField(), 8, bg, ink), &bg);
  w.palette("stipple", "name Stipple\nmatch intensity\n# 16 nested levels of ink dots.\n", toneLevels(stippleField(), 16, bg, ink), &bg);

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

  std::vector<ImageRGBA8> woods;
  for (int i = 0; i < 30; ++i) woods.push_back(wood(1.0f - float(i) / 29.0f));
  w.palette("wood", "name Wood (30, cherry to pine)\nmatch intensity\nbackground #FFFFFF\n", woods, nullptr, "wood");
  return w.ok ? 0 : 1;
}
