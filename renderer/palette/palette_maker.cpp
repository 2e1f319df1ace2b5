// The palette maker (see palette_maker.h).
#include "renderer/palette/palette_maker.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "renderer/core/colour.h"
#include "renderer/core/image_io.h"
#include "renderer/palette/tonal_art_map.h"
#include "renderer/settings/choice_names.h"

namespace npr {
namespace fs = std::filesystem;

std::optional<Ladder> parseLadder(const std::string& s) {
  for (Ladder l : {Ladder::Blur, Ladder::Offset, Ladder::Solarize, Ladder::Posterize, Ladder::Threshold, Ladder::Darken, Ladder::Desaturate})
    if (s == ladderName(l)) return l;
  return std::nullopt;
}

const char* ladderName(Ladder l) {
  switch (l) {
    case Ladder::Blur: return "blur";
    case Ladder::Offset: return "offset";
    case Ladder::Solarize: return "solarize";
    case Ladder::Posterize: return "posterize";
    case Ladder::Threshold: return "threshold";
    case Ladder::Darken: return "darken";
    case Ladder::Desaturate: return "desaturate";
  }
  return "?";
}

MatchMode ladderMatchMode(Ladder l) {
  switch (l) {
    case Ladder::Threshold:
    case Ladder::Darken: return MatchMode::Intensity;
    case Ladder::Desaturate: return MatchMode::Colors;
    default: return MatchMode::Order;
  }
}

namespace {

// Steps computed on the encoded values as floats, as an image editor does; alpha comes out
// opaque (palette images tile over the paper).
struct Planes {
  int width = 0, height = 0;
  std::vector<float> v;  // RGBA, 0..1
};

Planes toPlanes(const ImageRGBA8& img) {
  Planes p{img.width, img.height, std::vector<float>(img.pixels.size())};
  for (size_t i = 0; i < p.v.size(); ++i) p.v[i] = img.pixels[i] / 255.0f;
  return p;
}

ImageRGBA8 toImage(const Planes& p) {
  ImageRGBA8 img{p.width, p.height, std::vector<std::uint8_t>(p.v.size())};
  for (size_t i = 0; i < p.v.size(); ++i) img.pixels[i] = toByte(p.v[i]);
  for (size_t i = 3; i < p.v.size(); i += 4) img.pixels[i] = 255;
  return img;
}

// A Gaussian blur that wraps around the edges (palette images tile), separable. `width` is
// the kernel's full width; its weights fall as exp(-8 d^2 / width^2) (sigma = width / 4).
Planes wrappedBlur(const Planes& src, float width) {
  const int radius = std::max(1, int(width / 2.0f));
  std::vector<float> weight(size_t(2 * radius + 1));
  float sum = 0;
  for (int d = -radius; d <= radius; ++d) sum += weight[size_t(d + radius)] = std::exp(-8.0f * float(d * d) / (width * width));
  for (float& w : weight) w /= sum;
  const int w = src.width, h = src.height;
  auto pass = [&](const Planes& in, bool horizontal) {
    Planes out{w, h, std::vector<float>(in.v.size(), 0.0f)};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int d = -radius; d <= radius; ++d) {
          const int sx = horizontal ? ((x + d) % w + w) % w : x, sy = horizontal ? y : ((y + d) % h + h) % h;
          const float k = weight[size_t(d + radius)];
          for (size_t c = 0; c < 4; ++c) out.v[(size_t(y) * w + x) * 4 + c] += k * in.v[(size_t(sy) * w + sx) * 4 + c];
        }
    return out;
  };
  return pass(pass(src, true), false);
}

// Per-channel steps (solarize, posterize).
ImageRGBA8 mapChannels(const ImageRGBA8& src, const std::function<float(float)>& f) {
  ImageRGBA8 out = src;
  for (size_t i = 0; i < out.pixels.size(); i += 4)
    for (size_t k = 0; k < 3; ++k) out.pixels[i + k] = toByte(f(src.pixels[i + k] / 255.0f));
  return out;
}

float luminance(const std::uint8_t* p) { return (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f; }

}  // namespace

Result<std::vector<ImageRGBA8>> ladderImages(const ImageRGBA8& src, Ladder ladder, int levels) {
  if (levels < kMinMakerLevels || levels > kMaxPaletteEntries)
    return Error{"--levels must be " + std::to_string(kMinMakerLevels) + ".." + std::to_string(kMaxPaletteEntries) + ", got " + std::to_string(levels)};
  // Strength k of n - 1 for each step; order ladders list the strongest first.
  const int n = levels;
  std::vector<ImageRGBA8> steps;  // by strength
  const Planes base = toPlanes(src);
  switch (ladder) {
    case Ladder::Blur: {
      Planes cur = base;
      steps.push_back(src);
      const float width = std::max(3.0f, float(std::min(src.width, src.height)) / 32.0f);
      for (int k = 1; k < n; ++k) {
        cur = wrappedBlur(cur, width);
        steps.push_back(toImage(cur));
      }
      break;
    }
    case Ladder::Offset:
      for (int k = 0; k < n; ++k) {
        // Moved right and down, wrapping round the tile.
        const int dx = k * src.width / n, dy = k * src.height / (2 * n);
        ImageRGBA8 shifted = src;
        for (int y = 0; y < src.height; ++y)
          for (int x = 0; x < src.width; ++x)
            std::copy_n(&src.pixels[(size_t(y) * src.width + x) * 4], 4,
                        &shifted.pixels[(size_t((y + dy) % src.height) * src.width + (x + dx) % src.width) * 4]);
        for (size_t i = 3; i < shifted.pixels.size(); i += 4) shifted.pixels[i] = 255;
        steps.push_back(std::move(shifted));
      }
      break;
    case Ladder::Solarize:
      for (int k = 0; k < n; ++k) {
        const float t = 1.0f - 0.5f * float(k) / float(n - 1);
        steps.push_back(mapChannels(src, [t](float v) { return v > t ? 1.0f - v : v; }));
      }
      break;
    case Ladder::Posterize:
      for (int k = 0; k < n; ++k) {
        const float q = std::round(std::exp2(8.0f - 7.0f * float(k) / float(n - 1)));
        steps.push_back(mapChannels(src, [q](float v) { return std::round(v * (q - 1.0f)) / (q - 1.0f); }));
      }
      break;
    case Ladder::Threshold: {
      // Thresholds at the luminance's quantiles, so the share of black grows evenly.
      std::vector<float> lum;
      for (size_t i = 0; i < src.pixels.size(); i += 4) lum.push_back(luminance(&src.pixels[i]));
      std::vector<float> sorted = lum;
      std::sort(sorted.begin(), sorted.end());
      for (int k = 0; k < n; ++k) {
        const float share = float(k) / float(n - 1);
        ImageRGBA8 out = src;
        const size_t cut = size_t(std::lround(share * float(sorted.size())));
        for (size_t i = 0; i < lum.size(); ++i) {
          const bool black = cut > 0 && (cut >= sorted.size() || lum[i] < sorted[cut]);
          for (size_t c = 0; c < 3; ++c) out.pixels[i * 4 + c] = black ? 0 : 255;
        }
        steps.push_back(std::move(out));
      }
      break;
    }
    case Ladder::Darken:
      for (int k = 0; k < n; ++k) {
        const float f = 1.0f - 0.85f * float(k) / float(n - 1);
        Planes d = base;
        for (size_t i = 0; i < d.v.size(); ++i)
          if (i % 4 != 3) d.v[i] *= f;
        steps.push_back(toImage(d));
      }
      break;
    case Ladder::Desaturate:
      for (int k = 0; k < n; ++k) {
        // Towards the Rec. 709 luma of each texel.
        const float keep = 1.0f - float(k) / float(n - 1);
        Planes d = base;
        for (size_t i = 0; i < d.v.size(); i += 4) {
          const float luma = 0.2126f * d.v[i] + 0.7152f * d.v[i + 1] + 0.0722f * d.v[i + 2];
          for (size_t c = 0; c < 3; ++c) d.v[i + c] = luma + keep * (d.v[i + c] - luma);
        }
        steps.push_back(toImage(d));
      }
      break;
  }
  if (ladderMatchMode(ladder) == MatchMode::Order) std::reverse(steps.begin(), steps.end());
  return steps;
}

namespace {

struct Written {
  std::string paletteText;
  std::vector<std::pair<std::string, ImageRGBA8>> files;
};

Result<Written> tamPalette(const ImageRGBA8& stroke, int levels, const std::string& stem, const std::function<void(double)>& progress) {
  TamSpec spec;
  spec.tones = levels;
  spec.darkest = 0.85f;
  spec.seed = 5;
  spec.families = {StrokeFamily{45.0f, 5.0f, 0.3f, 0.35f, 2.0f, 0.3f, 0.0f, 1.0f, 0.1f, 0.0f},
                   StrokeFamily{135.0f, 5.0f, 0.3f, 0.35f, 2.0f, 0.3f, 0.0f, 1.0f, 0.1f, 0.4f}};
  spec.stamp = stroke;
  // The ink is the stroke's own colour: its texels' mean weighted by how much ink each holds.
  glm::dvec3 ink(0.0);
  double weight = 0;
  for (size_t i = 0; i < stroke.pixels.size(); i += 4) {
    const double w = (1.0 - luminance(&stroke.pixels[i])) * stroke.pixels[i + 3] / 255.0;
    ink += w * glm::dvec3(stroke.pixels[i], stroke.pixels[i + 1], stroke.pixels[i + 2]) / 255.0;
    weight += w;
  }
  if (weight < 1.0) return Error{"the stroke image has no ink: draw dark strokes on white or on transparency"};
  spec.ink = glm::vec3(ink / weight);
  ImageRGBA8 paper{spec.size, spec.size, std::vector<std::uint8_t>(size_t(spec.size) * size_t(spec.size) * 4, 255)};
  Result<TonalArtMap> tam = buildTonalArtMap(spec, paper, progress);
  if (!tam) return Error{tam.error()};
  Written w;
  w.paletteText = "name " + stem + " (tonal art map)\nmatch intensity\nbackground #FFFFFF\n";
  for (int t = 0; t < levels; ++t) {
    char name[64];
    std::snprintf(name, sizeof name, "level%02d.png", t);
    w.paletteText += std::string(name) + "\n";
    w.files.emplace_back(name, tam->levels[size_t(t)].mips[0]);
    for (size_t m = 1; m < tam->levels[size_t(t)].mips.size(); ++m) {
      char mip[80];
      std::snprintf(mip, sizeof mip, "level%02d-mip%zu.png", t, m);
      w.paletteText += "mip " + std::string(mip) + "\n";
      w.files.emplace_back(mip, tam->levels[size_t(t)].mips[m]);
    }
  }
  return w;
}

}  // namespace

Result<std::string> makePalette(const MakePaletteRequest& r, const std::function<void(double)>& progress) {
  if (r.tam == r.ladder.has_value()) return Error{"--make-palette needs either --ladder STEP or --tam"};
  if (r.levels < kMinMakerLevels || r.levels > kMaxPaletteEntries)
    return Error{"--levels must be " + std::to_string(kMinMakerLevels) + ".." + std::to_string(kMaxPaletteEntries) + ", got " + std::to_string(r.levels)};
  if (r.outDir.empty()) return Error{"--make-palette needs --out DIR, the palette folder to write"};
  const fs::path out = fs::absolute(r.outDir);
  std::error_code ec;
  if (fs::exists(out, ec)) {
    if (!fs::is_directory(out, ec)) return Error{"--out " + r.outDir + ": exists and is not a folder"};
    if (!fs::is_empty(out, ec)) return Error{"--out " + r.outDir + ": the folder is not empty; give a new or empty folder"};
  }
  const fs::path parent = out.parent_path();
  if (!fs::is_directory(parent, ec)) return Error{"--out " + r.outDir + ": its parent folder " + parent.string() + " does not exist"};

  Result<ImageRGBA8> src = loadImage(r.image, ImageSize{1024, 1024});
  if (!src) return Error{"--make-palette: " + src.error()};
  const std::string stem = fs::path(r.image).stem().string();
  Written w;
  if (r.tam) {
    Result<Written> t = tamPalette(*src, r.levels, stem, progress);
    if (!t) return Error{r.image + ": " + t.error()};
    w = std::move(*t);
  } else {
    for (size_t i = 3; i < src->pixels.size(); i += 4) src->pixels[i] = 255;  // ladders work on the opaque image
    Result<std::vector<ImageRGBA8>> images = ladderImages(*src, *r.ladder, r.levels);
    if (!images) return Error{images.error()};
    w.paletteText = "name " + stem + " (" + ladderName(*r.ladder) + ")\nmatch " + choiceName(ladderMatchMode(*r.ladder)) + "\n";
    for (size_t i = 0; i < images->size(); ++i) {
      char name[64];
      std::snprintf(name, sizeof name, "%s%02zu.png", ladderName(*r.ladder), i);
      w.paletteText += std::string(name) + "\n";
      w.files.emplace_back(name, std::move((*images)[i]));
      if (progress) progress(double(i + 1) / double(images->size()));
    }
  }
  w.paletteText = "# Made by npr-viewer --make-palette from " + fs::path(r.image).filename().string() + "\n" + w.paletteText;

  // Everything goes to a temporary sibling first and is moved into place at the end.
  const fs::path temp = parent / ("." + out.filename().string() + ".partial-" + std::to_string(::getpid()));
  fs::remove_all(temp, ec);
  if (!fs::create_directory(temp, ec)) return Error{"--out " + r.outDir + ": cannot write in " + parent.string() + (ec ? " (" + ec.message() + ")" : "")};
  auto fail = [&](const std::string& message) -> Result<std::string> {
    std::error_code ignored;
    fs::remove_all(temp, ignored);
    return Error{message};
  };
  for (const auto& [name, img] : w.files)
    if (Status s = writeImage((temp / name).string(), img); !s) return fail("--out " + r.outDir + ": " + s.error());
  const fs::path paletteFile = temp / (stem + ".palette");
  {
    std::ofstream pf(paletteFile);
    pf << w.paletteText;
    if (!pf.flush()) return fail("--out " + r.outDir + ": cannot write " + paletteFile.string());
  }
  if (fs::exists(out, ec)) fs::remove(out, ec);  // the empty folder the user gave
  fs::rename(temp, out, ec);
  if (ec) return fail("--out " + r.outDir + ": cannot move the finished palette into place (" + ec.message() + ")");
  return (out / (stem + ".palette")).string();
}

}  // namespace npr
