// Palette files: parsing a .palette, loading its images and their averages (see palette.h).
#include "renderer/palette/palette.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "renderer/core/colour.h"
#include "renderer/core/image_io.h"
#include "renderer/core/input_file.h"
#include "renderer/core/parallel.h"
#include "renderer/core/printable.h"
#include "renderer/palette/palette_analysis.h"
#include "renderer/palette/palette_mipmaps.h"
#include "renderer/settings/choice_names.h"

namespace npr {
namespace fs = std::filesystem;

// A palette file's `match` line: the settings' names, and the British and singular spellings.
std::optional<MatchMode> parseMatchMode(const std::string& s) {
  if (s == "colours" || s == "color") return MatchMode::Colors;
  return parseChoice<MatchMode>(s);
}

const char* paletteAxisName(PaletteAxisKind k) {
  switch (k) {
    case PaletteAxisKind::None: return "none";
    case PaletteAxisKind::Depth: return "depth";
    case PaletteAxisKind::Facing: return "facing";
    case PaletteAxisKind::Detail: return "detail";
  }
  return "?";
}

std::vector<glm::vec3> Palette::averages() const {
  std::vector<glm::vec3> a;
  a.reserve(entries.size());
  for (const auto& e : entries) a.push_back(e.average);
  return a;
}

namespace {

// Layers of the palette's texture array share one size; beyond this budget entries are
// reduced as they are read so the array still fits in memory.
constexpr std::size_t kTextureBudgetBytes = std::size_t(1) << 30;
// Images declaring more than this in all (four 16384 x 16384 images) are refused before any is
// decoded: reducing them would still mean inflating every declared pixel, minutes of work.
constexpr double kMaxDeclaredPixels = 4.0 * 16384.0 * 16384.0;

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

}  // namespace

Result<Palette> loadPalette(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    // A palette folder holds its palette file: accept the folder for convenience.
    for (const auto& e : fs::directory_iterator(path, ec))
      if (e.path().extension() == ".palette") return loadPalette(e.path().string());
    return Error{path + ": is a directory with no .palette file in it"};
  }
  Result<std::string> text = readInputFile(path, InputKind::Palette);
  if (!text) return Error{text.error()};
  std::istringstream in(*text);
  const fs::path dir = fs::path(path).parent_path();
  Palette p;
  p.file = path;
  p.name = fs::path(path).stem().string();
  std::string bgSpec;
  int bgLine = 0;
  struct Pending {
    std::string path;
    int line;
    std::vector<Pending> mips;
  };
  std::vector<Pending> images;
  std::vector<std::pair<std::size_t, int>> rowStarts{{0, 0}};  // first image of each row, and the 'row' line
  int axisLine = 0;
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
      if (!m) return Error{where + ": unknown match mode '" + printable(arg) + "' (use colors, intensity or order)"};
      p.defaultMatch = m;
    } else if (key == "range-scale") {
      char* end = nullptr;
      const float s = std::strtof(arg.c_str(), &end);
      if (arg.empty() || *end != '\0' || !std::isfinite(s) || s <= 0.0f)
        return Error{where + ": range-scale must be a finite number > 0, got '" + printable(arg) + "'"};
      p.defaultRangeScale = s;
    } else if (key == "axis") {
      if (axisLine) return Error{where + ": a second 'axis' line (the first is line " + std::to_string(axisLine) + ")"};
      std::istringstream words(arg);
      std::string kind, extra;
      words >> kind;
      if (kind == "depth") p.axis.kind = PaletteAxisKind::Depth;
      else if (kind == "facing") p.axis.kind = PaletteAxisKind::Facing;
      else if (kind == "detail") p.axis.kind = PaletteAxisKind::Detail;
      else return Error{where + ": unknown axis '" + printable(kind) + "' (use 'axis depth NEAR FAR', 'axis facing [FROM TO]' or 'axis detail [FROM TO]')"};
      std::string a, b;
      words >> a >> b;
      if (words >> extra) return Error{where + ": 'axis " + kind + "' takes two numbers, and there is more: '" + printable(extra) + "'"};
      if (a.empty() && p.axis.kind == PaletteAxisKind::Depth)
        return Error{where + ": 'axis depth' needs NEAR and FAR (distances from the eye in scene radii, e.g. 'axis depth 2 4')"};
      if (!a.empty()) {
        char* endA = nullptr;
        char* endB = nullptr;
        const float from = std::strtof(a.c_str(), &endA), to = std::strtof(b.c_str(), &endB);
        if (b.empty() || *endA != '\0' || *endB != '\0' || !std::isfinite(from) || !std::isfinite(to))
          return Error{where + ": 'axis " + kind + "' needs two numbers, got '" + printable(arg) + "'"};
        if (from >= to) return Error{where + ": 'axis " + kind + "': " + a + " must be less than " + b + " (the first row's value, then the last's)"};
        if (p.axis.kind == PaletteAxisKind::Depth && from < 0.0f) return Error{where + ": 'axis depth': NEAR must be 0 or more, got " + a};
        if (p.axis.kind == PaletteAxisKind::Facing && (from < 0.0f || to > 1.0f))
          return Error{where + ": 'axis facing': FROM and TO lie in [0, 1] (0 facing the eye, 1 edge-on), got '" + printable(arg) + "'"};
        if (p.axis.kind == PaletteAxisKind::Detail && (from < 0.0f || to > 1.0f))
          return Error{where + ": 'axis detail': FROM and TO lie in [0, 1] (an object's detail), got '" + printable(arg) + "'"};
        p.axis.from = from;
        p.axis.to = to;
      }
      axisLine = lineNo;
    } else if (key == "row") {
      if (!arg.empty()) return Error{where + ": 'row' takes nothing after it"};
      // A 'row' before any image starts the first row.
      if (!images.empty()) {
        if (images.size() == rowStarts.back().first) return Error{where + ": an empty row (no images since the 'row' on line " + std::to_string(rowStarts.back().second) + ")"};
        rowStarts.push_back({images.size(), lineNo});
      } else {
        rowStarts.front().second = lineNo;
      }
    } else if (key == "name") {
      p.name = arg;
    } else if (key == "mip") {
      if (images.empty()) return Error{where + ": 'mip' must follow the entry whose next mip level it is"};
      if (arg.empty()) return Error{where + ": 'mip' needs an image path"};
      images.back().mips.push_back({arg, lineNo, {}});
    } else {
      images.push_back({line, lineNo, {}});
    }
  }
  if (images.empty()) return Error{path + ": the palette lists no images (one image path per line)"};
  const std::size_t rows = rowStarts.size();
  if (rows > 1 && !axisLine) return Error{path + " line " + std::to_string(rowStarts[1].second) + ": 'row' lines need an 'axis' line saying what picks the row"};
  if (axisLine && rows < 2) return Error{path + " line " + std::to_string(axisLine) + ": an axis needs at least two rows ('row' lines between them)"};
  if (rows > 1) {
    const std::size_t columns = rowStarts[1].first;
    for (std::size_t r = 1; r < rows; ++r) {
      const std::size_t count = (r + 1 < rows ? rowStarts[r + 1].first : images.size()) - rowStarts[r].first;
      if (count != columns)
        return Error{path + " line " + std::to_string(rowStarts[r].second) + ": row " + std::to_string(r + 1) + " has " + std::to_string(count) +
                     (count == 1 ? " image" : " images") + "; every row needs as many as the first (" + std::to_string(columns) + ")"};
    }
    p.axis.rows = static_cast<int>(rows);
  }
  if (images.size() > static_cast<size_t>(kMaxPaletteEntries))
    return Error{path + " line " + std::to_string(images[kMaxPaletteEntries].line) + ": more than " +
                 std::to_string(kMaxPaletteEntries) + " entries (a palette holds at most " + std::to_string(kMaxPaletteEntries) + ")"};

  // Every image's declared size is read from its header first, so the budget decides how
  // large each is decoded before any pixel exists in memory.
  std::vector<ImageSize> sizes;
  double declaredPixels = 0.0;
  std::size_t maxW = 1, maxH = 1;
  for (const Pending& im : images) {
    Result<ImageSize> size = readImageSize((dir / im.path).string());
    if (!size) return Error{path + " line " + std::to_string(im.line) + ": " + size.error()};
    sizes.push_back(*size);
    declaredPixels += double(size->width) * size->height;
    maxW = std::max<std::size_t>(maxW, static_cast<size_t>(size->width));
    maxH = std::max<std::size_t>(maxH, static_cast<size_t>(size->height));
  }
  if (declaredPixels > kMaxDeclaredPixels)
    return Error{path + ": its images declare " + std::to_string(static_cast<long long>(declaredPixels / 1e6)) +
                 " megapixels in all, more than the " + std::to_string(static_cast<long long>(kMaxDeclaredPixels / 1e6)) +
                 " a palette may hold; use smaller images"};
  ImageSize fit{kMaxImageSide, kMaxImageSide};
  const std::size_t bytes = maxW * maxH * 4 * images.size();
  if (bytes > kTextureBudgetBytes) {
    const double f = std::sqrt(double(kTextureBudgetBytes) / double(bytes));
    fit = {std::max(1, int(double(maxW) * f)), std::max(1, int(double(maxH) * f))};
    p.warnings.push_back("textures reduced to at most " + std::to_string(fit.width) + "x" + std::to_string(fit.height) +
                         " so the palette's texture array fits in " + std::to_string(kTextureBudgetBytes >> 20) + " MiB");
  }

  if (!bgSpec.empty()) {
    if (auto c = parseHexColour(bgSpec)) {
      p.backgroundColour = *c;
    } else if (bgSpec[0] == '#') {
      return Error{path + " line " + std::to_string(bgLine) + ": background colour '" + bgSpec + "' is not #RRGGBB"};
    } else {
      Result<ImageRGBA8> bg = loadImage((dir / bgSpec).string(), fit);
      if (!bg) return Error{path + " line " + std::to_string(bgLine) + ": background: " + bg.error()};
      p.backgroundColour = linearToSrgb(linearMean(*bg));
      p.backgroundImage = std::move(*bg);
    }
  }
  // Each entry is decoded, analysed and given its levels on its own, the entries spread over
  // the cores (the crosshatch's ten levels with their mips: 110 ms on one core of this machine
  // before); errors and warnings are then said in the file's order, as one at a time would.
  auto loadEntry = [&](const Pending& im, const ImageSize& declared, std::vector<std::string>& warnings) -> Result<PaletteEntry> {
    Result<ImageRGBA8> img = loadImage((dir / im.path).string(), fit);
    if (!img) return Error{path + " line " + std::to_string(im.line) + ": " + img.error()};
    PaletteEntry e;
    e.path = im.path;
    e.image = std::move(*img);
    e.average = compositeAverage(e.image, p.backgroundColour, p.backgroundImage ? &*p.backgroundImage : nullptr);
    e.intensity = e.average.r + e.average.g + e.average.b;
    e.orientation = textureOrientation(e.image, p.backgroundColour);
    // Given levels must halve the level above exactly (GL's rule); an entry reduced to fit the
    // budget drops them (they are reduced from it instead).
    const bool reduced = e.image.width != declared.width || e.image.height != declared.height;
    if (reduced && !im.mips.empty()) warnings.push_back(im.path + ": its mip levels are reduced from the smaller image instead");
    for (const Pending& m : reduced ? std::vector<Pending>{} : im.mips) {
      const ImageRGBA8& above = e.mips.empty() ? e.image : e.mips.back();
      const int level = static_cast<int>(e.mips.size()) + 1;
      if (std::min(mipSide(e.image.width, level), mipSide(e.image.height, level)) < kMinMipSide)
        return Error{path + " line " + std::to_string(m.line) + ": mip level " + std::to_string(level) + " of " + im.path +
                     " is smaller than " + std::to_string(kMinMipSide) + " texels a side; palettes keep no levels that small"};
      const std::string mipWhere = path + " line " + std::to_string(m.line);
      // The declared size is checked before anything is decoded.
      Result<ImageSize> ms = readImageSize((dir / m.path).string());
      if (!ms) return Error{mipWhere + ": " + ms.error()};
      if (ms->width != mipSide(above.width, 1) || ms->height != mipSide(above.height, 1))
        return Error{mipWhere + ": mip level " + std::to_string(level) + " " + m.path + " is " + std::to_string(ms->width) + "x" +
                     std::to_string(ms->height) + "; it must be half the level above, " + std::to_string(mipSide(above.width, 1)) +
                     "x" + std::to_string(mipSide(above.height, 1))};
      Result<ImageRGBA8> mi = loadImage((dir / m.path).string());
      if (!mi) return Error{mipWhere + ": " + mi.error()};
      e.mips.push_back(std::move(*mi));
    }
    return e;
  };
  std::vector<std::optional<Result<PaletteEntry>>> loaded(images.size());
  std::vector<std::vector<std::string>> entryWarnings(images.size());
  parallelChunks(images.size(), workerCount(), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t i = b; i < e; ++i) loaded[i] = loadEntry(images[i], sizes[i], entryWarnings[i]);
  }, 1);
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (!*loaded[i]) return Error{loaded[i]->error()};
    for (std::string& w : entryWarnings[i]) p.warnings.push_back(std::move(w));
    p.entries.push_back(std::move(loaded[i]->value()));
  }
  return p;
}

}  // namespace npr
