// Palette file parsing, image loading through OpenImageIO and alpha-aware analysis.
#include "renderer/palette/palette.h"

#include "renderer/core/json.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "renderer/core/colour.h"

namespace npr {
namespace fs = std::filesystem;

const char* matchModeName(MatchMode m) {
  switch (m) {
    case MatchMode::Colors: return "colors";
    case MatchMode::Intensity: return "intensity";
    case MatchMode::Order: return "order";
  }
  return "?";
}

std::optional<MatchMode> parseMatchMode(const std::string& s) {
  if (s == "colors" || s == "colours" || s == "color") return MatchMode::Colors;
  if (s == "intensity") return MatchMode::Intensity;
  if (s == "order") return MatchMode::Order;
  return std::nullopt;
}

std::vector<glm::vec3> Palette::averages() const {
  std::vector<glm::vec3> a;
  a.reserve(entries.size());
  for (const auto& e : entries) a.push_back(e.average);
  return a;
}

namespace {

constexpr int kMaxImageSide = 16384;
// Layers of the palette's texture array share one size; beyond this budget entries are
// downsampled with OpenImageIO so the array still fits in memory.
constexpr std::size_t kTextureBudgetBytes = std::size_t(1) << 30;

const std::array<float, 256>& srgbTable() {
  static const std::array<float, 256> t = [] {
    std::array<float, 256> a{};
    for (int i = 0; i < 256; ++i) a[static_cast<size_t>(i)] = srgbToLinear(i / 255.0f);
    return a;
  }();
  return t;
}

std::uint8_t toByte(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r\n");
  return s.substr(a, b - a + 1);
}

std::optional<glm::vec3> parseHexColour(const std::string& s) {
  if (s.size() != 7 || s[0] != '#') return std::nullopt;
  unsigned v = 0;
  for (size_t i = 1; i < 7; ++i) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(s[i])));
    if (!std::isxdigit(static_cast<unsigned char>(c))) return std::nullopt;
    v = v * 16 + static_cast<unsigned>(std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : c - 'a' + 10);
  }
  return glm::vec3((v >> 16) & 255, (v >> 8) & 255, v & 255) / 255.0f;
}

glm::vec3 linearMean(const ImageRGBA8& img) {
  const auto& lut = srgbTable();
  glm::dvec3 s(0.0);
  const size_t n = static_cast<size_t>(img.width) * static_cast<size_t>(img.height);
  for (size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &img.pixels[i * 4];
    s += glm::dvec3(lut[p[0]], lut[p[1]], lut[p[2]]);
  }
  return n ? glm::vec3(s / double(n)) : glm::vec3(1.0f);
}

Result<ImageRGBA8> resizeImage(const ImageRGBA8& img, int w, int h) {
  OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
  OIIO::ImageBuf src(spec, const_cast<std::uint8_t*>(img.pixels.data()));
  OIIO::ImageBuf dst = OIIO::ImageBufAlgo::resize(src, "", 0.0f, OIIO::ROI(0, w, 0, h, 0, 1, 0, 4));
  if (dst.has_error()) return Error{"resize failed: " + dst.geterror()};
  ImageRGBA8 out{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
  dst.get_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, 4), OIIO::TypeDesc::UINT8, out.pixels.data());
  return out;
}

}  // namespace

