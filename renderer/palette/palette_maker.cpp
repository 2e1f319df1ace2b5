// The palette maker (see palette_maker.h).
#include "renderer/palette/palette_maker.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
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

OIIO::ImageBuf toBuf(const ImageRGBA8& img) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 4, OIIO::TypeDesc::FLOAT));
  std::vector<float> f(img.pixels.size());
  for (size_t i = 0; i < f.size(); ++i) f[i] = img.pixels[i] / 255.0f;
  buf.set_pixels(buf.roi(), OIIO::TypeDesc::FLOAT, f.data());
  return buf;
}

ImageRGBA8 fromBuf(const OIIO::ImageBuf& buf) {
  const OIIO::ImageSpec& s = buf.spec();
  std::vector<float> f(size_t(s.width) * size_t(s.height) * 4);
  buf.get_pixels(OIIO::ROI(0, s.width, 0, s.height, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT, f.data());
  ImageRGBA8 img{s.width, s.height, std::vector<std::uint8_t>(f.size())};
  for (size_t i = 0; i < f.size(); ++i) img.pixels[i] = toByte(f[i]);
  for (size_t i = 3; i < f.size(); i += 4) img.pixels[i] = 255;
  return img;
}

// A Gaussian blur that wraps around the edges (palette images tile): the image is blurred
// within a 3 x 3 tiling of itself and the middle cut out.
Result<OIIO::ImageBuf> wrappedBlur(const OIIO::ImageBuf& src, float width) {
  const int w = src.spec().width, h = src.spec().height;
  OIIO::ImageBuf tiled(OIIO::ImageSpec(3 * w, 3 * h, 4, OIIO::TypeDesc::FLOAT));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (!OIIO::ImageBufAlgo::paste(tiled, i * w, j * h, 0, 0, src)) return Error{"blur: " + tiled.geterror()};
  const OIIO::ImageBuf kernel = OIIO::ImageBufAlgo::make_kernel("gaussian", width, width);
  OIIO::ImageBuf blurred = OIIO::ImageBufAlgo::convolve(tiled, kernel);
  if (blurred.has_error()) return Error{"blur: " + blurred.geterror()};
  OIIO::ImageBuf out = OIIO::ImageBufAlgo::cut(blurred, OIIO::ROI(w, 2 * w, h, 2 * h, 0, 1, 0, 4));
  if (out.has_error()) return Error{"blur: " + out.geterror()};
  return out;
}

// Per-pixel steps OpenImageIO has no algorithm for (solarize, posterize, threshold).
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
  const OIIO::ImageBuf base = toBuf(src);
  switch (ladder) {
    case Ladder::Blur: {
      OIIO::ImageBuf cur = base;
      steps.push_back(src);
      const float width = std::max(3.0f, float(std::min(src.width, src.height)) / 32.0f);
      for (int k = 1; k < n; ++k) {
        Result<OIIO::ImageBuf> b = wrappedBlur(cur, width);
        if (!b) return Error{b.error()};
        cur = std::move(*b);
        steps.push_back(fromBuf(cur));
      }
      break;
    }
    case Ladder::Offset:
      for (int k = 0; k < n; ++k) {
        const OIIO::ImageBuf shifted = OIIO::ImageBufAlgo::circular_shift(base, k * src.width / n, k * src.height / (2 * n));
        if (shifted.has_error()) return Error{"offset: " + shifted.geterror()};
        steps.push_back(fromBuf(shifted));
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
        const float scale[4] = {f, f, f, 1.0f};
        const OIIO::ImageBuf d = OIIO::ImageBufAlgo::mul(base, OIIO::cspan<float>(scale, 4));
        if (d.has_error()) return Error{"darken: " + d.geterror()};
        steps.push_back(fromBuf(d));
      }
      break;
    case Ladder::Desaturate:
      for (int k = 0; k < n; ++k) {
        const OIIO::ImageBuf d = OIIO::ImageBufAlgo::saturate(base, 1.0f - float(k) / float(n - 1));
        if (d.has_error()) return Error{"desaturate: " + d.geterror()};
        steps.push_back(fromBuf(d));
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
