// Palette analysis (see palette_analysis.h).
#include "renderer/palette/palette_analysis.h"

#include "renderer/palette/palette_mipmaps.h"
#include "renderer/palette/tone_thresholds.h"

#include <algorithm>
#include <sstream>

#include "renderer/core/colour.h"
#include "renderer/core/json.h"
#include "renderer/settings/choice_names.h"

namespace npr {

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

PaletteAnalysis analysePalette(const Palette& p, int row) {
  PaletteAnalysis a;
  const std::size_t columns = std::size_t(p.columns());
  if (p.entries.empty() || columns == 0 || row < 0 || std::size_t(row + 1) * columns > p.entries.size()) return a;
  std::vector<float> v;
  for (std::size_t i = 0; i < columns; ++i) v.push_back(p.entries[std::size_t(row) * columns + i].intensity);
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
  const float range = a.maxIntensity - a.minIntensity;
  if (v.size() > 2 && range > 0.0f) {
    const float step = (v.back() - v.front()) / float(v.size() - 1);
    for (size_t i = 1; i < v.size(); ++i) a.spacingError = std::max(a.spacingError, std::fabs(v[i] - v[i - 1] - step) / range);
  }
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
      << "],\"intensity\":" << num(e.intensity) << ",\"orientation_degrees\":" << num(e.orientation.degrees)
      << ",\"orientation_strength\":" << num(e.orientation.strength) << ",\"oriented\":" << (e.orientation.oriented() ? "true" : "false")
      << ",\"row\":" << i / std::size_t(std::max(p.columns(), 1)) << ",\"column\":" << i % std::size_t(std::max(p.columns(), 1));
    // The tone at every mip level the renderer samples, and how far it drifts from level 0's
    // (as a fraction of white): what a scaled or zoomed pattern shows.
    const std::vector<float> tones = entryMipTones(p, i);
    float drift = 0;
    for (float t : tones) drift = std::max(drift, std::fabs(t - tones[0]) / 3.0f);
    o << ",\"mip_levels\":" << tones.size() << ",\"mip_levels_given\":" << e.mips.size() << ",\"mip_tone_drift\":" << num(drift) << "}";
  }
  o << "],\"background\":[" << num(p.backgroundColour.r) << "," << num(p.backgroundColour.g) << "," << num(p.backgroundColour.b)
    << "],\"intensity_range\":[" << num(a.minIntensity) << "," << num(a.maxIntensity) << "],\"largest_gap\":" << num(a.largestGap)
    << ",\"monotonic\":" << (a.monotonic ? "true" : "false") << ",\"spacing_error\":" << num(a.spacingError)
    << ",\"evenly_spaced\":" << (a.spacingError <= PaletteAnalysis::kEvenSpacing ? "true" : "false");
  if (p.defaultMatch) o << ",\"match\":\"" << choiceName(*p.defaultMatch) << "\"";
  // Both axes: the tone (columns, matched against the first row, whose figures are above) and
  // the second axis with each row's tone range.
  o << ",\"columns\":" << p.columns() << ",\"rows\":" << std::max(p.axis.rows, 1) << ",\"axis\":{\"kind\":" << str(paletteAxisName(p.axis.kind));
  if (p.axis.kind != PaletteAxisKind::None) {
    o << ",\"from\":" << num(p.axis.from) << ",\"to\":" << num(p.axis.to)
      << ",\"unit\":" << str(p.axis.kind == PaletteAxisKind::Depth    ? "distance from the eye in scene radii"
                                : p.axis.kind == PaletteAxisKind::Facing ? "1 - |N.V|"
                                                                         : "the object's detail") << ",\"row_intensity_ranges\":[";
    for (int r = 0; r < p.axis.rows; ++r) {
      const PaletteAnalysis ra = analysePalette(p, r);
      o << (r ? "," : "") << "[" << num(ra.minIntensity) << "," << num(ra.maxIntensity) << "]";
    }
    o << "]";
  }
  o << "}";
  // Whether the smooth path can show crisp tone (--tone-blend threshold), and if not, why.
  const Result<std::vector<std::uint8_t>> thresholds = paletteToneThresholds(p);
  o << ",\"tone_thresholds\":" << (thresholds ? "true" : "false");
  if (!thresholds) o << ",\"tone_thresholds_note\":" << str("no threshold map: " + thresholds.error());
  o << ",\"warnings\":[";
  std::vector<std::string> w = p.warnings;
  if (p.defaultMatch) for (auto& s : a.suitabilityWarnings(*p.defaultMatch)) w.push_back(s);
  for (size_t i = 0; i < w.size(); ++i) o << (i ? "," : "") << str(w[i]);
  o << "]}";
  return o.str();
}

}  // namespace npr