Result<ImageRGBA8> loadImage(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path + ": no such image file"};
  if (fs::is_directory(path, ec)) return Error{path + ": is a directory, not an image"};
  // Keep straight (unassociated) alpha: OpenImageIO would otherwise premultiply PNG and TGA
  // colours on read, and the compositing below expects straight alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    std::string why = OIIO::geterror();
    if (why.empty()) why = "unsupported or corrupt image";
    return Error{path + ": cannot read image: " + why};
  }
  const OIIO::ImageSpec spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide || spec.height > kMaxImageSide)
    return Error{path + ": image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                 " is outside 1.." + std::to_string(kMaxImageSide)};
  const int nc = spec.nchannels;
  if (nc < 1) return Error{path + ": image has no channels"};
  const int alpha = spec.alpha_channel >= 0 ? spec.alpha_channel : (nc == 2 ? 1 : (nc >= 4 ? 3 : -1));
  const bool isFloat = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
                       spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  ImageRGBA8 img{spec.width, spec.height, std::vector<std::uint8_t>(static_cast<size_t>(spec.width) * spec.height * 4)};
  const int rowsPerChunk = 64;
  std::vector<float> buf(static_cast<size_t>(spec.width) * rowsPerChunk * nc);
  for (int y0 = 0; y0 < spec.height; y0 += rowsPerChunk) {
    const int y1 = std::min(spec.height, y0 + rowsPerChunk);
    if (!in->read_scanlines(0, 0, y0 + spec.y, y1 + spec.y, 0, 0, nc, OIIO::TypeDesc::FLOAT, buf.data())) {
      std::string why = in->geterror();
      return Error{path + ": image data could not be read (truncated or corrupt): " + (why.empty() ? "read failed" : why)};
    }
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        const float* s = &buf[(static_cast<size_t>(y - y0) * spec.width + x) * nc];
        float rgb[3];
        if (nc <= 2) rgb[0] = rgb[1] = rgb[2] = s[0];
        else for (int k = 0; k < 3; ++k) rgb[k] = s[k];
        if (isFloat) for (float& v : rgb) v = linearToSrgb(v);  // float images hold linear light
        std::uint8_t* d = &img.pixels[(static_cast<size_t>(y) * spec.width + x) * 4];
        for (int k = 0; k < 3; ++k) d[k] = toByte(rgb[k]);
        d[3] = alpha >= 0 ? toByte(s[alpha]) : 255;
      }
    }
  }
  return img;
}

ImageRGBA8 compositeOver(const ImageRGBA8& img, const glm::vec3& bgColour, const ImageRGBA8* bgImage) {
  const bool perTexel = bgImage && bgImage->width == img.width && bgImage->height == img.height;
  ImageRGBA8 out{img.width, img.height, std::vector<std::uint8_t>(img.pixels.size())};
  const size_t n = static_cast<size_t>(img.width) * static_cast<size_t>(img.height);
  const glm::vec3 bgMean = bgColour * 255.0f;
  for (size_t i = 0; i < n; ++i) {
    const std::uint8_t* p = &img.pixels[i * 4];
    const float a = p[3] / 255.0f;
    for (int k = 0; k < 3; ++k) {
      const float b = perTexel ? float(bgImage->pixels[i * 4 + static_cast<size_t>(k)]) : bgMean[k];
      out.pixels[i * 4 + static_cast<size_t>(k)] = toByte((a * p[k] + (1.0f - a) * b) / 255.0f);
    }
    out.pixels[i * 4 + 3] = 255;
  }
  return out;
}

glm::vec3 compositeAverage(const ImageRGBA8& img, const glm::vec3& bgColour, const ImageRGBA8* bgImage) {
  const ImageRGBA8 c = compositeOver(img, bgColour, bgImage);
  return linearToSrgb(linearMean(c));
}

Result<Palette> loadPalette(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path + ": no such palette file"};
  if (fs::is_directory(path, ec)) {
    // A palette folder holds its palette file: accept the folder for convenience.
    for (const auto& e : fs::directory_iterator(path, ec))
      if (e.path().extension() == ".palette") return loadPalette(e.path().string());
    return Error{path + ": is a directory with no .palette file in it"};
  }
  std::ifstream in(path);
  if (!in) return Error{path + ": cannot be opened for reading"};
  const fs::path dir = fs::path(path).parent_path();
  Palette p;
  p.file = path;
  p.name = fs::path(path).stem().string();
  std::string bgSpec;
  int bgLine = 0;
  struct Pending { std::string path; int line; };
  std::vector<Pending> images;
  std::string raw;
  int lineNo = 0;
  while (std::getline(in, raw)) {
    ++lineNo;
    if (lineNo == 1 && raw.size() >= 2 && static_cast<unsigned char>(raw[0]) >= 0xFE) return Error{path + ": palette file is UTF-16; save it as UTF-8"};
    if (raw.find('\0') != std::string::npos) return Error{path + " line " + std::to_string(lineNo) + ": binary data in a palette file"};
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::string where = path + " line " + std::to_string(lineNo);
    const auto sp = line.find_first_of(" \t");
    const std::string key = line.substr(0, sp);
    const std::string arg = sp == std::string::npos ? "" : trim(line.substr(sp));
    if (key == "background") {
      if (arg.empty()) return Error{where + ": 'background' needs an image path or a #RRGGBB colour"};
      bgSpec = arg;
      bgLine = lineNo;
    } else if (key == "match") {
      auto m = parseMatchMode(arg);
      if (!m) return Error{where + ": unknown match mode '" + arg + "' (use colors, intensity or order)"};
      p.defaultMatch = m;
    } else if (key == "range-scale") {
      char* end = nullptr;
      const float s = std::strtof(arg.c_str(), &end);
      if (arg.empty() || *end != '\0' || !std::isfinite(s) || s <= 0.0f)
        return Error{where + ": range-scale must be a finite number > 0, got '" + arg + "'"};
      p.defaultRangeScale = s;
    } else if (key == "name") {
      p.name = arg;
    } else {
      images.push_back({line, lineNo});
    }
  }
  if (images.empty()) return Error{path + ": the palette lists no images (one image path per line)"};
  if (images.size() > static_cast<size_t>(kMaxPaletteEntries))
    return Error{path + " line " + std::to_string(images[kMaxPaletteEntries].line) + ": more than " +
                 std::to_string(kMaxPaletteEntries) + " entries (a palette holds at most " + std::to_string(kMaxPaletteEntries) + ")"};

  if (!bgSpec.empty()) {
    if (auto c = parseHexColour(bgSpec)) {
      p.backgroundColour = *c;
    } else if (bgSpec[0] == '#') {
      return Error{path + " line " + std::to_string(bgLine) + ": background colour '" + bgSpec + "' is not #RRGGBB"};
    } else {
      Result<ImageRGBA8> bg = loadImage((dir / bgSpec).string());
      if (!bg) return Error{path + " line " + std::to_string(bgLine) + ": background: " + bg.error()};
      p.backgroundColour = linearToSrgb(linearMean(*bg));
      p.backgroundImage = std::move(*bg);
    }
  }
  std::size_t maxW = 1, maxH = 1;
  for (const Pending& im : images) {
    Result<ImageRGBA8> img = loadImage((dir / im.path).string());
    if (!img) return Error{path + " line " + std::to_string(im.line) + ": " + img.error()};
    PaletteEntry e;
    e.path = im.path;
    e.image = std::move(*img);
    e.average = compositeAverage(e.image, p.backgroundColour, p.backgroundImage ? &*p.backgroundImage : nullptr);
    e.intensity = e.average.r + e.average.g + e.average.b;
    maxW = std::max<std::size_t>(maxW, static_cast<size_t>(e.image.width));
    maxH = std::max<std::size_t>(maxH, static_cast<size_t>(e.image.height));
    p.entries.push_back(std::move(e));
  }
  const std::size_t bytes = maxW * maxH * 4 * p.entries.size();
  if (bytes > kTextureBudgetBytes) {
    const double f = std::sqrt(double(kTextureBudgetBytes) / double(bytes));
    const int w = std::max(1, int(double(maxW) * f)), h = std::max(1, int(double(maxH) * f));
    for (PaletteEntry& e : p.entries) {
      if (e.image.width <= w && e.image.height <= h) continue;
      Result<ImageRGBA8> r = resizeImage(e.image, std::min(w, e.image.width), std::min(h, e.image.height));
      if (!r) return Error{path + ": " + e.path + ": " + r.error()};
      e.image = std::move(*r);
    }
    p.warnings.push_back("textures downsampled to at most " + std::to_string(w) + "x" + std::to_string(h) +
                         " so the palette's texture array fits in " + std::to_string(kTextureBudgetBytes >> 20) + " MiB");
  }
  return p;
}

PaletteAnalysis analysePalette(const Palette& p) {
  PaletteAnalysis a;
  if (p.entries.empty()) return a;
  std::vector<float> v;
  for (const auto& e : p.entries) v.push_back(e.intensity);
  a.minIntensity = *std::min_element(v.begin(), v.end());
  a.maxIntensity = *std::max_element(v.begin(), v.end());
  std::vector<float> s = v;
  std::sort(s.begin(), s.end());
  for (size_t i = 1; i < s.size(); ++i) a.largestGap = std::max(a.largestGap, s[i] - s[i - 1]);
  bool inc = true, dec = true;
  for (size_t i = 1; i < v.size(); ++i) {
    inc = inc && v[i] > v[i - 1];
    dec = dec && v[i] < v[i - 1];
  }
  a.monotonic = v.size() < 2 || inc || dec;
  return a;
}

std::vector<std::string> PaletteAnalysis::suitabilityWarnings(MatchMode mode) const {
  std::vector<std::string> w;
  const float range = maxIntensity - minIntensity;
  if (mode == MatchMode::Intensity) {
    if (range < 0.3f)
      w.push_back("palette intensities span only " + std::to_string(range) +
                  " of 3: most of the model gets one texture; raise range-scale or use match order");
    else if (largestGap > 0.5f * range && range > 0.0f)
      w.push_back("palette intensities are unevenly spaced (largest gap " + std::to_string(largestGap) + "): expect visible jumps");
  }
  if (mode == MatchMode::Intensity && !monotonic && range >= 0.3f)
    w.push_back("palette order is not monotonic in intensity: match intensity will reorder it (match order keeps the file's order)");
  return w;
}

std::string paletteReportJson(const Palette& p) {
  const PaletteAnalysis a = analysePalette(p);
  std::ostringstream o;
  auto num = [](float f) { return json::number(f); };
  auto str = [](const std::string& s) { return json::string(s); };
  o << "{\"file\":" << str(p.file) << ",\"name\":" << str(p.name) << ",\"entries\":[";
  for (size_t i = 0; i < p.entries.size(); ++i) {
    const auto& e = p.entries[i];
    o << (i ? "," : "") << "{\"path\":" << str(e.path) << ",\"width\":" << e.image.width << ",\"height\":" << e.image.height
      << ",\"average\":[" << num(e.average.r) << "," << num(e.average.g) << "," << num(e.average.b)
      << "],\"intensity\":" << num(e.intensity) << "}";
  }
  o << "],\"background\":[" << num(p.backgroundColour.r) << "," << num(p.backgroundColour.g) << "," << num(p.backgroundColour.b)
    << "],\"intensity_range\":[" << num(a.minIntensity) << "," << num(a.maxIntensity) << "],\"largest_gap\":" << num(a.largestGap)
    << ",\"monotonic\":" << (a.monotonic ? "true" : "false");
  if (p.defaultMatch) o << ",\"match\":\"" << matchModeName(*p.defaultMatch) << "\"";
  o << ",\"warnings\":[";
  std::vector<std::string> w = p.warnings;
  if (p.defaultMatch) for (auto& s : a.suitabilityWarnings(*p.defaultMatch)) w.push_back(s);
  for (size_t i = 0; i < w.size(); ++i) o << (i ? "," : "") << str(w[i]);
  o << "]}";
  return o.str();
}

}  // namespace npr
